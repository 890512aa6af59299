using Kosmos.PseudoHaptic.Evaluation;
using System.Globalization;
using System.Text.Json;
using Kosmos.PseudoHaptic.Cli.Commands;
using Kosmos.PseudoHaptic.Simulation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tools.Tests;

/// <summary>Issue 31: <c>tune</c>'s file contract, <c>replay --user</c> / <c>demo --user</c>, and the calibration line.</summary>
public class TuneCliTests : CliTestFolder
{
    public TuneCliTests() : base("ph-tune-") { }

    static string Trials => Path.Combine(RepositoryRoot.Path, "Packages", "com.kosmos.pseudohaptic", "Documentation~", "examples", "study", "trials.csv");
    static string Lift => Path.Combine(RepositoryRoot.Path, "Packages", "com.kosmos.pseudohaptic", "Documentation~", "examples", "lift.csv");

    static (int code, string stderr, string stdout) Run(params string[] args) => Capture(() => Cli.Cli.Run(args));

    static void OneLineNamingAndNothingWritten((int code, string stderr, string stdout) r, string command, string[] named, string output)
    {
        Assert.That(r.code, Is.EqualTo(2), r.stderr);
        Assert.That(r.stderr.TrimEnd('\n').Split('\n'), Has.Length.EqualTo(1), r.stderr);
        Assert.That(r.stderr, Does.StartWith($"pseudohaptic {command}: "));
        foreach (var n in named) Assert.That(r.stderr, Does.Contain(n));
        Assert.That(File.Exists(output) || Directory.Exists(output), Is.False, "nothing written");
    }

    [Test]
    public void TuneWritesTheUsersFileWithParticipantCueStrengthAndWeber()
    {
        string output = Path.Combine(_dir, "user.json");
        var (code, err, stdout) = Run("tune", "--trials", Trials, "--participant", "P3", "--condition", "pseudo-haptic", "--out", output);
        Assert.That(code, Is.EqualTo(0), err);
        using var doc = JsonDocument.Parse(File.ReadAllText(output));
        var root = doc.RootElement;
        Assert.That(root.GetProperty("participant").GetString(), Is.EqualTo("P3"));
        double s = root.GetProperty("cueStrength").GetDouble(), weber = root.GetProperty("weber").GetDouble();
        Assert.That(s, Is.InRange(WeightSolver.MinCueStrength, WeightSolver.MaxCueStrength));
        Assert.That(weber, Is.GreaterThan(0));
        // The file's numbers are the model's for its own fit: re-solving from the written threshold cue (the JND's upper
        // bound) gives the written s, and from its kg equivalent the same s within the bisection's tolerance.
        var again = CueStrengthTuning.SolveForThresholdCue(root.GetProperty("standardKg").GetDouble(), root.GetProperty("thresholdCue").GetDouble(), CueStrengthTuning.ExperimentOneBoxes);
        Assert.That(s, Is.EqualTo(again.CueStrength));
        var inKg = CueStrengthTuning.Solve(root.GetProperty("standardKg").GetDouble(), root.GetProperty("jndKgUpper").GetDouble(), CueStrengthTuning.ExperimentOneBoxes);
        Assert.That(inKg.CueStrength, Is.EqualTo(s).Within(1e-6));
        Assert.That(root.GetProperty("confidence").GetDouble(), Is.EqualTo(0.95));
        Assert.That(root.GetProperty("thresholdCue").GetDouble(), Is.GreaterThanOrEqualTo(root.GetProperty("fittedCue").GetDouble()), "the bound is at or above the fit");
        Assert.That(root.GetProperty("jndKgUpper").GetDouble(), Is.GreaterThanOrEqualTo(root.GetProperty("jndKg").GetDouble()));
        Assert.That(weber, Is.EqualTo(root.GetProperty("jndKg").GetDouble() / root.GetProperty("standardKg").GetDouble()).Within(1e-12));
        Assert.That(stdout, Does.StartWith("tune: P3: Weber "));
        // It is read back by replay.
        Assert.That(UserFile.ReadCueStrength("--user", output), Is.EqualTo(s));
    }

