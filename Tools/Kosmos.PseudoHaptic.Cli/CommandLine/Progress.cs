namespace Kosmos.PseudoHaptic.Cli.CommandLine;

/// <summary>
/// Where long work (demo, accuracy, the bootstrap of psychometric) reports its progress: standard error when it
/// is a terminal, nowhere when it is redirected (a log or a pipe gets the result, not the chatter).
/// </summary>
public static class Progress
{
    /// <summary>Set by tests to see the progress although standard error is not a terminal.</summary>
    public static bool Forced { get; set; }

    public static TextWriter Writer => Forced || !Console.IsErrorRedirected ? Console.Error : TextWriter.Null;
}
