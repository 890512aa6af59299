using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tools.Tests;

/// <summary>
/// Catch trials (the headset's <c>catch</c> = 1: differences no attentive participant misses) are attention checks, not
/// levels of a person's psychometric function: <c>tune</c> leaves them out of the fit that sets the cue strength, and
/// <c>psychometric --without-catch</c> does (its default fits every row, issue 11's contract: extra columns ignored).
/// Metamorphic: with catch trials left out, a missed catch trial changes nothing.
/// </summary>
public class CatchTrialTests : CliTestFolder
{
    public CatchTrialTests() : base("ph-catch-") { }

    static string Trials => Path.Combine(RepositoryRoot.Path, "Packages", "com.kosmos.pseudohaptic", "Documentation~", "examples", "study", "trials.csv");

    static (int code, string stderr, string stdout) Run(params string[] args) => Capture(() => Cli.Cli.Run(args));

    /// <summary>The worked example's trials with P1's pseudo-haptic catch trial at 1 kg (line 32 of the condition) missed.</summary>
    string WithAMissedCatchTrial()
    {
        string[] lines = File.ReadAllLines(Trials);
        int missed = Array.IndexOf(lines, "P1,pseudo-haptic,32,0.5,1,standard,1,1");
        Assert.That(missed, Is.GreaterThan(0), "the example's catch trial at 1 kg");
        lines[missed] = "P1,pseudo-haptic,32,0.5,1,standard,1,0";
        return Write("missed.csv", string.Join("\n", lines) + "\n");
    }

    string WithoutCatchRows() => Write("no-catch.csv", string.Join("\n", File.ReadAllLines(Trials).Where(l => l.Split(',')[6] != "1")) + "\n");

    string Fits(string trials, params string[] options)
    {
        string output = Path.Combine(_dir, "fits-" + Guid.NewGuid().ToString("N"));
        var (code, err, _) = Run(new[] { "psychometric", "--trials", trials, "--out", output, "--bootstrap", "0" }.Concat(options).ToArray());
        Assert.That(code, Is.EqualTo(0), err);
        return File.ReadAllText(Path.Combine(output, "fits.csv"));
    }

    [Test]
    public void WithoutCatchAMissedCatchTrialChangesNoFit()
    {
        string missed = WithAMissedCatchTrial();
        string clean = Fits(WithoutCatchRows());
        Assert.That(Fits(missed, "--without-catch"), Is.EqualTo(clean), "the fits of the file without its catch rows");
        Assert.That(Fits(Trials, "--without-catch"), Is.EqualTo(clean));
        // By default every row is fitted (the contract), and the one missed catch trial moves P1's fit.
        string fitted = Fits(missed);
        Assert.That(fitted, Is.Not.EqualTo(Fits(Trials)));
        string Row(string fits) => fits.Split('\n').First(l => l.StartsWith("P1,pseudo-haptic,"));
        double Jnd(string fits) => double.Parse(Row(fits).Split(',')[5], System.Globalization.CultureInfo.InvariantCulture);
        Assert.That(Jnd(fitted), Is.GreaterThan(1.5 * Jnd(clean)), "one lapse at 1 kg widens P1's JND");
    }

    [Test]
    public void TuneLeavesCatchTrialsOut()
    {
        string Tune(string trials)
        {
            string output = Path.Combine(_dir, "user-" + Guid.NewGuid().ToString("N") + ".json");
            var (code, err, _) = Run("tune", "--trials", trials, "--participant", "P1", "--condition", "pseudo-haptic", "--out", output);
            Assert.That(code, Is.EqualTo(0), err);
            return File.ReadAllText(output);
        }
        string clean = Tune(WithoutCatchRows());
        Assert.That(Tune(WithAMissedCatchTrial()), Is.EqualTo(clean), "a missed catch trial does not raise the cue strength");
        Assert.That(Tune(Trials), Is.EqualTo(clean));
        Assert.That(clean, Does.Contain("\"trials\": 84"), "the 88 trials less the 4 catch trials");
    }

    [Test]
    public void ACatchValueOtherThanZeroOrOneIsRefusedWhereItIsRead()
    {
        string bad = Write("bad.csv", "participant,standard,comparison,catch,response\nP1,0.5,0.6,0,1\nP1,0.5,0.4,yes,0\n");
        string output = Path.Combine(_dir, "out");
        var (code, err, _) = Run("psychometric", "--trials", bad, "--out", output, "--without-catch");
        Assert.That(code, Is.EqualTo(2));
        Assert.That(err, Does.Contain("bad.csv:3").And.Contain("catch 'yes'"));
        Assert.That(Directory.Exists(output), Is.False, "nothing written");
        // Without the option the column is one the fit ignores, as any other.
        (code, err, _) = Run("psychometric", "--trials", bad, "--out", output, "--bootstrap", "0");
        Assert.That(code, Is.EqualTo(0), err);
    }
}
