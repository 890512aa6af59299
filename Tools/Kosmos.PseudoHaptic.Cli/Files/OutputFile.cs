using System.Text;

namespace Kosmos.PseudoHaptic.Cli.Files;

/// <summary>An input a command reads: the option that named it and the path as the user wrote it.</summary>
public readonly record struct NamedPath(string Option, string? Path);

/// <summary>
/// One output file of a command, checked before any input is read and written by the tool's rules:
/// <list type="bullet">
/// <item><c>-</c>: standard output.</item>
/// <item>A regular file or a new name: written to a short temporary name (".ph" + 8 hex + extension) in the
/// same folder, then renamed over the destination (a symbolic link's final target), so an error or a signal
/// leaves the old file or none, never half of one, and never a temporary file; two runs writing the same
/// file both succeed, the last one wins.</item>
/// <item>A FIFO, a character or block device, a socket: written straight through, never replaced.</item>
/// <item>An empty path, a folder, a missing parent folder, the same file as one of the command's inputs (by
/// identity: any spelling, symbolic or hard link): exit 2 with one line naming the user's path.</item>
/// </list>
/// </summary>
public sealed class OutputFile
{
    enum Mode { StandardOutput, Straight, Replace }

    readonly Mode _mode;
    readonly string _target = "";

    OutputFile(string option, string path, Mode mode, string target)
    {
        Option = option;
        UserPath = path;
        _mode = mode;
        _target = target;
    }

    /// <summary>The option that named this output (e.g. --out).</summary>
    public string Option { get; }

    /// <summary>The path as the user wrote it.</summary>
    public string UserPath { get; }

    /// <summary>Where a command may keep scratch files for this output: the output's own folder for a regular
    /// file (the same disk the output goes to), the system's temporary folder otherwise.</summary>
    public string SpareFolder => _mode == Mode.Replace ? System.IO.Path.GetDirectoryName(_target) ?? "." : System.IO.Path.GetTempPath();

    /// <summary>True for <c>-</c>: the command's own report then goes to standard error.</summary>
    public bool IsStandardOutput => _mode == Mode.StandardOutput;

    /// <summary>Checks <paramref name="path"/> against the rules above and every input in <paramref name="inputs"/>.</summary>
    public static OutputFile Check(string option, string path, params NamedPath[] inputs)
    {
        if (path.Length == 0) throw new CliException($"option {option}: the path is empty");
        if (path == "-") return new OutputFile(option, path, Mode.StandardOutput, "");
        string shown = Messages.Path(path);
        if (path.IndexOf('\0') >= 0) throw new CliException($"{option} {shown}: a path may not hold a NUL character");
        if (path.EndsWith('/') || path.EndsWith(System.IO.Path.DirectorySeparatorChar))
        {
            if (Directory.Exists(path)) throw new CliException($"{option} {shown}: is a folder, not a file");
            throw new CliException($"{option} {shown}: names a folder (ends with '/'), not a file");
        }
        var id = FileIdentity.Of(path);
        SameAsInput(option, path, id, inputs);
        switch (id.Kind)
        {
            case FileKind.Folder:
                throw new CliException($"{option} {shown}: is a folder, not a file");
            case FileKind.Fifo:
            case FileKind.CharacterDevice:
            case FileKind.BlockDevice:
            case FileKind.Socket:
            case FileKind.Other:
                return new OutputFile(option, path, Mode.Straight, path);
        }
        string target = FinalTarget(path);
        string folder = System.IO.Path.GetDirectoryName(target) ?? ".";
        if (folder.Length == 0) folder = ".";
        var folderId = FileIdentity.Of(folder);
        if (folderId.Kind == FileKind.Missing)
            throw new CliException($"{option} {shown}: the folder {Messages.Path(System.IO.Path.GetDirectoryName(path) is { Length: > 0 } d ? d : folder)} does not exist");
        if (folderId.Kind != FileKind.Folder)
            throw new CliException($"{option} {shown}: {Messages.Path(System.IO.Path.GetDirectoryName(path) ?? folder)} is not a folder");
        WritableFolder.Check(option, path, folder);
        return new OutputFile(option, path, Mode.Replace, target);
    }

    /// <summary>Exit 2 when <paramref name="output"/> is one of the inputs or (for a folder output) holds one.</summary>
    internal static void SameAsInput(string option, string output, FileIdentity id, NamedPath[] inputs, bool folderOutput = false)
    {
        if (!id.Exists) return;
        foreach (var input in inputs)
        {
            if (string.IsNullOrEmpty(input.Path) || input.Path == "-") continue;
            var inputId = FileIdentity.Of(input.Path);
            if (!inputId.Exists) continue;
            if (id.SameAs(inputId))
                throw new CliException($"{option} {Messages.Path(output)} is the same file as {input.Option} {Messages.Path(input.Path)}; an input is never overwritten");
            if (folderOutput && Inside(input.Path, id))
                throw new CliException($"{option} {Messages.Path(output)} holds {input.Option} {Messages.Path(input.Path)}; the folder is replaced as a whole, so an input may not be inside it");
        }
    }

