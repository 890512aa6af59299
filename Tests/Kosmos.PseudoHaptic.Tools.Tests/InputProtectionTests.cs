using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tools.Tests;

/// <summary>
/// Issue 12's promises where an audit (twentieth session) found them broken: no output replaces a file the command read
/// (accuracy's motion capture found by default and the reports in a --costs folder; the SVG beside a chart), a folder
/// output replaces only the files its command writes, a small input file (a profile, a user's file) is read with bounded
/// memory, and a message shows a file's control characters escaped.
/// </summary>
public class InputProtectionTests : CliTestFolder
{
    public InputProtectionTests() : base("ph-inputs-") { }

    static string Examples => Path.Combine(RepositoryRoot.Path, "Packages", "com.kosmos.pseudohaptic", "Documentation~", "examples");

    static (int code, string stderr, string stdout) Run(params string[] args) => Capture(() => Cli.Cli.Run(args));

    /// <summary>Runs <paramref name="run"/> with <paramref name="folder"/> as the working folder (what a relative path means).</summary>
    static void InFolder(string folder, Action run)
    {
        string cwd = Directory.GetCurrentDirectory();
        try
        {
            Directory.SetCurrentDirectory(folder);
            run();
        }
        finally
        {
            Directory.SetCurrentDirectory(cwd);
        }
    }

    static void Refused((int code, string stderr, string stdout) r, string named)
    {
        Assert.That(r.code, Is.EqualTo(2), r.stderr);
        Assert.That(r.stderr.TrimEnd('\n').Split('\n'), Has.Length.EqualTo(1), r.stderr);
        Assert.That(r.stderr, Does.Contain(named));
    }

    [Test]
    public void AFolderHoldingAnotherStudysFilesIsRefusedNotEmptied()
    {
        string data = Path.Combine(_dir, "data");
        Directory.CreateDirectory(data);
        File.WriteAllText(Path.Combine(data, "other-study-responses.csv"), "participant,questionnaire,item,response\n");
        File.WriteAllText(Path.Combine(data, "notes.md"), "the experimenter's");
        var r = Run("compare", "--scores", Path.Combine(Examples, "study", "scores.csv"), "--out", data);
        Refused(r, "which this command does not write");
        Assert.That(Directory.GetFiles(data).Select(Path.GetFileName), Is.EquivalentTo(new[] { "other-study-responses.csv", "notes.md" }), "nothing removed");

        // A folder the command wrote before is replaced; one another command wrote is not.
        string compared = Path.Combine(_dir, "compared");
        Assert.That(Run("compare", "--scores", Path.Combine(Examples, "study", "scores.csv"), "--out", compared).code, Is.Zero);
        Assert.That(Run("compare", "--scores", Path.Combine(Examples, "study", "scores.csv"), "--out", compared).code, Is.Zero);
        string reported = Path.Combine(_dir, "reported");
        Assert.That(Run("report", "--scores", Path.Combine(Examples, "scores.csv"), "--out", reported).code, Is.Zero);
        Refused(Run("psychometric", "--trials", Path.Combine(Examples, "study", "trials.csv"), "--out", reported, "--bootstrap", "0"), "summary.csv");
        Assert.That(File.Exists(Path.Combine(reported, "summary.csv")), Is.True, "report's folder left as it was");
    }

    [Test]
    public void UnityPackageRefusesStandardOutputAsItsFolder()
    {
        InFolder(_dir, () => Refused(Run("unity-package", "--out", "-", "--package", Path.Combine(RepositoryRoot.Path, "Packages", "com.kosmos.pseudohaptic")), "--out -"));
        Assert.That(Directory.Exists(Path.Combine(_dir, "-")), Is.False, "no folder named '-'");
    }

    [Test]
    public void ReportRefusesScoresWithConditionsInWordsAndSaysWhatDoes()
    {
        string output = Path.Combine(_dir, "report");
        var r = Run("report", "--scores", Path.Combine(Examples, "study", "scores.csv"), "--out", output);
        Refused(r, "has a condition column");
        Assert.That(r.stderr, Does.Contain("pseudohaptic compare"));
        Assert.That(Directory.Exists(output), Is.False);
    }

    [Test]
    public void AProfileOrUsersFileOfUnboundedSizeIsRefusedInBoundedMemory()
    {
        if (!File.Exists("/dev/zero")) Assert.Ignore("needs /dev/zero");
        string output = Path.Combine(_dir, "out.csv");
        long before = GC.GetTotalAllocatedBytes();
        Refused(Run("replay", "--trace", Path.Combine(Examples, "lift.csv"), "--out", output, "--mass-kg", "1", "--profile", "/dev/zero"), "--profile /dev/zero");
        Refused(Run("replay", "--trace", Path.Combine(Examples, "lift.csv"), "--out", output, "--mass-kg", "1", "--user", "/dev/zero"), "--user /dev/zero");
        Assert.That(GC.GetTotalAllocatedBytes() - before, Is.LessThan(64L << 20), "bytes allocated: bounded, not the file");
        Assert.That(File.Exists(output), Is.False);
    }

