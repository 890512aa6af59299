using System.Text;
using Kosmos.PseudoHaptic.Cli.CommandLine;
using Kosmos.PseudoHaptic.Cli.Files;

namespace Kosmos.PseudoHaptic.Cli.Commands;

/// <summary>
/// <c>pseudohaptic profiles [--show NAME|FILE.json [--json]] [--out FILE]</c> (issue 33): lists the named profiles and every
/// registered effect (name, stage, summary, settings with units, defaults and ranges), or shows one profile, as text or as
/// the profile file every <c>--profile</c> takes. Everything it prints comes from the effects' descriptors
/// (<see cref="EffectRegistry"/>): it has no code of its own per effect.
/// </summary>
public static class ProfilesCommand
{
    public static CliCommand Define() => new(
        "profiles",
        "List the named profiles and the effects (name, stage, summary, settings with units and defaults), or show one profile, as text or as the JSON file --profile takes",
        Run,
        new[]
        {
            "pseudohaptic profiles",
            "pseudohaptic profiles --show xyz",
            "pseudohaptic profiles --show paper --json --out out/paper.json",
            "pseudohaptic profiles --markdown out/effects-table.md",
        },
        CliCommand.Value("--show", "NAME|FILE.json", $"show one profile: a named one ({string.Join(", ", NamedProfiles.Names)}) or a profile file (default: list every profile and effect)"),
        CliCommand.Flag("--json", "with --show: write the profile as JSON, the file any --profile takes (every effect with every setting, the limits)"),
        CliCommand.Value("--markdown", "FILE", "write the generated effects table instead, between its markers: a file that holds them (ALGORITHM.md) keeps the rest of its text, a new or empty one gets the table alone ('-': standard output; default: none)"),
        CliCommand.Value("--out", "FILE", "where the listing or the profile goes (default '-': standard output); replaced whole or not at all"));

    public static int Run(string[] args) => Cli.Run(args.Prepend("profiles").ToArray());

    static int Run(Options o)
    {
        string? markdown = o.Get("--markdown");
        if (markdown != null)
        {
            if (o.Get("--show") != null || o.Flag("--json") || o.Get("--out") != null)
                throw new CliException("option --markdown: writes the effects table alone; leave out --show, --json and --out");
            var table = OutputFile.Check("--markdown", markdown);
            string? existing = !table.IsStandardOutput && FileIdentity.Of(markdown).Kind == FileKind.Regular
                ? InputFile.ReadSmallText("--markdown", markdown, expected: "a Markdown file")
                : null;
            string page = EffectsTable.Into(existing)
                ?? throw new CliException($"option --markdown {Messages.Path(markdown)}: holds text but not one effects table between its markers " +
                                          $"('{EffectsTable.StartMarker}…' and '{EffectsTable.EndMarker}', each starting a line), so it is left as it is; give a new file, one that holds them, or '-'");
            table.Write(w => w.Write(page));
            (table.IsStandardOutput ? Console.Error : Console.Out).WriteLine($"profiles: the effects table, {EffectRegistry.Package.Count} effects -> {Messages.OneLine(markdown)}");
            return 0;
        }
        string? show = o.Get("--show");
        bool json = o.Flag("--json");
        if (json && show == null) throw new CliException("option --json: needs --show NAME (which profile to write)");
        string output = o.Get("--out") ?? "-";
        var target = OutputFile.Check("--out", output, new NamedPath("--show", show != null && !NamedProfiles.Names.Contains(show) ? show : null));
        string text, what;
        if (show == null)
        {
            text = Listing();
            what = $"{NamedProfiles.Names.Count} named profiles, {EffectRegistry.All.Count} effects";
        }
        else
        {
            var profile = ProfileOption.Resolve(show, option: "--show");
            text = json ? ProfileJson.Write(profile) : Show(profile);
            what = $"profile {Messages.OneLine(profile.Name)}, {profile.Effects.Count} effects{(json ? " as JSON" : "")}";
        }
        target.Write(w => w.Write(text));
        (target.IsStandardOutput ? Console.Error : Console.Out).WriteLine($"profiles: {what} -> {Messages.OneLine(output)}");
        return 0;
    }

    /// <summary>The named profiles, then every effect with its settings.</summary>
    public static string Listing()
    {
        var sb = new StringBuilder("Named profiles (--profile NAME; effects in the order a frame flows through them):\n");
        int width = NamedProfiles.Names.Max(n => n.Length);
        foreach (string name in NamedProfiles.Names)
            sb.Append("  ").Append(name.PadRight(width)).Append("  ").Append(string.Join(", ", NamedProfiles.Get(name).Effects.Select(e => e.Name))).Append('\n');
        sb.Append("\nEffects (a profile file lists them with \"effect\": NAME and any of their settings; a setting left out takes its default):\n");
        foreach (var d in EffectRegistry.All)
        {
            sb.Append("  ").Append(d.Name).Append(" [").Append(d.Stage).Append("]: ").Append(d.Summary).Append('\n');
            foreach (var s in d.Settings)
                sb.Append("      ").Append(s.Name).Append(" = ").Append(WithUnit(s, s.Default)).Append(" (").Append(s.RangeText).Append("): ").Append(s.Summary).Append('\n');
        }
        sb.Append("\nLimits (every profile; \"limits\" in a profile file):\n");
        foreach (var s in SolverLimits.Settings)
            sb.Append("      ").Append(s.Name).Append(" = ").Append(WithUnit(s, s.Default)).Append(" (").Append(s.RangeText).Append("): ").Append(s.Summary).Append('\n');
        return sb.ToString();
    }

    /// <summary>One profile as text: each effect with the value of every setting.</summary>
    public static string Show(WeightProfile profile)
    {
        var sb = new StringBuilder();
        sb.Append("Profile ").Append(Messages.OneLine(profile.Name)).Append(": ").Append(profile.Effects.Count).Append(" effects").Append(profile.HandFilter != null ? ", hand filter " + profile.HandFilter.Name : "").Append('\n');
        foreach (var e in profile.Effects)
        {
            var d = EffectRegistry.Of(e);
            var values = d.SettingsOf(e);
            sb.Append("  ").Append(d.Name).Append(" [").Append(d.Stage).Append(']');
            for (int i = 0; i < values.Count; i++)
                sb.Append(i == 0 ? ": " : ", ").Append(d.Settings[i].Name).Append(' ').Append(WithUnit(d.Settings[i], values[i]));
            sb.Append('\n');
        }
        sb.Append("  limits: ").Append(string.Join(", ", SolverLimits.Settings.Select(s => s.Name + " " + WithUnit(s, s.Read(profile.Limits))))).Append('\n');
        return sb.ToString();
    }

    static string WithUnit(SettingDescriptor s, double value) => s.Format(value) + (s.Unit.Length > 0 ? " " + s.Unit : "");
}
