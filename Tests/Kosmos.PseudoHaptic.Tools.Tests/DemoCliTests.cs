using System.Globalization;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tools.Tests;

/// <summary>The newcomer's command: it runs with nothing beside the clone, and with the shared recording when present.</summary>
public class DemoCliTests
{
    static (int code, string stdout, string stderr) Demo(params string[] args)
    {
        var out_ = new StringWriter();
        var err = new StringWriter();
        var (o, e) = (Console.Out, Console.Error);
        Console.SetOut(out_);
        Console.SetError(err);
        try { return (Cli.Cli.Run(args.Prepend("demo").ToArray()), out_.ToString(), err.ToString()); }
        finally { Console.SetOut(o); Console.SetError(e); }
    }

    /// <summary>A scene's chart height: one panel (600 px), two with the offset correction (height and offset), three for xyz.</summary>
    static int SceneHeight(string scene) => Path.GetFileNameWithoutExtension(scene) switch
    {
        "offset-correction" or "recorded-hand" => 560 + 520,
        "xyz-carry-lift" => 330 + 300 + 600,
        _ => 600,
    };

    static string TempDir() => Path.Combine(Path.GetTempPath(), "ph-demo-" + Guid.NewGuid().ToString("N"));

    [Test]
    public void RunsTheScenesWritesCsvAndPngAndPrintsTheSummary()
    {
        string dir = TempDir();
        try
        {
            // Progress goes to standard error when it is a terminal (forced here: the test's is a pipe).
            Kosmos.PseudoHaptic.Cli.CommandLine.Progress.Forced = true;
            int code;
            string stdout, stderr;
            try { (code, stdout, stderr) = Demo("--out", dir); }
            finally { Kosmos.PseudoHaptic.Cli.CommandLine.Progress.Forced = false; }
            Assert.That(code, Is.EqualTo(0), stderr);
            Assert.That(stderr, Does.Contain("[1/").And.Contain("v_std ="), "progress and calibration");
            Assert.That(stdout, Does.Contain("demo: ").And.Contain(" -> "), "the one line saying what was done");
            Assert.That(stdout, Does.Contain("box B").And.Contain("bottle 2 L").And.Contain("max offset"));
            foreach (var png in new[] { "experiment-1-boxes.png", "experiment-2-bottles.png", "offset-correction.png" })
                ChartFiles.AssertPng(Path.Combine(dir, png), 1000, SceneHeight(png));
            Assert.That(Directory.GetFiles(dir, "*.svg"), Is.Empty, "no SVG unless --svg");
            // Experiment 1: same size, B densest, so B lags most; the golf ball stays with the hand.
            double Peak(string file) => File.ReadLines(Path.Combine(dir, "experiment-1-boxes", file)).Skip(1)
                .Max(l => double.Parse(l.Split(',')[2], CultureInfo.InvariantCulture));
            Assert.That(Peak("box-b.csv"), Is.LessThan(Peak("box-c.csv")));
            Assert.That(Peak("box-c.csv"), Is.LessThan(Peak("box-a.csv")));
            Assert.That(Peak("box-a.csv"), Is.LessThan(Peak("golf-ball.csv")));

            // Issue 10's scene: x and y over time for several masses; heavier trails the sideways carry more.
            ChartFiles.AssertPng(Path.Combine(dir, "xyz-carry-lift.png"), 1000, SceneHeight("xyz-carry-lift"));
            Assert.That(stdout, Does.Contain("xyz-carry-lift").And.Contain("max x lag"));
            double Lag(string file)
            {
                var lines = File.ReadAllLines(Path.Combine(dir, "xyz-carry-lift", file));
                Assert.That(lines[0], Is.EqualTo("t,hand_x,hand_y,hand_z,hand2_x,hand2_y,hand2_z,object_x,object_y,object_z,hands"));
                var rows = lines.Skip(1).Select(l => l.Split(',').Select(v => double.Parse(v, CultureInfo.InvariantCulture)).ToArray()).ToList();
                Assert.That(rows.Select(r => r[10]).Distinct(), Is.EquivalentTo(new[] { 1.0, 2.0 }), "one hand, then two");
                return rows.Where(r => r[0] < 3).Max(r => (r[1] - rows[0][1]) - (r[7] - rows[0][7]));
            }
            Assert.That(Lag("box-0_1-kg.csv"), Is.LessThan(Lag("box-0_5-kg.csv")));
            Assert.That(Lag("box-0_5-kg.csv"), Is.LessThan(Lag("box-2-kg.csv")));
            Assert.That(Lag("box-2-kg.csv"), Is.LessThan(Lag("box-5-kg.csv")));
            Assert.That(Lag("box-5-kg.csv"), Is.LessThanOrEqualTo(0.10 + 1e-9));
        }
        finally { if (Directory.Exists(dir)) Directory.Delete(dir, true); }
    }

    [Test]
    public void SvgWritesAnSvgBesideEachPng()
    {
        string dir = TempDir();
        try
        {
            var (code, _, stderr) = Demo("--svg", "--out", dir);
            Assert.That(code, Is.EqualTo(0), stderr);
            foreach (var scene in new[] { "experiment-1-boxes", "experiment-2-bottles", "offset-correction", "xyz-carry-lift" })
            {
                ChartFiles.AssertPng(Path.Combine(dir, scene + ".png"), 1000, SceneHeight(scene));
                ChartFiles.AssertSvg(Path.Combine(dir, scene + ".svg"), 1000, SceneHeight(scene));
            }
        }
        finally { if (Directory.Exists(dir)) Directory.Delete(dir, true); }
    }

    [Test]
    public void ReplaysTheSharedMotionCaptureHand()
    {
        // Reads ../shared/data, which exists beside this repository in CI and here, not beside a user's clone.
        if (RepositoryRoot.Shared == null) Assert.Ignore("../shared is absent (a user's clone): the recorded-hand demo needs ../shared/data/mocap-hand-100hz.csv");
        string dir = TempDir();
        try
        {
            var (code, stdout, stderr) = Demo("--out", dir, "--trace", Path.Combine(RepositoryRoot.Shared, "data", "mocap-hand-100hz.csv"));
            Assert.That(code, Is.EqualTo(0), stderr);
            Assert.That(stdout, Does.Contain("recorded-hand"));
            ChartFiles.AssertPng(Path.Combine(dir, "recorded-hand.png"), 1000, SceneHeight("recorded-hand"));
            Assert.That(File.ReadLines(Path.Combine(dir, "recorded-hand", "box-b.csv")).Count(), Is.GreaterThan(60 * 90));
        }
        finally { if (Directory.Exists(dir)) Directory.Delete(dir, true); }
    }

    [Test]
    public void AMalformedTraceIsAOneLineError()
    {
        string dir = TempDir();
        Directory.CreateDirectory(dir);
        try
        {
            string trace = Path.Combine(dir, "bad.csv");
            File.WriteAllText(trace, "t,hand_y\n0,1\n0.1,oops\n");
            var (code, _, stderr) = Demo("--out", Path.Combine(dir, "out"), "--trace", trace);
            Assert.That(code, Is.EqualTo(2));
            Assert.That(stderr.Trim(), Does.Contain("bad.csv:3:").And.Not.Contain("\n"));
        }
        finally { Directory.Delete(dir, true); }
    }
}
