using System.Text;

namespace Kosmos.PseudoHaptic.Cli.Commands;

/// <summary>
/// ALGORITHM.md §6's effects table, generated from the package's effects (<see cref="EffectRegistry.Package"/>: name,
/// class, stage, source, summary, settings with defaults, units and ranges). <c>pseudohaptic profiles --markdown FILE</c>
/// writes it between its markers; <c>EffectsTableTests</c> fails when ALGORITHM.md holds anything else. No code per effect.
/// </summary>
public static class EffectsTable
{
    public const string Document = "Packages/com.kosmos.pseudohaptic/Documentation~/ALGORITHM.md";
    public const string Command = "pseudohaptic profiles --markdown -";
    const string Marker = "effects-table";

    /// <summary>The table wrapped in its markers, as ALGORITHM.md holds it.</summary>
    public static string Block()
    {
        var sb = new StringBuilder();
        sb.Append("<!-- generated: ").Append(Marker).Append(" (").Append(Command).Append("; EffectsTableTests) -->\n");
        sb.Append("| effect | stage | source | what it does | settings: default (valid range) |\n|---|---|---|---|---|\n");
        foreach (var d in EffectRegistry.Package)
        {
            sb.Append("| `").Append(d.Name).Append("` (`").Append(d.EffectType.Name).Append("`) | ").Append(d.Stage).Append(" | ")
              .Append(Cell(d.Source)).Append(" | ").Append(Cell(d.Summary)).Append(" | ");
            if (d.Settings.Count == 0) sb.Append("—");
            for (int i = 0; i < d.Settings.Count; i++)
            {
                var s = d.Settings[i];
                sb.Append(i == 0 ? "" : "; ").Append('`').Append(s.Name).Append("` ").Append(s.Format(s.Default)).Append(s.Unit.Length > 0 ? " " + s.Unit : "")
                  .Append(" (").Append(s.RangeText).Append(')');
            }
            sb.Append(" |\n");
        }
        sb.Append("<!-- end generated: ").Append(Marker).Append(" -->\n");
        return sb.ToString();
    }

    static string Cell(string text) => text.Replace("|", "\\|");
}
