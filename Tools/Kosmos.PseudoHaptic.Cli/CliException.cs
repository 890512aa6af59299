namespace Kosmos.PseudoHaptic.Cli;

/// <summary>A contract error: the command prints its one-line message on stderr and exits with <see cref="ExitCode"/>.</summary>
public sealed class CliException(string message, int exitCode = 2) : Exception(message)
{
    public int ExitCode { get; } = exitCode;
}
