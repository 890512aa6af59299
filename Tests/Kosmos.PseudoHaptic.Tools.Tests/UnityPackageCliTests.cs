using System.Diagnostics;
using System.Formats.Tar;
using System.IO.Compression;
using System.Text.Json;
using System.Text.RegularExpressions;
using Kosmos.PseudoHaptic.Cli.Commands;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tools.Tests;

/// <summary>
/// <c>pseudohaptic unity-package</c> (issue 34): the tarball Unity's "Add package from tarball" reads. The tests unpack
/// it with the BCL's own reader and check it by Unity's rules, not by the command's: entries under <c>package/</c>,
/// <c>package/package.json</c> with the version in the file's name, a .meta beside every asset Unity imports, the
/// files git tracks in the package and nothing else, the same bytes for the same content.
/// </summary>
public class UnityPackageCliTests : CliTestFolder
{
    static readonly string Package = Path.Combine(RepositoryRoot.Path, "Packages", "com.kosmos.pseudohaptic");

    public UnityPackageCliTests() : base("ph-unitypkg-") { }

    static (int code, string stderr, string stdout) Pack(params string[] args) => Capture(() => UnityPackageCommand.Run(args));

    static string Version(string packageJson)
    {
        using var doc = JsonDocument.Parse(File.ReadAllText(packageJson));
        return doc.RootElement.GetProperty("version").GetString()!;
    }

    /// <summary>Every entry of the tarball: its name, type, mode, time and content.</summary>
    static List<(string Name, TarEntryType Type, UnixFileMode Mode, DateTimeOffset Time, byte[] Data)> Unpack(string tgz)
    {
        var entries = new List<(string, TarEntryType, UnixFileMode, DateTimeOffset, byte[])>();
        using var file = File.OpenRead(tgz);
        using var gzip = new GZipStream(file, CompressionMode.Decompress);
        using var tar = new TarReader(gzip);
        while (tar.GetNextEntry() is { } e)
        {
            var data = new MemoryStream();
            e.DataStream?.CopyTo(data);
            entries.Add((e.Name, e.EntryType, e.Mode, e.ModificationTime, data.ToArray()));
        }
        return entries;
    }

