using FsCheck;
using FsCheck.Fluent;
using Kosmos.PseudoHaptic.Evaluation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Properties.Tests;

/// <summary>
/// Metamorphic properties of the study kit's statistics (evaluation.md, 8): what a change of unit, a mirror or a reordering
/// of the data must do to the result, over generated data sets.
/// </summary>
[TestFixture]
public class EvaluationProperties
{
    /// <summary>A 2AFC data set: 4–9 increasing levels (evenly spaced or not), 3–32 trials each, any count judged heavier,
    /// fitted under a lapse of 0 to 0.1.</summary>
    public sealed class Answers
    {
        public double[] Levels = { };
        public int[] Trials = { }, Heavier = { };
        public double Lapse;

        public StimulusLevel[] Data(Func<double, double> level, bool mirror = false)
            => Levels.Select((x, i) => new StimulusLevel(level(x), Trials[i], mirror ? Trials[i] - Heavier[i] : Heavier[i])).ToArray();

        public override string ToString() => $"lapse {Lapse}: " + string.Join(", ", Levels.Select((x, i) => $"{Heavier[i]}/{Trials[i]} at {x:R}"));

        public static Arbitrary<Answers> Arbitrary()
        {
            var gen =
                from m in Gen.Choose(4, 9)
                from steps in Gen.ArrayOf(Gen.Frequency((3, Gen.Constant(10)), (1, Gen.Choose(1, 40))), m)
                from start in Gen.Choose(50, 150)
                from trials in Gen.ArrayOf(Gen.Choose(3, 32), m)
                from shares in Gen.ArrayOf(Gen.Choose(0, 1000), m)
                from lapse in Gen.Elements(0.0, 0.0, 0.02, 0.05, 0.1)
                select new Answers
                {
                    Levels = Enumerable.Range(0, m).Select(i => (start + steps.Take(i).Sum()) / 100.0).ToArray(),
                    Trials = trials,
                    Heavier = trials.Select((n, i) => (int)Math.Round(n * shares[i] / 1000.0)).ToArray(),
                    Lapse = lapse,
                };
            return Arb.From(gen, Shrink);
        }

        // Fewer heavier answers or trials at one level at a time: a smaller data set that may still fail.
        static IEnumerable<Answers> Shrink(Answers a)
        {
            for (int i = 0; i < a.Levels.Length; i++)
            {
                int at = i;
                if (a.Trials[i] > 3) yield return a.With(x => { x.Trials[at] = Math.Max(3, a.Trials[at] / 2); x.Heavier[at] = Math.Min(x.Heavier[at], x.Trials[at]); });
                if (a.Heavier[i] > 0) yield return a.With(x => x.Heavier[at]--);
            }
            if (a.Lapse != 0) yield return a.With(x => x.Lapse = 0);
        }

        Answers With(Action<Answers> change)
        {
            var c = new Answers { Levels = (double[])Levels.Clone(), Trials = (int[])Trials.Clone(), Heavier = (int[])Heavier.Clone(), Lapse = Lapse };
            change(c);
            return c;
        }
    }

    static readonly (double Scale, double Shift)[] Units = { (1000, 0), (0.001, 0), (1, -100), (7.5, 3.25), (0.1, 250) };

