using System;
using System.Collections.Generic;
using Kosmos.PseudoHaptic.Evaluation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests.Evaluation
{
    /// <summary>
    /// compare's analysis (<see cref="ConditionComparison"/>, <see cref="ComparisonRow"/>): which rows, in which
    /// order, over which participants, and their statistics against values computed here from the formulas
    /// (rank sums by hand, the signed-rank p by enumerating the sign patterns, Holm by hand, the paired t with
    /// one degree of freedom in closed form).
    /// </summary>
    public class ConditionComparisonTests
    {
        static List<ConditionScore> Scores(params object[] rows)
        {
            // participant, condition, questionnaire, score (double or null), repeated
            var scores = new List<ConditionScore>();
            for (int i = 0; i < rows.Length; i += 4)
                scores.Add(new ConditionScore((string)rows[i], (string)rows[i + 1], (string)rows[i + 2], rows[i + 3] == null ? (double?)null : Convert.ToDouble(rows[i + 3]), i / 4 + 2));
            return scores;
        }

        /// <summary>Two-sided exact signed-rank p from all 2^N sign patterns of the ranks 1 … N (no ties).</summary>
        static double EnumeratedSignedRankP(IReadOnlyList<double> d)
        {
            var nonZero = new List<double>();
            foreach (double v in d) if (v != 0) nonZero.Add(v);
            int n = nonZero.Count;
            var abs = nonZero.ConvertAll(Math.Abs);
            abs.Sort();
            double w = 0;
            foreach (double v in nonZero) if (v > 0) w += abs.IndexOf(Math.Abs(v)) + 1;
            int below = 0, above = 0, total = 1 << n;
            for (int mask = 0; mask < total; mask++)
            {
                int s = 0;
                for (int r = 1; r <= n; r++) if ((mask & (1 << (r - 1))) != 0) s += r;
                if (s <= w) below++;
                if (s >= w) above++;
            }
            return Math.Min(1, 2.0 * Math.Min(below, above) / total);
        }

        static double[] Differences(ComparisonRow row)
        {
            var d = new double[row.A.Count];
            for (int i = 0; i < d.Length; i++) d[i] = row.B[i] - row.A[i];
            return d;
        }

        // Four participants complete in A, B and C (P10 first in the file, to be sorted last); P9 has no C.
        static List<ConditionScore> ThreeConditions() => Scores(
            "P10", "A", "SUS", 3.0, "P10", "B", "SUS", 3.9, "P10", "C", "SUS", 2.4,
            "P1", "A", "SUS", 1.0, "P1", "B", "SUS", 2.1, "P1", "C", "SUS", 3.5,
            "P2", "A", "SUS", 2.0, "P2", "B", "SUS", 4.3, "P2", "C", "SUS", 3.1,
            "P3", "A", "SUS", 5.0, "P3", "B", "SUS", 5.4, "P3", "C", "SUS", 7.8,
            "P9", "A", "SUS", 1.0, "P9", "B", "SUS", 1.7, "P9", "C", "SUS", null);

        [Test]
        public void NullScoresAreRefused()
        {
            var e = Assert.Throws<ArgumentNullException>(() => ConditionComparison.Compare(null));
            Assert.That(e.ParamName, Is.EqualTo("scores"));
        }

        [Test]
        public void NoScoresAreNoRows()
        {
            Assert.That(ConditionComparison.Compare(new ConditionScore[0]), Is.Empty);
        }

        [Test]
        public void ThreeConditionsGiveFriedmanFirstThenEveryPairInFileOrder()
        {
            var rows = ConditionComparison.Compare(ThreeConditions());
            Assert.That(rows.Count, Is.EqualTo(4));
            var f = rows[0];
            Assert.That(f.Questionnaire, Is.EqualTo("SUS"));
            Assert.That(f.ConditionA, Is.EqualTo("*"));
            Assert.That(f.ConditionB, Is.EqualTo("*"));
            Assert.That(f.Pair, Is.Null);
            Assert.That(f.Participants, Is.Empty);
            Assert.That(f.A, Is.Empty);
            Assert.That(f.B, Is.Empty);
            Assert.That(f.PHolm, Is.NaN, "Holm is over the pairs only");
            Assert.That(f.Method, Is.EqualTo("friedman"));
            Assert.That(f.Friedman.N, Is.EqualTo(4), "P9 has no C: not complete");
            Assert.That(f.Friedman.K, Is.EqualTo(3));
            // Ranks within participants (A, B, C): P10 2 3 1, P1 1 2 3, P2 1 3 2, P3 1 2 3: sums 5, 10, 9.
            double chi = 12.0 / (4 * 3 * 4) * (5 * 5 + 10 * 10 + 9 * 9) - 3 * 4 * 4;
            Assert.That(chi, Is.EqualTo(3.5).Within(1e-12));
            Assert.That(f.Friedman.Statistic, Is.EqualTo(chi).Within(1e-12));
            Assert.That(f.Friedman.P, Is.EqualTo(Math.Exp(-chi / 2)).Within(1e-12), "χ² with 2 degrees of freedom: p = e^(−χ²/2)");

            Assert.That(new[] { rows[1].ConditionA, rows[1].ConditionB, rows[2].ConditionA, rows[2].ConditionB, rows[3].ConditionA, rows[3].ConditionB },
                Is.EqualTo(new[] { "A", "B", "A", "C", "B", "C" }));
            foreach (var r in new[] { rows[1], rows[2], rows[3] })
            {
                Assert.That(r.Questionnaire, Is.EqualTo("SUS"));
                Assert.That(r.Friedman, Is.Null);
                Assert.That(r.Method, Is.EqualTo("t+wilcoxon-exact"));
            }

            var ab = rows[1];
            Assert.That(ab.Participants, Is.EqualTo(new[] { "P1", "P2", "P3", "P9", "P10" }), "in participant order, P9 included");
            Assert.That(ab.A, Is.EqualTo(new[] { 1.0, 2.0, 5.0, 1.0, 3.0 }));
            Assert.That(ab.B, Is.EqualTo(new[] { 2.1, 4.3, 5.4, 1.7, 3.9 }));
            Assert.That(rows[2].Participants, Is.EqualTo(new[] { "P1", "P2", "P3", "P10" }), "P9 has no C");
            Assert.That(rows[2].A, Is.EqualTo(new[] { 1.0, 2.0, 5.0, 3.0 }));
            Assert.That(rows[2].B, Is.EqualTo(new[] { 3.5, 3.1, 7.8, 2.4 }));
            Assert.That(rows[3].A, Is.EqualTo(new[] { 2.1, 4.3, 5.4, 3.9 }));
            Assert.That(rows[3].B, Is.EqualTo(new[] { 3.5, 3.1, 7.8, 2.4 }));

            // The paired t of b − a from its formula.
            double[] d = Differences(ab);
            double mean = 0;
            foreach (double v in d) mean += v;
            mean /= d.Length;
            double ss = 0;
            foreach (double v in d) ss += (v - mean) * (v - mean);
            double sd = Math.Sqrt(ss / (d.Length - 1));
            Assert.That(ab.Pair.N, Is.EqualTo(5));
            Assert.That(ab.Pair.MeanDifference, Is.EqualTo(1.08).Within(1e-12), "b − a, not a − b");
            Assert.That(ab.Pair.T, Is.EqualTo(mean / (sd / Math.Sqrt(5))).Within(1e-12));

            // Signed ranks: all five differences positive (W = 15, p = 2/32); A–C: W = 9 of 4 (p = 4/16); B–C: W = 6 of 4 (p = 14/16).
            Assert.That(EnumeratedSignedRankP(Differences(rows[1])), Is.EqualTo(0.0625));
            Assert.That(EnumeratedSignedRankP(Differences(rows[2])), Is.EqualTo(0.25));
            Assert.That(EnumeratedSignedRankP(Differences(rows[3])), Is.EqualTo(0.875));
            Assert.That(rows[1].Pair.W, Is.EqualTo(15));
            Assert.That(rows[2].Pair.W, Is.EqualTo(9));
            Assert.That(rows[3].Pair.W, Is.EqualTo(6));
            Assert.That(rows[1].Pair.WP, Is.EqualTo(0.0625).Within(1e-15));
            Assert.That(rows[2].Pair.WP, Is.EqualTo(0.25).Within(1e-15));
            Assert.That(rows[3].Pair.WP, Is.EqualTo(0.875).Within(1e-15));
            // Holm over the three: 3 × 0.0625, max(that, 2 × 0.25), max(that, 1 × 0.875).
            Assert.That(rows[1].PHolm, Is.EqualTo(0.1875).Within(1e-15));
            Assert.That(rows[2].PHolm, Is.EqualTo(0.5).Within(1e-15));
            Assert.That(rows[3].PHolm, Is.EqualTo(0.875).Within(1e-15));
        }

        [Test]
        public void HolmKeepsTheAdjustedPsMonotone()
        {
            // A–B: all five up (p = 2/32); A–C: W = 13, the rank-2 difference down (p = 6/32); B–C: all five
            // down (p = 2/32). Sorted: 3 × 2/32 = 0.1875, then 2 × 2/32 = 0.125 lifted to 0.1875 by the running
            // maximum, then 1 × 6/32 = 0.1875.
            var rows = ConditionComparison.Compare(Scores(
                "P1", "A", "Q", 0, "P1", "B", "Q", 1, "P1", "C", "Q", 0.1,
                "P2", "A", "Q", 0, "P2", "B", "Q", 2, "P2", "C", "Q", -0.2,
                "P3", "A", "Q", 0, "P3", "B", "Q", 3, "P3", "C", "Q", 0.3,
                "P4", "A", "Q", 0, "P4", "B", "Q", 4, "P4", "C", "Q", 0.4,
                "P5", "A", "Q", 0, "P5", "B", "Q", 5, "P5", "C", "Q", 0.5));
            Assert.That(rows.Count, Is.EqualTo(4));
            double[] p = { EnumeratedSignedRankP(Differences(rows[1])), EnumeratedSignedRankP(Differences(rows[2])), EnumeratedSignedRankP(Differences(rows[3])) };
            for (int i = 0; i < 3; i++) Assert.That(rows[i + 1].Pair.WP, Is.EqualTo(p[i]).Within(1e-15));
            // Holm by hand from the enumerated ps.
            var order = new List<int> { 0, 1, 2 };
            order.Sort((x, y) => p[x] != p[y] ? p[x].CompareTo(p[y]) : x.CompareTo(y));
            var expected = new double[3];
            double running = 0;
            for (int j = 0; j < 3; j++)
            {
                running = Math.Max(running, Math.Min(1, (3 - j) * p[order[j]]));
                expected[order[j]] = running;
            }
            for (int i = 0; i < 3; i++) Assert.That(rows[i + 1].PHolm, Is.EqualTo(expected[i]).Within(1e-15), "pair " + i);
            Assert.That(p, Is.EqualTo(new[] { 0.0625, 0.1875, 0.0625 }));
            Assert.That(new[] { rows[1].PHolm, rows[2].PHolm, rows[3].PHolm }, Is.EqualTo(new[] { 0.1875, 0.1875, 0.1875 }).Within(1e-15));
        }

        [Test]
        public void TwoConditionsGiveOnePairWithItsOwnP()
        {
            // d = 1, 3: mean 2, s = √2, t = 2 with 1 degree of freedom (Cauchy: p = 1 − (2/π)·atan 2).
            var rows = ConditionComparison.Compare(Scores("P1", "off", "SUS", 1, "P1", "on", "SUS", 2, "P2", "off", "SUS", 2, "P2", "on", "SUS", 5));
            Assert.That(rows.Count, Is.EqualTo(1), "no Friedman row with two conditions");
            var r = rows[0];
            Assert.That(r.Friedman, Is.Null);
            Assert.That(r.ConditionA, Is.EqualTo("off"));
            Assert.That(r.ConditionB, Is.EqualTo("on"));
            Assert.That(r.Pair.MeanDifference, Is.EqualTo(2.0));
            Assert.That(r.Pair.T, Is.EqualTo(2.0).Within(1e-12));
            Assert.That(r.Pair.TP, Is.EqualTo(1 - 2 / Math.PI * Math.Atan(2)).Within(1e-9));
            double crit = Math.Tan(Math.PI * (0.975 - 0.5));
            Assert.That(r.Pair.DifferenceLow, Is.EqualTo(2 - crit).Within(1e-7));
            Assert.That(r.Pair.DifferenceHigh, Is.EqualTo(2 + crit).Within(1e-7));
            Assert.That(r.Pair.WP, Is.EqualTo(0.5), "W = 3 of 2: 2 × 1/4");
            Assert.That(r.PHolm, Is.EqualTo(r.Pair.WP), "a single pair's p unchanged");
            Assert.That(r.Method, Is.EqualTo("t+wilcoxon-exact"));
        }

        [Test]
        public void QuestionnairesInFileOrderConditionsInTheFilesOrderAndSingleConditionsSkipped()
        {
            var rows = ConditionComparison.Compare(Scores(
                "P1", "A", "IPQ", 1,
                "P1", "B", "SUS", 2,
                "P1", "A", "SUS", 3,
                "P2", "B", "SUS", 5,
                "P2", "A", "SUS", 4,
                "P1", "C", "NASA", 1,
                "P2", "B", "IPQ", 3,
                "P1", "B", "IPQ", 2,
                "P2", "A", "IPQ", 1));
            Assert.That(rows.Count, Is.EqualTo(2), "NASA has one condition: no row");
            Assert.That(rows[0].Questionnaire, Is.EqualTo("IPQ"));
            Assert.That(rows[1].Questionnaire, Is.EqualTo("SUS"));
            Assert.That(rows[1].ConditionA, Is.EqualTo("A"), "A is first in the file, though SUS names B first");
            Assert.That(rows[1].ConditionB, Is.EqualTo("B"));
            Assert.That(rows[0].Participants, Is.EqualTo(new[] { "P1", "P2" }));
            Assert.That(rows[0].A, Is.EqualTo(new[] { 1.0, 1.0 }));
            Assert.That(rows[0].B, Is.EqualTo(new[] { 2.0, 3.0 }));
            Assert.That(rows[1].A, Is.EqualTo(new[] { 3.0, 4.0 }));
            Assert.That(rows[1].B, Is.EqualTo(new[] { 2.0, 5.0 }));
        }

        [Test]
        public void TheMethodSaysWhatCouldBeComputed()
        {
            Assert.That(PairMethod(1, 2, 1, 3), Is.EqualTo("t+wilcoxon-exact"), "d = 1, 2");
            Assert.That(PairMethod(0, 1, 0, -1, 0, 2), Is.EqualTo("t+wilcoxon-normal"), "|d| tied: 1, 1, 2");
            Assert.That(PairMethod(0, 2), Is.EqualTo("wilcoxon-exact"), "one pair: no t");
            Assert.That(PairMethod(0, 1, 0, 1), Is.EqualTo("wilcoxon-normal"), "d = 1, 1: no t, tied ranks");
            Assert.That(PairMethod(1, 1, 2, 2), Is.EqualTo("none"), "all differences zero");
            var none = ConditionComparison.Compare(Scores("P1", "A", "Q", 1, "P2", "B", "Q", 2));
            Assert.That(none.Count, Is.EqualTo(1));
            Assert.That(none[0].Pair.N, Is.EqualTo(0), "nobody has both");
            Assert.That(none[0].Participants, Is.Empty);
            Assert.That(none[0].Method, Is.EqualTo("none"));
            Assert.That(none[0].PHolm, Is.NaN);
        }

        static string PairMethod(params double[] ab)
        {
            var args = new List<object>();
            for (int i = 0; i < ab.Length; i += 2)
            {
                string p = "P" + (i / 2 + 1);
                args.AddRange(new object[] { p, "A", "Q", ab[i], p, "B", "Q", ab[i + 1] });
            }
            var rows = ConditionComparison.Compare(Scores(args.ToArray()));
            Assert.That(rows.Count, Is.EqualTo(1));
            return rows[0].Method;
        }

        [Test]
        public void FriedmanIsUndefinedWhenAllTiedOrNobodyIsComplete()
        {
            var tied = ConditionComparison.Compare(Scores(
                "P1", "A", "Q", 1, "P1", "B", "Q", 1, "P1", "C", "Q", 1,
                "P2", "A", "Q", 2, "P2", "B", "Q", 2, "P2", "C", "Q", 2));
            Assert.That(tied[0].Friedman.N, Is.EqualTo(2));
            Assert.That(tied[0].Friedman.Statistic, Is.NaN);
            Assert.That(tied[0].Method, Is.EqualTo("friedman-undefined"));
            var incomplete = ConditionComparison.Compare(Scores(
                "P1", "A", "Q", 1, "P1", "B", "Q", 2, "P1", "C", "Q", null,
                "P2", "A", "Q", 2, "P2", "C", "Q", 3));
            Assert.That(incomplete.Count, Is.EqualTo(4));
            Assert.That(incomplete[0].Friedman.N, Is.EqualTo(0));
            Assert.That(incomplete[0].Method, Is.EqualTo("friedman-undefined"));
            Assert.That(incomplete[1].Participants, Is.EqualTo(new[] { "P1" }), "A–B");
            Assert.That(incomplete[2].Participants, Is.EqualTo(new[] { "P2" }), "A–C: P1's empty C does not count");
            Assert.That(incomplete[3].Participants, Is.Empty, "B–C");
            Assert.That(incomplete[3].PHolm, Is.NaN, "an undefined p stays undefined");
            // Holm over the two defined ps (each 1): m = 2.
            Assert.That(incomplete[1].PHolm, Is.EqualTo(1.0));
            Assert.That(incomplete[2].PHolm, Is.EqualTo(1.0));
        }
    }
}