    [Test]
    public void AProfilesNameIsShownWithItsControlCharactersEscaped()
    {
        string paper = Path.Combine(_dir, "paper.json");
        var (code, err, _) = Run("profiles", "--show", "paper", "--json", "--out", paper);
        Assert.That(code, Is.Zero, err);
        string json = File.ReadAllText(paper);
        Assert.That(json, Does.Contain("\"name\": \"paper\""));
        string profile = Write("ctl.json", json.Replace("\"name\": \"paper\"", "\"name\": \"x\\n\\u001b[31m\""));
        Assert.That(profile, Does.Not.Contain("\u001b"));
        var r = Run("replay", "--trace", Path.Combine(Examples, "lift.csv"), "--out", Path.Combine(_dir, "out.csv"), "--mass-kg", "1", "--profile", profile);
        Assert.That(r.code, Is.Zero, r.stderr);
        Assert.That(r.stderr, Does.Not.Contain("\u001b"), "no raw escape reaches the terminal");
        Assert.That(r.stderr.Split('\n').Where(l => l.StartsWith("replay: v_std")).ToArray(), Has.Length.EqualTo(1));
        Assert.That(r.stderr.Split('\n').Count(l => l.Length > 0), Is.EqualTo(1), r.stderr);
        var shown = Run("profiles", "--show", profile);
        Assert.That(shown.code, Is.Zero, shown.stderr);
        Assert.That(shown.stdout + shown.stderr, Does.Not.Contain("\u001b"));
    }

    [Test]
    public void AccuracyNeverReplacesAReportItReadsFromACostsFolder()
    {
        string costs = Path.Combine(_dir, "costs");
        Directory.CreateDirectory(costs);
        string report = Path.Combine(costs, "EstimatorBenchmarks-report.csv");
        File.Copy(Path.Combine(RepositoryRoot.Path, "Packages", "com.kosmos.pseudohaptic", "Documentation~", "benchmarks", "EstimatorBenchmarks-report.csv"), report);
        byte[] was = File.ReadAllBytes(report);
        Refused(Run("accuracy", "--lifts", "none", "--mocap", "none", "--trace", Path.Combine(Examples, "lift.csv"), "--long-minutes", "0",
            "--costs", costs, "--csv", report), "--csv");
        Assert.That(File.ReadAllBytes(report), Is.EqualTo(was));
    }

    [Test]
    public void AccuracyNeverReplacesTheMotionCaptureItFindsByDefault()
    {
        // A clone beside a ../shared of its own: the motion capture found there is an input like any named one.
        string repo = Path.Combine(_dir, "repo"), shared = Path.Combine(_dir, "shared", "data");
        Directory.CreateDirectory(Path.Combine(repo, "Packages", "com.kosmos.pseudohaptic"));
        File.WriteAllText(Path.Combine(repo, "Packages", "com.kosmos.pseudohaptic", "package.json"), "{}");
        Directory.CreateDirectory(shared);
        string mocap = Path.Combine(shared, "mocap-hand-100hz.csv");
        File.Copy(Path.Combine(Examples, "lift.csv"), mocap);
        byte[] was = File.ReadAllBytes(mocap);
        InFolder(repo, () => Refused(Run("accuracy", "--lifts", "none", "--long-minutes", "0", "--csv", "../shared/data/mocap-hand-100hz.csv"), "--csv"));
        Assert.That(File.ReadAllBytes(mocap), Is.EqualTo(was));
    }

    [Test]
    public void AccuracysSvgIsAnOutputOfItsOwnAndNeedsAChartFile()
    {
        string costs = Path.Combine(RepositoryRoot.Path, "Packages", "com.kosmos.pseudohaptic", "Documentation~", "benchmarks", "EstimatorBenchmarks-report.csv");
        string[] common = { "accuracy", "--lifts", "none", "--mocap", "none", "--trace", Path.Combine(Examples, "lift.csv"), "--long-minutes", "0", "--costs", costs };
        Refused(Run(common.Concat(new[] { "--chart", "-", "--svg" }).ToArray()), "--svg");
        // The SVG beside the chart is refused where it would replace an input.
        string chart = Path.Combine(_dir, "lift.png"), svgInput = Path.Combine(_dir, "lift.svg");
        File.Copy(Path.Combine(Examples, "lift.csv"), svgInput);
        var trace = new[] { "accuracy", "--lifts", "none", "--mocap", "none", "--trace", svgInput, "--long-minutes", "0", "--costs", costs, "--chart", chart, "--svg" };
        Refused(Run(trace), "--svg");
        Assert.That(File.Exists(chart), Is.False, "nothing written");
    }
}