    /// <summary>
    /// The fit does not depend on the unit of the levels: with levels c·x + d (grams for kilograms, a shifted origin) the
    /// verdict is the same (estimable, a step, decreasing, …) and the curve is the same maximum of the likelihood: the moved
    /// fit's curve, taken back to the original unit (μ' − d)/c, σ'/c, is as likely on the original data as the original
    /// fit, and the original fit's curve taken to the new unit is as likely on the moved data, to 1e-9 of the
    /// log-likelihood. (μ and σ themselves agree only as well as a flat maximum locates them: with lapses, where the
    /// likelihood barely curves along a ridge, two fits of one data set in different units were found 1.8e-5 of the levels'
    /// spread apart with log-likelihoods equal to the last digits: PSEUDOHAPTIC_PROPERTY_SEED=2, PSEUDOHAPTIC_PROPERTY_SCALE=10.)
    /// </summary>
    [Test]
    public void TheFitDoesNotDependOnTheLevelsUnit() => Checks.Hold(Answers.Arbitrary(), a =>
    {
        var data = a.Data(x => x);
        var fit = PsychometricFit.Fit(data, a.Lapse);
        foreach (var (c, d) in Units)
        {
            var movedData = a.Data(x => c * x + d);
            var moved = PsychometricFit.Fit(movedData, a.Lapse);
            string unit = $" in the unit ×{c} + {d}";
            Expect.That(moved.Reason == fit.Reason, "verdict" + unit + ": '" + moved.Reason + "' against '" + fit.Reason + "'");
            if (!fit.Estimable) continue;
            SameMaximum(LogLikelihood(data, (moved.Mu - d) / c, moved.Sigma / c, a.Lapse), fit.LogLikelihood, "the moved fit's curve on the data" + unit);
            SameMaximum(LogLikelihood(movedData, c * fit.Mu + d, c * fit.Sigma, a.Lapse), moved.LogLikelihood, "the fit's curve on the moved data" + unit);
        }
    }, 200);

    /// <summary>
    /// Ψ with γ = λ is symmetric (Ψ(μ − t) = 1 − Ψ(μ + t)), so the mirrored data set (levels −x, answers n − k) is fitted by
    /// the mirrored curve: a step stays a step and a decreasing set stays decreasing, and the curve (−μ', σ') of the
    /// mirrored fit is as likely on the data as the fit itself, and the fit's (−μ, σ) on the mirrored data as the mirrored
    /// fit, to 1e-9 of the log-likelihood.
    /// </summary>
    [Test]
    public void MirroredAnswersGiveTheMirroredFit() => Checks.Hold(Answers.Arbitrary(), a =>
    {
        var data = a.Data(x => x);
        var mirroredData = a.Data(x => -x, mirror: true);
        var fit = PsychometricFit.Fit(data, a.Lapse);
        var mirrored = PsychometricFit.Fit(mirroredData, a.Lapse);
        Expect.That(mirrored.Reason == fit.Reason, "verdict: '" + mirrored.Reason + "' against '" + fit.Reason + "'");
        if (!fit.Estimable) return;
        SameMaximum(LogLikelihood(data, -mirrored.Mu, mirrored.Sigma, a.Lapse), fit.LogLikelihood, "the mirrored fit's curve on the data");
        SameMaximum(LogLikelihood(mirroredData, -fit.Mu, fit.Sigma, a.Lapse), mirrored.LogLikelihood, "the fit's curve on the mirrored data");
    }, 200);

    /// <summary>ℓ(μ, σ) = Σ k·ln Ψ + (n − k)·ln(1 − Ψ), Ψ = γ + (1 − 2γ)·Φ((x − μ)/σ), in the levels' own unit.</summary>
    static double LogLikelihood(IEnumerable<StimulusLevel> data, double mu, double sigma, double lapse)
    {
        double ll = 0;
        foreach (var l in data)
        {
            double z = (l.Level - mu) / sigma;
            if (l.Heavier > 0) ll += l.Heavier * Math.Log(lapse + (1 - 2 * lapse) * Normal.Cdf(z));
            if (l.Trials > l.Heavier) ll += (l.Trials - l.Heavier) * Math.Log(lapse + (1 - 2 * lapse) * Normal.UpperTail(z));
        }
        return ll;
    }

    /// <summary>A curve as likely as the fit's maximum: within 1e-9 of it (both ways: a likelier one is another maximum).</summary>
    static void SameMaximum(double ll, double maximum, string what)
        => Expect.AtMost(Math.Abs(ll - maximum), 1e-9 * (1 + Math.Abs(maximum)), what + $", log-likelihood {ll:R} against the maximum {maximum:R}");

