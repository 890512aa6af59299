using Kosmos.PseudoHaptic.Cli.Files;

namespace Kosmos.PseudoHaptic.Cli;

/// <summary>
/// A command's output file by the tool's rules (<see cref="OutputFile"/>): checked, then written through
/// write-then-rename (or straight into a FIFO, a device or standard output for "-"). Prefer checking with
/// <see cref="OutputFile.Check"/> before reading any input, and passing the inputs so an input is never
/// overwritten; this shortcut checks at the moment of writing.
/// </summary>
public static class AtomicFile
{
    public static void Write(string path, Action<TextWriter> write, string option = "--out", params NamedPath[] inputs)
        => OutputFile.Check(option, path, inputs).Write(write);
}
