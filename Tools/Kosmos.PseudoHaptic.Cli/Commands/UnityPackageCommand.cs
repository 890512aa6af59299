using System.Formats.Tar;
using System.IO.Compression;
using System.Text.Json;
using System.Text.RegularExpressions;
using Kosmos.PseudoHaptic.Cli.CommandLine;
using Kosmos.PseudoHaptic.Cli.Files;

namespace Kosmos.PseudoHaptic.Cli.Commands;

/// <summary>
/// <c>pseudohaptic unity-package --out DIR [--package DIR]</c>: the Unity package as the tarball Unity's Package
/// Manager installs with <i>Add package from tarball</i> (and a manifest's <c>file:…tgz</c> dependency): an npm-style
/// gzipped tar whose entries are <c>package/…</c>, named <c>com.kosmos.pseudohaptic-VERSION.tgz</c> from package.json.
/// <para>What goes in (<see cref="Select"/>): every file under the package folder except hidden files and folders
/// (a leading '.') and build output (<c>bin/</c>, <c>obj/</c>, <c>TestResults/</c>, <c>*.csproj</c>, …), and the package's
/// <c>Tests/</c> (issue 34: "no test-only or build files"; the git-URL and embedded installs keep them, for <c>testables</c>).
/// Every asset Unity imports (outside folders
/// ending in '~') must have its .meta, or the command refuses (exit 2): an immutable package drops assets without one.</para>
/// <para>Deterministic: entries sorted by ordinal path, files only (as npm pack writes them), ustar headers with a fixed
/// modification time (npm's, 1985-10-26 08:15 UTC), mode 0644, owner 0:0 and no user names; the same tree gives the
/// same bytes (UnityPackageCliTests).</para>
/// </summary>
public static class UnityPackageCommand
{
    public const string DefaultPackage = "Packages/com.kosmos.pseudohaptic";

    /// <summary>The package's test folder, left out of the tarball with its .meta.</summary>
    public const string TestsFolder = "Tests";

    /// <summary>npm pack's fixed time for every entry, so a tarball depends on the files' content only.</summary>
    public static readonly DateTimeOffset FixedTime = new(1985, 10, 26, 8, 15, 0, TimeSpan.Zero);

    static readonly string[] BuildFolders = { "bin", "obj", "TestResults", "StrykerOutput", "BenchmarkDotNet.Artifacts", "Library", "Temp", "Logs" };
    static readonly string[] BuildExtensions = { ".csproj", ".sln", ".user", ".rsp", ".nupkg", ".tgz" };
    static readonly Regex SemVer = new(@"^\d+\.\d+\.\d+(-[0-9A-Za-z.-]+)?$", RegexOptions.CultureInvariant);

    public static CliCommand Define() => new(
        "unity-package",
        "Write the Unity package as DIR/com.kosmos.pseudohaptic-VERSION.tgz, for Unity's Package Manager 'Add package from tarball' (unity.md §1)",
        Run,
        new[]
        {
            "pseudohaptic unity-package --out out/unity",
        },
        CliCommand.Value("--out", "DIR", "the folder the tarball is written to, created with its parents if missing; an older tarball of the same version there is replaced", required: true),
        CliCommand.Value("--package", "DIR", $"the package folder, holding package.json (default: {DefaultPackage}, from the repository's root)"));

    public static int Run(string[] args) => Cli.Run(args.Prepend("unity-package").ToArray());

