using System;
using Kosmos.PseudoHaptic.Evaluation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests.Evaluation
{
    /// <summary>
    /// The normal and chi-square distributions at their edges, beside the table values in PsychophysicsTests: the density,
    /// the quantile near ½ (to the CDF's own resolution) and in the far tails, the round trip
    /// through the CDF over 600 probabilities, NaN and infinities, and the refused arguments.
    /// </summary>
    public class DistributionsContractTests
    {
        [TestCase(0.0, 0.3989422804014327)]
        [TestCase(1.0, 0.24197072451914337)]
        [TestCase(-2.0, 0.05399096651318806)]
        [TestCase(7.5, 2.4343205330290e-13)]
        public void TheDensityIsTheGaussian(double z, double expected)
            => Assert.That(Normal.Pdf(z), Is.EqualTo(expected).Within(1e-13 * expected));

        [Test]
        public void AQuantileNearAHalfIsRightToTheCdfsOwnResolution()
        {
            // Φ(z) = ½ + z·φ(0) + O(z³). Near ½ the probabilities a double can hold are 5.6e-17 apart, so z is known only to
            // 5.6e-17/φ(0) = 1.4e-16 whatever the method: the quantile is asked that absolute accuracy there (measured: its
            // relative error at ½ − 1e-10 is 2.5e-7, all of it this resolution).
            foreach (double delta in new[] { 1e-10, 3e-13, 2.5e-9, 1e-4 })
            {
                double below = 0.5 - delta, above = 0.5 + delta;
                double expectedBelow = -(0.5 - below) * Math.Sqrt(2 * Math.PI);
                double expectedAbove = (above - 0.5) * Math.Sqrt(2 * Math.PI);
                double cubic = Math.Pow(Math.Abs(expectedBelow), 3) / 6; // the next term's size, well below 1e-16 but at 1e-4
                Assert.That(Normal.Quantile(below), Is.EqualTo(expectedBelow).Within(2e-16 + cubic), "½ − " + delta);
                Assert.That(Normal.Quantile(above), Is.EqualTo(expectedAbove).Within(2e-16 + cubic), "½ + " + delta);
            }
        }

        [Test]
        public void TheQuantileInvertsTheCdfOverEveryDecade()
        {
            for (int i = 0; i < 300; i++)
            {
                double p = Math.Pow(10, -300 + i * 299.9 / 299); // 1e-300 … ~0.8
                if (p >= 1) continue;
                double z = Normal.Quantile(p);
                // z itself is held to its last bit (2.2e-16·|z|), which moves Φ by z²·2.2e-16 of itself in the tail.
                Assert.That(Normal.Cdf(z), Is.EqualTo(p).Within(p * (2e-15 + z * z * 2.3e-16)), "p = " + p);
                // The upper quantile by symmetry, judged on the upper tail where it has its digits (1 − p is 1 below 1e-16).
                if (p <= 1e-15) continue;
                double zu = Normal.Quantile(1 - p);
                if (p > 1e-15 && p < 0.5) Assert.That(Normal.UpperTail(zu), Is.EqualTo(1 - (1 - p)).Within(1e-13 * (1 - (1 - p)) + 1e-300), "1 − " + p);
            }
            for (int i = 1; i < 300; i++)
            {
                double p = i / 300.0;
                Assert.That(Normal.Cdf(Normal.Quantile(p)), Is.EqualTo(p).Within(2e-16), "p = " + p);
            }
        }

        /// <summary>The next double above (+1) or below (−1) a finite, non-zero x. Math.BitIncrement is not in Unity's
        /// .NET profile (the per-asmdef compile tests say so).</summary>
        static double Neighbour(double x, int direction)
        {
            long bits = BitConverter.DoubleToInt64Bits(x);
            return BitConverter.Int64BitsToDouble(x > 0 ? bits + direction : bits - direction);
        }

        /// <summary>The Newton steps after the bisection: the quantile is the double whose CDF lies nearest p (or ties with
        /// it) for 91 % of 4,000 seeded probabilities below ½, uniform and log-uniform down to 1e-300 (measured), and within
        /// one double of it for 99.5 %; the bisection's bracket alone gives 55 % and 99.1 % (measured with the steps cut out).</summary>
        [Test]
        public void TheQuantileIsTheDoubleWhoseCdfIsNearestMostOfTheTime()
        {
            var rng = new SeededRandom(1);
            int n = 0, nearest = 0;
            for (int i = 0; i < 4000; i++)
            {
                double p = i % 2 == 0 ? 0.5 * rng.NextDouble() : Math.Pow(10, -300 * rng.NextDouble());
                if (!(p > 0 && p < 0.5)) continue;
                double z = Normal.Quantile(p);
                double at = Math.Abs(Normal.Cdf(z) - p);
                double below = Math.Abs(Normal.Cdf(Neighbour(z, -1)) - p), above = Math.Abs(Normal.Cdf(Neighbour(z, +1)) - p);
                n++;
                if (at <= below && at <= above) nearest++;
            }
            Assert.That(n, Is.GreaterThan(3900));
            Assert.That(nearest, Is.GreaterThan(0.85 * n), nearest + " of " + n);
        }

        [Test]
        public void AQuantileOfAHalfIsZeroAndTheTwoHalvesAreMirrors()
        {
            Assert.That(Normal.Quantile(0.5), Is.EqualTo(0));
            foreach (double p in new[] { 0.001, 0.1, 0.3, 0.49 })
                Assert.That(Normal.Quantile(1 - p), Is.EqualTo(-Normal.Quantile(p)).Within(1e-15 * Math.Abs(Normal.Quantile(p)) + 1e-16 / p), "p = " + p);
        }

        [TestCase(0.0)]
        [TestCase(1.0)]
        [TestCase(-0.1)]
        [TestCase(1.5)]
        [TestCase(double.NaN)]
        public void AQuantileOutsideTheOpenUnitIntervalIsRefused(double p)
        {
            var e = Assert.Throws<ArgumentOutOfRangeException>(() => Normal.Quantile(p));
            Assert.That(e.ParamName, Is.EqualTo("p"));
            Assert.That(e.Message, Does.StartWith("probability must be in (0, 1)"));
        }

        [Test]
        public void NaNAndTheInfinitiesGoThrough()
        {
            double lower, upper;
            Normal.Both(double.NaN, out lower, out upper);
            Assert.That(double.IsNaN(lower) && double.IsNaN(upper));
            Assert.That(double.IsNaN(Normal.Cdf(double.NaN)) && double.IsNaN(Normal.UpperTail(double.NaN)) && double.IsNaN(Normal.CdfByGamma(double.NaN)));
            Normal.Both(double.PositiveInfinity, out lower, out upper);
            Assert.That(new[] { lower, upper }, Is.EqualTo(new[] { 1.0, 0.0 }));
            Normal.Both(double.NegativeInfinity, out lower, out upper);
            Assert.That(new[] { lower, upper }, Is.EqualTo(new[] { 0.0, 1.0 }));
            Assert.That(Normal.CdfByGamma(double.PositiveInfinity), Is.EqualTo(1));
            Assert.That(Normal.CdfByGamma(double.NegativeInfinity), Is.EqualTo(0));
            Assert.That(Normal.CdfByGamma(0), Is.EqualTo(0.5));
        }

        [Test]
        public void BothTailsSumToOneAndEachKeepsItsOwnDigits()
        {
            // Across every branch: the central rational form, Cody's middle form, the asymptotic form, and beyond 40.
            foreach (double z in new[] { -45.0, -39.9, -12.0, -5.656854249492380195, -5.6, -1.0, -0.67448975, -0.5, -1e-17, 0.0, 1e-17, 0.3, 0.67448975, 0.7, 3.0, 5.7, 20.0, 41.0 })
            {
                double lower, upper;
                Normal.Both(z, out lower, out upper);
                Assert.That(lower + upper, Is.EqualTo(1).Within(2e-16), "z = " + z);
                double byGamma = Normal.CdfByGamma(z), upperByGamma = Normal.CdfByGamma(-z);
                Assert.That(lower, Is.EqualTo(byGamma).Within(1e-12 * byGamma + 1e-320), "Φ(" + z + ")");
                Assert.That(upper, Is.EqualTo(upperByGamma).Within(1e-12 * upperByGamma + 1e-320), "1 − Φ(" + z + ")");
            }
        }

        /// <summary>Far in the tail Φ(z) = e^(−z²/2)·r: z² rounds by up to 2.8e-14 at |z| = 36.7, which the exponential
        /// would pass on whole; the code splits z² so that it does not (Cody 1993). References: mpmath at 40 digits, at the
        /// very doubles the literals denote.</summary>
        [TestCase(-36.7, 3.651529302803418e-295)]
        [TestCase(-30.3, 5.7317235033154953e-202)]
        [TestCase(-25.3, 1.5971151302421998e-141)]
        [TestCase(-12.345, 2.591712067896197e-35)]
        [TestCase(-7.77, 3.9243063161315743e-15)]
        [TestCase(-6.1, 5.3034232629488415e-10)]
        public void TheFarTailKeepsItsDigits(double z, double expected)
        {
            Assert.That(Normal.Cdf(z), Is.EqualTo(expected).Within(4e-15 * expected));
            Assert.That(Normal.UpperTail(-z), Is.EqualTo(expected).Within(4e-15 * expected));
        }

        [Test]
        public void AChiSquareTailOfNothingOrLessIsOneAndOfNaNIsNaN()
        {
            Assert.That(ChiSquare.UpperTail(-3, 2), Is.EqualTo(1));
            Assert.That(ChiSquare.UpperTail(0, 0.5), Is.EqualTo(1));
            Assert.That(double.IsNaN(ChiSquare.UpperTail(double.NaN, 2)));
            Assert.That(ChiSquare.UpperTail(double.PositiveInfinity, 2), Is.EqualTo(0));
            // ν = 2: e^(−x/2) exactly, also where x is tiny and Q is nearly 1 (the series branch, x < a + 1).
            Assert.That(ChiSquare.UpperTail(1e-8, 2), Is.EqualTo(Math.Exp(-0.5e-8)).Within(1e-15));
            Assert.That(ChiSquare.UpperTail(2.5, 4), Is.EqualTo(Math.Exp(-1.25) * 2.25).Within(1e-15), "x just below a + 1 = 3, in x/2 = 1.25");
            Assert.That(ChiSquare.UpperTail(6, 4), Is.EqualTo(Math.Exp(-3) * 4).Within(1e-15), "x/2 = a + 1 exactly: the continued fraction");
        }

        [TestCase(0.0)]
        [TestCase(-1.0)]
        [TestCase(double.NaN)]
        [TestCase(1000000.0000000001)]
        [TestCase(double.PositiveInfinity)]
        public void ChiSquareDegreesOfFreedomOutsideZeroToAMillionAreRefused(double df)
        {
            var e = Assert.Throws<ArgumentOutOfRangeException>(() => ChiSquare.UpperTail(1, df));
            Assert.That(e.ParamName, Is.EqualTo("degreesOfFreedom"));
            Assert.That(e.Message, Does.StartWith("degrees of freedom must be positive and at most a million"));
        }

        // Q(ν/2, x/2) at 40 digits (mpmath 1.3.0, gammainc regularized). At ν = 10⁶ the series and the continued fraction
        // still converge within their 100,000 terms; ln Γ(ν/2) cancels: 5.2e-10 of the tail at x = ν, 3.3e-11 below it.
        [TestCase(1e6, 0.49981193680339449952)]
        [TestCase(1.002e6, 0.078718661386129633385)]
        [TestCase(0.998e6, 0.92141970801285505352)]
        public void AtAMillionDegreesOfFreedomTheChiSquareTailKeepsNineDigits(double x, double expected)
        {
            Assert.That(ChiSquare.UpperTail(x, 1e6), Is.EqualTo(expected).Within(1e-7).Percent);
        }
    }
}
