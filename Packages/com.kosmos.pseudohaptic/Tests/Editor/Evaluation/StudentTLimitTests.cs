using System;
using Kosmos.PseudoHaptic.Evaluation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests.Evaluation
{
    /// <summary>
    /// Student's t where the tables stop: ν = ∞ (the normal distribution) and very large ν (the Cornish–Fisher
    /// branch), and the arguments it refuses. Expected values: the t CDF as the regularized incomplete beta
    /// function and its root, computed independently to 40 digits (mpmath 1.3.0).
    /// </summary>
    public class StudentTLimitTests
    {
        [TestCase(-1.5, 0.0668072012688581)]
        [TestCase(1.0, 0.841344746068543)]
        [TestCase(1.959963984540054, 0.975)]
        [TestCase(0.0, 0.5)]
        [TestCase(-40.0, 0.0)]
        public void CdfAtInfiniteDegreesOfFreedomIsTheNormalCdf(double z, double expected)
        {
            Assert.That(StudentT.Cdf(z, double.PositiveInfinity), Is.EqualTo(expected).Within(1e-12));
        }

        [TestCase(3.0, 2.0, 0.952267016866645)]
        [TestCase(-0.5, 7.0, 0.316203567844642)]
        public void CdfAtFiniteDegreesOfFreedom(double t, double df, double expected)
        {
            Assert.That(StudentT.Cdf(t, df), Is.EqualTo(expected).Within(1e-12));
            Assert.That(StudentT.Cdf(-t, df), Is.EqualTo(1 - expected).Within(1e-12), "symmetric");
        }

        [Test]
        public void CdfOfNaNIsNaNAndOfInfinityIsOneOrZero()
        {
            Assert.That(StudentT.Cdf(double.NaN, 5), Is.NaN);
            Assert.That(StudentT.Cdf(double.NaN, double.PositiveInfinity), Is.NaN);
            Assert.That(StudentT.Cdf(double.PositiveInfinity, 5), Is.EqualTo(1));
            Assert.That(StudentT.Cdf(double.NegativeInfinity, 5), Is.EqualTo(0));
        }

        [TestCase(0.975, 5000.0, 1.96043855170651)]
        [TestCase(0.995, 1e6, 2.57583422010533)]
        [TestCase(0.9, 2000.0, 1.28197500068314)]
        [TestCase(0.975, 1001.0, 1.96233670528088)]
        public void QuantileForManyDegreesOfFreedom(double p, double df, double expected)
        {
            Assert.That(StudentT.Quantile(p, df), Is.EqualTo(expected).Within(1e-9));
            Assert.That(StudentT.Quantile(1 - p, df), Is.EqualTo(-expected).Within(1e-9));
        }

        [Test]
        public void QuantileAtInfinityIsTheNormalQuantile()
        {
            Assert.That(StudentT.Quantile(0.975, double.PositiveInfinity), Is.EqualTo(1.959963984540054).Within(1e-12));
            Assert.That(StudentT.TwoSidedCritical(0.95, double.PositiveInfinity), Is.EqualTo(1.959963984540054).Within(1e-12));
            Assert.That(StudentT.Quantile(0.5, 3), Is.EqualTo(0));
        }

        [TestCase(0.0)]
        [TestCase(-1.0)]
        [TestCase(double.NaN)]
        public void RefusesDegreesOfFreedomThatAreNotPositive(double df)
        {
            var e = Assert.Throws<ArgumentOutOfRangeException>(() => StudentT.Cdf(1, df));
            Assert.That(e.ParamName, Is.EqualTo("degreesOfFreedom"));
            Assert.That(() => StudentT.Quantile(0.9, df), Throws.InstanceOf<ArgumentOutOfRangeException>());
        }

        [TestCase(0.0)]
        [TestCase(1.0)]
        [TestCase(-0.1)]
        [TestCase(double.NaN)]
        public void RefusesProbabilitiesAndConfidencesOutsideTheOpenInterval(double p)
        {
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => StudentT.Quantile(p, 4)).ParamName, Is.EqualTo("p"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => StudentT.TwoSidedCritical(p, 4)).ParamName, Is.EqualTo("confidence"));
        }
    }
}