    static int Run(Options o)
    {
        string outDir = o.Require("--out");
        string package = o.Get("--package") ?? DefaultPackage;
        if (outDir.Length == 0) throw new CliException("option --out: the path is empty");
        if (outDir == "-") throw new CliException("--out -: this command writes a tarball into a folder, not to standard output");
        if (package.Length == 0) throw new CliException("option --package: the path is empty");
        var (name, version) = Manifest(package);
        var files = Select(package);

        if (File.Exists(outDir)) throw new CliException($"--out {Messages.Path(outDir)}: is a file, not a folder");
        // The folders to create: the nearest one that exists must be a folder, and one this user can create files in
        // (/proc exists but allows none: "does not exist" would be wrong, issue 32).
        string existing = Path.TrimEndingDirectorySeparator(outDir);
        while (!Directory.Exists(existing) && !File.Exists(existing) && Path.GetDirectoryName(existing) is { Length: > 0 } up) existing = up;
        if (File.Exists(existing)) throw new CliException($"--out {Messages.Path(outDir)}: {Messages.Path(existing)} is not a folder");
        WritableFolder.Check("--out", outDir, outDir);
        try { Directory.CreateDirectory(outDir); }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            throw new CliException($"--out {Messages.Path(outDir)}: cannot create the folder: {Messages.Reason(e)}", 1);
        }
        string fileName = $"{name}-{version}.tgz";
        string path = Path.Combine(outDir, fileName);
        var target = OutputFile.Check("--out", path, new NamedPath("--package", Path.Combine(package, "package.json")));
        long bytes = 0;
        target.WriteStream(stream =>
        {
            var counting = new CountingStream(stream);
            Write(counting, package, files);
            bytes = counting.Count;
        });
        Console.Out.WriteLine($"unity-package: {name} {version}, {files.Count} files -> {Messages.OneLine(path)} ({bytes} bytes)");
        return 0;
    }

    /// <summary>The package's name and version from its package.json; exit 2 naming the file when either is missing or not semver.</summary>
    public static (string Name, string Version) Manifest(string package)
    {
        string manifest = Path.Combine(package, "package.json");
        if (Directory.Exists(package) == false)
            throw new CliException($"--package {Messages.Path(package)}: does not exist (run from the repository's root or give --package)");
        if (!File.Exists(manifest))
            throw new CliException($"--package {Messages.Path(package)}: holds no package.json (run from the repository's root or give --package)");
        string text;
        try { text = File.ReadAllText(manifest); }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            throw new CliException($"{Messages.Path(manifest)}: cannot read: {Messages.Reason(e)}", Cli.InputOutputError);
        }
        try
        {
            using var doc = JsonDocument.Parse(text);
            var root = doc.RootElement;
            string? name = root.ValueKind == JsonValueKind.Object && root.TryGetProperty("name", out var n) && n.ValueKind == JsonValueKind.String ? n.GetString() : null;
            string? version = root.ValueKind == JsonValueKind.Object && root.TryGetProperty("version", out var v) && v.ValueKind == JsonValueKind.String ? v.GetString() : null;
            if (string.IsNullOrEmpty(name) || !Regex.IsMatch(name, @"^[a-z0-9][a-z0-9._-]*$"))
                throw new CliException($"{Messages.Path(manifest)}: \"name\" is missing or not a package name (lower case letters, digits, '.', '-', '_')");
            if (string.IsNullOrEmpty(version) || !SemVer.IsMatch(version))
                throw new CliException($"{Messages.Path(manifest)}: \"version\" is missing or not MAJOR.MINOR.PATCH");
            return (name, version);
        }
        catch (JsonException e)
        {
            throw new CliException($"{Messages.Path(manifest)}:{(e.LineNumber ?? 0) + 1}: not valid JSON: {e.Message}");
        }
    }

    /// <summary>The package's files to ship, as '/'-separated paths relative to <paramref name="package"/>, sorted by
    /// ordinal; exit 2 naming the first asset Unity would import without a .meta.</summary>
    public static List<string> Select(string package)
    {
        var files = new List<string>();
        var missingMeta = new List<string>();
        Walk(package, "", imported: true, files, missingMeta);
        if (missingMeta.Count > 0)
            throw new CliException($"--package {Messages.Path(package)}: {missingMeta[0]} has no .meta{(missingMeta.Count > 1 ? $" (and {missingMeta.Count - 1} more)" : "")}; Unity would not import it from a tarball (run python3 Tools/generate-meta.py)");
        files.Sort(StringComparer.Ordinal);
        return files;
    }

    static void Walk(string root, string relative, bool imported, List<string> files, List<string> missingMeta)
    {
        string dir = relative.Length == 0 ? root : Path.Combine(root, relative);
        var entries = Directory.GetFileSystemEntries(dir).Select(Path.GetFileName).OfType<string>().OrderBy(e => e, StringComparer.Ordinal).ToArray();
        var names = new HashSet<string>(entries, StringComparer.Ordinal);
        foreach (var name in entries)
        {
            if (name.StartsWith('.')) continue;
            if (relative.Length == 0 && (name == TestsFolder || name == TestsFolder + ".meta")) continue; // test-only: not in the tarball
            string rel = relative.Length == 0 ? name : relative + "/" + name;
            string full = Path.Combine(root, rel);
            bool isFolder = Directory.Exists(full);
            if (isFolder)
            {
                if (BuildFolders.Contains(name, StringComparer.Ordinal)) continue;
                // Unity imports a folder ending in '~' (Documentation~, Samples~) as nothing: no .meta needed inside.
                bool inside = imported && !name.EndsWith('~');
                if (inside && !names.Contains(name + ".meta")) missingMeta.Add(rel + "/");
                Walk(root, rel, inside, files, missingMeta);
                continue;
            }
            if (BuildExtensions.Any(x => name.EndsWith(x, StringComparison.OrdinalIgnoreCase))) continue;
            if (imported && !name.EndsWith(".meta", StringComparison.Ordinal) && !names.Contains(name + ".meta")) missingMeta.Add(rel);
            files.Add(rel);
        }
    }

    /// <summary>Writes the gzipped tar of <paramref name="files"/> (relative to <paramref name="package"/>) under "package/".</summary>
    public static void Write(Stream output, string package, IReadOnlyList<string> files)
    {
        using var gzip = new GZipStream(output, CompressionLevel.SmallestSize, leaveOpen: true);
        using (var tar = new TarWriter(gzip, TarEntryFormat.Ustar, leaveOpen: true))
        {
            foreach (var rel in files)
            {
                string full = Path.Combine(package, rel.Replace('/', Path.DirectorySeparatorChar));
                var entry = new UstarTarEntry(TarEntryType.RegularFile, "package/" + rel)
                {
                    ModificationTime = FixedTime,
                    Mode = UnixFileMode.UserRead | UnixFileMode.UserWrite | UnixFileMode.GroupRead | UnixFileMode.OtherRead,
                    Uid = 0,
                    Gid = 0,
                    UserName = "",
                    GroupName = "",
                };
                try
                {
                    using var content = new MemoryStream(File.ReadAllBytes(full), writable: false);
                    entry.DataStream = content;
                    tar.WriteEntry(entry);
                }
                catch (Exception e) when (e is IOException or UnauthorizedAccessException)
                {
                    throw new CliException($"--package {Messages.Path(full)}: cannot read: {Messages.Reason(e)}", 1);
                }
                catch (ArgumentException e)
                {
                    throw new CliException($"--package {Messages.Path(rel)}: cannot be stored in a tar entry: {e.Message}");
                }
            }
        }
    }

    sealed class CountingStream(Stream inner) : Stream
    {
        public long Count { get; private set; }
        public override bool CanRead => false;
        public override bool CanSeek => false;
        public override bool CanWrite => true;
        public override long Length => throw new NotSupportedException();
        public override long Position { get => Count; set => throw new NotSupportedException(); }
        public override void Flush() => inner.Flush();
        public override int Read(byte[] buffer, int offset, int count) => throw new NotSupportedException();
        public override long Seek(long offset, SeekOrigin origin) => throw new NotSupportedException();
        public override void SetLength(long value) => throw new NotSupportedException();
        public override void Write(byte[] buffer, int offset, int count) { inner.Write(buffer, offset, count); Count += count; }
        public override void Write(ReadOnlySpan<byte> buffer) { inner.Write(buffer); Count += buffer.Length; }
    }
}
