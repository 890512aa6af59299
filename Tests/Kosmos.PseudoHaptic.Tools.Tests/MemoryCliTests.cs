using System.Globalization;
using System.Text;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tools.Tests;

/// <summary>
/// Peak memory of the built tool on inputs that used to take it past gigabytes (issue 12): 10 M-row traces,
/// an endless line (/dev/zero), a trace spanning 10^12 s. Each runs the tool in a child process and reads its
/// peak resident memory (VmHWM, see <see cref="ToolProcess"/>); the bound is 200 MB. In category "Memory",
/// which the ordinary test run (CI) includes; the whole category takes under a minute on an idle 2-core
/// machine.
/// </summary>
[Category("Memory"), NonParallelizable]
public class MemoryCliTests
{
    const long BoundKb = 200 * 1000;
    static string _dir = "";
    static string _untracked = "", _dense = "";

    [OneTimeSetUp]
    public void Files()
    {
        if (!ToolProcess.IsLinux) Assert.Ignore("peak memory is read from /proc (Linux)");
        _dir = Path.Combine(Path.GetTempPath(), "ph-mem-" + Guid.NewGuid().ToString("N")[..8]);
        Directory.CreateDirectory(_dir);
        // 10 M untracked rows before the first usable pose (these were all buffered: 846 MB).
        _untracked = Path.Combine(_dir, "untracked.csv");
        using (var w = new StreamWriter(_untracked, false, new UTF8Encoding(false), 1 << 16))
        {
            w.Write("t,hand_y,tracked\n");
            for (int i = 0; i < 10_000_000; i++) { w.Write(i.ToString(CultureInfo.InvariantCulture)); w.Write("e-5,,0\n"); }
            w.Write("100,0.8,1\n101,0.9,1\n");
        }
        // 10 M usable rows in 100 s (100 kHz).
        _dense = Path.Combine(_dir, "dense.csv");
        using (var w = new StreamWriter(_dense, false, new UTF8Encoding(false), 1 << 16))
        {
            w.Write("t,hand_y\n");
            for (int i = 0; i < 10_000_000; i++)
            {
                w.Write(i.ToString(CultureInfo.InvariantCulture));
                w.Write(i % 200_000 < 100_000 ? "e-5,0.8\n" : "e-5,1.1\n");
            }
        }
    }

    [OneTimeTearDown]
    public void Remove()
    {
        if (_dir.Length > 0 && Directory.Exists(_dir)) Directory.Delete(_dir, recursive: true);
    }

    static ToolProcess.Result Run(params string[] args)
    {
        var r = ToolProcess.Run(_dir, TimeSpan.FromMinutes(3), args);
        TestContext.Progress.WriteLine($"pseudohaptic {string.Join(' ', args.Select(a => a.Replace(_dir, ".")))}: exit {r.Code}, peak {r.PeakKb / 1000.0:0.0} MB");
        Assert.That(r.PeakKb, Is.GreaterThan(0), "peak memory was reported");
        Assert.That(r.PeakKb, Is.LessThan(BoundKb), "peak resident memory");
        Assert.That(Directory.GetFiles(_dir, ".ph*"), Is.Empty, "no temporary file left");
        return r;
    }

    [Test]
    public void ReplayOfTenMillionUntrackedRowsBeforeTheFirstPose()
    {
        var r = Run("replay", "--trace", _untracked, "--out", Path.Combine(_dir, "o.csv"), "--mass-kg", "1");
        Assert.That(r.Code, Is.EqualTo(0), r.Stderr);
        Assert.That(new FileInfo(Path.Combine(_dir, "o.csv")).Length, Is.GreaterThan(10_000_000 * 10L));
        File.Delete(Path.Combine(_dir, "o.csv"));
    }

    [Test]
    public void DemoOfTenMillionRowsIn100Seconds()
    {
        var r = Run("demo", "--trace", _dense, "--out", Path.Combine(_dir, "demo"));
        Assert.That(r.Code, Is.EqualTo(0), r.Stderr);
        Assert.That(Directory.Exists(Path.Combine(_dir, "demo", "recorded-hand")), Is.True);
        Directory.Delete(Path.Combine(_dir, "demo"), true);
    }

