using System.CommandLine;
using System.CommandLine.Parsing;
using System.Text.RegularExpressions;

namespace Kosmos.PseudoHaptic.Cli.CommandLine;

/// <summary>
/// The parser's errors in the words of the tool's other messages ("option --out is required", "unknown option
/// '--x'; expected …"): System.CommandLine finds them, this only words them. An error it has no wording for is
/// passed on as the library gives it.
/// </summary>
public static partial class ParseErrors
{
    public static string Describe(ParseResult result)
    {
        // An unknown word first: "frob" says more than "no command given".
        var error = result.Errors.FirstOrDefault(e => Unrecognized().IsMatch(e.Message)) ?? result.Errors[0];
        string message = error.Message;
        var command = result.CommandResult.Command;
        if (Unrecognized().Match(message) is { Success: true } u)
        {
            string token = u.Groups[1].Value;
            if (command is RootCommand && token.StartsWith('-'))
                return $"unknown option '{token}'; expected --help, --version or a command: {string.Join(", ", command.Subcommands.Select(c => c.Name))}";
            if (command is RootCommand)
                return $"unknown command '{token}'; expected {string.Join(", ", command.Subcommands.Select(c => c.Name))}";
            string known = string.Join(", ", command.Options.Where(o => !o.Name.StartsWith("-?", StringComparison.Ordinal) && o.Name != "--help").Select(o => o.Name));
            return token.StartsWith('-')
                ? $"unknown option '{token}'; expected {known}"
                : $"unexpected argument '{token}' (every value follows its option: {known})";
        }
        if (Required().Match(message) is { Success: true } r) return $"option {r.Groups[1].Value} is required";
        if (MissingValue().Match(message) is { Success: true } m) return $"option {m.Groups[1].Value} needs a value";
        if (command is RootCommand && message.StartsWith("Required command", StringComparison.Ordinal))
            return $"no command given; expected {string.Join(", ", command.Subcommands.Select(c => c.Name))}";
        return message.TrimEnd('.');
    }

    [GeneratedRegex(@"^Unrecognized command or argument '(.*)'\.?$", RegexOptions.Singleline)]
    private static partial Regex Unrecognized();

    [GeneratedRegex(@"^Option '(.*)' is required\.?$")]
    private static partial Regex Required();

    [GeneratedRegex(@"^Required argument missing for option: '(.*)'\.?$")]
    private static partial Regex MissingValue();
}
