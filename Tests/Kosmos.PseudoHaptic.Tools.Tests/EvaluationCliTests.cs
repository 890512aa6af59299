using System.Text;
using Kosmos.PseudoHaptic.Cli;
using Kosmos.PseudoHaptic.Evaluation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tools.Tests;

/// <summary>
/// The score and report commands' file contracts (issue 6), run in-process: good scoring against a hand
/// computation, every malformed input refused with one line naming the line and nothing written, and
/// randomly damaged files never escaping as an unhandled exception.
/// </summary>
public class EvaluationCliTests : CliTestFolder
{
    public EvaluationCliTests() : base("ph-eval-") { }

    const string Header = "participant,questionnaire,item,response";
    string Out => Path.Combine(_dir, "S.csv");

    static (int code, string stderr, string stdout) Report(params string[] args) => Capture(() => ReportCommand.Run(args));

    /// <summary>Rows answering every item of a 10-item part with answers[i] for item i + 1.</summary>
    static IEnumerable<string> Part(string participant, string questionnaire, params int[] answers)
        => answers.Select((a, i) => $"{participant},{questionnaire},{i + 1},{a}");

    /// <summary>A complete, valid responses file of two participants.</summary>
    static string GoodResponses()
    {
        var rows = new List<string> { Header };
        // P1, Part 1: items 4 and 7 reversed (6 − x): 5 4 5 [2→4] 4 5 [1→5] 4 3 5 = 44 → 4.4
        rows.AddRange(Part("P1", "weight-detection", 5, 4, 5, 2, 4, 5, 1, 4, 3, 5));
        // P1, Part 2: items 3, 5, 8, 9 reversed: 4 4 [2→4] 3 [1→5] 4 4 [2→4] [3→3] 5 = 40 → 4.0
        rows.AddRange(Part("P1", "immersion", 4, 4, 2, 3, 1, 4, 4, 2, 3, 5));
        rows.Add("P1,self-assessment,1,9");
        // P10 (listed before P2 in the file, after it in the output): Part 1 all 3s → 3.0; Part 2 items
        // all 1: reversed four count 5, the rest 1 → 26 → 2.6; no self-assessment row at all.
        rows.AddRange(Part("P10", "weight-detection", 3, 3, 3, 3, 3, 3, 3, 3, 3, 3));
        rows.AddRange(Part("P10", "immersion", 1, 1, 1, 1, 1, 1, 1, 1, 1, 1));
        // P2: Part 3 only, 10 → 10; Part 1 missing item 10 → incomplete.
        rows.Add("P2,self-assessment,1,10");
        rows.AddRange(Part("P2", "weight-detection", 5, 5, 5, 5, 5, 5, 5, 5, 5));
        return string.Join("\n", rows) + "\n";
    }

    const string GoodScores =
        "participant,questionnaire,score\n" +
        "P1,weight-detection,4.4\n" +
        "P1,immersion,4\n" +
        "P1,self-assessment,9\n" +
        "P2,weight-detection,\n" +
        "P2,self-assessment,10\n" +
        "P10,weight-detection,3\n" +
        "P10,immersion,2.6\n";

    [Test]
    public void ScoresMatchAHandComputation()
    {
        string responses = Write("R.csv", GoodResponses());
        var (code, stderr, _) = Score("--responses", responses, "--out", Out);
        Assert.That(code, Is.EqualTo(0), stderr);
        Assert.That(stderr, Is.Empty);
        Assert.That(File.ReadAllText(Out), Is.EqualTo(GoodScores));
        Assert.That(Directory.GetFiles(_dir).Select(Path.GetFileName), Is.EquivalentTo(new[] { "R.csv", "S.csv" }), "no temporary file left");
    }

    [Test]
    public void ColumnsMayComeInAnyOrderWithCrLfAndExtraColumns()
    {
        var lines = GoodResponses().Split('\n', StringSplitOptions.RemoveEmptyEntries).Skip(1)
            .Select(l => l.Split(','))
            .Select(f => $"{f[3]},x,{f[2]},{f[0]},{f[1]}");
        string responses = Write("R.csv", "response,comment,item,participant,questionnaire\r\n" + string.Join("\r\n", lines) + "\r\n");
        var (code, stderr, _) = Score("--responses", responses, "--out", Out);
        Assert.That(code, Is.EqualTo(0), stderr);
        Assert.That(File.ReadAllText(Out), Is.EqualTo(GoodScores));
    }

