using System.Text.Json;
using System.Text.RegularExpressions;

namespace Kosmos.PseudoHaptic.UnityCompile;

/// <summary>
/// The repository as the Unity project it is: the editor version (ProjectSettings/ProjectVersion.txt), the package
/// versions a versionDefine can name (Packages/manifest.json, the embedded package's own package.json and its
/// dependencies, and the packages the pinned ones pull in: <see cref="Transitive"/>), the testables, the embedded
/// package's asmdefs and the sources each one owns.
/// </summary>
public sealed class UnityProject
{
    public const string PackageName = "com.kosmos.pseudohaptic";

    /// <summary>
    /// Packages the manifest does not list but a pinned package depends on (their own package.json at the pinned
    /// tags): Unity resolves them, so a versionDefine may name them. The lowest version asked for is used; Unity
    /// may resolve a higher one, which no versionDefine of this package distinguishes.
    /// </summary>
    public static readonly IReadOnlyDictionary<string, string> Transitive = new Dictionary<string, string>
    {
        ["com.meta.xr.sdk.interaction"] = "68.0.0",  // com.meta.xr.sdk.interaction.ovr 68.0.0 depends on it
        ["com.unity.xr.core-utils"] = "2.2.0",       // com.unity.xr.hands 1.5.0
        ["com.unity.inputsystem"] = "1.3.0",         // com.unity.xr.hands 1.5.0 (XRI 2.5.4 asks for 1.7.0)
        ["com.unity.mathematics"] = "1.2.6",         // com.unity.xr.hands 1.5.0, com.unity.xr.interaction.toolkit 2.5.4
        ["com.unity.xr.legacyinputhelpers"] = "2.1.10", // com.unity.xr.interaction.toolkit 2.5.4
        ["com.unity.ext.nunit"] = "1.0.6",           // com.unity.test-framework 1.1.33
    };

    public string Root { get; }
    public string PackageFolder => Path.Combine(Root, "Packages", PackageName);
    public string UnityVersion { get; }
    public IReadOnlyDictionary<string, string> PackageVersions { get; }
    public IReadOnlyCollection<string> Testables { get; }

    public UnityProject(string root)
    {
        Root = root;
        UnityVersion = Regex.Match(File.ReadAllText(Path.Combine(root, "ProjectSettings", "ProjectVersion.txt")), @"m_EditorVersion:\s*(\S+)").Groups[1].Value;
        var versions = new Dictionary<string, string>(Transitive);
        using (var manifest = JsonDocument.Parse(File.ReadAllText(Path.Combine(root, "Packages", "manifest.json"))))
        {
            foreach (JsonProperty p in manifest.RootElement.GetProperty("dependencies").EnumerateObject()) versions[p.Name] = p.Value.GetString()!;
            Testables = manifest.RootElement.TryGetProperty("testables", out JsonElement t) ? t.EnumerateArray().Select(e => e.GetString()!).ToList() : new List<string>();
        }
        using (var package = JsonDocument.Parse(File.ReadAllText(Path.Combine(PackageFolder, "package.json"))))
        {
            versions[PackageName] = package.RootElement.GetProperty("version").GetString()!;
            foreach (JsonProperty p in package.RootElement.GetProperty("dependencies").EnumerateObject())
                if (!versions.ContainsKey(p.Name)) versions[p.Name] = p.Value.GetString()!;
        }
        versions["Unity"] = UnityVersion;
        PackageVersions = versions;
    }

    UnityProject(UnityProject other, IReadOnlyDictionary<string, string> versions)
    {
        Root = other.Root;
        UnityVersion = other.UnityVersion;
        Testables = other.Testables;
        PackageVersions = versions;
    }

    /// <summary>
    /// This project with package <paramref name="name"/> at <paramref name="version"/>, or without it when null: what Unity
    /// would compile in a project whose manifest says so (an optional package installed, removed, or at another version).
    /// </summary>
    public UnityProject WithPackage(string name, string? version)
    {
        var versions = new Dictionary<string, string>(PackageVersions);
        if (version == null) versions.Remove(name);
        else versions[name] = version;
        return new UnityProject(this, versions);
    }

    /// <summary>Every asmdef of the embedded package (Unity ignores folders ending in ~ and hidden ones).</summary>
    public IReadOnlyList<Asmdef> Asmdefs() => Files(PackageFolder, "*.asmdef").Select(Asmdef.Read).ToList();

