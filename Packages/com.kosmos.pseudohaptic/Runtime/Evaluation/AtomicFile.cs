using System;
using System.IO;
using System.Text;

namespace Kosmos.PseudoHaptic.Evaluation
{
    /// <summary>
    /// Write-then-rename: the text goes to a temporary file in the destination's own folder (so the rename
    /// stays on one file system), which then replaces the destination in one step. A crash or an error
    /// leaves either the old file or the new one, never half of one; the temporary file is removed on error.
    /// </summary>
    public static class AtomicFile
    {
        static readonly UTF8Encoding Utf8NoBom = new UTF8Encoding(false);

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
            string directory = Path.GetDirectoryName(full);
            if (string.IsNullOrEmpty(directory)) directory = ".";
            string temp = Path.Combine(directory, "." + Path.GetFileName(full) + "." + Guid.NewGuid().ToString("N").Substring(0, 8) + ".tmp");
            try
            {
                write(temp);
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
            }
            catch
            {
                try { if (File.Exists(temp)) File.Delete(temp); } catch (IOException) { } catch (UnauthorizedAccessException) { }
                throw;
            }
        }
    }
}