    /// <summary>
    /// Without lapses the probit likelihood is concave, so the fit is its global maximum: no curve is likelier, computed
    /// here in the levels' own unit from Ψ, neither far from the fit (μ from two spreads below the levels to three above,
    /// σ from 1/100 to 10 spreads) nor near it (μ and ln σ moved by 10⁻⁶ to 10⁻¹, where an ascent stopped short of the
    /// maximum would be beaten).
    /// </summary>
    [Test]
    public void WithoutLapsesNoCurveIsLikelierThanTheFit()
    {
        var far = Gen.Zip(Gen.Choose(-200, 300), Gen.Choose(0, 300)).Select(p => (Near: false, M: p.Item1 / 100.0, S: p.Item2 / 100.0 - 2));
        var near = from dm in Gen.Choose(-1000, 1000)
                   from ds in Gen.Choose(-1000, 1000)
                   from exponent in Gen.Choose(1, 5)
                   select (Near: true, M: dm / 1000.0 * Math.Pow(10, -exponent), S: ds / 1000.0 * Math.Pow(10, -exponent));
        var gen = from a in Answers.Arbitrary().Generator
                  from points in Gen.ArrayOf(Gen.OneOf(far, near), 30)
                  select (Answers: a, Points: points);
        Checks.Hold(Arb.From(gen), c =>
        {
            var a = c.Answers;
            var data = a.Data(x => x);
            var fit = PsychometricFit.Fit(data, 0);
            if (!fit.Estimable) return;
            double low = a.Levels[0], spread = a.Levels[^1] - low;
            foreach (var (isNear, m, s) in c.Points)
            {
                double mu = isNear ? fit.Mu + m * spread : low + m * spread;
                double sigma = isNear ? fit.Sigma * Math.Exp(s) : spread * Math.Pow(10, s);
                double ll = LogLikelihood(data, mu, sigma, 0);
                Expect.AtMost(ll, fit.LogLikelihood + 1e-9 * (1 + Math.Abs(fit.LogLikelihood)), $"log-likelihood at μ {mu:R}, σ {sigma:R} against the fit's");
            }
        }, 200);
    }

    /// <summary>Scores of n participants under two conditions: whole numbers, as questionnaire sums and Likert items are.</summary>
    static Arbitrary<(int[] A, int[] B, int Shift, int[] Order)> PairedScores()
    {
        var gen =
            from n in Gen.Choose(2, 40)
            from a in Gen.ArrayOf(Gen.Choose(1, 7), n)
            from b in Gen.ArrayOf(Gen.Choose(1, 7), n)
            from shift in Gen.Choose(-50, 50)
            from order in Gen.Shuffle(Enumerable.Range(0, n).ToArray())
            select (a, b, shift, order);
        return Arb.From(gen);
    }

    /// <summary>
    /// The paired comparison is about the differences: swapping the conditions negates the mean difference, t, d_z, z and r
    /// and keeps both p-values; adding the same whole number to every score, or listing the participants in another order,
    /// changes nothing.
    /// </summary>
    [Test]
    public void APairedComparisonDependsOnlyOnTheDifferences() => Checks.Hold(PairedScores(), s =>
    {
        double[] a = s.A.Select(v => (double)v).ToArray(), b = s.B.Select(v => (double)v).ToArray();
        var r = PairedComparison.Compute(a, b);
        var swapped = PairedComparison.Compute(b, a);
        Same(swapped.MeanDifference, -r.MeanDifference, "mean difference, swapped");
        Same(swapped.T, -r.T, "t, swapped"); Same(swapped.TP, r.TP, "p of t, swapped");
        Same(swapped.Dz, -r.Dz, "d_z, swapped"); Same(swapped.WP, r.WP, "p of W, swapped");
        Same(swapped.Z, -r.Z, "z, swapped"); Same(swapped.R, -r.R, "r, swapped");
        var shifted = PairedComparison.Compute(a.Select(v => v + s.Shift).ToArray(), b.Select(v => v + s.Shift).ToArray());
        var reordered = PairedComparison.Compute(s.Order.Select(i => a[i]).ToArray(), s.Order.Select(i => b[i]).ToArray());
        foreach (var (other, how) in new[] { (shifted, "shifted by " + s.Shift), (reordered, "reordered") })
        {
            Same(other.MeanDifference, r.MeanDifference, "mean difference, " + how); Same(other.T, r.T, "t, " + how);
            Same(other.TP, r.TP, "p of t, " + how); Same(other.W, r.W, "W, " + how); Same(other.WP, r.WP, "p of W, " + how);
            Same(other.Z, r.Z, "z, " + how); Same(other.DifferenceLow, r.DifferenceLow, "interval, " + how);
        }
    }, 300);

