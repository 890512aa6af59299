using System.Runtime.InteropServices;

namespace Kosmos.PseudoHaptic.Cli.Files;

/// <summary>
/// The temporary files and folders the tool has made and not yet renamed into place. On SIGINT or SIGTERM
/// they are removed before the process ends the way the signal says (exit code 130 or 143), so an
/// interrupted run leaves nothing behind.
/// </summary>
public static class Temporaries
{
    static readonly object Gate = new();
    static readonly List<string> Paths = new();
    static readonly List<PosixSignalRegistration> Registrations = new();
    static bool _ending;

    /// <summary>Adds <paramref name="path"/>; call before creating it. Throws when the process is already ending.</summary>
    public static void Track(string path)
    {
        lock (Gate)
        {
            if (_ending) throw new OperationCanceledException("the tool is being stopped");
            if (Registrations.Count == 0) Register();
            Paths.Add(path);
        }
    }

    /// <summary>Removes <paramref name="path"/> from the list (it was renamed into place or deleted).</summary>
    public static void Forget(string path)
    {
        lock (Gate) Paths.Remove(path);
    }

    /// <summary>Runs <paramref name="action"/> (a rename into place) so that a signal cannot remove the temporary halfway.</summary>
    public static void Commit(string path, Action action)
    {
        lock (Gate)
        {
            if (_ending) throw new OperationCanceledException("the tool is being stopped");
            action();
            Paths.Remove(path);
        }
    }

    /// <summary>Deletes a temporary file or folder, quietly.</summary>
    public static void Delete(string path)
    {
        try
        {
            if (Directory.Exists(path) && File.ResolveLinkTarget(path, false) == null) Directory.Delete(path, recursive: true);
            else File.Delete(path);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException) { }
        Forget(path);
    }

    static void Register()
    {
        try
        {
            Registrations.Add(PosixSignalRegistration.Create(PosixSignal.SIGINT, OnSignal));
            Registrations.Add(PosixSignalRegistration.Create(PosixSignal.SIGTERM, OnSignal));
        }
        catch (PlatformNotSupportedException) { }
    }

    static void OnSignal(PosixSignalContext context)
    {
        string[] paths;
        lock (Gate)
        {
            _ending = true;
            paths = Paths.ToArray();
            Paths.Clear();
        }
        foreach (var p in paths)
        {
            try
            {
                if (Directory.Exists(p)) Directory.Delete(p, recursive: true);
                else File.Delete(p);
            }
            catch (Exception e) when (e is IOException or UnauthorizedAccessException) { }
        }
        // Exit as the signal says: 128 + 2 for SIGINT, 128 + 15 for SIGTERM.
        context.Cancel = true;
        Environment.Exit(context.Signal == PosixSignal.SIGINT ? 130 : 143);
    }
}
