using System.CommandLine;

namespace Kosmos.PseudoHaptic.Cli.CommandLine;

/// <summary>
/// One command of the tool as System.CommandLine sees it: its options (each with a value name, a description
/// that gives the unit and the default), the examples its help shows (and <c>CliExamplesTests</c> runs), and its
/// body. Values are taken as text and checked by the command, so every message names the option the same way.
/// </summary>
public sealed class CliCommand
{
    public CliCommand(string name, string summary, Func<Options, int> run, string[] examples, params Symbol[] symbols)
    {
        Name = name;
        Examples = examples;
        Command = new Command(name, summary);
        var options = symbols.OfType<Option>().ToArray();
        foreach (var option in options) Command.Options.Add(option);
        foreach (var argument in symbols.OfType<Argument>()) Command.Arguments.Add(argument);
        // An option given twice is refused (the parser would keep the last value without a word).
        Command.Validators.Add(result =>
        {
            foreach (var option in options)
                if (result.GetResult(option) is { IdentifierTokenCount: > 1 })
                    result.AddError($"option {option.Name} is given twice");
        });
        Command.SetAction(result => run(new Options(result, Command)));
    }

    public string Name { get; }

    /// <summary>Command lines as a user types them, each runnable from the repository's root.</summary>
    public string[] Examples { get; }

    public Command Command { get; }

    /// <summary>An option that takes a value (<paramref name="valueName"/> in the help: FILE, M, DIR).</summary>
    public static Option<string> Value(string name, string valueName, string description, bool required = false) =>
        new(name) { HelpName = valueName, Description = description, Required = required };

    /// <summary>An option without a value (a switch such as --svg).</summary>
    public static Option<bool> Flag(string name, string description) => new(name) { Description = description, Arity = ArgumentArity.Zero };

    /// <summary>An option that takes one of <paramref name="choices"/>; the shell completes them.</summary>
    public static Option<string> Choice(string name, string description, params string[] choices)
    {
        var option = Value(name, string.Join('|', choices), description);
        option.CompletionSources.Add(choices);
        return option;
    }
}
