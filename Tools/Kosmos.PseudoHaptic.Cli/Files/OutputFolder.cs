using System.Runtime.InteropServices;

namespace Kosmos.PseudoHaptic.Cli.Files;

/// <summary>
/// A folder a command writes (report, demo): built complete in a temporary folder beside it (".ph" + 8 hex +
/// ".tmp"), then renamed into place, so it appears all at once or not at all. An existing folder is replaced
/// as a whole (on Linux by an atomic exchange), but only when it is empty or holds nothing but what the
/// command writes (<see cref="Owns"/>): a folder with other files is refused, never emptied. An empty path,
/// a file, a missing parent folder, a folder that is or holds one of the command's inputs: exit 2 naming the
/// user's path. The temporary folder is removed on any error and on SIGINT/SIGTERM.
/// </summary>
public sealed class OutputFolder
{
    readonly string _target;
    bool _done;

    OutputFolder(string option, string path, string target, string temp)
    {
        Option = option;
        UserPath = path;
        _target = target;
        Temp = temp;
    }

    public string Option { get; }
    public string UserPath { get; }

    /// <summary>The temporary folder to write into; it becomes <see cref="UserPath"/> at <see cref="Commit"/>.</summary>
    public string Temp { get; }

    /// <summary>Whether an entry of an existing folder is one this command writes.</summary>
    public delegate bool Owns(FileSystemInfo entry);

    /// <summary>Files with one of <paramref name="extensions"/> (".csv", ".png", ...) and, when <paramref name="folders"/>, folders holding only such files.</summary>
    public static Owns FilesEndingWith(bool folders, params string[] extensions) => entry =>
    {
        if (entry.LinkTarget != null) return false;
        if (entry is FileInfo) return Array.Exists(extensions, e => entry.Name.EndsWith(e, StringComparison.OrdinalIgnoreCase));
        if (!folders || entry is not DirectoryInfo dir) return false;
        foreach (var inner in dir.EnumerateFileSystemInfos())
            if (inner is not FileInfo || inner.LinkTarget != null || !Array.Exists(extensions, e => inner.Name.EndsWith(e, StringComparison.OrdinalIgnoreCase)))
                return false;
        return true;
    };

    /// <summary>
    /// Files whose names match one of <paramref name="patterns"/> ("fits.csv", "fit-*.png"; case-insensitive), the names
    /// the command writes: a folder holding another study's CSV or the user's notes is refused, not replaced.
    /// </summary>
    public static Owns FilesNamed(params string[] patterns) => entry =>
        entry is FileInfo && entry.LinkTarget == null
        && Array.Exists(patterns, p => System.IO.Enumeration.FileSystemName.MatchesSimpleExpression(p, entry.Name, ignoreCase: true));

    /// <summary>Checks <paramref name="path"/> (nothing is created).</summary>
    public static void Check(string option, string path, Owns owns, bool createParents, params NamedPath[] inputs)
        => Resolve(option, path, owns, createParents, inputs, create: false);

    /// <summary>Checks <paramref name="path"/> and creates the temporary folder beside it.</summary>
    public static OutputFolder Begin(string option, string path, Owns owns, bool createParents, params NamedPath[] inputs)
        => Resolve(option, path, owns, createParents, inputs, create: true)!;

