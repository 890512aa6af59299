using System.Globalization;
using System.Text;
using Kosmos.PseudoHaptic.Cli.Accuracy;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tools.Tests;

/// <summary>
/// <c>pseudohaptic accuracy</c> (issue 4), run in-process: on a user's own small trace, its errors, its
/// documented columns, its determinism and the Pareto chart from a benchmark report. Kept fast with
/// <c>--lifts none --mocap none --long-minutes 0</c> except where the lifts themselves are under test.
/// </summary>
public class AccuracyCliTests
{
    string _dir = "";

    [SetUp]
    public void SetUp()
    {
        _dir = Path.Combine(Path.GetTempPath(), "ph-accuracy-" + Guid.NewGuid().ToString("N"));
        Directory.CreateDirectory(_dir);
    }

    [TearDown]
    public void TearDown() => Directory.Delete(_dir, recursive: true);

    static (int code, string stdout, string stderr) Accuracy(params string[] args)
    {
        var out_ = new StringWriter();
        var err = new StringWriter();
        var (o, e) = (Console.Out, Console.Error);
        Console.SetOut(out_);
        Console.SetError(err);
        try { return (Cli.Cli.Run(args.Prepend("accuracy").ToArray()), out_.ToString(), err.ToString()); }
        finally { Console.SetOut(o); Console.SetError(e); }
    }

    string Write(string name, string text)
    {
        string path = Path.Combine(_dir, name);
        File.WriteAllText(path, text);
        return path;
    }

    /// <summary>A recorded-looking hand: 90 Hz rows, 30 Hz poses with pose_t, a lift of 0.25 m and back, 4 s.</summary>
    static string SmallTrace()
    {
        var sb = new StringBuilder("t,hand_y,tracked,pose_t\n");
        for (int i = 0; i <= 90 * 4; i++)
        {
            double t = i / 90.0, pt = Math.Floor(t * 30) / 30;
            double s = Math.Clamp((pt - 0.8) / 0.7, 0, 1), d = Math.Clamp((pt - 2.3) / 0.7, 0, 1);
            double y = 0.9 + 0.25 * (Smooth(s) - Smooth(d));
            sb.Append(CultureInfo.InvariantCulture, $"{t:R},{y:R},1,{pt:R}\n");
        }
        return sb.ToString();

        static double Smooth(double s) => s * s * s * (10 + s * (-15 + 6 * s));
    }

    static readonly string[] Quick = { "--lifts", "none", "--mocap", "none", "--long-minutes", "0" };

    /// <summary>The rows (split on spaces) after the line starting <paramref name="sectionStart"/>, header first, up to a blank line.</summary>
    static List<string[]> Table(string stdout, string sectionStart)
    {
        var lines = stdout.Split('\n').Select(l => l.TrimEnd('\r')).ToList();
        int section = lines.FindIndex(l => l.StartsWith(sectionStart, StringComparison.Ordinal));
        Assert.That(section, Is.GreaterThanOrEqualTo(0), "section " + sectionStart + " in\n" + stdout);
        var rows = new List<string[]>();
        for (int i = section + 1; i < lines.Count && lines[i].Length > 0; i++)
            if (!lines[i].StartsWith("--", StringComparison.Ordinal)) rows.Add(lines[i].Split(' ', StringSplitOptions.RemoveEmptyEntries));
        return rows;
    }

