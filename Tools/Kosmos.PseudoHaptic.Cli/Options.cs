using System.CommandLine;

namespace Kosmos.PseudoHaptic.Cli;

/// <summary>
/// A command's options as parsed by System.CommandLine (unknown and repeated options and missing values are
/// refused by the parser before a command runs), read by name. Numbers are parsed here, so a bad one names
/// its option: "option --mass-kg: cannot parse 'x' as a number".
/// </summary>
public sealed class Options
{
    readonly ParseResult _result;
    readonly Command _command;

    public Options(ParseResult result, Command command)
    {
        _result = result;
        _command = command;
    }

    Option Find(string name) => _command.Options.FirstOrDefault(o => o.Name == name)
        ?? throw new InvalidOperationException($"{_command.Name} has no option {name}");

    /// <summary>The option's text, or null when it was not given.</summary>
    public string? Get(string name)
    {
        var option = Find(name);
        var result = _result.GetResult(option);
        return result == null || result.Implicit ? null : _result.GetValue<string>(name);
    }

    /// <summary>A positional argument's text (its default when not given).</summary>
    public string? Argument(string name) => _result.GetValue<string>(name);

    /// <summary>Whether the switch (an option without a value) was given.</summary>
    public bool Flag(string name) => _result.GetResult(Find(name)) is { Implicit: false };

    public string Require(string name) => Get(name) ?? throw new CliException($"option {name} is required");

    public double? Number(string name)
    {
        var text = Get(name);
        if (text == null) return null;
        if (!NumberText.TryParse(text, out double v))
            throw new CliException($"option {name}: cannot parse '{Files.Messages.OneLine(text)}' as a number");
        return v;
    }
}