    /// <summary>Whether a parent folder of <paramref name="path"/> (its real location) is <paramref name="folder"/>.</summary>
    static bool Inside(string path, FileIdentity folder)
    {
        string? dir;
        try { dir = System.IO.Path.GetDirectoryName(FinalTarget(path)); }
        catch (Exception e) when (e is IOException or ArgumentException) { return false; }
        for (int depth = 0; !string.IsNullOrEmpty(dir) && depth < 256; depth++)
        {
            if (FileIdentity.Of(dir).SameAs(folder)) return true;
            dir = System.IO.Path.GetDirectoryName(dir);
        }
        return false;
    }

    /// <summary>The full path, through symbolic links to the final target (which may not exist yet).</summary>
    internal static string FinalTarget(string path)
    {
        string full = System.IO.Path.GetFullPath(path);
        try
        {
            var target = File.ResolveLinkTarget(full, returnFinalTarget: true);
            if (target != null) return target.FullName;
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException) { }
        // Resolve links in the folders too, so a folder link's file is compared and written where it lives.
        string? dir = System.IO.Path.GetDirectoryName(full);
        if (!string.IsNullOrEmpty(dir) && Directory.Exists(dir))
        {
            string real = new DirectoryInfo(dir).ResolveLinkTarget(true)?.FullName ?? dir;
            return System.IO.Path.Combine(real, System.IO.Path.GetFileName(full));
        }
        return full;
    }

    /// <summary>Writes text (UTF-8 without a byte-order mark, "\n" line ends).</summary>
    public void Write(Action<TextWriter> write) => WriteStream(stream =>
    {
        using var writer = new StreamWriter(stream, new UTF8Encoding(false), 65536, leaveOpen: true) { NewLine = "\n" };
        write(writer);
        writer.Flush();
    });

    public void WriteBytes(byte[] bytes) => WriteStream(stream => stream.Write(bytes, 0, bytes.Length));

    /// <summary>Writes through a stream, by the rules of the output's kind.</summary>
    public void WriteStream(Action<Stream> write)
    {
        switch (_mode)
        {
            case Mode.StandardOutput:
            {
                Console.Out.Flush();
                using var stdout = Console.OpenStandardOutput();
                write(stdout);
                stdout.Flush();
                return;
            }
            case Mode.Straight:
            {
                FileStream stream;
                try { stream = new FileStream(_target, FileMode.Open, FileAccess.Write, FileShare.ReadWrite, 1, FileOptions.None); }
                catch (Exception e) when (e is IOException or UnauthorizedAccessException)
                {
                    throw new CliException($"{Option} {Messages.Path(UserPath)}: cannot write: {Messages.Reason(e)}", 1);
                }
                try
                {
                    using (stream)
                    {
                        write(stream);
                        stream.Flush();
                    }
                }
                catch (IOException e) { throw new CliException($"{Option} {Messages.Path(UserPath)}: cannot write: {Messages.Reason(e)}", 1); }
                return;
            }
            default:
                WriteWith(temp =>
                {
                    using var stream = new FileStream(temp, FileMode.Truncate, FileAccess.Write, FileShare.None, 65536);
                    write(stream);
                    stream.Flush();
                });
                return;
        }
    }

    static void CreateEmpty(string path) => new FileStream(path, FileMode.CreateNew, FileAccess.Write, FileShare.None, 1).Dispose();

    /// <summary>
    /// Lets <paramref name="write"/> create a file at a temporary path (with the output's extension, for
    /// writers that go by it), then moves it into place: renamed over a regular file, copied into a FIFO,
    /// device or standard output.
    /// </summary>
    public void WriteWith(Action<string> write)
    {
        if (_mode != Mode.Replace)
        {
            string spare = Kosmos.PseudoHaptic.Evaluation.AtomicFile.TemporaryPath(System.IO.Path.GetTempPath(), System.IO.Path.GetExtension(UserPath));
            Temporaries.Create(spare, CreateEmpty);
            try
            {
                write(spare);
                using var source = new FileStream(spare, FileMode.Open, FileAccess.Read, FileShare.Read, 1, FileOptions.DeleteOnClose);
                WriteStream(stream => source.CopyTo(stream));
            }
            finally { Temporaries.Delete(spare); }
            return;
        }
        string folder = System.IO.Path.GetDirectoryName(_target) ?? ".";
        string temp = Kosmos.PseudoHaptic.Evaluation.AtomicFile.TemporaryPath(folder, System.IO.Path.GetExtension(_target));
        try
        {
            Temporaries.Create(temp, CreateEmpty);
            write(temp);
            Temporaries.Commit(temp, () => File.Move(temp, _target, overwrite: true));
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            Temporaries.Delete(temp);
            if (Directory.Exists(_target)) throw new CliException($"{Option} {Messages.Path(UserPath)}: is a folder, not a file");
            throw new CliException($"{Option} {Messages.Path(UserPath)}: cannot write: {Messages.Reason(e)}", 1);
        }
        catch
        {
            Temporaries.Delete(temp);
            throw;
        }
    }
}