    [Test]
    public void RunsOnASmallGivenTrace()
    {
        var (code, stdout, stderr) = Accuracy(Quick.Prepend(Write("mine.csv", SmallTrace())).Prepend("--trace").ToArray());
        Assert.That(code, Is.EqualTo(0), stderr);
        Assert.That(stdout, Does.Contain("trace          mine.csv: 121 usable samples"), "the trace is read as the true hand: one sample per pose");
        var rows = Table(stdout, "== trace:");
        Assert.That(rows[0], Is.EqualTo(AccuracyTable.SourceColumns));
        var keys = rows.Skip(1).Select(r => r[0]).ToList();
        Assert.That(keys, Is.EquivalentTo(EstimatorCatalog.EstimatorKeys.Concat(new[] { "increments", "increments-float", "velocity-dt", "velocity-substep4", "paper-literal" })));
        foreach (var row in rows.Skip(1))
            foreach (var cell in row.Skip(1))
                Assert.That(double.TryParse(cell.TrimEnd('*').TrimStart('±'), NumberStyles.Float, CultureInfo.InvariantCulture, out double v) && double.IsFinite(v), Is.True, string.Join(" ", row));

        double Column(string key, string column) => double.Parse(rows.First(r => r[0] == key)[Array.IndexOf(AccuracyTable.SourceColumns, column)].TrimEnd('*'), CultureInfo.InvariantCulture);
        // What the harness must see on any trace: the headset's 45 ms at least, the 1 s window far more.
        Assert.That(Column("no-filter", "lag_ms"), Is.InRange(50, 90));
        Assert.That(Column("window-1s", "lag_ms"), Is.GreaterThan(300));
        Assert.That(Column("window-1s", "rms_mm"), Is.GreaterThan(3 * Column("no-filter", "rms_mm")));
        Assert.That(Column("increments-float", "rms_mm"), Is.EqualTo(Column("increments", "rms_mm")).Within(0.01), "float state is harmless over seconds");
    }

    [Test]
    public void TheTablesHaveTheDocumentedColumns()
    {
        var (code, stdout, stderr) = Accuracy("--mocap", "none", "--long-minutes", "0.2");
        Assert.That(code, Is.EqualTo(0), stderr);
        var summary = Table(stdout, "== summary");
        Assert.That(summary[0], Is.EqualTo(new[] { "config", "rms_mm", "rms_ci", "raw_mm", "max_mm", "lag_ms", "added_ms", "added_ci", "creep_mm", "rest_mm" }));
        Assert.That(summary.Skip(1).Select(r => r.Length), Is.All.EqualTo(10));
        foreach (var lift in new[] { "lift-slow", "lift-medium", "lift-fast" })
            Assert.That(Table(stdout, "== " + lift)[0], Is.EqualTo(new[] { "config", "rms_mm", "rms_ci", "raw_mm", "max_mm", "lag_ms", "added_ms", "added_ci" }));
        var longRun = Table(stdout, "== long run");
        Assert.That(longRun[0], Is.EqualTo(new[] { "scheme", "end_mm", "end_ci", "max_mm", "what" }));
        Assert.That(longRun.Skip(1).Select(r => r[0]), Is.EqualTo(new[] { "increments", "increments-double", "increments-float", "velocity-dt", "velocity-substep4", "paper-literal" }));
        foreach (var column in AccuracyTable.SummaryColumns.Skip(1))
            Assert.That(stdout, Does.Contain("  " + column + " "), "the legend explains " + column);

        // The default pipeline on the synthetic lifts meets the accuracy targets at 1 kg, interval and all.
        var row = summary.First(r => r[0] == EstimatorCatalog.Default);
        double Cell(int k) => double.Parse(row[k].TrimStart('±'), CultureInfo.InvariantCulture);
        Assert.That(Cell(1) + Cell(2), Is.LessThanOrEqualTo(5), "rms_mm + its interval's half-width");
        Assert.That(Cell(6) + Cell(7), Is.LessThanOrEqualTo(40), "added_ms + its half-width");
        Assert.That(Cell(8), Is.LessThan(10), "creep_mm");
    }

    [Test]
    public void SameArgumentsSameTables()
    {
        string trace = Write("mine.csv", SmallTrace());
        var a = Accuracy(Quick.Prepend(trace).Prepend("--trace").ToArray());
        var b = Accuracy(Quick.Prepend(trace).Prepend("--trace").ToArray());
        Assert.That(a.code, Is.EqualTo(0), a.stderr);
        Assert.That(b.stdout, Is.EqualTo(a.stdout));
    }

