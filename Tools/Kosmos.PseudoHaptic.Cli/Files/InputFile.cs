using System.Text;

namespace Kosmos.PseudoHaptic.Cli.Files;

/// <summary>
/// Opens a command's input files. A missing file or a folder: exit 2 (an input error) with one line naming the user's
/// path ("does not exist", "is a folder"); a file that cannot be read (no permission, a device error): exit 1, the
/// tool's code for I/O (issue 25), "cannot read: REASON". A FIFO or a device is read as a stream. Text is UTF-8 with
/// or without a byte-order mark.
/// </summary>
public static class InputFile
{
    /// <summary>Checks that <paramref name="path"/> can be opened for reading, without reading it.</summary>
    public static void Check(string option, string path)
    {
        var kind = path.Length == 0 || path.IndexOf('\0') >= 0 ? FileKind.Missing : FileIdentity.Of(path).Kind;
        if (kind is FileKind.Fifo or FileKind.Socket or FileKind.CharacterDevice or FileKind.Other) return; // opening would consume it
        using var stream = Open(option, path);
    }

    public static Stream Open(string option, string path)
    {
        if (path.Length == 0) throw new CliException($"option {option}: the path is empty");
        string shown = $"{option} {Messages.Path(path)}";
        if (path.IndexOf('\0') >= 0) throw new CliException($"{shown}: a path may not hold a NUL character");
        var id = FileIdentity.Of(path);
        if (id.Kind == FileKind.Folder || Directory.Exists(path)) throw new CliException($"{shown}: is a folder, not a file");
        try
        {
            return new FileStream(path, FileMode.Open, FileAccess.Read, FileShare.ReadWrite | FileShare.Delete, 1, FileOptions.SequentialScan);
        }
        catch (Exception e) when (e is FileNotFoundException or DirectoryNotFoundException)
        {
            throw new CliException($"{shown}: does not exist");
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException or NotSupportedException or ArgumentException)
        {
            throw new CliException($"{shown}: cannot read: {Messages.Reason(e)}", Cli.InputOutputError);
        }
    }

    /// <summary>The file as text, read as it is consumed (UTF-8, a byte-order mark dropped).</summary>
    public static StreamReader OpenText(string option, string path)
        => new(new ReadErrors(Open(option, path), option, path), new UTF8Encoding(false), detectEncodingFromByteOrderMarks: true, 65536);

    /// <summary>
    /// A small file whole (a profile, a user's file), read up to <paramref name="maxCharacters"/>: beyond it (a wrong file,
    /// /dev/zero) it is refused naming the option, so memory stays bounded whatever the file's size.
    /// </summary>
    public static string ReadSmallText(string option, string path, int maxCharacters = MaxSmallFile, string expected = "a small JSON file")
    {
        using var reader = OpenText(option, path);
        var buffer = new char[maxCharacters + 1];
        int read = 0, n;
        while (read < buffer.Length && (n = reader.Read(buffer, read, buffer.Length - read)) > 0) read += n;
        if (read > maxCharacters)
            throw new CliException($"{option} {Messages.Path(path)}: longer than {maxCharacters:N0} characters; expected {expected}");
        return new string(buffer, 0, read);
    }

    /// <summary>The longest profile or user's file read, characters (a profile of every effect is about 3,000).</summary>
    public const int MaxSmallFile = 1 << 20;

    /// <summary>Turns a failure while reading into one line naming the input.</summary>
    sealed class ReadErrors(Stream inner, string option, string path) : Stream
    {
        public override int Read(byte[] buffer, int offset, int count)
        {
            try { return inner.Read(buffer, offset, count); }
            catch (Exception e) when (e is IOException or UnauthorizedAccessException)
            {
                throw new CliException($"{option} {Messages.Path(path)}: cannot read: {Messages.Reason(e)}", Cli.InputOutputError);
            }
        }

        public override int Read(Span<byte> buffer)
        {
            try { return inner.Read(buffer); }
            catch (Exception e) when (e is IOException or UnauthorizedAccessException)
            {
                throw new CliException($"{option} {Messages.Path(path)}: cannot read: {Messages.Reason(e)}", Cli.InputOutputError);
            }
        }

        public override bool CanRead => true;
        public override bool CanSeek => false;
        public override bool CanWrite => false;
        public override long Length => throw new NotSupportedException();
        public override long Position { get => throw new NotSupportedException(); set => throw new NotSupportedException(); }
        public override void Flush() { }
        public override long Seek(long offset, SeekOrigin origin) => throw new NotSupportedException();
        public override void SetLength(long value) => throw new NotSupportedException();
        public override void Write(byte[] buffer, int offset, int count) => throw new NotSupportedException();

        protected override void Dispose(bool disposing)
        {
            if (disposing) inner.Dispose();
            base.Dispose(disposing);
        }
    }
}