    [Test]
    public void AHeaderOnlyFileScoresToAHeaderOnlyFile()
    {
        var (code, stderr, _) = Score("--responses", Write("R.csv", Header + "\n"), "--out", Out);
        Assert.That(code, Is.EqualTo(0), stderr);
        Assert.That(File.ReadAllText(Out), Is.EqualTo(ScoresCsv.Header + "\n"));
    }

    // Each case: a data row appended to a good file (line 2 is the first data row), its line, a phrase of the reason.
    [TestCase("P1,immersion,1,6", "outside the scale 1 to 5")]
    [TestCase("P1,immersion,1,0", "outside the scale")]
    [TestCase("P1,self-assessment,1,11", "outside the scale 1 to 10")]
    [TestCase("P1,immersion,1,-3", "outside the scale")]
    [TestCase("P1,immersion,1,2.5", "not a whole number")]
    [TestCase("P1,presence,1,3", "unknown questionnaire 'presence'")]
    [TestCase("P1,immersion,11,3", "no item 11")]
    [TestCase("P1,self-assessment,2,3", "no item 2")]
    [TestCase("P1,immersion,x,3", "item 'x' is not a whole number")]
    [TestCase("P1,immersion,1,abc", "response 'abc' is not a number")]
    [TestCase("P1,immersion,1,", "response is empty")]
    [TestCase("P1,immersion,1", "expected 4 fields")]
    [TestCase(",immersion,1,3", "participant is empty")]
    public void AMalformedRowIsRefusedNamingItsLine(string badRow, string reason)
    {
        var text = new StringBuilder(Header + "\n");
        text.Append("P9,immersion,1,3\n\n");          // lines 2 and 3 (blank lines still count)
        text.Append(badRow).Append('\n');             // line 4
        text.Append("P9,immersion,2,3\n");
        AssertRefused(text.ToString(), 4, reason);
    }

    [Test]
    public void ADuplicateAnswerIsRefusedAtItsSecondLine()
    {
        AssertRefused(Header + "\nP1,immersion,4,3\nP2,immersion,4,3\nP1,immersion,4,5\n", 4, "duplicate answer");
    }

    [TestCase("participant,questionnaire,item\nP1,immersion,1\n", 1, "missing column 'response'")]
    [TestCase("participant,item,response\nP1,1,3\n", 1, "missing column 'questionnaire'")]
    [TestCase("", 1, "empty file")]
    [TestCase("P1,immersion,1,3\n", 1, "missing column")]
    [TestCase(Header + "\n\"P1,immersion,1,3\n", 2, "unterminated")]
    public void AMalformedFileIsRefusedNamingItsLine(string text, int line, string reason) => AssertRefused(text, line, reason);

    void AssertRefused(string text, int line, string reason)
    {
        string responses = Write("R.csv", text);
        File.WriteAllText(Out, "previous output\n");
        var (code, stderr, _) = Score("--responses", responses, "--out", Out);
        Assert.That(code, Is.EqualTo(2));
        Assert.That(stderr.TrimEnd('\n').Split('\n'), Has.Length.EqualTo(1), "one line: " + stderr);
        Assert.That(stderr, Does.StartWith($"pseudohaptic score: {responses}:{line}: "));
        Assert.That(stderr, Does.Contain(reason));
        Assert.That(File.ReadAllText(Out), Is.EqualTo("previous output\n"), "an existing output is left as it was");
        File.Delete(Out);
        Assert.That(Directory.GetFiles(_dir).Select(Path.GetFileName), Is.EqualTo(new[] { "R.csv" }), "nothing else written");
    }

    [Test]
    public void NoOutputAppearsWhenTheInputIsRefused()
    {
        string responses = Write("R.csv", Header + "\nP1,immersion,1,9\n");
        var (code, _, _) = Score("--responses", responses, "--out", Out);
        Assert.That(code, Is.EqualTo(2));
        Assert.That(File.Exists(Out), Is.False);
    }

    [TestCase(new[] { "--out", "S.csv" }, "option --responses is required")]
    [TestCase(new[] { "--responses", "R.csv" }, "option --out is required")]
    [TestCase(new[] { "--responses", "R.csv", "--out" }, "needs a value")]
    [TestCase(new[] { "--responses", "R.csv", "--out", "S.csv", "--verbose", "1" }, "unknown option '--verbose'")]
    public void BadOptionsAreOneLineAndExitTwo(string[] args, string reason)
    {
        var (code, stderr, _) = Score(args);
        Assert.That(code, Is.EqualTo(2));
        Assert.That(stderr.TrimEnd('\n').Split('\n'), Has.Length.EqualTo(1));
        Assert.That(stderr, Does.StartWith("pseudohaptic score: ").And.Contain(reason));
    }