    [TestCase("t,hand_y\n0,0.8\n0.01,0.8\n0.02,abc\n", 4, "hand_y")]
    [TestCase("t,hand_y\n0,0.8\n0.01\n", 3, "fields")]
    [TestCase("time,hand_y\n0,0.8\n", 1, "missing column 't'")]
    [TestCase("t,hand_y,tracked\n0,0.8,1\n0.01,0.8,maybe\n", 3, "tracked")]
    public void MalformedTraceIsOneLineNamingTheLine(string text, int line, string what)
    {
        var (code, stdout, stderr) = Accuracy(Quick.Prepend(Write("bad.csv", text)).Prepend("--trace").ToArray());
        Assert.That(code, Is.EqualTo(2));
        Assert.That(stderr.TrimEnd('\n').Split('\n'), Has.Length.EqualTo(1), stderr);
        Assert.That(stderr, Does.Contain($"bad.csv:{line}:").And.Contain(what));
        Assert.That(stdout, Is.Empty, "no table for a trace that did not parse");
    }

    [Test]
    public void ATraceTooShortToServeAsTheHandIsAnError()
    {
        var (code, _, stderr) = Accuracy(Quick.Prepend(Write("short.csv", "t,hand_y,tracked\n0,0.8,1\n0.1,nan,1\n0.2,0.9,0\n")).Prepend("--trace").ToArray());
        Assert.That(code, Is.EqualTo(2));
        Assert.That(stderr, Does.Contain("short.csv").And.Contain("usable rows"));
    }

    [TestCase("--mass-kg", "0")]
    [TestCase("--standard-speed", "9")]
    [TestCase("--long-minutes", "-1")]
    [TestCase("--lifts", "some")]
    [TestCase("--chart", "x.png")]
    public void BadOptionsNameTheOption(string option, string value)
    {
        var (code, stdout, stderr) = Accuracy(option, value, "--mocap", "none");
        Assert.That(code, Is.EqualTo(2));
        Assert.That(stderr, Does.Contain(option));
        Assert.That(stdout, Is.Empty);
    }

    [Test]
    public void ParetoChartFromABenchmarkReport()
    {
        // BenchmarkDotNet's CSV as the benchmark project writes it (units in the header), and one with units in the cells.
        var csv = new StringBuilder("Method,Job,Estimator,Mean [ns],Error [ns],Allocated [B]\n");
        double ns = 20;
        foreach (var key in EstimatorCatalog.EstimatorKeys.Append(EstimatorCatalog.PaperLiteral)) csv.Append(CultureInfo.InvariantCulture, $"Update,Job-X,{key},{ns += 3},0.1,0\n");
        string results = Path.Combine(_dir, "results");
        Directory.CreateDirectory(results);
        File.WriteAllText(Path.Combine(results, "EstimatorBenchmarks-report.csv"), csv.ToString());
        File.WriteAllText(Path.Combine(results, "Other-report.csv"), "Method,Mean\nPaperLiteral,\"1,234.5 ns\"\n");
        string png = Path.Combine(_dir, "pareto.png");
        var (code, _, stderr) = Accuracy(Quick.Concat(new[] { "--trace", Write("mine.csv", SmallTrace()), "--costs", results, "--chart", png, "--svg" }).ToArray());
        Assert.That(code, Is.EqualTo(0), stderr);
        ChartFiles.AssertPng(png, 1000, 600);
        ChartFiles.AssertSvg(Path.ChangeExtension(png, ".svg"), 1000, 600);

        var costs = BenchmarkCosts.Read(results);
        Assert.That(costs[EstimatorCatalog.Default], Is.EqualTo(26));
        var (code2, _, stderr2) = Accuracy(Quick.Concat(new[] { "--trace", Write("m2.csv", SmallTrace()), "--costs", Path.Combine(results, "Other-report.csv"), "--chart", png }).ToArray());
        Assert.That(code2, Is.EqualTo(2));
        Assert.That(stderr2, Does.Contain("--costs").And.Contain("Estimator"));
    }

    [Test]
    public void SvgWithoutAChartIsAnError()
    {
        var (code, stdout, stderr) = Accuracy(Quick.Concat(new[] { "--trace", Write("s.csv", SmallTrace()), "--svg" }).ToArray());
        Assert.That(code, Is.EqualTo(2));
        Assert.That(stderr, Does.Contain("--svg needs --chart"));
        Assert.That(stdout, Is.Empty);
    }
}