    [Test]
    public void The_package_unpacks_as_Unity_reads_a_tarball()
    {
        string version = Version(Path.Combine(Package, "package.json"));
        var (code, stderr, stdout) = Pack("--out", Path.Combine(_dir, "a", "b"), "--package", Package);
        Assert.That(code, Is.EqualTo(0), stderr);
        string tgz = Path.Combine(_dir, "a", "b", $"com.kosmos.pseudohaptic-{version}.tgz");
        Assert.That(File.Exists(tgz), Is.True, "the tarball is named from package.json's version: " + stdout);
        Assert.That(Directory.GetFiles(Path.Combine(_dir, "a", "b")), Has.Length.EqualTo(1), "no temporary file is left");
        var entries = Unpack(tgz);
        var names = entries.Select(e => e.Name).ToList();

        Assert.That(entries.All(e => e.Type == TarEntryType.RegularFile), "files only, as npm pack writes them");
        Assert.That(names.All(n => n.StartsWith("package/", StringComparison.Ordinal)), "every entry under package/");
        Assert.That(names, Is.Unique);
        Assert.That(names, Is.Ordered.Using((IComparer<string>)StringComparer.Ordinal), "sorted entries");
        var manifest = entries.Single(e => e.Name == "package/package.json");
        using (var doc = JsonDocument.Parse(manifest.Data))
        {
            Assert.That(doc.RootElement.GetProperty("name").GetString(), Is.EqualTo("com.kosmos.pseudohaptic"));
            Assert.That(Path.GetFileName(tgz), Is.EqualTo($"com.kosmos.pseudohaptic-{doc.RootElement.GetProperty("version").GetString()}.tgz"));
            foreach (var sample in doc.RootElement.GetProperty("samples").EnumerateArray())
                Assert.That(names.Any(n => n.StartsWith("package/" + sample.GetProperty("path").GetString() + "/", StringComparison.Ordinal)), sample.ToString());
        }

        // Unity imports every file and folder outside a folder ending in '~' only with its .meta.
        var set = new HashSet<string>(names, StringComparer.Ordinal);
        var folders = new HashSet<string>(StringComparer.Ordinal);
        foreach (var n in names)
        {
            var parts = n.Split('/');
            for (int i = 2; i < parts.Length; i++) folders.Add(string.Join('/', parts.Take(i)));
        }
        foreach (var asset in names.Where(n => !n.EndsWith(".meta", StringComparison.Ordinal)).Concat(folders))
        {
            var parts = asset.Split('/');
            if (parts.Skip(1).Take(parts.Length - 2).Any(p => p.EndsWith('~')) || (folders.Contains(asset) && parts[^1].EndsWith('~'))) continue;
            Assert.That(set.Contains(asset + ".meta"), Is.True, asset + " has no .meta in the tarball");
        }
        foreach (var meta in names.Where(n => n.EndsWith(".meta", StringComparison.Ordinal)))
            Assert.That(set.Contains(meta[..^5]) || folders.Contains(meta[..^5]), Is.True, "orphaned " + meta);

        // What ships: the files git tracks or would track (not ignored) in the package folder, none other (no build output, nothing
        // hidden), less Tests/ (issue 34: "no test-only or build files").
        var tracked = Git("ls-files", "-z", "--cached", "--others", "--exclude-standard", "--", "Packages/com.kosmos.pseudohaptic");
        if (tracked != null)
        {
            var expected = tracked.Split('\0', StringSplitOptions.RemoveEmptyEntries)
                .Select(p => "package/" + p["Packages/com.kosmos.pseudohaptic/".Length..])
                .Where(p => File.Exists(Path.Combine(Package, p["package/".Length..])))
                .Where(p => !p.StartsWith("package/Tests/", StringComparison.Ordinal) && p != "package/Tests.meta")
                .OrderBy(p => p, StringComparer.Ordinal).ToList();
            Assert.That(names, Is.EqualTo(expected));
        }
        Assert.That(names.Where(n => Regex.IsMatch(n, @"/(bin|obj|\.[^/]+)/|\.csproj$|/\.")), Is.Empty);
        Assert.That(names.Where(n => n.StartsWith("package/Tests", StringComparison.Ordinal)), Is.Empty, "no test-only files (issue 34)");
        Assert.That(names, Does.Contain("package/Runtime/Core/Kosmos.PseudoHaptic.Core.asmdef"));
        Assert.That(names, Does.Contain("package/Documentation~/unity.md"));
        foreach (var e in entries)
            Assert.That(e.Data, Is.EqualTo(File.ReadAllBytes(Path.Combine(Package, e.Name["package/".Length..]))), e.Name);
    }

    static string? Git(params string[] args)
    {
        try
        {
            var info = new ProcessStartInfo("git") { WorkingDirectory = RepositoryRoot.Path, RedirectStandardOutput = true, RedirectStandardError = true, UseShellExecute = false };
            foreach (var a in args) info.ArgumentList.Add(a);
            using var p = Process.Start(info)!;
            string output = p.StandardOutput.ReadToEnd();
            p.WaitForExit();
            return p.ExitCode == 0 && output.Length > 0 ? output : null;
        }
        catch (System.ComponentModel.Win32Exception) { return null; }
    }

    string SmallPackage(string version = "1.2.3")
    {
        string root = Path.Combine(_dir, "pkg");
        Directory.CreateDirectory(Path.Combine(root, "Runtime"));
        Directory.CreateDirectory(Path.Combine(root, "Samples~", "One"));
        Directory.CreateDirectory(Path.Combine(root, "obj"));
        File.WriteAllText(Path.Combine(root, "package.json"), $"{{ \"name\": \"com.example.small\", \"version\": \"{version}\" }}");
        File.WriteAllText(Path.Combine(root, "package.json.meta"), "guid: 0\n");
        File.WriteAllText(Path.Combine(root, "Runtime.meta"), "guid: 1\n");
        File.WriteAllText(Path.Combine(root, "Runtime", "A.cs"), "class A {}\n");
        File.WriteAllText(Path.Combine(root, "Runtime", "A.cs.meta"), "guid: 2\n");
        File.WriteAllText(Path.Combine(root, "Samples~", "One", "S.cs"), "class S {}\n");
        File.WriteAllText(Path.Combine(root, "obj", "x.dll"), "build output");
        File.WriteAllText(Path.Combine(root, ".hidden"), "no");
        File.WriteAllText(Path.Combine(root, "Small.csproj"), "<Project/>");
        return root;
    }

