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

    /// <summary>
    /// Creates a temporary file or folder through <paramref name="create"/> and adds it to the list, both under
    /// the lock the signal handler takes: a signal either comes first (then nothing is created) or finds it.
    /// </summary>
    public static void Create(string path, Action<string> create)
    {
        lock (Gate)
        {
            if (_ending) throw new OperationCanceledException("the tool is being stopped");
            if (Registrations.Count == 0) Register();
            Paths.Add(path);
            try { create(path); }
            catch
            {
                Paths.Remove(path);
                throw;
            }
        }
    }

    /// <summary>
    /// Runs <paramref name="action"/> (a step that may create folders, such as writing a chart into a temporary
    /// folder) so that a signal waits for it to end, and no such step starts once the removal began.
    /// </summary>
    public static void Guard(Action action)
    {
        lock (Gate)
        {
            if (_ending) throw new OperationCanceledException("the tool is being stopped");
            action();
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
        Remove(path);
        Forget(path);
    }

    /// <summary>
    /// Removes a temporary file, or a folder the command may still be writing into: the folder is first moved
    /// to another name, so files the command opens after that fail instead of landing in it, then deleted.
    /// </summary>
    static void Remove(string path)
    {
        try
        {
            if (!Directory.Exists(path) || File.ResolveLinkTarget(path, false) != null)
            {
                File.Delete(path);
                return;
            }
            string doomed = path + ".del";
            try { Directory.Move(path, doomed); }
            catch (IOException) { doomed = path; }
            for (int attempt = 0; attempt < 100 && Directory.Exists(doomed); attempt++)
            {
                try { Directory.Delete(doomed, recursive: true); }
                catch (IOException) { Thread.Sleep(1); }
            }
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException) { }
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
        // The lock is kept to the end: nothing new is created, and no rename happens, once the removal began.
        Monitor.Enter(Gate);
        _ending = true;
        foreach (var p in Paths) Remove(p);
        Paths.Clear();
        // Exit as the signal says: 128 + 2 for SIGINT, 128 + 15 for SIGTERM.
        context.Cancel = true;
        Environment.Exit(context.Signal == PosixSignal.SIGINT ? 130 : 143);
    }
}
