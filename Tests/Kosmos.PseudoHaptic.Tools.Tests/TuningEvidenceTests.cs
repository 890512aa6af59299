using Kosmos.PseudoHaptic.Cli.Personalization;
using Kosmos.PseudoHaptic.Evaluation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tools.Tests;

/// <summary>
/// Issue 31's evidence, a test per claim, on the seeded simulated observers of <see cref="TuningEvidence"/> (the table in
/// evaluation.md §9). The thresholds are the issue's: 75 % correct, Weber 0.05–0.6, s &lt; 1 for the sensitive.
/// </summary>
public class TuningEvidenceTests
{
    static List<TuningEvidence.Row>? _rows;
    static List<TuningEvidence.Row> Rows => _rows ??= TuningEvidence.Run();

    [Test]
    public void TheObserversWeberFractionsAtStrengthOneSpan005To06()
    {
        Assert.That(TuningEvidence.Webers.Min(), Is.EqualTo(0.05));
        Assert.That(TuningEvidence.Webers.Max(), Is.EqualTo(0.6));
        // Each observer is what it says: at s = 1 a comparison one Weber fraction heavier than the 2 kg standard is judged
        // heavier 75 % of the time (its own psychometric function, through the solver's cue).
        var answers = TrialsCsv.Read(new StringReader(TuningEvidence.TrialsFile()), "trials.csv");
        for (int k = 0; k < TuningEvidence.Webers.Length; k++)
        {
            var mine = answers.Where(a => a.Participant == TuningEvidence.Participant(k)).ToList();
            Assert.That(mine, Has.Count.EqualTo((2 * TuningEvidence.LevelsEachSide + 1) * TuningEvidence.Repetitions));
            // The answers at the level just above one Weber fraction (√(1+w)² = 1+w: level +2) are about 75 % "heavier".
            double level = mine.Select(a => a.Comparison).Distinct().OrderBy(c => c).ElementAt(TuningEvidence.LevelsEachSide + 2);
            Assert.That(level, Is.EqualTo(2 * (1 + TuningEvidence.Webers[k])).Within(1e-9));
            double p = mine.Where(a => a.Comparison == level).Average(a => a.Response);
            Assert.That(p, Is.InRange(0.75 - 0.2, 0.75 + 0.2), $"observer {k + 1}: 40 answers at +1 JND (binomial sd 0.07)");
        }
    }

    [Test]
    public void BeforeTuningTheInsensitiveOrderTheAdjacentBoxesBelow75Percent()
    {
        var insensitive = Rows.Where(r => r.Weber >= 0.45).ToList();
        Assert.That(insensitive, Is.Not.Empty);
        foreach (var r in insensitive)
        {
            Assert.That(r.BeforePooled, Is.LessThan(75), r.Participant + ": both pairs at s = 1");
            Assert.That(r.BeforeWorst, Is.LessThan(75), r.Participant + ": the worse pair at s = 1");
        }
    }

    [Test]
    public void AfterTuningEveryObserverWithinTheBoundOrdersTheAdjacentBoxesAtLeast75Percent()
    {
        var within = Rows.Where(r => r.Reached).ToList();
        Assert.That(within, Has.Count.EqualTo(Rows.Count), "every observer's strength lies within the bounds here");
        foreach (var r in within) Assert.That(r.AfterPooled, Is.GreaterThanOrEqualTo(75), r.Participant);
        // And tuning helps exactly those who needed it: every observer below 75 % before is better after.
        foreach (var r in Rows.Where(r => r.BeforePooled < 75)) Assert.That(r.AfterPooled, Is.GreaterThan(r.BeforePooled), r.Participant);
    }

    [Test]
    public void TheSensitiveGetLessOffset()
    {
        var sensitive = Rows.Where(r => r.Weber <= 0.15).ToList();
        Assert.That(sensitive, Has.Count.EqualTo(3));
        foreach (var r in sensitive) Assert.That(r.CueStrength, Is.LessThan(1), r.Participant);
    }

    [Test]
    public void TheTunedStrengthIsMonotoneInTheThreshold()
    {
        var byWeber = Rows.OrderBy(r => r.Weber).ToList();
        for (int i = 1; i < byWeber.Count; i++)
            Assert.That(byWeber[i].CueStrength, Is.GreaterThanOrEqualTo(byWeber[i - 1].CueStrength), $"{byWeber[i].Participant} after {byWeber[i - 1].Participant}");
        // The mapping itself is monotone in the JND: a denser sweep straight through the model.
        double last = 0;
        for (double jnd = 0.02; jnd <= 2.0; jnd *= 1.25)
        {
            double s = CueStrengthTuning.Solve(2, jnd, CueStrengthTuning.ExperimentOneBoxes).CueStrength;
            Assert.That(s, Is.GreaterThanOrEqualTo(last), $"JND {jnd} kg");
            last = s;
        }
    }
}