    [Test]
    public void The_same_content_gives_the_same_bytes_whatever_the_files_times()
    {
        string pkg = SmallPackage();
        Assert.That(Pack("--out", Path.Combine(_dir, "one"), "--package", pkg).code, Is.EqualTo(0));
        foreach (var f in Directory.GetFiles(pkg, "*", SearchOption.AllDirectories)) File.SetLastWriteTimeUtc(f, new DateTime(2030, 1, 2, 3, 4, 5, DateTimeKind.Utc));
        Assert.That(Pack("--out", Path.Combine(_dir, "two"), "--package", pkg).code, Is.EqualTo(0));
        byte[] one = File.ReadAllBytes(Path.Combine(_dir, "one", "com.example.small-1.2.3.tgz"));
        Assert.That(File.ReadAllBytes(Path.Combine(_dir, "two", "com.example.small-1.2.3.tgz")), Is.EqualTo(one));
        var entries = Unpack(Path.Combine(_dir, "one", "com.example.small-1.2.3.tgz"));
        Assert.That(entries.Select(e => e.Name), Is.EqualTo(new[] { "package/Runtime.meta", "package/Runtime/A.cs", "package/Runtime/A.cs.meta", "package/Samples~/One/S.cs", "package/package.json", "package/package.json.meta" }),
            "sorted; no hidden file, no obj/, no .csproj; a sample needs no .meta");
        Assert.That(entries.Select(e => e.Time).Distinct().Count(), Is.EqualTo(1), "one fixed time");
        Assert.That(entries.Select(e => e.Time.Year), Has.All.LessThan(2000), "not the files' times");

        // A changed file changes the tarball (the comparison above can fail).
        File.AppendAllText(Path.Combine(pkg, "Runtime", "A.cs"), "// more\n");
        Assert.That(Pack("--out", Path.Combine(_dir, "one"), "--package", pkg).code, Is.EqualTo(0));
        Assert.That(File.ReadAllBytes(Path.Combine(_dir, "one", "com.example.small-1.2.3.tgz")), Is.Not.EqualTo(one), "the older tarball is replaced");
    }

    [Test]
    public void An_asset_without_its_meta_is_refused_naming_it()
    {
        string pkg = SmallPackage();
        File.WriteAllText(Path.Combine(pkg, "Runtime", "B.cs"), "class B {}\n");
        var (code, stderr, _) = Pack("--out", Path.Combine(_dir, "o"), "--package", pkg);
        Assert.That(code, Is.EqualTo(2));
        Assert.That(stderr, Does.StartWith("pseudohaptic unity-package: --package ").And.Contain("Runtime/B.cs has no .meta").And.Contain("generate-meta.py"));
        Assert.That(stderr.TrimEnd('\n').Split('\n'), Has.Length.EqualTo(1));
        Assert.That(Directory.Exists(Path.Combine(_dir, "o")) ? Directory.GetFiles(Path.Combine(_dir, "o")) : Array.Empty<string>(), Is.Empty, "nothing written");
    }

    [TestCase("1.2", "\"version\" is missing or not MAJOR.MINOR.PATCH")]
    [TestCase("v1.2.3", "\"version\" is missing or not MAJOR.MINOR.PATCH")]
    public void A_bad_version_is_refused_naming_package_json(string version, string message)
    {
        string pkg = SmallPackage(version);
        var (code, stderr, _) = Pack("--out", Path.Combine(_dir, "o"), "--package", pkg);
        Assert.That(code, Is.EqualTo(2));
        Assert.That(stderr, Does.StartWith("pseudohaptic unity-package: ").And.Contain("package.json: " + message));
    }

