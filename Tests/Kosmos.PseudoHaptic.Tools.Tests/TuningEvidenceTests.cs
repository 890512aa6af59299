using Kosmos.PseudoHaptic.Cli.Personalization;
using Kosmos.PseudoHaptic.Evaluation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tools.Tests;

/// <summary>
/// Issue 31's evidence, a test per claim, on the seeded simulated observers of <see cref="TuningEvidence"/> (the table in
/// evaluation.md §9). The thresholds are the issue's: 75 % correct, Weber 0.05–0.6, s &lt; 1 for the sensitive. Each
/// observer is tuned on the JND's upper bound at the Bonferroni confidence 1 − 0.05/7 (all seven at once with ≥ 95 %);
/// the replications below measure that rate on other seeds, so the table's seed is not the only evidence.
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
            Assert.That(p, Is.InRange(0.75 - 0.2, 0.75 + 0.2), $"observer {k + 1}: {TuningEvidence.Repetitions} answers at +1 JND (binomial sd 0.05 at 80)");
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
    public void AfterTuningEveryObserverWithinTheBoundOrdersEveryAdjacentPairAtLeast75Percent()
    {
        // The claim is the issue's: every observer within the bound. An observer whose JND's upper bound needs more than
        // s = 3 gets 3 (Reached false) and is shown as such; the insensitive half must still be tested within the bound.
        var within = Rows.Where(r => r.Reached).ToList();
        Assert.That(within.Count(r => r.Weber >= 0.3), Is.GreaterThanOrEqualTo(2), "insensitive observers within the bound");
        foreach (var r in within)
        {
            Assert.That(r.AfterWorst, Is.GreaterThanOrEqualTo(75), r.Participant + ": the worse adjacent pair");
            Assert.That(r.AfterPooled, Is.GreaterThanOrEqualTo(75), r.Participant + ": both pairs");
        }
        // And tuning helps exactly those who needed it: every observer below 75 % before is better after.
        foreach (var r in Rows.Where(r => r.BeforeWorst < 75)) Assert.That(r.AfterWorst, Is.GreaterThan(r.BeforeWorst), r.Participant);
    }

    static readonly Dictionary<double, List<List<TuningEvidence.Row>>> _replications = new();

    /// <summary>Replications 1…20 of the whole evidence (other seeds than the table's 0), at tune's confidence.</summary>
    static List<List<TuningEvidence.Row>> Replications(double confidence)
    {
        if (!_replications.TryGetValue(confidence, out var runs))
            _replications[confidence] = runs = Enumerable.Range(1, 20).Select(b => TuningEvidence.Run(b, TuningEvidence.Repetitions, confidence)).ToList();
        return runs;
    }

    [Test]
    public void TheFitInTheCueFindsTheObserversTrueThresholdWithoutBias()
    {
        // The cause of the earlier shortfall: a Gaussian fitted in kg to observers Gaussian in the cue put the JND of the
        // insensitive 10–20 % low. Fitted on the cue difference, the median fitted Weber (the point estimate, before any
        // confidence bound) over 20 replications lies within 5 % of each observer's true one (20 runs of 720 trials: the
        // median's own sampling error is about 2 %).
        var runs = Replications(0.5);
        for (int k = 0; k < TuningEvidence.Webers.Length; k++)
        {
            var ratios = runs.Select(r => r[k].FittedWeber / TuningEvidence.Webers[k]).OrderBy(x => x).ToList();
            double median = 0.5 * (ratios[9] + ratios[10]);
            Assert.That(median, Is.InRange(0.95, 1.05), $"observer {k + 1}");
        }
    }

    [Test]
    public void TheConfidenceBoundIsWhatMakes75PercentMoreThanACoinFlip()
    {
        // On 20 replications × 7 observers, tuned at the evidence's confidence (1 − 0.05/7 per observer, nominally ≥ 99.3 %
        // each): at least 133 of the 140 runs within the bound (95 %) order every adjacent pair at least 75 %; the
        // percentile bootstrap runs a little narrow, so the allowance is wider than the nominal 1 miss.
        var bounded = Replications(TuningEvidence.Confidence).SelectMany(r => r).Where(r => r.Reached).ToList();
        Assert.That(bounded.Count, Is.GreaterThanOrEqualTo(133));
        int reached = bounded.Count(r => r.AfterWorst >= 75);
        Assert.That(reached, Is.GreaterThanOrEqualTo((int)Math.Ceiling(0.95 * bounded.Count)), $"{reached} of {bounded.Count}");
        TestContext.Progress.WriteLine($"tuning evidence, 20 replications: {reached} of {bounded.Count} runs within the bound reach 75 % on every pair at confidence {TuningEvidence.Confidence:F4}");
        // The same runs tuned on the fitted JND itself (confidence 0.5) land on 75 % as a coin flip: far more of the
        // observers whose strength is tuned (not at the lower bound) fall short. The bound is needed, not decoration.
        var point = Replications(0.5).SelectMany(r => r).Where(r => r.Reached && r.CueStrength > WeightSolver.MinCueStrength).ToList();
        int pointReached = point.Count(r => r.AfterWorst >= 75);
        Assert.That(pointReached, Is.LessThan(0.8 * point.Count), $"{pointReached} of {point.Count} on the point estimate");
        TestContext.Progress.WriteLine($"tuning evidence, 20 replications: {pointReached} of {point.Count} tuned runs reach 75 % on every pair on the fitted JND itself");
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