    /// <summary>The .cs files an asmdef owns: those under its folder that no nested asmdef claims.</summary>
    public static IReadOnlyList<string> SourcesOf(string folder) => Files(folder, "*.cs", stopAtAsmdef: true).ToList();

    /// <summary>The samples' scripts, as they compile once imported into Assets (no asmdef: Assembly-CSharp).</summary>
    public IReadOnlyList<string> SampleSources() =>
        Directory.EnumerateFiles(Path.Combine(PackageFolder, "Samples~"), "*.cs", SearchOption.AllDirectories).OrderBy(p => p, StringComparer.Ordinal).ToList();

    static IEnumerable<string> Files(string folder, string pattern, bool stopAtAsmdef = false, bool top = true)
    {
        if (!top && stopAtAsmdef && Directory.EnumerateFiles(folder, "*.asmdef").Any()) yield break;
        foreach (string f in Directory.EnumerateFiles(folder, pattern).OrderBy(p => p, StringComparer.Ordinal)) yield return f;
        foreach (string d in Directory.EnumerateDirectories(folder).OrderBy(p => p, StringComparer.Ordinal))
        {
            string n = Path.GetFileName(d);
            if (n.EndsWith('~') || n.StartsWith('.') || n is "bin" or "obj") continue;
            foreach (string f in Files(d, pattern, stopAtAsmdef, false)) yield return f;
        }
    }

    /// <summary>The repository root: the folder above this test's output that holds PseudoHaptic.sln.</summary>
    public static string FindRoot()
    {
        for (var d = new DirectoryInfo(AppContext.BaseDirectory); d != null; d = d.Parent)
            if (File.Exists(Path.Combine(d.FullName, "PseudoHaptic.sln"))) return d.FullName;
        throw new DirectoryNotFoundException("PseudoHaptic.sln not found above " + AppContext.BaseDirectory);
    }
}

/// <summary>The two builds that matter: the editor with Android as the active target, and the Android (Quest) player.</summary>
public enum UnityTarget
{
    EditorAndroid,
    PlayerAndroid,
}

/// <summary>
/// Unity's scripting symbols for a build (manual: "Unity scripting symbol reference", 2022.3): the version symbols,
/// the platform, the scripting backend, the API profile (.NET Standard 2.1 for player-compatible assemblies, the
/// .NET Framework profile for editor-only ones), and in the editor UNITY_EDITOR and UNITY_INCLUDE_TESTS (which the
/// Test Framework's editor compilation always has, so that testable packages' test assemblies compile).
/// </summary>
public static class ScriptingSymbols
{
    public static HashSet<string> For(UnityTarget target, string unityVersion, bool editorOnlyAssembly)
    {
        var m = Regex.Match(unityVersion, @"^(\d+)\.(\d+)\.(\d+)");
        int major = int.Parse(m.Groups[1].Value), minor = int.Parse(m.Groups[2].Value), patch = int.Parse(m.Groups[3].Value);
        var s = new HashSet<string> { "UNITY_" + major, "UNITY_" + major + "_" + minor, "UNITY_" + major + "_" + minor + "_" + patch };
        foreach ((int y, int last) in new[] { (5, 6), (2017, 4), (2018, 4), (2019, 4), (2020, 3), (2021, 3), (major, minor) })
            for (int n = y == 5 ? 3 : 1; n <= last; n++)
                if (y < major || (y == major && n <= minor)) s.Add("UNITY_" + y + "_" + n + "_OR_NEWER");
        s.UnionWith(new[] { "UNITY_ANDROID", "PLATFORM_ANDROID", "UNITY_64", "CSHARP_7_3_OR_NEWER", "CSHARP_7_OR_LATER", "ENABLE_VR" });
        s.UnionWith(editorOnlyAssembly ? new[] { "NET_4_6", "NET_UNITY_4_8" } : new[] { "NET_STANDARD_2_1", "NET_STANDARD", "NETSTANDARD2_1", "NETSTANDARD" });
        if (target == UnityTarget.EditorAndroid)
            s.UnionWith(new[] { "UNITY_EDITOR", "UNITY_EDITOR_64", "ENABLE_MONO", "UNITY_INCLUDE_TESTS" });
        else
            s.Add("ENABLE_IL2CPP");
        if (editorOnlyAssembly) s.Add("UNITY_EDITOR_ONLY_COMPILATION");
        return s;
    }
}
