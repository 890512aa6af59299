using System;
using System.Collections.Generic;
using System.Linq;
using Kosmos.PseudoHaptic.Evaluation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests.Evaluation
{
    /// <summary>
    /// The within-participant tests at their edges, beside R's examples in ComparisonTestsTests: the direction of the
    /// comparison (b − a), another confidence, the exact Wilcoxon test's last size and the first beyond it, the continuity
    /// correction either way and at the centre, the threshold below which differences count as all equal, Friedman's
    /// refusals and undefined cases, Holm's cap and equal p-values, and every refused input.
    /// </summary>
    public class PairedTestsContractTests
    {
        // R's ?wilcox.test example: before (a) and after (b).
        static readonly double[] A = ComparisonTestsTests.Y;
        static readonly double[] B = ComparisonTestsTests.X;

        [Test]
        public void SwappingTheConditionsMirrorsEveryFigure()
        {
            var ab = PairedComparison.Compute(A, B);
            var ba = PairedComparison.Compute(B, A);
            Assert.That(ba.N, Is.EqualTo(9));
            Assert.That(ba.MeanDifference, Is.EqualTo(-ab.MeanDifference).Within(1e-15));
            Assert.That(ba.T, Is.EqualTo(-ab.T).Within(1e-12));
            Assert.That(ba.TP, Is.EqualTo(ab.TP).Within(1e-15));
            Assert.That(ba.Dz, Is.EqualTo(-ab.Dz).Within(1e-12));
            Assert.That(ba.DifferenceLow, Is.EqualTo(-ab.DifferenceHigh).Within(1e-12));
            Assert.That(ba.DifferenceHigh, Is.EqualTo(-ab.DifferenceLow).Within(1e-12));
            // W of the swapped pairs is the sum of the other ranks: 45 − 40; the correction is then +½, not −½.
            Assert.That(ba.W, Is.EqualTo(5));
            Assert.That(ba.WP, Is.EqualTo(ab.WP).Within(1e-15));
            double z = (5 - 22.5 + 0.5) / Math.Sqrt(9 * 10 * 19 / 24.0);
            Assert.That(ba.Z, Is.EqualTo(z).Within(1e-12));
            Assert.That(ba.R, Is.EqualTo(z / 3).Within(1e-12));
        }

        [Test]
        public void AnotherConfidenceGivesItsOwnInterval()
        {
            var c = PairedComparison.Compute(A, B, 0.9);
            var d = A.Zip(B, (a, b) => b - a).ToArray();
            double mean = d.Average(), sd = Math.Sqrt(d.Sum(v => (v - mean) * (v - mean)) / 8);
            double half = 1.8595480375308957 * sd / 3; // t(0.95, 8): qt(0.95, 8), from the closed form of the t CDF for even ν
            Assert.That(c.DifferenceLow, Is.EqualTo(mean - half).Within(1e-9));
            Assert.That(c.DifferenceHigh, Is.EqualTo(mean + half).Within(1e-9));
        }

        [Test]
        public void AtTheCentreThereIsNoContinuityCorrection()
        {
            // d = 1, −2, −3, 4 (no ties): ranks 1, 2, 3, 4; W = 1 + 4 = 5 = N(N+1)/4 exactly.
            var c = PairedComparison.Compute(new[] { 0.0, 0, 0, 0 }, new[] { 1.0, -2, -3, 4 });
            Assert.That(c.W, Is.EqualTo(5));
            Assert.That(c.Z, Is.EqualTo(0));
            Assert.That(c.R, Is.EqualTo(0));
            Assert.That(c.WP, Is.EqualTo(1));
            Assert.That(c.TP, Is.EqualTo(1).Within(1e-15), "t = 0: p = 1");
        }

        static PairedComparison Untied(int n, int seed)
        {
            var rng = new SeededRandom(seed);
            var a = new double[n];
            var b = new double[n];
            for (int i = 0; i < n; i++) { a[i] = 0; b[i] = (i + 1) * (rng.NextInt(3) == 0 ? -1 : 1); }
            return PairedComparison.Compute(a, b);
        }

        [Test]
        public void WithTiesTheNormalPIsTwoSidedEitherWay()
        {
            // ComparisonTestsTests' tied example (W = 26 of 28, z > 0) and its mirror (W = 2, z < 0): the same p.
            double[] a = { 5, 5, 5, 5, 5, 5, 5, 5 };
            double[] b = { 5, 6, 6, 4, 7, 7, 7, 8 };
            var up = PairedComparison.Compute(a, b);
            var down = PairedComparison.Compute(b, a);
            Assert.That(up.WilcoxonExact || down.WilcoxonExact, Is.False);
            Assert.That(down.W, Is.EqualTo(2));
            Assert.That(down.Z, Is.EqualTo(-up.Z).Within(1e-15));
            Assert.That(down.WP, Is.EqualTo(up.WP).Within(1e-15));
            Assert.That(down.WP, Is.LessThan(0.05));
        }

        [Test]
        public void TheExactTestRunsToTwentyFiveDifferencesAndTheNormalOneBeyond()
        {
            var at = Untied(PairedComparison.ExactUpTo, 4);
            Assert.That(at.WilcoxonExact, Is.True);
            Assert.That(at.WP, Is.EqualTo(PairedComparison.SignedRankExactTwoSided((int)at.W, 25)).Within(0));
            var beyond = Untied(PairedComparison.ExactUpTo + 1, 4);
            Assert.That(beyond.WilcoxonExact, Is.False);
            Assert.That(beyond.HasTies, Is.False);
            Assert.That(beyond.WP, Is.EqualTo(Math.Min(1, 2 * Normal.UpperTail(Math.Abs(beyond.Z)))).Within(1e-15));
            Assert.That(PairedComparison.ExactUpTo, Is.EqualTo(25));
        }

        [Test]
        public void TheExactPIsTwiceTheSmallerTailCappedAtOne()
        {
            // N = 3: the 8 sign patterns give W = 0, 1, 2, 3, 3, 4, 5, 6.
            Assert.That(PairedComparison.SignedRankExactTwoSided(0, 3), Is.EqualTo(2.0 / 8));
            Assert.That(PairedComparison.SignedRankExactTwoSided(1, 3), Is.EqualTo(4.0 / 8));
            Assert.That(PairedComparison.SignedRankExactTwoSided(2, 3), Is.EqualTo(6.0 / 8));
            Assert.That(PairedComparison.SignedRankExactTwoSided(3, 3), Is.EqualTo(1), "2·5/8, capped");
            Assert.That(PairedComparison.SignedRankExactTwoSided(6, 3), Is.EqualTo(2.0 / 8));
            Assert.That(PairedComparison.SignedRankExactTwoSided(21, 6), Is.EqualTo(2.0 / 64));
        }

        [Test]
        public void DifferencesEqualToTwelveDigitsLeaveTheTTestUndefined()
        {
            // Spread 1e-13 around a mean of 1: below 1e-12 of the mean, the t test is undefined; 1e-11 is a spread.
            var flat = PairedComparison.Compute(new[] { 0.0, 0, 0 }, new[] { 1.0, 1 + 1e-13, 1 - 1e-13 });
            Assert.That(double.IsNaN(flat.T) && double.IsNaN(flat.TP) && double.IsNaN(flat.Dz) && double.IsNaN(flat.DifferenceLow));
            Assert.That(flat.MeanDifference, Is.EqualTo(1).Within(1e-15));
            var spread = PairedComparison.Compute(new[] { 0.0, 0, 0 }, new[] { 1.0, 1 + 1e-11, 1 - 1e-11 });
            Assert.That(double.IsNaN(spread.T), Is.False);
            // Around a mean of 1e6 the same threshold scales: a spread of 1e-8 (1e-14 of it) is still flat.
            var large = PairedComparison.Compute(new[] { 0.0, 0, 0 }, new[] { 1e6, 1e6 + 1e-8, 1e6 - 1e-8 });
            Assert.That(double.IsNaN(large.T));
            // Around zero the threshold is absolute, 1e-12: a spread of 1e-11 is one.
            var small = PairedComparison.Compute(new[] { 0.0, 0, 0 }, new[] { 1e-11, 2e-11, 0 });
            Assert.That(double.IsNaN(small.T), Is.False);
            var tiny = PairedComparison.Compute(new[] { 0.0, 0, 0 }, new[] { 1e-13, 2e-13, 0 });
            Assert.That(double.IsNaN(tiny.T), "a spread of 1e-13 around zero is none");
        }

        [Test]
        public void OneParticipantHasAMeanDifferenceAndNothingElse()
        {
            var c = PairedComparison.Compute(new[] { 2.0 }, new[] { 3.5 });
            Assert.That(c.N, Is.EqualTo(1));
            Assert.That(c.MeanDifference, Is.EqualTo(1.5));
            Assert.That(double.IsNaN(c.T) && double.IsNaN(c.DifferenceLow) && double.IsNaN(c.Dz), Is.True, "the t test needs two differences");
        }

        [Test]
        public void DifferencesThatAreAllZeroHaveNoRanksAndNoTies()
        {
            var c = PairedComparison.Compute(new[] { 1.0, 2.0, 3.0 }, new[] { 1.0, 2.0, 3.0 });
            Assert.That(c.NonZero, Is.Zero);
            Assert.That(c.HasTies, Is.False);
            Assert.That(c.WilcoxonExact, Is.False);
            Assert.That(double.IsNaN(c.W) && double.IsNaN(c.WP), Is.True);
        }

        [Test]
        public void TheIntervalsWidthDoesNotChangeWhenEveryDifferenceIsShiftedFarFromZero()
        {
            // The spread of the differences is the same; only the mean moves (its rounding at 10⁸ costs 3e-10 of the width).
            // A variance summed as Σv² − n·mean², the same number in exact arithmetic, loses every digit there.
            var a = new[] { 0.0, 0.0, 0.0 };
            var near = PairedComparison.Compute(a, new[] { 1.0, 2.0, 4.0 });
            var far = PairedComparison.Compute(a, new[] { 1e8 + 1, 1e8 + 2, 1e8 + 4 }); // a mean of 100000002.33…, not a double
            Assert.That(far.DifferenceHigh - far.DifferenceLow, Is.EqualTo(near.DifferenceHigh - near.DifferenceLow).Within(1e-6).Percent);
            Assert.That(far.MeanDifference - 1e8, Is.EqualTo(near.MeanDifference).Within(1e-8), "to the double nearest 100000002.33…");
        }

        [Test]
        public void BadInputIsRefusedNamingIt()
        {
            Assert.That(Assert.Throws<ArgumentNullException>(() => PairedComparison.Compute(null, new[] { 1.0 })).ParamName, Is.EqualTo("a"));
            Assert.That(Assert.Throws<ArgumentNullException>(() => PairedComparison.Compute(new[] { 1.0 }, null)).ParamName, Is.EqualTo("b"));
            Assert.That(Assert.Throws<ArgumentException>(() => PairedComparison.Compute(new[] { 1.0 }, new[] { 1.0, 2.0 })).Message, Does.StartWith("a and b differ in length"));
            Assert.That(Assert.Throws<ArgumentException>(() => PairedComparison.Compute(new[] { 1.0, 2.0 }, new[] { 1.0, double.NaN })).Message, Does.StartWith("values must be finite"));
            Assert.That(Assert.Throws<ArgumentException>(() => PairedComparison.Compute(new[] { double.NegativeInfinity }, new[] { 1.0 })).Message, Does.StartWith("values must be finite"));
        }

        [Test]
        public void ScoresGivenToADecimalTieWhereTheirDifferencesAreEqual()
        {
            // The worked example's weight-detection scores (evaluation.md §8.5): the differences 1, 1.1, 0.7, 0.3, −0.2, 1,
            // 0.7, 0.2 come out of b − a as 0.2999999999999998, −0.20000000000000018, 0.19999999999999973, …: the two 0.2s
            // share ranks 1 and 2. W = 6.5 + 8 + 4.5 + 3 + 6.5 + 4.5 + 1.5 = 34.5; p from scipy.stats.wilcoxon(
            // method='approx', correction=True) on the differences rounded to 10 decimals (R's wilcox.test on them agrees).
            var a = new[] { 2.8, 2.6, 2.8, 3.2, 3.6, 2.8, 2.9, 3.2 };
            var b = new[] { 3.8, 3.7, 3.5, 3.5, 3.4, 3.8, 3.6, 3.4 };
            var c = PairedComparison.Compute(a, b);
            Assert.That(c.W, Is.EqualTo(34.5));
            Assert.That(c.HasTies, Is.True);
            Assert.That(c.WilcoxonExact, Is.False, "tied: the normal approximation");
            Assert.That(c.WP, Is.EqualTo(0.024529629606437342).Within(1e-12));
            // Tied 0.3s that the exact test would otherwise take for three different sizes.
            c = PairedComparison.Compute(new[] { 2.0, 3.0, 3.1, 3.7, 4.5, 2.8, 2.3, 3.4 }, new[] { 1.7, 3.6, 2.8, 4.2, 4.2, 2.4, 3.0, 3.2 });
            Assert.That(c.HasTies, Is.True);
            Assert.That(c.WilcoxonExact, Is.False);
            // Scores of a thousand: the subtraction's rounding grows with them (0.1999999999999318 and 0.20000000000004547), and
            // so does the resolution (10⁻¹² of the largest |score|, 1.001e-9 here): the 0.2s and the 0.3s tie. W = 2.5 + 2.5 +
            // 4.5 + 6 = 15.5; p from scipy as above (Stryker's survivors PairedTests.cs:137–138 failed it: a resolution of
            // 10⁻¹² ÷ the scale, or of the smaller score of each pair, ties nothing at this size).
            c = PairedComparison.Compute(new[] { 1000.2, 1000.4, 1000.8, 1000.5, 1001.0, 1000.1 }, new[] { 1000.4, 1000.6, 1000.5, 1000.8, 1000.9, 1000.6 });
            Assert.That(c.W, Is.EqualTo(15.5));
            Assert.That(c.WP, Is.EqualTo(0.34278171114791145).Within(1e-12));
            // The resolution follows the largest score, not each pair's smaller one: 1000.41 − 0.01 = 1000.4 and
            // 0.04 − 1000.44 = −1000.4000000000001 tie (ranks 2.5 each; 999.9 ranks 1): W = 2.5 + 1 (the smaller scores,
            // 0.04 at most, would give a resolution of 4e-14, below the 1.1e-13 between them).
            c = PairedComparison.Compute(new[] { 0.01, 1000.44, 0.02 }, new[] { 1000.41, 0.04, 999.92 });
            Assert.That(c.HasTies, Is.True);
            Assert.That(c.W, Is.EqualTo(3.5));
            // A difference that is zero but for the rounding of its scores is dropped: 0.1 + 0.2 against 0.3.
            c = PairedComparison.Compute(new[] { 0.1 + 0.2, 1, 1 }, new[] { 0.3, 2, 3 });
            Assert.That(c.NonZero, Is.EqualTo(2));
            Assert.That(c.W, Is.EqualTo(3));
        }

        [Test]
        public void AverageRanksShareTheirSpanAndCountTheTies()
        {
            double ties;
            var ranks = Ranks.Average(new[] { 3.0, 1.0, 3.0, 2.0, 3.0, 0.5 }, out ties);
            Assert.That(ranks, Is.EqualTo(new[] { 5.0, 2.0, 5.0, 3.0, 5.0, 1.0 }));
            Assert.That(ties, Is.EqualTo(24), "one group of three: 3³ − 3");
            ranks = Ranks.Average(new[] { 2.0, 2.0, 1.0, 1.0 }, out ties);
            Assert.That(ranks, Is.EqualTo(new[] { 3.5, 3.5, 1.5, 1.5 }));
            Assert.That(ties, Is.EqualTo(12));
            // Within a resolution: each next value within it of its group's first joins the group.
            ranks = Ranks.Average(new[] { 0.30000000000000004, 0.2999999999999998, 0.5, 0.3 }, 1e-12, out ties);
            Assert.That(ranks, Is.EqualTo(new[] { 2.0, 2.0, 4.0, 2.0 }));
            Assert.That(ties, Is.EqualTo(24));
            ranks = Ranks.Average(new double[0], out ties);
            Assert.That(ranks, Is.Empty);
            Assert.That(ties, Is.EqualTo(0));
        }

        [Test]
        public void FriedmanWithoutRowsOrWithAllTiedRowsIsUndefined()
        {
            var none = FriedmanTest.Compute(new List<IReadOnlyList<double>>(), 3);
            Assert.That(none.N, Is.EqualTo(0));
            Assert.That(none.K, Is.EqualTo(3));
            Assert.That(none.DegreesOfFreedom, Is.EqualTo(2));
            Assert.That(double.IsNaN(none.Statistic) && double.IsNaN(none.P));
            var tied = FriedmanTest.Compute(new List<IReadOnlyList<double>> { new[] { 1.0, 1, 1 }, new[] { 2.0, 2, 2 } });
            Assert.That(tied.N, Is.EqualTo(2));
            Assert.That(double.IsNaN(tied.Statistic) && double.IsNaN(tied.P));
            var empty = FriedmanTest.Compute(new List<IReadOnlyList<double>>());
            Assert.That(empty.N, Is.EqualTo(0));
            Assert.That(empty.K, Is.EqualTo(0));
        }

        [Test]
        public void FriedmanOfTwoConditionsIsTheSignTestsChiSquare()
        {
            // k = 2, n = 5, the second higher in 4 rows: R = 6, 9 about 7.5; χ² = 12·(2.25 + 2.25)/(5·2·3) = 1.8, ν = 1.
            var rows = new List<IReadOnlyList<double>> { new[] { 1.0, 2 }, new[] { 1.0, 3 }, new[] { 5.0, 4 }, new[] { 0.0, 1 }, new[] { 2.0, 9 } };
            var f = FriedmanTest.Compute(rows);
            Assert.That(f.N, Is.EqualTo(5));
            Assert.That(f.K, Is.EqualTo(2));
            Assert.That(f.DegreesOfFreedom, Is.EqualTo(1));
            Assert.That(f.Statistic, Is.EqualTo(1.8).Within(1e-14));
            Assert.That(f.P, Is.EqualTo(ChiSquare.UpperTail(1.8, 1)).Within(1e-15));
        }

        [Test]
        public void FriedmanRefusesWhatIsNotATable()
        {
            Assert.That(Assert.Throws<ArgumentNullException>(() => FriedmanTest.Compute(null)).ParamName, Is.EqualTo("rows"));
            Assert.That(Assert.Throws<ArgumentNullException>(() => FriedmanTest.Compute(null, 3)).ParamName, Is.EqualTo("rows"));
            var one = Assert.Throws<ArgumentException>(() => FriedmanTest.Compute(new List<IReadOnlyList<double>> { new[] { 1.0 }, new[] { 2.0 } }));
            Assert.That(one.Message, Does.StartWith("need at least two conditions"));
            var ragged = Assert.Throws<ArgumentException>(() => FriedmanTest.Compute(new List<IReadOnlyList<double>> { new[] { 1.0, 2 }, new[] { 2.0, 1, 3 } }));
            Assert.That(ragged.Message, Does.StartWith("rows differ in length"));
        }

        [Test]
        public void HolmCapsAtOneGivesEqualPValuesOneValueAndRefusesNoList()
        {
            Assert.That(Holm.Adjust(new[] { 0.6, 0.7 }), Is.EqualTo(new[] { 1.0, 1.0 }));
            // Equal p-values end at one value, the running maximum, whichever is taken first.
            Assert.That(Holm.Adjust(new[] { 0.02, 0.01, 0.02 }), Is.EqualTo(new[] { 0.04, 0.03, 0.04 }).Within(1e-15));
            Assert.That(Holm.Adjust(new[] { 0.04 }), Is.EqualTo(new[] { 0.04 }));
            Assert.That(Holm.Adjust(new double[0]), Is.Empty);
            // The running maximum: a smaller p further down the order does not lower the adjusted value.
            Assert.That(Holm.Adjust(new[] { 0.001, 0.03, 0.031 }), Is.EqualTo(new[] { 0.003, 0.06, 0.06 }).Within(1e-15));
            Assert.That(Assert.Throws<ArgumentNullException>(() => Holm.Adjust(null)).ParamName, Is.EqualTo("p"));
        }
    }
}
