using Kosmos.PseudoHaptic.Cli.Commands;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tools.Tests;

/// <summary>
/// Issue 33 item 4: ALGORITHM.md §6's effects table is what the effects declare (as AccuracyPageTests checks the accuracy
/// page): the command writes it, and the document must hold exactly that block.
/// </summary>
public class EffectsTableTests : CliTestFolder
{
    public EffectsTableTests() : base("ph-effects-table-") { }

    [Test]
    [Category("Docs")]
    public void AlgorithmMdHoldsTheTableTheCommandWrites()
    {
        string table = Path.Combine(_dir, "table.md");
        var (code, stderr, _) = Capture(() => Cli.Cli.Run(new[] { "profiles", "--markdown", table }));
        Assert.That(code, Is.EqualTo(0), stderr);
        string written = File.ReadAllText(table);
        Assert.That(written, Is.EqualTo(EffectsTable.Block()));
        string document = File.ReadAllText(Path.Combine(RepositoryRoot.Path, EffectsTable.Document));
        Assert.That(document, Does.Contain(written),
            $"{EffectsTable.Document}'s effects table is stale: rerun\n  {EffectsTable.Command}\nand replace the block between its markers with what it writes");
    }

    [Test]
    public void TheTableNamesEveryEffectItsStageAndEverySettingWithItsDefault()
    {
        string block = EffectsTable.Block();
        foreach (var d in EffectRegistry.Package)
        {
            string row = block.Split('\n').Single(l => l.StartsWith("| `" + d.Name + "` ", StringComparison.Ordinal));
            Assert.That(row, Does.Contain(" | " + d.Stage + " | ").And.Contain(d.Summary));
            foreach (var s in d.Settings) Assert.That(row, Does.Contain("`" + s.Name + "` " + s.Format(s.Default)));
        }
        // A value in the table changes when the declaration does (not a copy): the offset correction's threshold.
        Assert.That(block, Does.Contain("`threshold` " + OffsetCorrection.Descriptor.Settings[0].Format(new OffsetCorrection().Threshold) + " m"));
    }
}
