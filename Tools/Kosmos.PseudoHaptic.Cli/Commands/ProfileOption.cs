using System.CommandLine;
using Kosmos.PseudoHaptic.Cli.CommandLine;
using Kosmos.PseudoHaptic.Cli.Files;

namespace Kosmos.PseudoHaptic.Cli.Commands;

/// <summary>
/// <c>--profile NAME|FILE.json</c> for every command that takes a profile (issue 33): a named profile, or a profile file as
/// <c>pseudohaptic profiles --show NAME --json</c> and the Unity asset's export write it (<see cref="ProfileJson"/>). A
/// file that describes a named profile exactly is that profile, so <c>--profile paper</c> and <c>--profile paper.json</c>
/// give the same output byte for byte. Errors are one line naming the option, the file and line, the effect and the setting.
/// </summary>
public static class ProfileOption
{
    public const string Name = "--profile";

    public static Option<string> Define(string description)
    {
        var option = CliCommand.Value(Name, string.Join('|', NamedProfiles.Names) + "|FILE.json", description + "; or a profile file (FILE.json, as 'pseudohaptic profiles --show NAME --json' writes it)");
        option.CompletionSources.Add(NamedProfiles.Names.ToArray());
        return option;
    }

    /// <summary>The profile <paramref name="value"/> names (null: <paramref name="fallback"/>).</summary>
    public static WeightProfile Resolve(string? value, string fallback = NamedProfiles.PaperName, string option = Name)
    {
        string name = value ?? fallback;
        if (NamedProfiles.Names.Contains(name)) return NamedProfiles.Get(name);
        if (!IsPath(name))
            throw new CliException($"option {option}: unknown profile '{Messages.OneLine(name)}'; expected {string.Join(", ", NamedProfiles.Names)} or a profile file FILE.json");
        string text = InputFile.ReadSmallText(option, name);
        try { return ProfileJson.Read(text, Messages.OneLine(name)); }
        catch (ProfileFormatException e) { throw new CliException($"option {option}: {Messages.OneLine(e.Message)}"); }
        catch (ArgumentException e) { throw new CliException($"option {option}: {Messages.OneLine(name)}: {Messages.OneLine(e.Message)}"); }
    }

    /// <summary>--profile as an input file the output must not replace (none when it names a profile).</summary>
    public static NamedPath AsInput(Options o)
    {
        string? value = o.Get(Name);
        return new NamedPath(Name, value != null && !NamedProfiles.Names.Contains(value) ? value : null);
    }

    /// <summary>A value that is not a profile's name is a file when it looks like one: it ends in .json, holds a path
    /// separator, or exists.</summary>
    static bool IsPath(string value)
        => value.EndsWith(".json", StringComparison.OrdinalIgnoreCase) || value.Contains('/') || value.Contains(Path.DirectorySeparatorChar) || File.Exists(value);
}
