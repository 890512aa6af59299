using System.Text;
using Kosmos.PseudoHaptic.Cli.Files;

namespace Kosmos.PseudoHaptic.Cli.Commands;

/// <summary>
/// ALGORITHM.md §6's effects table, generated from the package's effects (<see cref="EffectRegistry.Package"/>: name,
/// class, stage, source, summary, settings with defaults, units and ranges). <c>pseudohaptic profiles --markdown FILE</c>
/// writes it between its markers (<see cref="Into"/>: in a file that holds them, the rest of the file kept);
/// <c>EffectsTableTests</c> fails when ALGORITHM.md holds anything else there. No code per effect.
/// </summary>
public static class EffectsTable
{
    public const string Document = "Packages/com.kosmos.pseudohaptic/Documentation~/ALGORITHM.md";
    public const string Command = "pseudohaptic profiles --markdown " + Document;
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

    /// <summary>The first line of the block, up to the command it names.</summary>
    public static readonly string StartMarker = GeneratedBlock.StartMarker(Marker);

    /// <summary>The last line of the block.</summary>
    public static readonly string EndMarker = GeneratedBlock.EndMarker(Marker);

    /// <summary>
    /// What a file holding <paramref name="existing"/> becomes: the block in place of the one between its markers, the text
    /// before and after kept (<see cref="GeneratedBlock.Replace"/>); the block alone for a new or empty file. Null when the
    /// file holds text but not exactly one pair of markers: replacing it whole would lose that text.
    /// </summary>
    public static string? Into(string? existing)
        => string.IsNullOrEmpty(existing) ? Block() : GeneratedBlock.Replace(existing, Marker, Block());

    static string Cell(string text) => text.Replace("|", "\\|");
}
