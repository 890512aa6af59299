using System;
using System.Collections.Generic;
using System.IO;
using System.Runtime.InteropServices;
using System.Text;

namespace Kosmos.PseudoHaptic.Evaluation
{
    /// <summary>
    /// Durable write-then-rename: the text goes to a temporary file in the destination's own folder (so the
    /// rename stays on one file system), its data is synced to the storage device (<c>fsync</c>, <see cref="SyncStream"/>),
    /// the temporary file then replaces the destination in one step, and on
    /// Linux, Android and macOS the folder itself is synced after the rename (<see cref="SyncDirectory"/>), so the
    /// new name is on the device too. A crash or an error leaves either the old file or the new one, never half of
    /// one; after this returns, a power cut leaves the new one. The temporary file is removed on error, and every
    /// error (a failed write, sync or rename) is thrown, never swallowed.
    /// The temporary name is short and fixed in length (".ph" + 8 hex digits + ".tmp"), so any destination
    /// name the file system accepts works; two writers racing for one destination both succeed, the last
    /// rename wins.
    /// </summary>
    /// <remarks>
    /// Where the folder cannot be synced (Windows, where .NET cannot open a folder as a file; a file system that
    /// refuses <c>fsync</c> on a folder with EINVAL or EOPNOTSUPP) the file's data is still synced before the
    /// rename, so the destination is never empty or half-written after a power cut, but the rename itself may be
    /// lost: the old file comes back. <see cref="DirectorySync"/> says what this platform does; evaluation.md,
    /// "Session recording", says what survives what.
    /// A kill or a power cut between the temporary file's creation and its rename leaves it behind; a study session
    /// removes such leftovers from its folder when it starts or resumes (<see cref="RemoveStaleTemporaries"/>).
    /// </remarks>
    public static class AtomicFile
    {
        /// <summary>Whether <see cref="WriteWith"/> syncs (default true). Off only for a measurement of what the sync costs.</summary>
        public static bool Durable { get; set; } = true;

        /// <summary>The temporary names <see cref="Write"/> is using now (file names only), which <see cref="RemoveStaleTemporaries"/> leaves alone.</summary>
        static readonly HashSet<string> InFlight = new HashSet<string>(StringComparer.Ordinal);

        /// <summary>A fresh temporary name in <paramref name="directory"/>: ".ph" + 8 lowercase hex digits + <paramref name="extension"/>.</summary>
        public static string TemporaryPath(string directory, string extension = ".tmp")
            => Path.Combine(directory, ".ph" + Guid.NewGuid().ToString("N").Substring(0, 8) + extension);

        public static void WriteAllText(string path, string text)
        {
            Write(path, synced: true, write: temp =>
            {
                using (var stream = new FileStream(temp, FileMode.CreateNew, FileAccess.Write, FileShare.None, 4096))
                {
                    byte[] bytes = Encoding.UTF8.GetBytes(text ?? ""); // GetBytes never writes a byte order mark
                    stream.Write(bytes, 0, bytes.Length);
                    if (Durable) SyncStream(stream); // fsync: the data is on the device before the rename
                }
            });
        }

        /// <summary>
        /// Lets <paramref name="write"/> create the temporary file (any content), syncs it, renames it to
        /// <paramref name="path"/> and syncs the folder.
        /// </summary>
        public static void WriteWith(string path, Action<string> write) => Write(path, false, write);

        /// <summary>As <see cref="WriteWith(string, Action{string})"/>; <paramref name="synced"/>: <paramref name="write"/> syncs the temporary file itself (<see cref="FileStream.Flush(bool)"/> before closing it), so it is not synced again.</summary>
        public static void Write(string path, bool synced, Action<string> write)
        {
            if (string.IsNullOrEmpty(path)) throw new ArgumentException("empty path", nameof(path));
            if (write == null) throw new ArgumentNullException(nameof(write));
            string full = Path.GetFullPath(path);
            if (Directory.Exists(full)) throw new IOException(path + ": is a folder");
            string directory = Path.GetDirectoryName(full); // a full path that is not a folder (not a root) has one
            string temp = TemporaryPath(directory), tempName = Path.GetFileName(temp);
            // Registered before the file exists, so a cleanup that sees the file also sees that it is in use.
            lock (InFlight) InFlight.Add(tempName);
            try
            {
                write(temp);
                if (Durable && !synced) SyncFile(temp);
                Rename(temp, full);
                if (Durable) SyncDirectory(directory);
            }
            catch
            {
                // Before the rename the temporary file goes; after it (a failed folder sync) its name no longer exists.
                try { if (File.Exists(temp)) File.Delete(temp); } catch (IOException) { } catch (UnauthorizedAccessException) { }
                throw;
            }
            finally
            {
                lock (InFlight) InFlight.Remove(tempName);
            }
        }