    [Test]
    public void AMissingResponsesFileExitsTwo()
    {
        var (code, stderr, _) = Score("--responses", Path.Combine(_dir, "none.csv"), "--out", Out);
        Assert.That(code, Is.EqualTo(2));
        Assert.That(stderr, Does.Contain("none.csv: does not exist"));
        Assert.That(File.Exists(Out), Is.False);
    }

    [Test]
    public void ReplacementDefinitionsComeFromAFolder()
    {
        string folder = Path.Combine(_dir, "q");
        Directory.CreateDirectory(folder);
        File.WriteAllText(Path.Combine(folder, "mood.json"),
            "{ \"id\": \"mood\", \"title\": \"Mood\", \"scale\": { \"min\": 0, \"max\": 6 }, \"items\": [ { \"number\": 1, \"text\": \"Calm?\" }, { \"number\": 2, \"text\": \"Not calm?\", \"reverse\": true } ] }");
        string responses = Write("R.csv", Header + "\nA,mood,1,6\nA,mood,2,1\n");
        var (code, stderr, _) = Score("--responses", responses, "--out", Out, "--questionnaires", folder);
        Assert.That(code, Is.EqualTo(0), stderr);
        Assert.That(File.ReadAllText(Out), Is.EqualTo("participant,questionnaire,score\nA,mood,5.5\n"), "(6 + (0 + 6 − 1)) / 2");
        var (refused, message, _) = Score("--responses", Write("R2.csv", Header + "\nA,immersion,1,3\n"), "--out", Out, "--questionnaires", folder);
        Assert.That(refused, Is.EqualTo(2));
        Assert.That(message, Does.Contain("unknown questionnaire 'immersion'"));
    }

    [Test]
    public void DamagedFilesNeverEscapeAsExceptions()
    {
        string good = GoodResponses();
        var random = new Random(20221); // fixed: a failure names a reproducible case
        int accepted = 0, refused = 0;
        for (int round = 0; round < 400; round++)
        {
            string text = Damage(good, random, round);
            string responses = Write("R.csv", text);
            if (File.Exists(Out)) File.Delete(Out);
            (int code, string stderr, string stdout) result = (-1, "", "");
            Assert.DoesNotThrow(() => result = Score("--responses", responses, "--out", Out), $"round {round}");
            Assert.That(result.code, Is.EqualTo(0).Or.EqualTo(2), $"round {round}: {result.stderr}");
            if (result.code == 2)
            {
                refused++;
                Assert.That(result.stderr, Does.StartWith("pseudohaptic score: " + responses + ":"), $"round {round}");
                Assert.That(result.stderr.TrimEnd('\n').Split('\n'), Has.Length.EqualTo(1), $"round {round}");
                Assert.That(File.Exists(Out), Is.False, $"round {round}: nothing written");
            }
            else
            {
                accepted++;
                Assert.DoesNotThrow(() => ScoresCsv.Parse(File.ReadAllText(Out), Out, ReadDefaultCatalog()), $"round {round}: output reads back");
            }
            Assert.That(Directory.GetFiles(_dir).Where(f => f.EndsWith(".tmp", StringComparison.Ordinal)), Is.Empty, $"round {round}");
        }
        Assert.That(accepted, Is.GreaterThan(20), "some damage leaves a valid file (a truncation at a line end, a dropped row)");
        Assert.That(refused, Is.GreaterThan(100));
        TestContext.Progress.WriteLine($"damaged files: {accepted} accepted, {refused} refused");
    }

    /// <summary>Truncation, random bytes, dropped or repeated lines, swapped fields, stray quotes and commas.</summary>
    static string Damage(string text, Random random, int round)
    {
        switch (round % 6)
        {
            case 0: return text.Substring(0, random.Next(text.Length + 1));
            case 1:
            {
                const string noise = "\",;\n\r 0-9.eE+x\u00e9\0";
                var chars = text.ToCharArray();
                for (int k = 0; k < 1 + random.Next(5); k++)
                    chars[random.Next(chars.Length)] = noise[random.Next(noise.Length)];
                return new string(chars);
            }
            case 2:
            {
                var lines = text.Split('\n').ToList();
                int at = random.Next(lines.Count);
                if (random.Next(2) == 0) lines.RemoveAt(at); else lines.Insert(random.Next(lines.Count), lines[at]);
                return string.Join("\n", lines);
            }
            case 3:
            {
                var bytes = new byte[random.Next(200)];
                random.NextBytes(bytes);
                return Encoding.Latin1.GetString(bytes);
            }
            case 4:
            {
                var lines = text.Split('\n');
                int at = 1 + random.Next(lines.Length - 1);
                var fields = lines[at].Split(',');
                if (fields.Length == 4)
                {
                    fields[random.Next(4)] = new[] { "", "99", "-1", "1e309", "NaN", "\"q\"", "3.0", "2147483648", " 4 " }[random.Next(9)];
                    lines[at] = string.Join(",", fields);
                }
                return string.Join("\n", lines);
            }
            default:
                return new string(text.Where(_ => random.Next(60) != 0).ToArray());
        }
    }

