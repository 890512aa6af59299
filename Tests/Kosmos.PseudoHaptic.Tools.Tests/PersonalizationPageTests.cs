using Kosmos.PseudoHaptic.Cli.Files;
using Kosmos.PseudoHaptic.Cli.Personalization;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tools.Tests;

/// <summary>
/// Issue 31's generated tables are not stale: the page <c>personalization-results.md</c> is what its command writes, and
/// ALGORITHM.md §12 and evaluation.md §9 hold the same tables between their markers (as AccuracyPageTests checks the
/// accuracy page).
/// </summary>
public class PersonalizationPageTests : CliTestFolder
{
    public PersonalizationPageTests() : base("ph-personal-page-") { }

    static string Docs(string file) => Path.Combine(RepositoryRoot.Path, "Packages", "com.kosmos.pseudohaptic", "Documentation~", file);

    [Test]
    [Category("Docs")]
    public void The_committed_page_is_what_the_command_writes()
    {
        string page = Path.Combine(_dir, "page.md");
        var args = PersonalizationPage.Command.Split(' ').Skip(1).ToArray();
        args[Array.IndexOf(args, "--markdown") + 1] = page;
        var (code, stderr, _) = Capture(() => Cli.Cli.Run(args));
        Assert.That(code, Is.EqualTo(0), stderr);
        string committed = File.ReadAllText(Path.Combine(RepositoryRoot.Path, PersonalizationPage.PagePath)), written = File.ReadAllText(page);
        if (committed != written)
        {
            var a = committed.Split('\n');
            var b = written.Split('\n');
            int line = Enumerable.Range(0, Math.Min(a.Length, b.Length)).FirstOrDefault(i => a[i] != b[i], Math.Min(a.Length, b.Length));
            Assert.Fail($"{PersonalizationPage.PagePath} is stale: rerun\n  {PersonalizationPage.Command}\nfirst difference at line {line + 1}:\n  committed: {(line < a.Length ? a[line] : "(end)")}\n  now:       {(line < b.Length ? b[line] : "(end)")}");
        }
    }

    [TestCase("ALGORITHM.md", "paper-table"), TestCase("ALGORITHM.md", "speed-table"), TestCase("ALGORITHM.md", "strength-table"), TestCase("evaluation.md", "tuning-table")]
    [Category("Docs")]
    public void The_documents_hold_the_generated_tables(string document, string block)
    {
        string text = File.ReadAllText(Docs(document));
        var table = PersonalizationPage.Blocks().Single(b => b.Name == block).Table();
        Assert.That(text, Does.Contain(PersonalizationPage.Block(block, table)),
            $"{document}'s block '{block}' is stale or missing: copy it from {PersonalizationPage.PagePath} after rerunning {PersonalizationPage.Command}");
        // Exactly one pair of markers around exactly that block (Does.Contain alone passes a block written twice).
        Assert.That(GeneratedBlock.Replace(text, block, PersonalizationPage.Block(block, table)), Is.EqualTo(text),
            $"{document} must hold block '{block}' once, between one start and one end marker");
    }
}
