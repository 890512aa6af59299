namespace Kosmos.PseudoHaptic.Cli;

/// <summary>
/// The command's output files, written through the package's write-then-rename
/// (<see cref="Kosmos.PseudoHaptic.Evaluation.AtomicFile"/>): a failure or an error leaves no output and no
/// temporary file behind, and an existing file as it was.
/// </summary>
public static class AtomicFile
{
    public static void Write(string path, Action<TextWriter> write)
    {
        string dir = Path.GetDirectoryName(Path.GetFullPath(path)) ?? ".";
        if (!Directory.Exists(dir)) throw new CliException($"{path}: the folder {dir} does not exist");
        Kosmos.PseudoHaptic.Evaluation.AtomicFile.WriteWith(path, temp =>
        {
            using var writer = new StreamWriter(temp, false, new System.Text.UTF8Encoding(false)) { NewLine = "\n" };
            write(writer);
        });
    }
}