    /// <summary>
    /// Scores given to one decimal (means of ten items, as the questionnaires' are) compare as the same scores in tenths:
    /// W, its p, z, r and the count of non-zero differences are those of the whole numbers, which the subtraction leaves
    /// exact; t and its p to rounding (10⁻¹²).
    /// </summary>
    [Test]
    public void ScoresInTenthsCompareAsTheSameScoresInWholeNumbers() => Checks.Hold(PairedScores(), s =>
    {
        double[] a = s.A.Select(v => (double)v).ToArray(), b = s.B.Select(v => (double)v).ToArray();
        var whole = PairedComparison.Compute(a, b);
        // Tenths of a scale from 1 to 7 with its shift: 0.1·(score + shift) as a parser reads "3.4".
        double[] Tenths(int[] v) => v.Select(x => double.Parse((0.1m * (x + s.Shift)).ToString(System.Globalization.CultureInfo.InvariantCulture), System.Globalization.CultureInfo.InvariantCulture)).ToArray();
        var tenths = PairedComparison.Compute(Tenths(s.A), Tenths(s.B));
        Expect.That(tenths.NonZero == whole.NonZero, $"non-zero differences {tenths.NonZero} in tenths, {whole.NonZero} whole");
        Expect.That(tenths.HasTies == whole.HasTies && tenths.WilcoxonExact == whole.WilcoxonExact, "ties and method in tenths as whole");
        Same(tenths.W, whole.W, "W in tenths"); Same(tenths.WP, whole.WP, "p of W in tenths");
        Same(tenths.Z, whole.Z, "z in tenths"); Same(tenths.R, whole.R, "r in tenths");
        Same(tenths.T, whole.T, "t in tenths"); Same(tenths.TP, whole.TP, "p of t in tenths");
    }, 300);

    /// <summary>Friedman's test ranks within each participant: listing the participants or the conditions in another
    /// order changes neither the statistic nor p.</summary>
    [Test]
    public void FriedmansTestDoesNotDependOnTheOrderOfRowsOrConditions()
    {
        var gen =
            from n in Gen.Choose(2, 30)
            from k in Gen.Choose(2, 6)
            from rows in Gen.ArrayOf(Gen.ArrayOf(Gen.Choose(1, 7), k), n)
            from rowOrder in Gen.Shuffle(Enumerable.Range(0, n).ToArray())
            from columnOrder in Gen.Shuffle(Enumerable.Range(0, k).ToArray())
            select (Rows: rows, RowOrder: rowOrder, ColumnOrder: columnOrder);
        Checks.Hold(Arb.From(gen), c =>
        {
            IReadOnlyList<IReadOnlyList<double>> Table(IEnumerable<int[]> rows, int[] columns)
                => rows.Select(r => (IReadOnlyList<double>)columns.Select(j => (double)r[j]).ToArray()).ToArray();
            var identity = Enumerable.Range(0, c.Rows[0].Length).ToArray();
            var f = FriedmanTest.Compute(Table(c.Rows, identity));
            var g = FriedmanTest.Compute(Table(c.RowOrder.Select(i => c.Rows[i]), c.ColumnOrder));
            Same(g.Statistic, f.Statistic, "statistic");
            Same(g.P, f.P, "p");
        }, 300);
    }

    /// <summary>Equal to 1e-12 of the larger magnitude (both NaN counts as equal: a statistic that is undefined for both).</summary>
    static void Same(double actual, double expected, string what)
    {
        if (double.IsNaN(actual) && double.IsNaN(expected)) return;
        Expect.AtMost(Math.Abs(actual - expected), 1e-12 * Math.Max(1, Math.Max(Math.Abs(actual), Math.Abs(expected))), what + $" ({actual:R} against {expected:R})");
    }
}