    /// <summary>The same built-in definitions the command uses, read from the package (the single source of truth).</summary>
    static QuestionnaireCatalog ReadDefaultCatalog() => QuestionnaireJson.LoadDirectory(
        Path.Combine(RepositoryRoot.Path, "Packages", "com.kosmos.pseudohaptic", "Runtime", "Evaluation", "Questionnaires"));

    // ---- report ---------------------------------------------------------------------------------------

    [Test]
    public void ReportWritesTablesStatisticsAndCharts()
    {
        string responses = Write("R.csv", GoodResponses());
        Assert.That(Score("--responses", responses, "--out", Out).code, Is.EqualTo(0));
        string dir = Path.Combine(_dir, "report");
        var (code, stderr, _) = Report("--scores", Out, "--out", dir, "--responses", responses);
        Assert.That(code, Is.EqualTo(0), stderr);
        Assert.That(stderr, Is.Empty, "scores and responses agree: no warning");

        Assert.That(Directory.GetFiles(dir).Select(Path.GetFileName), Is.EquivalentTo(new[]
        {
            "report.md", "summary.csv",
            "table1-weight-detection.csv", "table2-immersion.csv", "table3-self-assessment.csv",
            "chart1-weight-detection.png", "chart2-immersion.png", "chart3-self-assessment.png",
        }));
        foreach (string png in Directory.GetFiles(dir, "*.png"))
            ChartFiles.AssertPng(png, 900, 500);

        Assert.That(File.ReadAllText(Path.Combine(dir, "table1-weight-detection.csv")),
            Is.EqualTo("participant,score\nP1,4.4\nP2,\nP10,3\n"));

        var summary = File.ReadAllLines(Path.Combine(dir, "summary.csv"));
        Assert.That(summary[0], Is.EqualTo("questionnaire,title,items,scale_min,scale_max,n,incomplete,mean,sd,median,min,max,ci95_low,ci95_high,alpha,alpha_n"));
        var part1 = summary[1].Split(',');
        // Part 1: complete scores 4.4 and 3 → n 2, mean 3.7, SD = |4.4 − 3|/√2 = 0.98995, one incomplete (P2).
        Assert.That(part1[0], Is.EqualTo("weight-detection"));
        Assert.That(part1[5..8], Is.EqualTo(new[] { "2", "1", "3.7" }));
        Assert.That(double.Parse(part1[8], System.Globalization.CultureInfo.InvariantCulture), Is.EqualTo(1.4 / Math.Sqrt(2)).Within(1e-12));
        // 95 % CI: 3.7 ± t(0.975, 1) · 0.7 = 3.7 ± 12.7062047 · 0.7.
        Assert.That(double.Parse(part1[12], System.Globalization.CultureInfo.InvariantCulture), Is.EqualTo(3.7 - 12.706204736174705 * 0.7).Within(1e-9));
        Assert.That(part1[15], Is.EqualTo("2"), "α over the two complete participants");
        var part3 = summary[3].Split(',');
        Assert.That(part3[14], Is.Empty, "no α for a single item");

        string md = File.ReadAllText(Path.Combine(dir, "report.md"));
        Assert.That(md, Does.Contain("## Table 1. Part 1: Weight detection"));
        Assert.That(md, Does.Contain("| P1 | P2 | P10 |"));
        Assert.That(md, Does.Contain("| 4.4 | incomplete | 3.0 |"));
        Assert.That(md, Does.Contain(": score per participant](chart2-immersion.png)").And.Not.Contain("![Table"), "a figure, not a table");
    }

    [Test]
    public void ReportWarnsWhenScoresAndResponsesDisagree()
    {
        string responses = Write("R.csv", GoodResponses());
        string scores = Write("S2.csv", GoodScores.Replace("P1,immersion,4", "P1,immersion,3.9"));
        var (code, stderr, _) = Report("--scores", scores, "--out", Path.Combine(_dir, "r"), "--responses", responses);
        Assert.That(code, Is.EqualTo(0));
        Assert.That(stderr, Does.Contain("warning: 1 scores").And.Contain("P1 immersion"));
    }

