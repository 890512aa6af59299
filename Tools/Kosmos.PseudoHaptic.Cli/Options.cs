using System.Globalization;

namespace Kosmos.PseudoHaptic.Cli;

/// <summary>
/// "--name value" options after a command. Unknown or repeated options and missing values are errors that
/// name the option.
/// </summary>
public sealed class Options
{
    readonly Dictionary<string, string> _values = new(StringComparer.Ordinal);

    public Options(string[] args, params string[] known)
    {
        for (int i = 0; i < args.Length; i++)
        {
            string a = args[i];
            if (!a.StartsWith("--", StringComparison.Ordinal) || Array.IndexOf(known, a) < 0)
                throw new CliException($"unknown option '{a}'; expected {string.Join(", ", known)}");
            if (i + 1 >= args.Length)
                throw new CliException($"option {a} needs a value");
            if (!_values.TryAdd(a, args[++i]))
                throw new CliException($"option {a} is given twice");
        }
    }

    public string? Get(string name) => _values.TryGetValue(name, out var v) ? v : null;

    public string Require(string name) => Get(name) ?? throw new CliException($"option {name} is required");

    public double? Number(string name)
    {
        var text = Get(name);
        if (text == null) return null;
        if (!NumberText.TryParse(text, out double v))
            throw new CliException($"option {name}: cannot parse '{text}' as a number");
        return v;
    }
}