    [Test]
    public void AHigherConfidenceNeverGivesLessCueAndTheFitItselfIsConfidenceHalf()
    {
        // Metamorphic: the same answers tuned at a higher confidence take a higher bound of the same fit, so never a
        // weaker strength; at 0.5 the threshold is the fitted JND itself, read in the cue.
        var answers = TrialsCsv.Read(new StringReader(File.ReadAllText(Trials)), "trials.csv");
        foreach (string p in new[] { "P1", "P3" })
        {
            double last = 0;
            foreach (double c in new[] { 0.5, 0.8, 0.95, 0.999 })
            {
                var (_, fit, fittedKg, tuning, _, _) = TuneCommand.Tune(answers, p, "pseudo-haptic", new[] { 0.3, 0.35, 0.4 }, "trials.csv", c);
                Assert.That(tuning.CueStrength, Is.GreaterThanOrEqualTo(last), $"{p} at {c}");
                Assert.That(tuning.ThresholdCue, Is.GreaterThanOrEqualTo(fit.Jnd));
                if (c == 0.5) { Assert.That(tuning.ThresholdCue, Is.EqualTo(fit.Jnd)); Assert.That(tuning.JndKg, Is.EqualTo(fittedKg)); }
                last = tuning.CueStrength;
            }
        }
    }

    /// <summary>--interval: the JND's upper bound is the BCa one by default (the engine's, at the one-sided confidence), the
    /// plain percentile's with --interval percentile; the fit itself is the same.</summary>
    [Test]
    public void TheBoundIsBcaByDefaultAndThePercentileOnRequest()
    {
        string bca = Path.Combine(_dir, "bca.json"), percentile = Path.Combine(_dir, "percentile.json");
        Assert.That(Run("tune", "--trials", Trials, "--participant", "P3", "--condition", "pseudo-haptic", "--out", bca).code, Is.EqualTo(0));
        Assert.That(Run("tune", "--trials", Trials, "--participant", "P3", "--condition", "pseudo-haptic", "--interval", "percentile", "--out", percentile).code, Is.EqualTo(0));
        using var b = JsonDocument.Parse(File.ReadAllText(bca));
        using var p = JsonDocument.Parse(File.ReadAllText(percentile));
        double fitted = b.RootElement.GetProperty("fittedCue").GetDouble();
        Assert.That(p.RootElement.GetProperty("fittedCue").GetDouble(), Is.EqualTo(fitted), "the same fit");
        var answers = TrialsCsv.Read(new StringReader(File.ReadAllText(Trials)), "trials.csv", int.MaxValue, long.MaxValue, leaveOutCatch: true, out _);
        var (_, fit, _, _, _, _) = TuneCommand.Tune(answers, "P3", "pseudo-haptic", CueStrengthTuning.ExperimentOneBoxes, "trials.csv");
        Assert.That(fit.Jnd, Is.EqualTo(fitted), "the command's fit (catch trials left out)");
        foreach (var (doc, kind) in new[] { (b, BootstrapInterval.Bca), (p, BootstrapInterval.Percentile) })
        {
            var boot = PsychometricBootstrap.Run(fit, TuneCommand.Resamples, TuneCommand.BootstrapSeed, 0.9, kind);
            Assert.That(doc.RootElement.GetProperty("thresholdCue").GetDouble(), Is.EqualTo(Math.Max(fit.Jnd, boot.JndHigh)), kind.ToString());
        }
        Assert.That(b.RootElement.GetProperty("thresholdCue").GetDouble(), Is.Not.EqualTo(p.RootElement.GetProperty("thresholdCue").GetDouble()));
    }

    [Test]
    public void AnUnreachableStrengthIsTheBoundWithOneStderrLine()
    {
        // An insensitive participant (a JND of 3 kg at 2 kg: every answer near chance) for masses 1.0 and 1.05 kg.
        var rows = new System.Text.StringBuilder("participant,standard,comparison,response\n");
        var rng = new Random(5);
        foreach (double c in new[] { 0.5, 1.0, 1.5, 2.0, 2.5, 3.0, 3.5 })
            for (int i = 0; i < 30; i++) rows.Append(CultureInfo.InvariantCulture, $"X,2,{c},{(rng.NextDouble() < 0.5 + 0.08 * (c - 2) ? 1 : 0)}\n");
        string trials = Write("t.csv", rows.ToString()), output = Path.Combine(_dir, "user.json");
        var (code, err, _) = Run("tune", "--trials", trials, "--participant", "X", "--out", output, "--masses", "1,1.05");
        Assert.That(code, Is.EqualTo(0), err);
        Assert.That(err.TrimEnd('\n').Split('\n'), Has.Length.EqualTo(1));
        Assert.That(err, Does.StartWith("pseudohaptic tune: warning: X: even the largest cue strength 3"));
        using var doc = JsonDocument.Parse(File.ReadAllText(output));
        Assert.That(doc.RootElement.GetProperty("cueStrength").GetDouble(), Is.EqualTo(WeightSolver.MaxCueStrength));
        Assert.That(doc.RootElement.GetProperty("reached").GetBoolean(), Is.False);
    }

