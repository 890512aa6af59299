using System;
using System.IO;
using System.Text;

namespace Kosmos.PseudoHaptic.Evaluation
{
    /// <summary>
    /// Write-then-rename: the text goes to a temporary file in the destination's own folder (so the rename
    /// stays on one file system), which then replaces the destination in one step. A crash or an error
    /// leaves either the old file or the new one, never half of one; the temporary file is removed on error.
    /// The temporary name is short and fixed in length (".ph" + 8 hex digits + ".tmp"), so any destination
    /// name the file system accepts works; two writers racing for one destination both succeed, the last
    /// rename wins.
    /// </summary>
    public static class AtomicFile
    {
        static readonly UTF8Encoding Utf8NoBom = new UTF8Encoding(false);

        /// <summary>A fresh temporary name in <paramref name="directory"/>: ".ph" + 8 hex digits + <paramref name="extension"/>.</summary>
        public static string TemporaryPath(string directory, string extension = ".tmp")
            => Path.Combine(directory, ".ph" + Guid.NewGuid().ToString("N").Substring(0, 8) + extension);

        public static void WriteAllText(string path, string text)
        {
            WriteWith(path, temp => File.WriteAllText(temp, text ?? "", Utf8NoBom));
        }

        /// <summary>Lets <paramref name="write"/> create the temporary file (any content), then renames it to <paramref name="path"/>.</summary>
        public static void WriteWith(string path, Action<string> write)
        {
            if (string.IsNullOrEmpty(path)) throw new ArgumentException("empty path", nameof(path));
            if (write == null) throw new ArgumentNullException(nameof(write));
            string full = Path.GetFullPath(path);
            if (Directory.Exists(full)) throw new IOException(path + ": is a folder");
            string directory = Path.GetDirectoryName(full);
            if (string.IsNullOrEmpty(directory)) directory = ".";
            string temp = TemporaryPath(directory);
            try
            {
                write(temp);
                Rename(temp, full);
            }
            catch
            {
                try { if (File.Exists(temp)) File.Delete(temp); } catch (IOException) { } catch (UnauthorizedAccessException) { }
                throw;
            }
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
                        try { File.Replace(temp, full, null); }
                        catch (PlatformNotSupportedException)
                        {
                            // Some runtimes lack an atomic replace: the old file goes, then the new one takes its name.
                            File.Delete(full);
                            File.Move(temp, full);
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