    [TestCase("participant,questionnaire,score\nP1,immersion,4\nP1,immersion,3\n", 3, "duplicate score")]
    [TestCase("participant,questionnaire,score\nP1,immersion,7\n", 2, "outside its scale")]
    [TestCase("participant,questionnaire,score\n\nP1,immersion,x\n", 3, "not a number")]
    [TestCase("participant,questionnaire,score\nP1,presence,3\n", 2, "unknown questionnaire")]
    [TestCase("participant,questionnaire\nP1,immersion\n", 1, "missing column 'score'")]
    [TestCase("participant,questionnaire,score\nP1,immersion\n", 2, "expected 3 fields")]
    public void AMalformedScoresFileWritesNoReport(string text, int line, string reason)
    {
        string scores = Write("S.csv", text);
        string dir = Path.Combine(_dir, "report");
        var (code, stderr, _) = Report("--scores", scores, "--out", dir);
        Assert.That(code, Is.EqualTo(2));
        Assert.That(stderr.TrimEnd('\n').Split('\n'), Has.Length.EqualTo(1));
        Assert.That(stderr, Does.StartWith($"pseudohaptic report: {scores}:{line}: ").And.Contain(reason));
        Assert.That(Directory.Exists(dir), Is.False, "nothing written");
    }

    [Test]
    public void AMalformedResponsesFileWritesNoReport()
    {
        string scores = Write("S.csv", GoodScores);
        string responses = Write("R.csv", Header + "\nP1,immersion,1,8\n");
        string dir = Path.Combine(_dir, "report");
        var (code, stderr, _) = Report("--scores", scores, "--out", dir, "--responses", responses);
        Assert.That(code, Is.EqualTo(2));
        Assert.That(stderr, Does.StartWith($"pseudohaptic report: {responses}:2: "));
        Assert.That(Directory.Exists(dir), Is.False);
    }

    [Test]
    public void ReportWithSvgWritesAnSvgBesideEachChart()
    {
        string dir = Path.Combine(_dir, "report-svg");
        var (code, stderr, _) = Report("--scores", Write("S.csv", GoodScores), "--out", dir, "--svg");
        Assert.That(code, Is.EqualTo(0), stderr);
        foreach (string stem in new[] { "chart1-weight-detection", "chart2-immersion", "chart3-self-assessment" })
        {
            ChartFiles.AssertPng(Path.Combine(dir, stem + ".png"), 900, 500);
            ChartFiles.AssertSvg(Path.Combine(dir, stem + ".svg"), 900, 500);
        }
    }

    [Test]
    public void ReportOfThePapersTablesGivesItsMeans()
    {
        string? tables = RepositoryRoot.Shared is { } shared ? Path.Combine(shared, "data", "paper-tables.csv") : null;
        if (tables == null || !File.Exists(tables)) Assert.Ignore("shared/data/paper-tables.csv is not beside this repository");

        string[] ids = { "", "weight-detection", "immersion", "self-assessment" };
        var scores = new StringBuilder("participant,questionnaire,score\n");
        foreach (string row in File.ReadAllLines(tables!).Skip(1).Where(l => l.Length > 0))
        {
            var f = row.Split(',');
            scores.Append($"{f[0]},{ids[int.Parse(f[1], System.Globalization.CultureInfo.InvariantCulture)]},{f[2]}\n");
        }
        string dirOut = Path.Combine(_dir, "paper");
        var (code, stderr, _) = Report("--scores", Write("paper.csv", scores.ToString()), "--out", dirOut);
        Assert.That(code, Is.EqualTo(0), stderr);
        string md = File.ReadAllText(Path.Combine(dirOut, "report.md"));
        Assert.That(md, Does.Contain("| Part 1: Weight detection | 12 | 0 | 4.28 |"));
        Assert.That(md, Does.Contain("| Part 2: Immersion | 12 | 0 | 4.05 |"));
        Assert.That(md, Does.Contain("| Part 3: Immersion self-assessment | 12 | 0 | 8.42 |"));
        Assert.That(md, Does.Contain("| P1 | P2 | P3 | P4 | P5 | P6 |"));
        Assert.That(md, Does.Contain("| 4.6 | 5.0 | 3.8 | 3.2 | 4.3 | 4.8 |"), "Table 1's first row as the paper prints it");
    }
}