    [Test]
    public void TuneRefusesWhatItCannotUseNamingTheOptionOrFile()
    {
        string output = Path.Combine(_dir, "user.json");
        OneLineNamingAndNothingWritten(Run("tune", "--trials", Trials, "--participant", "nobody", "--out", output), "tune", new[] { "--participant", "nobody" }, output);
        OneLineNamingAndNothingWritten(Run("tune", "--trials", Trials, "--participant", "P1", "--out", output), "tune", new[] { "--condition", "visual", "pseudo-haptic" }, output);
        OneLineNamingAndNothingWritten(Run("tune", "--trials", Trials, "--participant", "P1", "--condition", "none", "--out", output), "tune", new[] { "--condition", "none" }, output);
        OneLineNamingAndNothingWritten(Run("tune", "--trials", Trials, "--participant", "P1", "--condition", "visual", "--masses", "1,x", "--out", output), "tune", new[] { "--masses", "'x'" }, output);
        OneLineNamingAndNothingWritten(Run("tune", "--trials", Trials, "--participant", "P1", "--condition", "visual", "--masses", "1,1", "--out", output), "tune", new[] { "--masses" }, output);
        string flat = Write("flat.csv", "participant,standard,comparison,response\nQ,1,0.5,0\nQ,1,1.5,1\n");
        OneLineNamingAndNothingWritten(Run("tune", "--trials", flat, "--participant", "Q", "--out", output), "tune", new[] { "flat.csv", "not estimable" }, output);
        string broken = Write("broken.csv", "participant,standard,comparison,response\nQ,1,abc,0\n");
        OneLineNamingAndNothingWritten(Run("tune", "--trials", broken, "--participant", "Q", "--out", output), "tune", new[] { "broken.csv:2" }, output);
        OneLineNamingAndNothingWritten(Run("tune", "--trials", Trials, "--participant", "P3", "--condition", "pseudo-haptic", "--confidence", "0.4", "--out", output), "tune", new[] { "--confidence", "0.4" }, output);
        OneLineNamingAndNothingWritten(Run("tune", "--trials", Trials, "--participant", "P3", "--condition", "pseudo-haptic", "--confidence", "x", "--out", output), "tune", new[] { "--confidence", "'x'" }, output);
        OneLineNamingAndNothingWritten(Run("tune", "--trials", Trials, "--participant", "P3", "--condition", "pseudo-haptic", "--interval", "basic", "--out", output), "tune", new[] { "--interval", "'basic'" }, output);
        var (help, _, text) = Run("tune", "--help");
        Assert.That(help, Is.EqualTo(0));
        Assert.That(text, Does.Contain("--trials").And.Contain("--participant").And.Contain("--condition").And.Contain("--masses").And.Contain("--out").And.Contain("--confidence").And.Contain("--interval"));
    }

    [TestCase("{\"participant\": \"P\"}", "field cueStrength is missing")]
    [TestCase("{\"cueStrength\": 0}", "field cueStrength: must be a positive number")]
    [TestCase("{\"cueStrength\": -1}", "field cueStrength: must be a positive number")]
    [TestCase("{\"cueStrength\": \"1\"}", "field cueStrength: \"1\" is not a number")]
    [TestCase("{\"cueStrength\": 7}", "field cueStrength: must lie in")]
    [TestCase("[1]", "field cueStrength: the file holds a JSON array")]
    [TestCase("cueStrength = 1", "not JSON")]
    public void AMalformedUsersFileIsRefusedByReplayAndDemo(string json, string message)
    {
        string user = Write("user.json", json), output = Path.Combine(_dir, "out.csv"), folder = Path.Combine(_dir, "demo");
        var r = Run("replay", "--trace", Lift, "--out", output, "--mass-kg", "2", "--user", user);
        OneLineNamingAndNothingWritten(r, "replay", new[] { "--user", user, message }, output);
        Assert.That(r.stderr, Does.Contain("cueStrength"));
        OneLineNamingAndNothingWritten(Run("demo", "--out", folder, "--user", user), "demo", new[] { "--user", user, message }, folder);
    }

