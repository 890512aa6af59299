namespace Kosmos.PseudoHaptic.Cli.Files;

/// <summary>
/// Fail before work: an output's folder is proven writable before anything is computed, by creating and deleting
/// a temporary file in it (the one test that covers permissions, read-only disks and root alike). A folder that
/// does not exist yet and will be created (demo's default) is proven creatable through its nearest existing parent.
/// </summary>
public static class WritableFolder
{
    /// <summary>Exit 1 ("cannot write: REASON", naming the user's path) when nothing can be created in <paramref name="folder"/>.</summary>
    public static void Check(string option, string userPath, string folder)
    {
        string existing = Path.GetFullPath(folder);
        while (!Directory.Exists(existing) && Path.GetDirectoryName(existing) is { } up) existing = up;
        string probe = Kosmos.PseudoHaptic.Evaluation.AtomicFile.TemporaryPath(existing);
        try
        {
            Temporaries.Create(probe, p => new FileStream(p, FileMode.CreateNew, FileAccess.Write, FileShare.None, 1, FileOptions.DeleteOnClose).Dispose());
        }
        catch (Exception e) when ((e is FileNotFoundException or DirectoryNotFoundException) && Directory.Exists(existing))
        {
            // ENOENT from creating a file in a folder that exists: a file system that allows no new files (/proc).
            throw new CliException($"{option} {Messages.Path(userPath)}: cannot write: cannot create files in {Messages.Path(existing)} (the folder exists, but its file system does not allow new files)", 1);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            throw new CliException($"{option} {Messages.Path(userPath)}: cannot write: {Messages.Reason(e)}", 1);
        }
        finally
        {
            Temporaries.Forget(probe);
        }
    }
}
