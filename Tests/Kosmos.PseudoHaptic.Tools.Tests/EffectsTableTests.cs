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
        Assert.That(document, Does.Contain(written), $"{EffectsTable.Document}'s effects table is stale: rerun\n  {EffectsTable.Command}");
        // Exactly one pair of markers around exactly that block (a doubled marker line went unseen by Does.Contain).
        Assert.That(EffectsTable.Into(document), Is.EqualTo(document), $"{EffectsTable.Document} must hold one start and one end marker around the table");
    }

    [Test]
    public void IntoAFileThatHoldsTheMarkersTheTableReplacesTheBlockAndTheRestIsKept()
    {
        string page = Path.Combine(_dir, "ALGORITHM.md");
        File.WriteAllText(page, "# Title\n\ntext before\n" + EffectsTable.StartMarker + "(old command) -->\n| old | table |\n" + EffectsTable.EndMarker + "\ntext after\n");
        var (code, stderr, _) = Capture(() => Cli.Cli.Run(new[] { "profiles", "--markdown", page }));
        Assert.That(code, Is.EqualTo(0), stderr);
        Assert.That(File.ReadAllText(page), Is.EqualTo("# Title\n\ntext before\n" + EffectsTable.Block() + "text after\n"));
        // Again: nothing changes; and an end marker on the file's last line, without a line end, is replaced too.
        Assert.That(Capture(() => Cli.Cli.Run(new[] { "profiles", "--markdown", page })).Item1, Is.EqualTo(0));
        Assert.That(File.ReadAllText(page), Is.EqualTo("# Title\n\ntext before\n" + EffectsTable.Block() + "text after\n"));
        File.WriteAllText(page, "x\n" + EffectsTable.StartMarker + "-->\n" + EffectsTable.EndMarker);
        Assert.That(Capture(() => Cli.Cli.Run(new[] { "profiles", "--markdown", page })).Item1, Is.EqualTo(0));
        Assert.That(File.ReadAllText(page), Is.EqualTo("x\n" + EffectsTable.Block()));
    }

    [Test]
    public void MarkersOnTheFilesFirstLineAreReplacedAndTheRestIsKept()
    {
        // The start marker at offset 0 has no line end before it: it still starts a line.
        string page = Path.Combine(_dir, "first-line.md");
        File.WriteAllText(page, EffectsTable.StartMarker + "-->\n| old |\n" + EffectsTable.EndMarker + "\ntext after\n");
        var (code, stderr, _) = Capture(() => Cli.Cli.Run(new[] { "profiles", "--markdown", page }));
        Assert.That(code, Is.EqualTo(0), stderr);
        Assert.That(File.ReadAllText(page), Is.EqualTo(EffectsTable.Block() + "text after\n"));
    }

    [TestCase("# a page without the markers\n", TestName = "NoMarkers")]
    [TestCase("S\nS\nt\nE\nE\n", TestName = "DoubledMarkers")]
    [TestCase("S\nt\nS\nE\n", TestName = "DoubledStartOneEnd")]
    [TestCase("S\nt\nE\nE\n", TestName = "OneStartDoubledEnd")]
    [TestCase("E\nt\nS\n", TestName = "EndBeforeStart")]
    [TestCase("S\nt\n", TestName = "NoEnd")]
    [TestCase("text S\nE\n", TestName = "StartNotAtALineStart")]
    public void AFileWithTextButNotOnePairOfMarkersIsLeftAsItIsAndTheCommandExits2(string content)
    {
        // Written whole it would lose the page: `profiles --markdown ALGORITHM.md` once wrote 18 lines over 847.
        content = content.Replace("S\n", EffectsTable.StartMarker + "-->\n").Replace("E\n", EffectsTable.EndMarker + "\n");
        string page = Path.Combine(_dir, "page.md");
        File.WriteAllText(page, content);
        var (code, stderr, _) = Capture(() => Cli.Cli.Run(new[] { "profiles", "--markdown", page }));
        Assert.That(code, Is.EqualTo(2));
        Assert.That(stderr, Does.Contain($"option --markdown {page}: holds text but not one effects table between its markers"));
        Assert.That(stderr.TrimEnd('\n').Split('\n'), Has.Length.EqualTo(1), "one line");
        Assert.That(File.ReadAllText(page), Is.EqualTo(content));
    }

    [Test]
    public void ANewOrEmptyFileGetsTheTableAlone([Values(false, true)] bool empty)
    {
        string page = Path.Combine(_dir, "table.md");
        if (empty) File.WriteAllText(page, "");
        var (code, stderr, _) = Capture(() => Cli.Cli.Run(new[] { "profiles", "--markdown", page }));
        Assert.That(code, Is.EqualTo(0), stderr);
        Assert.That(File.ReadAllText(page), Is.EqualTo(EffectsTable.Block()));
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