    [Test]
    public void Usage_errors_exit_2_with_one_line()
    {
        string pkg = SmallPackage();
        string file = Write("afile", "x");
        foreach (var (args, message) in new[]
        {
            (new[] { "--out", file, "--package", pkg }, "--out " + file + ": is a file, not a folder"),
            (new[] { "--out", Path.Combine(_dir, "o"), "--package", Path.Combine(_dir, "nope") }, "does not exist"),
            (new[] { "--out", Path.Combine(_dir, "o"), "--package", _dir }, "holds no package.json"),
            (new[] { "--out", "", "--package", pkg }, "option --out: the path is empty"),
            (new[] { "--package", pkg }, "option --out is required"),
        })
        {
            var (code, stderr, _) = Pack(args);
            Assert.That(code, Is.EqualTo(2), string.Join(' ', args) + ": " + stderr);
            Assert.That(stderr, Does.StartWith("pseudohaptic unity-package: ").And.Contain(message).IgnoreCase, string.Join(' ', args));
            Assert.That(stderr.TrimEnd('\n').Split('\n'), Has.Length.EqualTo(1), stderr);
        }
    }

    [Test]
    public void Help_gives_the_options_defaults_and_an_example()
    {
        var (code, _, stdout) = Pack("--help");
        Assert.That(code, Is.EqualTo(0));
        Assert.That(stdout, Does.Contain("--out").And.Contain("--package").And.Contain(UnityPackageCommand.DefaultPackage).And.Contain("pseudohaptic unity-package --out out/unity"));
    }

    [Test]
    public void The_default_package_is_the_repositorys_from_its_root()
    {
        var result = ToolProcess.Run(RepositoryRoot.Path, "unity-package", "--out", _dir);
        Assert.That(result.Code, Is.EqualTo(0), result.Stderr);
        Assert.That(File.Exists(Path.Combine(_dir, $"com.kosmos.pseudohaptic-{Version(Path.Combine(Package, "package.json"))}.tgz")), Is.True, result.Stdout);
        Assert.That(result.Stdout, Does.StartWith("unity-package: com.kosmos.pseudohaptic "));
    }

    /// <summary>
    /// A package installed by version: every git URL's <c>#tag</c> and every tarball name the install instructions show
    /// (README.md, unity.md) is the version <c>package.json</c> holds, the CHANGELOG has a section for it, and where the clone
    /// has tags, the tag exists (the docs once pinned <c>#0.2.0</c>, a tag that did not exist, while the package said 0.3.0).
    /// </summary>
    [Test]
    public void The_install_instructions_pin_the_packages_version_and_its_tag()
    {
        string version = Version(Path.Combine(Package, "package.json"));
        foreach (var doc in new[] { Path.Combine(RepositoryRoot.Path, "README.md"), Path.Combine(Package, "Documentation~", "unity.md") })
        {
            string text = File.ReadAllText(doc);
            var pins = Regex.Matches(text, @"\.git\?path=/?Packages/com\.kosmos\.pseudohaptic#([^\s`""]+)").Select(m => m.Groups[1].Value).ToList();
            var tarballs = Regex.Matches(text, @"com\.kosmos\.pseudohaptic-(\d[^\s`""/]*)\.tgz").Select(m => m.Groups[1].Value).ToList();
            Assert.That(pins, Is.Not.Empty, doc + " shows no git URL with a version's tag");
            Assert.That(pins.Concat(tarballs), Is.All.EqualTo(version), doc + ": package.json says " + version);
        }
        Assert.That(File.ReadAllText(Path.Combine(Package, "CHANGELOG.md")), Does.Contain("## [" + version + "] - "), "the CHANGELOG's section of the version");
        var tags = Git("tag", "-l");
        if (tags != null)
            Assert.That(tags.Split('\n', StringSplitOptions.RemoveEmptyEntries), Does.Contain(version), "git tag -l: the version's tag");
    }

    [Test]
    public void The_tools_version_is_the_packages_major_and_minor()
    {
        string csproj = File.ReadAllText(Path.Combine(RepositoryRoot.Path, "Tools", "Kosmos.PseudoHaptic.Cli", "Kosmos.PseudoHaptic.Cli.csproj"));
        var package = Version(Path.Combine(Package, "package.json")).Split('.');
        string majorMinor = package[0] + "." + package[1];
        Assert.That(Regex.Match(csproj, @"<Version>(\d+\.\d+)\.0</Version>").Groups[1].Value, Is.EqualTo(majorMinor));
        Assert.That(csproj, Does.Contain($"<Version>{majorMinor}.$(CommitCount)</Version>"));
    }
}
