using System.CommandLine;
using System.CommandLine.Help;
using System.CommandLine.Invocation;

namespace Kosmos.PseudoHaptic.Cli.CommandLine;

/// <summary>
/// System.CommandLine's help (usage, options with their descriptions), followed by the command's examples and
/// the tool's exit codes. The library keeps its help layout internal, so the sections are added after it.
/// </summary>
public sealed class HelpWithExamples(HelpAction standard, IReadOnlyList<CliCommand> commands) : SynchronousCommandLineAction
{
    public override bool ClearsParseErrors => true;

    public override int Invoke(ParseResult result)
    {
        standard.MaxWidth = 110;
        int code = standard.Invoke(result);
        var w = result.InvocationConfiguration.Output;
        var command = commands.FirstOrDefault(c => c.Command == result.CommandResult.Command);
        if (command is { Examples.Length: > 0 })
        {
            w.WriteLine("Examples (from the repository's root; they write under out/: run mkdir -p out first):");
            foreach (var e in command.Examples) w.WriteLine("  " + e);
            w.WriteLine();
        }
        w.WriteLine("Exit codes: 0 done; 1 a file could not be read or written; 2 a usage or input error (a bad option, a malformed file).");
        w.WriteLine("Errors are one line on standard error: pseudohaptic COMMAND: …");
        return code;
    }
}
