using System.Globalization;
using System.Text;
using Kosmos.PseudoHaptic.Cli.Accuracy;
using Kosmos.PseudoHaptic.Simulation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tools.Tests;

/// <summary>
/// Issue 31, item 1: <c>replay --profile paper-literal</c> runs the accuracy page's baseline. On every degraded render of
/// the page's synthetic lifts (each frame rate and jitter, the first replicate), for the page's two objects, the replayed
/// object_y is the baseline's object height bit for bit, so every baseline figure of accuracy-results.md (a function of
/// that path and the true hand) is what replay gives.
/// </summary>
public class ReplayPaperLiteralCliTests : CliTestFolder
{
    public ReplayPaperLiteralCliTests() : base("ph-literal-") { }

    static string Trace(TraceFrame[] frames)
    {
        var sb = new StringBuilder("t,hand_y,tracked,pose_t\n");
        foreach (var f in frames)
            sb.Append(CultureInfo.InvariantCulture, $"{f.Time:R},{f.HandY:R},{(f.Tracked ? 1 : 0)},{f.PoseTime:R}\n");
        return sb.ToString();
    }

    [TestCase(1.0), TestCase(PhysicalConstants.StandardMassKg)]
    public void ReplayReproducesTheAccuracyBaselineBitForBit(double massKg)
    {
        int compared = 0;
        foreach (var source in AccuracySource.Lifts())
            foreach (var render in Degradation.Renders(source.Hand).Take(Degradation.FrameRates.Length * Degradation.JitterMm.Length))
            {
                var baseline = IntegratorReplay.Run(new IntegratorReplay.PaperLiteral(massKg), render.Frames);
                string input = Write("in.csv", Trace(render.Frames)), output = Path.Combine(_dir, "out.csv");
                var (code, err, _) = Capture(() => Cli.Cli.Run(new[] { "replay", "--trace", input, "--out", output, "--mass-kg", massKg.ToString("R", CultureInfo.InvariantCulture), "--profile", "paper-literal" }));
                Assert.That(code, Is.EqualTo(0), err);
                var rows = File.ReadAllLines(output).Skip(1).Select(l => double.Parse(l.Split(',')[2], CultureInfo.InvariantCulture)).ToArray();
                Assert.That(rows, Is.EqualTo(baseline), $"{source.Name} {render.Label}");
                compared++;
            }
        Assert.That(compared, Is.EqualTo(3 * 6));
    }

    [Test]
    public void TheLiteralProfileIsNamedInHelpAndRefusesBreakAway()
    {
        var (code, _, stdout) = Capture(() => Cli.Cli.Run(new[] { "replay", "--help" }));
        Assert.That(code, Is.EqualTo(0));
        Assert.That(stdout, Does.Contain("paper-literal"));
        string input = Write("in.csv", "t,hand_y\n0,1\n0.1,1.1\n"), output = Path.Combine(_dir, "out.csv");
        var (bad, err, _) = Capture(() => Cli.Cli.Run(new[] { "replay", "--trace", input, "--out", output, "--mass-kg", "2", "--profile", "paper-literal", "--break-away", "0.3" }));
        Assert.That(bad, Is.EqualTo(2));
        Assert.That(err.Trim().Split('\n'), Has.Length.EqualTo(1));
        Assert.That(err, Does.StartWith("pseudohaptic replay: option --break-away"));
        Assert.That(File.Exists(output), Is.False);
    }

    [Test]
    public void AHeavyObjectLagsALightOneLeadsAndNothingGoesBelowZero()
    {
        var sb = new StringBuilder("t,hand_y\n");
        // At rest 1.5 s (the 1 s window fills), up 0.3 m in 1 s, down to 0 in 1 s, at rest 1.5 s.
        for (int i = 0; i <= 450; i++) { double t = i / 90.0, u = t - 1.5; sb.Append(CultureInfo.InvariantCulture, $"{t:R},{(u < 0 ? 0.05 : u < 1 ? 0.05 + 0.3 * u : u < 2 ? 0.35 - 0.35 * (u - 1) : 0.0):R}\n"); }
        string input = Write("in.csv", sb.ToString());
        double End(string mass, out double lowest)
        {
            string output = Path.Combine(_dir, "out-" + mass + ".csv");
            var (code, err, _) = Capture(() => Cli.Cli.Run(new[] { "replay", "--trace", input, "--out", output, "--mass-kg", mass, "--profile", "paper-literal" }));
            Assert.That(code, Is.EqualTo(0), err);
            var ys = File.ReadAllLines(output).Skip(1).Select(l => double.Parse(l.Split(',')[2], CultureInfo.InvariantCulture)).ToArray();
            lowest = ys.Min();
            return ys[225];
        }
        double heavy = End("2", out double heavyLow), light = End("0.01", out double lightLow);
        Assert.That(heavy, Is.LessThan(0.35 - 0.05), "2 kg lags the hand's 0.35 m at the top");
        Assert.That(light, Is.GreaterThan(0.35), "10 g leads it");
        Assert.That(Math.Min(heavyLow, lightLow), Is.GreaterThanOrEqualTo(0), "y ≥ 0, the paper's only bound");
        Assert.That(lightLow, Is.EqualTo(0), "the light object, leading the hand down to 0, is stopped at the floor");
    }

    /// <summary>The gain cap holds under paper-literal too (P3), at the profile file's own maxGain: a file written by
    /// <c>profiles --show paper-literal --json</c> with maxGain 1.5 lifts a 1 g object 1.5 times the hand's 0.1 m, the
    /// named profile 3 times (Eq. 4–6 alone: 23 times, which the file's maxGain did not change before).</summary>
    [Test]
    public void TheProfilesMaxGainCapsTheLiteralSolver()
    {
        var sb = new StringBuilder("t,hand_y\n");
        for (int i = 0; i <= 270; i++) { double t = i / 90.0; sb.Append(CultureInfo.InvariantCulture, $"{t:R},{(t < 0.5 ? 1.0 : t < 1 ? 1.0 + 0.2 * (t - 0.5) : 1.1):R}\n"); }
        string input = Write("lift.csv", sb.ToString());
        string shownFile = Path.Combine(_dir, "shown.json");
        var (shown, showErr, _) = Capture(() => Cli.Cli.Run(new[] { "profiles", "--show", "paper-literal", "--json", "--out", shownFile }));
        Assert.That(shown, Is.EqualTo(0), showErr);
        string json = File.ReadAllText(shownFile);
        Assert.That(json, Does.Contain("\"maxGain\": 3"));
        string file = Write("paper-literal.json", json.Replace("\"maxGain\": 3", "\"maxGain\": 1.5"));
        double Rise(string profile)
        {
            string output = Path.Combine(_dir, "out.csv");
            var (code, err, _) = Capture(() => Cli.Cli.Run(new[] { "replay", "--trace", input, "--out", output, "--mass-kg", "0.001", "--profile", profile }));
            Assert.That(code, Is.EqualTo(0), err);
            var ys = File.ReadAllLines(output).Skip(1).Select(l => double.Parse(l.Split(',')[2], CultureInfo.InvariantCulture)).ToArray();
            return ys[^1] - ys[0];
        }
        Assert.That(Rise("paper-literal"), Is.EqualTo(3 * 0.1).Within(1e-9), "the cap of every profile: 3");
        Assert.That(Rise(file), Is.EqualTo(1.5 * 0.1).Within(1e-9), "the file's maxGain");
    }
}
