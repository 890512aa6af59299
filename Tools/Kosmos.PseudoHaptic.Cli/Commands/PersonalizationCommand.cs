using Kosmos.PseudoHaptic.Cli.CommandLine;
using Kosmos.PseudoHaptic.Cli.Files;
using Kosmos.PseudoHaptic.Cli.Personalization;

namespace Kosmos.PseudoHaptic.Cli.Commands;

/// <summary><c>pseudohaptic personalization --markdown FILE</c>: writes issue 31's generated page (<see cref="PersonalizationPage"/>).</summary>
public static class PersonalizationCommand
{
    public static CliCommand Define() => new(
        "personalization",
        "Write the generated tables of ALGORITHM.md §12 and evaluation.md §9: the paper per profile, what v_std and the lift's pace do, the cue strength, tuning on simulated participants",
        Run,
        new[] { "pseudohaptic personalization --markdown out/personalization-results.md" },
        CliCommand.Value("--markdown", "FILE", "where the page goes ('-': standard output); replaced whole or not at all", required: true));

    static int Run(Options o)
    {
        string output = o.Require("--markdown");
        var target = OutputFile.Check("--markdown", output);
        string page = PersonalizationPage.Page();
        target.Write(w => w.Write(page));
        (target.IsStandardOutput ? Console.Error : Console.Out).WriteLine($"personalization: {PersonalizationPage.Blocks().Count} tables -> {Messages.OneLine(output)}");
        return 0;
    }
}
