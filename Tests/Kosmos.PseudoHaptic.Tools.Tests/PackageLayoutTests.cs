using System.Text.Json;
using System.Text.RegularExpressions;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tools.Tests;

/// <summary>Unity's package rules, checked without Unity: every asset has a .meta with a unique GUID, the
/// manifest and assembly definitions say what the package promises.</summary>
public class PackageLayoutTests
{
    static readonly string Package = Path.Combine(RepositoryRoot.Path, "Packages", "com.kosmos.pseudohaptic");
    static readonly string[] AssetRoots = { Package, Path.Combine(RepositoryRoot.Path, "Assets", "Samples") };
    static readonly Regex Guid = new(@"^guid: ([0-9a-f]{32})\s*$", RegexOptions.Multiline);

    static IEnumerable<string> Assets(string root)
    {
        if (!Directory.Exists(root)) yield break;
        foreach (var entry in Directory.EnumerateFileSystemEntries(root))
        {
            string name = Path.GetFileName(entry);
            if (name.StartsWith('.') || name.EndsWith(".meta")) continue;
            bool isDir = Directory.Exists(entry);
            // Documentation~ and Samples~ are ignored by Unity, so they have no .meta; but the Package Manager imports a
            // sample with its .meta files, and a scene using a sample's script loses it on re-import without them.
            if (isDir && name == "Samples~") { foreach (var inner in Assets(entry)) yield return inner; continue; }
            if (isDir && name.EndsWith('~')) continue;
            if (isDir && (name is "bin" or "obj")) continue;
            yield return entry;
            if (isDir) foreach (var inner in Assets(entry)) yield return inner;
        }
    }

    [Test]
    public void EveryAssetHasAMetaWithAUniqueGuid()
    {
        var missing = new List<string>();
        var seen = new Dictionary<string, string>();
        var duplicates = new List<string>();
        foreach (var root in AssetRoots)
            foreach (var asset in Assets(root))
            {
                string meta = asset + ".meta";
                if (!File.Exists(meta)) { missing.Add(Path.GetRelativePath(RepositoryRoot.Path, asset)); continue; }
                var m = Guid.Match(File.ReadAllText(meta));
                Assert.That(m.Success, Is.True, meta + " has no 32-hex guid");
                if (!seen.TryAdd(m.Groups[1].Value, asset)) duplicates.Add(asset + " and " + seen[m.Groups[1].Value]);
            }
        Assert.That(missing, Is.Empty, "assets without .meta (run python3 Tools/generate-meta.py)");
        Assert.That(duplicates, Is.Empty, "duplicate GUIDs");
        Assert.That(seen.Count, Is.GreaterThan(20));
    }

    [Test]
    public void NoMetaIsOrphaned()
    {
        foreach (var root in AssetRoots)
        {
            if (!Directory.Exists(root)) continue;
            foreach (var meta in Directory.EnumerateFiles(root, "*.meta", SearchOption.AllDirectories))
            {
                string asset = meta[..^".meta".Length];
                Assert.That(File.Exists(asset) || Directory.Exists(asset), Is.True, "orphaned " + meta);
            }
        }
    }

    [Test]
    public void ManifestSaysWhatThePackagePromises()
    {
        using var doc = JsonDocument.Parse(File.ReadAllText(Path.Combine(Package, "package.json")));
        var root = doc.RootElement;
        Assert.That(root.GetProperty("name").GetString(), Is.EqualTo("com.kosmos.pseudohaptic"));
        Assert.That(root.GetProperty("version").GetString(), Does.Match(@"^\d+\.\d+\.\d+$"));
        Assert.That(root.GetProperty("unity").GetString(), Is.EqualTo("2022.3"));
        Assert.That(root.GetProperty("displayName").GetString(), Is.Not.Empty);
        Assert.That(root.GetProperty("description").GetString(), Is.Not.Empty);
        if (root.TryGetProperty("dependencies", out var deps))
            foreach (var d in deps.EnumerateObject())
                Assert.That(d.Name, Does.StartWith("com.unity.").Or.StartWith("com.meta."), "the package depends only on Unity/Meta packages");
        if (root.TryGetProperty("samples", out var samples))
            foreach (var s in samples.EnumerateArray())
                Assert.That(Directory.Exists(Path.Combine(Package, s.GetProperty("path").GetString()!)), Is.True, "sample folder " + s.GetProperty("path"));
        foreach (var f in new[] { "CHANGELOG.md", "LICENSE.md", "Documentation~/ALGORITHM.md" })
            Assert.That(File.Exists(Path.Combine(Package, f)), Is.True, f);
    }

    [Test]
    public void TheCoreIsEngineFree()
    {
        var core = Path.Combine(Package, "Runtime", "Core");
        using var asmdef = JsonDocument.Parse(File.ReadAllText(Path.Combine(core, "Kosmos.PseudoHaptic.Core.asmdef")));
        Assert.That(asmdef.RootElement.GetProperty("name").GetString(), Is.EqualTo("Kosmos.PseudoHaptic.Core"));
        Assert.That(asmdef.RootElement.GetProperty("noEngineReferences").GetBoolean(), Is.True);
        foreach (var cs in Directory.EnumerateFiles(core, "*.cs", SearchOption.AllDirectories))
            Assert.That(File.ReadAllText(cs), Does.Not.Contain("UnityEngine").And.Not.Contain("System.Linq"), cs);
    }

    [Test]
    public void EditModeTestsAreWiredForUnity()
    {
        var dir = Path.Combine(Package, "Tests", "Editor");
        var asmdefPath = Directory.GetFiles(dir, "*.asmdef").Single();
        using var asmdef = JsonDocument.Parse(File.ReadAllText(asmdefPath));
        var root = asmdef.RootElement;
        Assert.That(root.GetProperty("defineConstraints").EnumerateArray().Select(e => e.GetString()), Does.Contain("UNITY_INCLUDE_TESTS"));
        Assert.That(root.GetProperty("references").EnumerateArray().Select(e => e.GetString()), Does.Contain("Kosmos.PseudoHaptic.Core"));
        Assert.That(root.GetProperty("precompiledReferences").EnumerateArray().Select(e => e.GetString()), Does.Contain("nunit.framework.dll"));
        using var manifest = JsonDocument.Parse(File.ReadAllText(Path.Combine(RepositoryRoot.Path, "Packages", "manifest.json")));
        Assert.That(manifest.RootElement.GetProperty("testables").EnumerateArray().Select(e => e.GetString()), Does.Contain("com.kosmos.pseudohaptic"));
        Assert.That(File.ReadAllText(Path.Combine(RepositoryRoot.Path, "ProjectSettings", "ProjectVersion.txt")), Does.Contain("m_EditorVersion: 2022.3."));
    }
}
