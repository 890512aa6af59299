using System;
using Kosmos.PseudoHaptic.Evaluation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests.Evaluation
{
    public class StatisticsTests
    {
        // Two-sided 95 % critical values t(0.975, ν): published tables, checked to 1e-10 against a Simpson integration of the t density.
        [TestCase(1, 12.706204736174705)]
        [TestCase(2, 4.302652729749464)]
        [TestCase(4, 2.7764451051977987)]
        [TestCase(5, 2.5705818356363146)]
        [TestCase(10, 2.2281388519862744)]
        [TestCase(11, 2.2009851600916384)]
        [TestCase(30, 2.0422724563012378)]
        [TestCase(100, 1.9839715185235556)]
        [TestCase(1000, 1.9623390808264078)]
        [TestCase(1001, 1.9623367052822)]
        [TestCase(100000, 1.9599877077018)]
        public void TQuantileMatchesTables(int df, double expected)
        {
            Assert.That(StudentT.Quantile(0.975, df), Is.EqualTo(expected).Within(1e-7));
            Assert.That(StudentT.Quantile(0.025, df), Is.EqualTo(-expected).Within(1e-7), "symmetric");
        }

        [Test]
        public void TQuantileAtOtherLevelsAndInfinity()
        {
            Assert.That(StudentT.Quantile(0.995, 3), Is.EqualTo(5.840909309733351).Within(1e-8));
            Assert.That(StudentT.Quantile(0.9, 1), Is.EqualTo(3.077683537175253).Within(1e-8));
            Assert.That(StudentT.Quantile(0.5, 7), Is.EqualTo(0.0));
            Assert.That(StudentT.Quantile(0.975, double.PositiveInfinity), Is.EqualTo(1.959963984540054).Within(1e-9));
            Assert.That(StudentT.TwoSidedCritical(0.95, 11), Is.EqualTo(StudentT.Quantile(0.975, 11)));
            Assert.Throws<ArgumentOutOfRangeException>(() => StudentT.Quantile(1.0, 5));
            Assert.Throws<ArgumentOutOfRangeException>(() => StudentT.Quantile(0.9, 0));
        }

        [TestCase(0.3, 1)]
        [TestCase(-1.7, 3)]
        [TestCase(2.2009851600916384, 11)]
        [TestCase(4.0, 50)]
        public void CdfInvertsQuantile(double t, double df)
        {
            Assert.That(StudentT.Quantile(StudentT.Cdf(t, df), df), Is.EqualTo(t).Within(1e-9));
        }

        [Test]
        public void CauchyCdfIsKnownInClosedForm()
        {
            // ν = 1 is the Cauchy distribution: F(t) = ½ + atan(t)/π.
            foreach (double t in new[] { -5.0, -0.5, 0.0, 1.0, 3.0 })
                Assert.That(StudentT.Cdf(t, 1), Is.EqualTo(0.5 + Math.Atan(t) / Math.PI).Within(1e-13));
        }

        [Test]
        public void SummaryOfOneToFive()
        {
            // By hand: mean 3, squares 4+1+0+1+4 = 10, SD = √(10/4) = 1.5811388, SE = SD/√5 = 0.7071068,
            // t(0.975, 4) = 2.7764451, half-width 1.9632432 → CI [1.0367568, 4.9632432].
            var s = SummaryStatistics.Compute(new[] { 4.0, 2.0, 5.0, 1.0, 3.0 });
            Assert.That(s.N, Is.EqualTo(5));
            Assert.That(s.Mean, Is.EqualTo(3.0));
            Assert.That(s.StandardDeviation, Is.EqualTo(Math.Sqrt(2.5)).Within(1e-12));
            Assert.That(s.Median, Is.EqualTo(3.0));
            Assert.That(s.Min, Is.EqualTo(1.0));
            Assert.That(s.Max, Is.EqualTo(5.0));
            Assert.That(s.ConfidenceLevel, Is.EqualTo(0.95));
            Assert.That(s.ConfidenceLow, Is.EqualTo(1.0367568).Within(1e-6));
            Assert.That(s.ConfidenceHigh, Is.EqualTo(4.9632432).Within(1e-6));
        }

        [Test]
        public void MedianOfAnEvenCountIsTheMiddlePairsMean()
        {
            Assert.That(SummaryStatistics.Compute(new[] { 7.0, 1.0, 3.0, 10.0 }).Median, Is.EqualTo(5.0));
        }

        [Test]
        public void TooFewValuesLeaveUndefinedFiguresNaN()
        {
            var none = SummaryStatistics.Compute(new double[0]);
            Assert.That(none.N, Is.EqualTo(0));
            Assert.That(double.IsNaN(none.Mean), Is.True);
            var one = SummaryStatistics.Compute(new[] { 4.2 });
            Assert.That(one.Mean, Is.EqualTo(4.2));
            Assert.That(one.Median, Is.EqualTo(4.2));
            Assert.That(double.IsNaN(one.StandardDeviation), Is.True);
            Assert.That(double.IsNaN(one.ConfidenceLow) && double.IsNaN(one.ConfidenceHigh), Is.True);
            Assert.Throws<ArgumentException>(() => SummaryStatistics.Compute(new[] { 1.0, double.NaN }));
        }

        [Test]
        public void IncompleteScoresAreLeftOutOfTheSummary()
        {
            var s = SummaryStatistics.OfScores(new[]
            {
                new ParticipantScore("P1", "immersion", 4.0),
                new ParticipantScore("P2", "immersion", null, new[] { 3 }),
                new ParticipantScore("P3", "immersion", 2.0),
            });
            Assert.That(s.N, Is.EqualTo(2));
            Assert.That(s.Mean, Is.EqualTo(3.0));
        }
    }
}
