using System;
using System.Collections.Generic;
using System.Linq;
using Kosmos.PseudoHaptic.Evaluation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests.Evaluation
{
    /// <summary>
    /// Paired t, Wilcoxon signed-rank, Friedman and Holm against published R output, brute-force
    /// enumeration and numerical integration; trial plans and the staircase with simulated observers.
    /// </summary>
    public class ComparisonTestsTests
    {
        // R's ?wilcox.test example (Hollander and Wolfe 1973, p. 29): depression scale before (y) and after (x).
        internal static readonly double[] X = { 1.83, 0.50, 1.62, 2.48, 1.68, 1.88, 1.55, 3.06, 1.30 };
        internal static readonly double[] Y = { 0.878, 0.647, 0.598, 2.05, 1.06, 1.29, 1.06, 3.14, 1.29 };

        /// <summary>P(T &gt; t) by Simpson's rule on the t density: independent of the incomplete beta.</summary>
        static double TTailBySimpson(double t, int df)
        {
            double logC = StudentTLogGamma((df + 1) / 2.0) - StudentTLogGamma(df / 2.0) - 0.5 * Math.Log(df * Math.PI);
            Func<double, double> f = u => Math.Exp(logC - (df + 1) / 2.0 * Math.Log(1 + u * u / df));
            // ∫_0^t f, then ½ − that; 200000 panels.
            int m = 200000;
            double h = t / m, sum = f(0) + f(t);
            for (int i = 1; i < m; i++) sum += f(i * h) * (i % 2 == 1 ? 4 : 2);
            return 0.5 - sum * h / 3;
        }

        static double StudentTLogGamma(double x)
        {
            // ln Γ for half-integers and integers, exactly by recurrence.
            double r = 0;
            while (x > 1) { x -= 1; r += Math.Log(x); }
            return r + (Math.Abs(x - 0.5) < 1e-12 ? 0.5 * Math.Log(Math.PI) : 0);
        }

        [Test]
        public void WilcoxonMatchesRsExample()
        {
            var c = PairedComparison.Compute(Y, X); // b − a = x − y, as wilcox.test(x, y, paired = TRUE)
            Assert.That(c.W, Is.EqualTo(40));
            Assert.That(c.WilcoxonExact, Is.True);
            Assert.That(c.WP, Is.EqualTo(20.0 / 512).Within(1e-15)); // R: p-value = 0.03906
            // Paired t by hand: d̄ and s_d from the differences, p by Simpson integration of the density.
            var d = X.Zip(Y, (x, y) => x - y).ToArray();
            double mean = d.Average();
            double sd = Math.Sqrt(d.Sum(v => (v - mean) * (v - mean)) / 8);
            double t = mean / (sd / 3);
            Assert.That(c.T, Is.EqualTo(t).Within(1e-12 * Math.Abs(t)));
            Assert.That(c.T, Is.EqualTo(3.0353).Within(1e-4)); // R's t.test(x, y, paired = TRUE): t = 3.0353, df = 8
            Assert.That(c.TP, Is.EqualTo(2 * TTailBySimpson(t, 8)).Within(1e-9));
            Assert.That(c.TP, Is.EqualTo(0.01618).Within(1e-5));
            Assert.That(c.Dz, Is.EqualTo(mean / sd).Within(1e-12));
            double half = 2.306004135204166 * sd / 3; // t(0.975, 8)
            Assert.That(c.DifferenceLow, Is.EqualTo(mean - half).Within(1e-9));
            Assert.That(c.DifferenceHigh, Is.EqualTo(mean + half).Within(1e-9));
            // The normal approximation with continuity correction gives r: (40 − 22.5 − 0.5)/√(9·10·19/24).
            double z = (40 - 22.5 - 0.5) / Math.Sqrt(9 * 10 * 19 / 24.0);
            Assert.That(c.Z, Is.EqualTo(z).Within(1e-12));
            Assert.That(c.R, Is.EqualTo(z / 3).Within(1e-12));
        }

        [Test]
        public void ExactWilcoxonMatchesEnumerationOfSignPatterns()
        {
            var rng = new SeededRandom(3);
            for (int trial = 0; trial < 30; trial++)
            {
                int n = 1 + rng.NextInt(14);
                var a = new double[n];
                var b = new double[n];
                for (int i = 0; i < n; i++) { a[i] = rng.NextDouble(); b[i] = a[i] + (rng.NextDouble() - 0.3) * (i + 1); }
                var c = PairedComparison.Compute(a, b);
                Assert.That(c.WilcoxonExact, Is.True);
                // All 2^n sign patterns of the ranks 1 … n.
                int below = 0, above = 0;
                for (int mask = 0; mask < 1 << n; mask++)
                {
                    int s = 0;
                    for (int r = 1; r <= n; r++) if ((mask & (1 << (r - 1))) != 0) s += r;
                    if (s <= c.W) below++;
                    if (s >= c.W) above++;
                }
                double p = Math.Min(1, 2.0 * Math.Min(below, above) / (1 << n));
                Assert.That(c.WP, Is.EqualTo(p).Within(1e-15), "n = " + n);
            }
        }

        [Test]
        public void WilcoxonWithTiesAndZerosUsesTheCorrectedNormalApproximation()
        {
            // d = 0 (dropped), 1, 1, −1, 2, 2, 2, 3: |d| ranks 2,2,2 | 5,5,5 | 7; W = 2+2+5+5+5+7 = 26, N = 7.
            double[] a = { 5, 5, 5, 5, 5, 5, 5, 5 };
            double[] b = { 5, 6, 6, 4, 7, 7, 7, 8 };
            var c = PairedComparison.Compute(a, b);
            Assert.That(c.NonZero, Is.EqualTo(7));
            Assert.That(c.W, Is.EqualTo(26));
            Assert.That(c.WilcoxonExact, Is.False);
            double variance = 7 * 8 * 15 / 24.0 - (24 + 24) / 48.0; // two tie groups of 3: 3³ − 3 = 24 each
            double z = (26 - 14 - 0.5) / Math.Sqrt(variance);
            Assert.That(c.Z, Is.EqualTo(z).Within(1e-12));
            Assert.That(c.WP, Is.EqualTo(2 * Normal.UpperTail(z)).Within(1e-15));
            Assert.That(c.R, Is.EqualTo(z / Math.Sqrt(7)).Within(1e-12));
        }

        [Test]
        public void UndefinedFiguresAreNaNNotCrashes()
        {
            var same = PairedComparison.Compute(new[] { 1.0, 2.0 }, new[] { 1.0, 2.0 });
            Assert.That(double.IsNaN(same.T) && double.IsNaN(same.W) && double.IsNaN(same.WP), Is.True);
            Assert.That(same.MeanDifference, Is.EqualTo(0));
            var one = PairedComparison.Compute(new[] { 1.0 }, new[] { 3.0 });
            Assert.That(double.IsNaN(one.T), Is.True);
            Assert.That(one.W, Is.EqualTo(1));
            Assert.That(one.WP, Is.EqualTo(1));
            var constant = PairedComparison.Compute(new[] { 1.0, 2.0, 3.0 }, new[] { 2.0, 3.0, 4.0 });
            Assert.That(double.IsNaN(constant.T), Is.True, "differences all equal: t undefined");
            var none = PairedComparison.Compute(new double[0], new double[0]);
            Assert.That(none.N, Is.EqualTo(0));
        }

        [Test]
        public void FriedmanMatchesHandComputation()
        {
            // 4 participants × 3 conditions, no ties: ranks (1,2,3) (1,3,2) (1,2,3) (2,1,3): R = 5, 8, 11.
            var rows = new List<IReadOnlyList<double>>
            {
                new[] { 1.0, 2, 3 }, new[] { 1.0, 3, 2 }, new[] { 1.0, 2, 3 }, new[] { 2.0, 1, 3 },
            };
            var f = FriedmanTest.Compute(rows);
            // 12/(n k (k+1)) ΣR² − 3n(k+1) = 12/48·(25+64+121) − 48 = 52.5 − 48 = 4.5; p = e^{−2.25}.
            Assert.That(f.Statistic, Is.EqualTo(4.5).Within(1e-12));
            Assert.That(f.P, Is.EqualTo(Math.Exp(-2.25)).Within(1e-14));
            // With a tie in one row: (1, 2.5, 2.5): R = 4, 8.5, 11.5 hmm — by the formula with correction.
            rows[0] = new[] { 1.0, 2, 2 };
            var g = FriedmanTest.Compute(rows);
            double[] r = { 1 + 1 + 1 + 2, 2.5 + 3 + 2 + 1, 2.5 + 2 + 3 + 3 };
            double num = r.Sum(x => (x - 8) * (x - 8));
            double expected = 12 * num / (4 * 3 * 4 - 6.0 / 2);
            Assert.That(g.Statistic, Is.EqualTo(expected).Within(1e-12));
            Assert.That(g.P, Is.EqualTo(Math.Exp(-expected / 2)).Within(1e-14));
        }

        [Test]
        public void HolmMatchesRsPAdjust()
        {
            // p.adjust(c(0.01, 0.04, 0.03, 0.02, 0.05), "holm") = 0.05 0.09 0.09 0.08 0.09
            var adjusted = Holm.Adjust(new[] { 0.01, 0.04, 0.03, 0.02, 0.05 });
            Assert.That(adjusted, Is.EqualTo(new[] { 0.05, 0.09, 0.09, 0.08, 0.09 }).Within(1e-15));
            var withNaN = Holm.Adjust(new[] { 0.2, double.NaN, 0.6 });
            Assert.That(withNaN[0], Is.EqualTo(0.4).Within(1e-15));
            Assert.That(double.IsNaN(withNaN[1]), Is.True);
            Assert.That(withNaN[2], Is.EqualTo(0.6).Within(1e-15));
        }

        [Test]
        public void ConstantStimuliPlanIsCounterbalancedShuffledAndReproducible()
        {
            var plan = new ConstantStimuliPlan { Standard = 1, Levels = new[] { 0.8, 1.0, 1.2 }, Repetitions = 5, CatchLevels = new[] { 0.5, 2.0 }, CatchRepetitions = 2, Seed = 11 };
            var a = plan.Build("P1", "with");
            var b = plan.Build("P1", "with");
            Assert.That(a.Count, Is.EqualTo(3 * 5 + 2 * 2));
            Assert.That(a.Select(t => t.Comparison + "/" + t.ComparisonFirst), Is.EqualTo(b.Select(t => t.Comparison + "/" + t.ComparisonFirst)));
            foreach (double level in new[] { 0.8, 1.0, 1.2 })
            {
                int first = a.Count(t => t.Comparison == level && t.ComparisonFirst);
                Assert.That(first, Is.InRange(2, 3), "counterbalanced within level " + level);
            }
            Assert.That(a.Count(t => t.Catch), Is.EqualTo(4));
            Assert.That(a.Select(t => t.Index), Is.EqualTo(Enumerable.Range(1, a.Count)));
            plan.Seed = 12;
            Assert.That(plan.Build("P1").Select(t => t.Comparison), Is.Not.EqualTo(a.Select(t => t.Comparison)), "another seed, another order");
        }

        /// <summary>Issue 11 item 5: the staircase's threshold lies within one final step of the targeted point on average.</summary>
        [TestCase(2)]
        [TestCase(3)]
        public void StaircaseConvergesOnItsTarget(int down)
        {
            const double pse = 1.05, sigma = 0.1;
            double target = pse + sigma * Normal.Quantile(Math.Pow(0.5, 1.0 / down));
            double sum = 0, finalStep = 0;
            const int runs = 200;
            for (int seed = 0; seed < runs; seed++)
            {
                var observer = new SimulatedObserver(pse, sigma, 100 + seed);
                var s = new Staircase("P", "", 1.0, 1.4, 0.08, down, 14, 8, seed, halvingReversals: 3);
                Trial t;
                while ((t = s.Next()) != null) s.Record(observer.Answer(t.Comparison));
                Assert.That(s.ReversalLevels.Count, Is.EqualTo(14));
                sum += s.Threshold;
                finalStep = s.Step;
            }
            double mean = sum / runs;
            TestContext.WriteLine("1-up-" + down + "-down: mean threshold " + mean + ", target " + target + ", final step " + finalStep);
            Assert.That(finalStep, Is.EqualTo(0.01).Within(1e-12));
            Assert.That(Math.Abs(mean - target), Is.LessThan(finalStep));
        }

        [Test]
        public void StaircaseStepsAndReversalsByHand()
        {
            var s = new Staircase("P", "", 1, 1.2, 0.1, 2, 3, 2, 1, halvingReversals: 1);
            // heavier, heavier → down to 1.1; not → up (reversal at 1.1, step halves to 0.05) → 1.15;
            // heavier, heavier → down (reversal at 1.15) → 1.10; not → up (reversal at 1.10) → stop.
            foreach (int r in new[] { 1, 1, 0, 1, 1, 0 }) s.Record(r);
            Assert.That(s.ReversalLevels, Is.EqualTo(new[] { 1.1, 1.15, 1.1 }).Within(1e-12));
            Assert.That(s.Finished, Is.True);
            Assert.That(s.Next(), Is.Null);
            Assert.That(s.Threshold, Is.EqualTo(1.125).Within(1e-12));
            Assert.Throws<ArgumentOutOfRangeException>(() => new Staircase("P", "", 1, 1, 0.1, 4, 3, 2, 1));
        }
    }
}