    double[] ObjectY(string path) => File.ReadAllLines(path).Skip(1).Select(l => double.Parse(l.Split(',')[2], CultureInfo.InvariantCulture)).ToArray();

    [TestCase("paper"), TestCase("paper-experiment"), TestCase("gain"), TestCase("xyz"), TestCase("paper-literal")]
    public void AUserAtStrengthOneReplaysByteIdenticalAndAWeakerOneLagsLess(string profile)
    {
        string plain = Path.Combine(_dir, "plain.csv"), one = Path.Combine(_dir, "one.csv"), weak = Path.Combine(_dir, "weak.csv");
        Assert.That(Run("replay", "--trace", Lift, "--out", plain, "--mass-kg", "2", "--profile", profile).code, Is.EqualTo(0));
        Assert.That(Run("replay", "--trace", Lift, "--out", one, "--mass-kg", "2", "--profile", profile, "--user", Write("one.json", "{\"cueStrength\": 1}")).code, Is.EqualTo(0));
        Assert.That(Run("replay", "--trace", Lift, "--out", weak, "--mass-kg", "2", "--profile", profile, "--user", Write("weak.json", "{\"cueStrength\": 0.5}")).code, Is.EqualTo(0));
        Assert.That(File.ReadAllBytes(one), Is.EqualTo(File.ReadAllBytes(plain)), "s = 1 is today's output, byte for byte");
        var hand = File.ReadAllLines(plain).Skip(1).Select(l => double.Parse(l.Split(',')[1], CultureInfo.InvariantCulture)).ToArray();
        double Largest(double[] y) => y.Select((v, i) => double.IsFinite(hand[i]) ? hand[i] - v : 0).Max();
        Assert.That(Largest(ObjectY(weak)), Is.LessThan(Largest(ObjectY(plain)) - 0.01), "a 2 kg object at s = 0.5 lags at least 1 cm less at its largest");
    }

    [TestCase("paper", 2.0), TestCase("paper-experiment", 0.6), TestCase("gain", 5.0), TestCase("paper-literal", 2.0)]
    public void ReplaySaysOnOneStderrLineHowFarVStdMovesTheReferenceLift(string profile, double massKg)
    {
        string output = Path.Combine(_dir, "out.csv");
        var (code, err, _) = Run("replay", "--trace", Lift, "--out", output, "--mass-kg", massKg.ToString(CultureInfo.InvariantCulture), "--profile", profile, "--standard-speed", "0.5");
        Assert.That(code, Is.EqualTo(0), err);
        var lines = err.TrimEnd('\n').Split('\n');
        Assert.That(lines, Has.Length.EqualTo(1));
        var mm = System.Text.RegularExpressions.Regex.Matches(lines[0], @"(\d+\.\d) mm").Select(m => double.Parse(m.Groups[1].Value, CultureInfo.InvariantCulture)).ToArray();
        Assert.That(lines[0], Does.StartWith($"replay: v_std 0.5 m/s: a 0.2 m lift of {massKg.ToString(CultureInfo.InvariantCulture)} kg in 0.6 s ends "));
        // The numbers, run here independently: the reference lift's hand through a solver of each standard speed.
        var frames = ReferenceLift.Frames();
        double Lag(double v)
        {
            double end;
            if (profile == "paper-literal")
            {
                var literal = new PaperLiteralSolver(massKg);
                literal.BeginHold(frames[0].HandY, frames[0].HandY);
                for (int i = 1; i < frames.Length; i++) literal.Step(frames[i].HandY, true, frames[i].Time - frames[i - 1].Time);
                end = literal.ObjectY;
            }
            else end = TraceReplay.Run(new WeightSolver(WeightModel.FromMass(massKg), NamedProfiles.Get(profile), v), frames)[^1];
            return Math.Round((frames[^1].HandY - end) * 1000, 1);
        }
        Assert.That(mm.Take(3), Is.EqualTo(new[] { Lag(0.5), Lag(0.25), Lag(1.0) }));
    }
}