    static OutputFolder? Resolve(string option, string path, Owns owns, bool createParents, NamedPath[] inputs, bool create)
    {
        if (path.Length == 0) throw new CliException($"option {option}: the path is empty");
        string shown = Messages.Path(path);
        if (path == "-") throw new CliException($"{option} -: this command writes a folder, not standard output");
        if (path.IndexOf('\0') >= 0) throw new CliException($"{option} {shown}: a path may not hold a NUL character");
        var id = FileIdentity.Of(path);
        OutputFile.SameAsInput(option, path, id, inputs, folderOutput: true);
        if (id.Kind != FileKind.Missing && id.Kind != FileKind.Folder)
            throw new CliException($"{option} {shown}: is a file, not a folder");
        string target = OutputFile.FinalTarget(System.IO.Path.TrimEndingDirectorySeparator(path));
        if (id.Kind == FileKind.Folder)
        {
            target = new DirectoryInfo(target).ResolveLinkTarget(true)?.FullName ?? target;
            if (System.IO.Path.GetPathRoot(target) == target) throw new CliException($"{option} {shown}: is the root folder");
            foreach (var entry in new DirectoryInfo(target).EnumerateFileSystemInfos())
            {
                if (!owns(entry))
                    throw new CliException($"{option} {shown}: is a folder holding {Messages.Path(entry.Name)}, which this command does not write; give a new or empty folder, or one it wrote before");
            }
        }
        string parent = System.IO.Path.GetDirectoryName(target) ?? ".";
        var parentId = FileIdentity.Of(parent);
        if (parentId.Kind == FileKind.Missing && !createParents)
            throw new CliException($"{option} {shown}: the folder {Messages.Path(System.IO.Path.GetDirectoryName(System.IO.Path.TrimEndingDirectorySeparator(path)) is { Length: > 0 } d ? d : parent)} does not exist");
        if (parentId.Kind != FileKind.Missing && parentId.Kind != FileKind.Folder)
            throw new CliException($"{option} {shown}: {Messages.Path(parent)} is not a folder");
        if (!create)
        {
            WritableFolder.Check(option, path, parent);
            return null;
        }
        try
        {
            if (parentId.Kind == FileKind.Missing) Directory.CreateDirectory(parent);
            string temp = Kosmos.PseudoHaptic.Evaluation.AtomicFile.TemporaryPath(parent);
            Temporaries.Create(temp, p => Directory.CreateDirectory(p));
            return new OutputFolder(option, path, target, temp);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            throw new CliException($"{option} {shown}: cannot write: {Messages.Reason(e)}", 1);
        }
    }

    /// <summary>Puts the finished folder in place of <see cref="UserPath"/>.</summary>
    public void Commit()
    {
        if (_done) throw new InvalidOperationException("committed already");
        try
        {
            Temporaries.Commit(Temp, () =>
            {
                for (int attempt = 0; ; attempt++)
                {
                    // Linux: one atomic exchange with the folder there; the temporary name then holds the old one.
                    if (Directory.Exists(_target) && Exchange(Temp, _target))
                    {
                        Temporaries.Delete(Temp);
                        return;
                    }
                    try
                    {
                        if (!Directory.Exists(_target))
                        {
                            Directory.Move(Temp, _target);
                            return;
                        }
                        if (OperatingSystem.IsLinux() && attempt < 8) continue; // it appeared: exchange with it
                        // No atomic exchange: the old folder steps aside under a temporary name, then goes.
                        string parent = System.IO.Path.GetDirectoryName(_target) ?? ".";
                        string old = Kosmos.PseudoHaptic.Evaluation.AtomicFile.TemporaryPath(parent);
                        Directory.Move(_target, old);
                        Directory.Move(Temp, _target);
                        Temporaries.Delete(old);
                        return;
                    }
                    catch (IOException) when (attempt < 8 && Directory.Exists(Temp))
                    {
                        // Another run put its folder in place between the check and the move: go again.
                    }
                }
            });
            _done = true;
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            Abandon();
            throw new CliException($"{Option} {Messages.Path(UserPath)}: cannot write: {Messages.Reason(e)}", 1);
        }
    }

    /// <summary>Removes the temporary folder (on an error).</summary>
    public void Abandon()
    {
        if (_done) return;
        _done = true;
        Temporaries.Delete(Temp);
    }

    const int AtFdCwd = -100;
    const uint RenameExchange = 2;

    [DllImport("libc.so.6", EntryPoint = "renameat2", SetLastError = true)]
    static extern int RenameAt2(int olddirfd, [MarshalAs(UnmanagedType.LPUTF8Str)] string oldpath, int newdirfd, [MarshalAs(UnmanagedType.LPUTF8Str)] string newpath, uint flags);

    /// <summary>Swaps two folders in one step (Linux renameat2 RENAME_EXCHANGE); false where that is not available.</summary>
    static bool Exchange(string a, string b)
    {
        if (!OperatingSystem.IsLinux()) return false;
        try { return RenameAt2(AtFdCwd, a, AtFdCwd, b, RenameExchange) == 0; }
        catch (Exception e) when (e is DllNotFoundException or EntryPointNotFoundException) { return false; }
    }

    /// <summary>Runs <paramref name="write"/> into <see cref="Temp"/>, then commits; on any error the temporary folder goes.</summary>
    public void Build(Action<string> write)
    {
        try { write(Temp); }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            // A full device or a lost permission while writing into the temporary folder: the user's path, never the temporary one.
            Abandon();
            throw new CliException($"{Option} {Messages.Path(UserPath)}: cannot write: {Messages.Reason(e)}", 1);
        }
        catch
        {
            Abandon();
            throw;
        }
        Commit();
    }
}