        /// <summary>
        /// Whether <paramref name="fileName"/> (a name, not a path) is exactly the name of this writer's temporary
        /// files: ".ph" + 8 lowercase hex digits + ".tmp" (".ph3f9a01c2.tmp"). Other extensions (the CLI's
        /// ".ph3f9a01c2.csv"), upper-case or fewer or more digits, and other names are not.
        /// </summary>
        public static bool IsTemporaryName(string fileName)
        {
            if (fileName == null || fileName.Length != 15) return false;
            if (!fileName.StartsWith(".ph", StringComparison.Ordinal) || !fileName.EndsWith(".tmp", StringComparison.Ordinal)) return false;
            for (int i = 3; i < 11; i++)
            {
                char c = fileName[i];
                if (!((c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'))) return false;
            }
            return true;
        }

        /// <summary>
        /// Removes from <paramref name="directory"/> (not its subfolders) the files left by writes that a kill or a power
        /// cut stopped before their rename: files, not folders, whose name is exactly a temporary one
        /// (<see cref="IsTemporaryName"/>), except those a write in this process is using now. A study session calls it
        /// on its own folder when it starts or resumes (one writer per folder: another app writing into the same
        /// folder at the same time is not supported, its temporary file could be removed under it). Best effort: a
        /// missing or unreadable folder, or a file that cannot be deleted, is left as it is, never an error (the
        /// session's own write reports a folder it cannot write). Returns how many files were removed.
        /// </summary>
        public static int RemoveStaleTemporaries(string directory)
        {
            if (string.IsNullOrEmpty(directory)) return 0;
            int removed = 0;
            try
            {
                string full = Path.GetFullPath(directory);
                if (!Directory.Exists(full)) return 0;
                foreach (string file in Directory.GetFiles(full, ".ph*"))
                {
                    string name = Path.GetFileName(file);
                    if (!IsTemporaryName(name)) continue;
                    lock (InFlight)
                    {
                        // Checked and deleted under the lock: a write registers its name before creating the file.
                        if (InFlight.Contains(name)) continue;
                        try
                        {
                            if (!File.Exists(file)) continue; // a folder of that name, or gone meanwhile
                            File.Delete(file);
                            removed++;
                        }
                        catch (IOException) { }
                        catch (UnauthorizedAccessException) { }
                    }
                }
            }
            catch (IOException) { }
            catch (UnauthorizedAccessException) { }
            catch (ArgumentException) { }
            catch (NotSupportedException) { }
            return removed;
        }

        /// <summary>Syncs an existing file's data and size to the device (<c>fsync</c>); throws <see cref="IOException"/> when the device refuses.</summary>
        public static void SyncFile(string path)
        {
            using (var stream = new FileStream(path, FileMode.Open, FileAccess.Write, FileShare.ReadWrite, 1))
                SyncStream(stream);
        }

        /// <summary>
        /// Writes <paramref name="stream"/>'s buffer and syncs the file's data and size to the device. On Linux and Android
        /// this calls libc's <c>fsync</c> itself and checks its result: <see cref="FileStream.Flush(bool)"/> does not
        /// report a failing <c>fsync</c> (.NET 10 on Linux: an EIO injected into it passes unnoticed, DurabilityTests), so
        /// a device that failed to store the answer would go unsaid. A failure throws <see cref="IOException"/> naming the
        /// file and the errno, except EINVAL and EOPNOTSUPP: a file system that cannot sync this file, where there is
        /// nothing more to do (as .NET itself treats them). On Windows and macOS (where .NET uses the stronger
        /// <c>F_FULLFSYNC</c>), or without libc, <see cref="FileStream.Flush(bool)"/>.
        /// </summary>
        public static void SyncStream(FileStream stream)
        {
            if (stream == null) throw new ArgumentNullException(nameof(stream));
            stream.Flush();
            if (!IsUnix || IsDarwin)
            {
                stream.Flush(true);
                return;
            }
            var handle = stream.SafeFileHandle;
            bool added = false;
            int result = 0, errno = 0;
            try
            {
                handle.DangerousAddRef(ref added);
                result = Fsync((int)handle.DangerousGetHandle(), out errno);
            }
            catch (Exception e) when (e is DllNotFoundException || e is EntryPointNotFoundException)
            {
                stream.Flush(true);
                return;
            }
            finally
            {
                if (added) handle.DangerousRelease();
            }
            if (result != 0 && !IsRefusal(errno))
                throw new IOException(stream.Name + ": the file could not be synced to the device (errno " + errno + ")");
        }

        /// <summary>libc's <c>fsync</c>, again while a signal interrupts it (EINTR, as .NET's own shim does); the errno of a failure.</summary>
        static int Fsync(int fd, out int errno)
        {
            int result;
            errno = 0;
            while ((result = Libc.Fsync(fd)) != 0 && (errno = Marshal.GetLastWin32Error()) == EINTR) { }
            return result;
        }

        /// <summary>The errno of a file system that does not sync this kind of file (EINVAL, EOPNOTSUPP; ENOTSUP on macOS).</summary>
        static bool IsRefusal(int errno) => errno == EINVAL || errno == EOPNOTSUPP_Linux || (errno == ENOTSUP_Darwin && IsDarwin);

        /// <summary>
        /// Creates <paramref name="directory"/> and any missing parent, syncing the folder above each one created,
        /// so that a folder made for a session is on the device before the first answer in it is acknowledged.
        /// </summary>
        public static void CreateDirectory(string directory)
        {
            if (string.IsNullOrEmpty(directory)) return;
            string full = Path.GetFullPath(directory);
            if (Directory.Exists(full)) return;
            string parent = Path.GetDirectoryName(full);
            if (!string.IsNullOrEmpty(parent)) CreateDirectory(parent);
            Directory.CreateDirectory(full);
            if (Durable && !string.IsNullOrEmpty(parent)) SyncDirectory(parent);
        }

        /// <summary>What <see cref="SyncDirectory"/> does on this platform.</summary>
        public enum DirectorySyncKind
        {
            /// <summary>Not tried yet on this platform (the first sync decides).</summary>
            Unknown,
            /// <summary>The folder is opened and <c>fsync</c>ed (Linux, Android, macOS: libc <c>open</c>/<c>fsync</c>/<c>close</c>).</summary>
            Synced,
            /// <summary>Windows, or no libc to call: the rename is not synced (the file's data is).</summary>
            Unsupported,
            /// <summary>The file system refused <c>fsync</c> on a folder (EINVAL, EOPNOTSUPP): the rename is not synced.</summary>
            Refused,
        }

        /// <summary>What the last <see cref="SyncDirectory"/> did.</summary>
        public static DirectorySyncKind DirectorySync { get; private set; }

        /// <summary>
        /// Syncs the folder's entries (the names in it, so a rename into it) to the device. On Linux, Android and
        /// macOS: open, fsync, close through libc; an error other than "not supported for a folder" throws
        /// <see cref="IOException"/> naming the errno. On Windows it does nothing (<see cref="DirectorySync"/> =
        /// <see cref="DirectorySyncKind.Unsupported"/>).
        /// </summary>
        public static void SyncDirectory(string directory)
        {
            if (!IsUnix)
            {
                DirectorySync = DirectorySyncKind.Unsupported;
                return;
            }
            int fd, errno;
            try
            {
                fd = Libc.Open(directory, OpenReadOnly | OpenCloseOnExec);
                errno = Marshal.GetLastWin32Error(); // read only when fd < 0
            }
            catch (Exception e) when (e is DllNotFoundException || e is EntryPointNotFoundException)
            {
                DirectorySync = DirectorySyncKind.Unsupported;
                return;
            }
            if (fd < 0) throw new IOException(directory + ": the folder could not be opened to sync it (errno " + errno + ")");
            try
            {
                if (Fsync(fd, out errno) != 0)
                {
                    if (IsRefusal(errno))
                    {
                        DirectorySync = DirectorySyncKind.Refused;
                        return;
                    }
                    throw new IOException(directory + ": the folder could not be synced to the device (errno " + errno + ")");
                }
                DirectorySync = DirectorySyncKind.Synced;
            }
            finally
            {
                Libc.Close(fd);
            }
        }

        // O_RDONLY and O_CLOEXEC have these values on Linux (x86, x86-64, ARM, ARM64: Android) and macOS differs only
        // in O_CLOEXEC, which is then left out (it only keeps the descriptor from a child process). A folder opens
        // read-only without O_DIRECTORY, whose value differs between x86-64 and ARM64.
        const int OpenReadOnly = 0;
        static int OpenCloseOnExec => IsDarwin ? 0 : 0x80000;
        const int EINTR = 4, EINVAL = 22, EOPNOTSUPP_Linux = 95, ENOTSUP_Darwin = 45;

        /// <summary>The platforms whose syncs differ (<see cref="SyncStream"/>, <see cref="SyncDirectory"/>).</summary>
        internal enum SyncPlatform
        {
            /// <summary>Linux and Android: libc's fsync, checked; folders synced.</summary>
            Linux,
            /// <summary>macOS: .NET's F_FULLFSYNC for files; folders through libc, opened without O_CLOEXEC; ENOTSUP a refusal.</summary>
            MacOS,
            /// <summary>Windows: .NET's FlushFileBuffers for files; folders not synced.</summary>
            Windows,
        }

        /// <summary>
        /// The platform whose syncs are made instead of the running one: null but in the edit-mode tests, which set one on
        /// Linux to run that platform's branch (AtomicFilePlatformTests); the kernel then answers as Linux's.
        /// </summary>
        internal static SyncPlatform? PlatformForTests { get; set; }

        /// <summary>The platform whose syncs are made.</summary>
        internal static SyncPlatform Platform => PlatformForTests ?? RunningPlatform();

        static SyncPlatform RunningPlatform()
        {
            if (RuntimeInformation.IsOSPlatform(OSPlatform.OSX)) return SyncPlatform.MacOS;
            var platform = Environment.OSVersion.Platform;
            return platform == PlatformID.Unix || platform == PlatformID.MacOSX ? SyncPlatform.Linux : SyncPlatform.Windows;
        }

        static bool IsUnix => Platform != SyncPlatform.Windows;
        static bool IsDarwin => Platform == SyncPlatform.MacOS;

        /// <summary>libc's open/fsync/close/rename: plain DllImport (no marshalling beyond a string), which IL2CPP and Mono support.</summary>
        static class Libc
        {
            [DllImport("libc", EntryPoint = "open", SetLastError = true)]
            public static extern int Open([MarshalAs(UnmanagedType.LPStr)] string path, int flags);

            [DllImport("libc", EntryPoint = "fsync", SetLastError = true)]
            public static extern int Fsync(int fd);

            [DllImport("libc", EntryPoint = "close", SetLastError = true)]
            public static extern int Close(int fd);

            [DllImport("libc", EntryPoint = "rename", SetLastError = true)]
            public static extern int Rename([MarshalAs(UnmanagedType.LPStr)] string from, [MarshalAs(UnmanagedType.LPStr)] string to);
        }

        /// <summary>
        /// Set only in the edit-mode tests: <see cref="Rename"/> acts as on a runtime whose <see cref="File.Replace(string, string, string)"/>
        /// throws <see cref="PlatformNotSupportedException"/>, so the fallback runs on this machine (AtomicFileSyscallTests).
        /// </summary>
        internal static bool ReplaceUnsupportedForTests { get; set; }

        /// <summary>
        /// The replace of a runtime without <see cref="File.Replace(string, string, string)"/>. On Linux, Android and macOS, libc's
        /// <c>rename</c>, which replaces the destination in one step as File.Replace does there (removing the old file first
        /// would leave, after a kill or power cut between the two, no answers file at all but a temporary one that the
        /// session's next start removes). Without libc (Windows, whose .NET always has File.Replace), the old file goes,
        /// then the new one takes its name.
        /// </summary>
        static void ReplaceWithoutFileReplace(string temp, string full)
        {
            if (IsUnix && TryLibcRename(temp, full)) return;
            File.Delete(full);
            File.Move(temp, full);
        }

        /// <summary>libc's <c>rename</c>; false without libc; a failure throws <see cref="IOException"/> naming the destination and the errno.</summary>
        static bool TryLibcRename(string temp, string full)
        {
            int result;
            try { result = Libc.Rename(temp, full); }
            catch (Exception e) when (e is DllNotFoundException || e is EntryPointNotFoundException) { return false; }
            if (result != 0) throw new IOException(full + ": could not be replaced (errno " + Marshal.GetLastWin32Error() + ")");
            return true;
        }

        /// <summary>
        /// Moves <paramref name="temp"/> onto <paramref name="full"/>, replacing a file there. A writer that
        /// creates or removes the destination at the same moment does not make this fail: it tries again.
        /// </summary>
        public static void Rename(string temp, string full)
        {
            for (int attempt = 0; ; attempt++)
            {
                try
                {
                    if (!File.Exists(full)) File.Move(temp, full);
                    else
                    {
                        try
                        {
                            if (ReplaceUnsupportedForTests) throw new PlatformNotSupportedException("File.Replace (as the tests set)");
                            File.Replace(temp, full, null);
                        }
                        catch (PlatformNotSupportedException)
                        {
                            ReplaceWithoutFileReplace(temp, full);
                        }
                    }
                    return;
                }
                catch (IOException) when (attempt < 8 && File.Exists(temp) && !Directory.Exists(full))
                {
                    // Another writer created (Move: "already exists") or removed (Replace: "not found") the
                    // destination between the check and the rename.
                }
            }
        }
    }
}