    [Test]
    public void ScoreAndReportStreamAStudyOfTenThousandParticipantsInBoundedMemory()
    {
        // 210,000 answers (the old row limit was 100,000): score keeps a sheet per participant, not the rows.
        string responses = Path.Combine(_dir, "R.csv");
        using (var w = new StreamWriter(responses))
        {
            w.Write("participant,questionnaire,item,response\n");
            for (int p = 0; p < 10_000; p++)
            {
                for (int i = 1; i <= 10; i++) w.Write($"P{p},weight-detection,{i},{(p + i) % 5 + 1}\n");
                for (int i = 1; i <= 10; i++) w.Write($"P{p},immersion,{i},{(3 * p + i) % 5 + 1}\n");
                w.Write($"P{p},self-assessment,1,{p % 10 + 1}\n");
            }
        }
        string scores = Path.Combine(_dir, "S.csv");
        var score = Run("score", "--responses", responses, "--out", scores);
        Assert.That(score.Code, Is.EqualTo(0), score.Stderr);
        Assert.That(score.Stdout, Does.Contain("30000 scores of 10000 participants from 210000 answers"));
        Assert.That(score.PeakKb, Is.LessThan(200_000), "score's peak resident memory, kB");
        var report = Run("report", "--scores", scores, "--out", Path.Combine(_dir, "report"), "--responses", responses);
        Assert.That(report.Code, Is.EqualTo(0), report.Stderr);
        Assert.That(report.PeakKb, Is.LessThan(200_000), "report's peak resident memory, kB");
        TestContext.WriteLine($"score {score.PeakKb} kB, report {report.PeakKb} kB peak");
        Directory.Delete(Path.Combine(_dir, "report"), true);
        File.Delete(responses);
        File.Delete(scores);
    }

    [Test]
    public void ScoreRefusesTheParticipantBeyondItsBoundNamingTheLine()
    {
        int max = Kosmos.PseudoHaptic.Cli.EvaluationInputsLimits.MaxParticipants;
        string responses = Path.Combine(_dir, "R.csv");
        using (var w = new StreamWriter(responses))
        {
            w.Write("participant,questionnaire,item,response\n");
            for (int i = 0; i <= max; i++) w.Write($"P{i},self-assessment,1,{i % 10 + 1}\n");
        }
        var refused = Run("score", "--responses", responses, "--out", Path.Combine(_dir, "S2.csv"));
        Assert.That(refused.Code, Is.EqualTo(2));
        Assert.That(refused.Stderr, Does.Contain($"R.csv:{max + 2}: more than {max} participants"));
        Assert.That(File.Exists(Path.Combine(_dir, "S2.csv")), Is.False);
        File.Delete(responses);
    }

    [Test]
    public void LongFieldsCannotAddUpPastTheBound()
    {
        // Rows near the 1 MiB row limit: what score keeps of them is bounded by characters, not only by rows.
        string responses = Path.Combine(_dir, "R.csv");
        using (var w = new StreamWriter(responses))
        {
            w.Write("participant,questionnaire,item,response\n");
            for (int i = 0; i < 50; i++) w.Write($"P{i}{new string('x', 1_000_000)},immersion,1,4\n");
        }
        var r = Run("score", "--responses", responses, "--out", Path.Combine(_dir, "S.csv"));
        Assert.That(r.Code, Is.EqualTo(2));
        Assert.That(r.Stderr, Does.Contain("R.csv:8: the participants' and conditions' names add up to more than 6400000 characters"));
        File.Delete(responses);
    }

    [TestCase("replay")]
    [TestCase("score")]
    [TestCase("report")]
    [TestCase("demo")]
    [TestCase("accuracy")]
    public void AnEndlessLineIsRefusedAtTheLimit(string command)
    {
        string[] args = command switch
        {
            "replay" => new[] { "replay", "--trace", "/dev/zero", "--out", "o.csv", "--mass-kg", "1" },
            "score" => new[] { "score", "--responses", "/dev/zero", "--out", "o.csv" },
            "report" => new[] { "report", "--scores", "/dev/zero", "--out", "rep" },
            "demo" => new[] { "demo", "--trace", "/dev/zero", "--out", "d" },
            _ => new[] { "accuracy", "--trace", "/dev/zero", "--lifts", "none", "--mocap", "none", "--long-minutes", "0" },
        };
        var r = Run(args);
        Assert.That(r.Code, Is.EqualTo(2));
        Assert.That(r.Stderr.TrimEnd('\n'), Does.Contain("/dev/zero:1: the row is longer than 1048576 characters").And.Not.Contain('\n'));
        Assert.That(Directory.GetFileSystemEntries(_dir).Select(Path.GetFileName), Is.EquivalentTo(new[] { "untracked.csv", "dense.csv" }));
    }

    [TestCase("demo", "1e12")]
    [TestCase("accuracy", "1e12")]
    [TestCase("demo", "10000000")]
    [TestCase("accuracy", "4000")]
    public void AHugeSpanIsRefusedNamingTheRow(string command, string glitch)
    {
        string trace = Path.Combine(_dir, "span.csv");
        File.WriteAllText(trace, "t,hand_y\n0,0.8\n1,0.9\n2,1.0\n" + glitch + ",1.0\n3,0.8\n4,0.8\n");
        string[] args = command == "demo"
            ? new[] { "demo", "--trace", trace, "--out", Path.Combine(_dir, "d") }
            : new[] { "accuracy", "--trace", trace, "--lifts", "none", "--mocap", "none", "--long-minutes", "0" };
        var r = Run(args);
        File.Delete(trace);
        Assert.That(r.Code, Is.EqualTo(2));
        Assert.That(r.Stderr, Does.Contain("span.csv:5: t = ").And.Contain("after the first usable row (line 2)"));
        Assert.That(Directory.Exists(Path.Combine(_dir, "d")), Is.False);
    }
}
