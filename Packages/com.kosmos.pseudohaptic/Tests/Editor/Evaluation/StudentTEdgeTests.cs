using System;
using Kosmos.PseudoHaptic.Evaluation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests.Evaluation
{
    /// <summary>
    /// Student's t at the edges StatisticsTests and StudentTLimitTests leave open: fractional ν below 1,
    /// the first ν of the Cornish–Fisher branch held to its full accuracy, the last exact ν in a far tail,
    /// t = 0 and huge t at huge ν, and the messages a caller reads. Expected values: the t CDF as
    /// ½·I_{ν/(ν+t²)}(ν/2, ½) and its root, computed independently to 40 digits (mpmath 1.3.0, betainc and
    /// findroot).
    /// </summary>
    public class StudentTEdgeTests
    {
        // ν < 1 is a proper t distribution too (heavier tails than Cauchy); ln Γ(ν/2) then needs the reflection formula.
        [TestCase(2.0, 0.5, 0.77724255490843438)]
        [TestCase(1.0, 0.5, 0.69887838915867792)]
        [TestCase(-3.0, 0.25, 0.27403280105930886)]
        public void CdfBelowOneDegreeOfFreedom(double t, double df, double expected)
        {
            Assert.That(StudentT.Cdf(t, df), Is.EqualTo(expected).Within(1e-12));
        }

        [Test]
        public void QuantileBelowOneDegreeOfFreedom()
        {
            Assert.That(StudentT.Quantile(0.9, 0.5), Is.EqualTo(10.270324410234511).Within(1e-9));
            Assert.That(StudentT.Quantile(0.1, 0.5), Is.EqualTo(-10.270324410234511).Within(1e-9));
        }

        // ν = 1001, the first whole ν past the exact range: the expansion's next term is O(ν⁻⁵) ≈ 1e-15 here,
        // so the quantile must agree with the exact root to a few dozen ulps, every term of ν⁻¹ … ν⁻⁴ counting.
        [TestCase(0.975, 1.9623367052808798947)]
        [TestCase(0.6, 0.25341444848349828255)]
        public void CornishFisherAtTheFirstDegreeOfFreedomPastTheExactRangeIsFullyAccurate(double p, double expected)
        {
            Assert.That(StudentT.Quantile(p, 1001), Is.EqualTo(expected).Within(2e-14));
            Assert.That(StudentT.Quantile(1 - p, 1001), Is.EqualTo(-expected).Within(2e-14), "symmetric");
        }

        [Test]
        public void QuantileAtOneThousandDegreesOfFreedomIsExactFarIntoTheTail()
        {
            // P(T ≤ t) = 1e-12 at ν = 1000: the four-term expansion is 2e-10 off there; the exact root is not.
            Assert.That(StudentT.Quantile(1e-12, 1000), Is.EqualTo(-7.1242289253144091385).Within(1e-11));
        }

        // The CDF's side of the same edge: ν = 1000 is still the beta form's; the expansion, inverted, would be 1.3e-9
        // (at 1e-12) and 5.9e-8 (at t = −10) off the tail (mpmath 1.3.0, betainc and findroot, 40 digits).
        [TestCase(-7.1242289253144091385, 9.9999999999999717827e-13)]
        [TestCase(-10.0, 8.3353514793000331542e-23)]
        public void CdfAtOneThousandDegreesOfFreedomIsExactFarIntoTheTail(double t, double expected)
        {
            Assert.That(StudentT.Cdf(t, 1000), Is.EqualTo(expected).Within(1e-9).Percent);
        }

        // As ν grows the incomplete beta function cancels (1 − ν/(ν + t²), ln Γ(ν/2 + ½) − ln Γ(ν/2)): before the fix
        // P(T ≤ 1) was 3.7e-8 off at ν = 1e8 and read ½ at ν = 1e16 (found through Stryker mutant 4185). Past ν = 1000
        // the CDF now inverts the quantile's Cornish–Fisher expansion.
        [TestCase(1.0, 1001.0, 0.84122391176174445697)]
        [TestCase(1.0, 1e4, 0.84133264783478543801)]
        [TestCase(1.0, 10001.0, 0.84133264904445760222)]
        [TestCase(-2.0, 5000.0, 0.022777129994146986172)]
        [TestCase(3.0, 1e5, 0.9986497695579676404)]
        [TestCase(1.0, 1e8, 0.84134474485868932901)]
        [TestCase(3.0, 1e8, 0.99865010163598125281)]
        [TestCase(1.0, 1e16, 0.84134474606854293649)]
        public void CdfPastOneThousandDegreesOfFreedomKeepsItsDigits(double t, double df, double expected)
        {
            Assert.That(StudentT.Cdf(t, df), Is.EqualTo(expected).Within(1e-12));
            Assert.That(StudentT.Cdf(-t, df), Is.EqualTo(1 - expected).Within(1e-12), "symmetric");
        }

        // Near the median at large ν, I_x(ν/2, ½) has x close to 1, where its continued fraction converges only slowly:
        // it must be taken as 1 − I₁₋ₓ(½, ν/2) there.
        [TestCase(0.001, 1000.0, 0.50039884249077363486)]
        [TestCase(0.001, 500.0, 0.50039874279266357296)]
        public void CdfJustAboveTheMedianAtManyDegreesOfFreedom(double t, double df, double expected)
        {
            Assert.That(StudentT.Cdf(t, df), Is.EqualTo(expected).Within(1e-10));
        }

        [TestCase(-10.0, 1e4, 9.81640371433191447e-24)]
        [TestCase(-10.0, 10001.0, 9.8161567307099124948e-24)]
        [TestCase(-20.0, 1e5, 4.1117469553271810757e-89)]
        public void CdfFarInTheTailIsRightToElevenDigitsOfTheTailItself(double t, double df, double expected)
        {
            Assert.That(StudentT.Cdf(t, df), Is.EqualTo(expected).Within(1e-9).Percent);
        }

        [TestCase(-10.0, 2e4)]
        [TestCase(0.3, 2000.0)]
        [TestCase(2.5, 1e6)]
        [TestCase(-1.0, 1e16)]
        public void CdfAndQuantileAreInversesPastOneThousandDegreesOfFreedom(double t, double df)
        {
            Assert.That(StudentT.Quantile(StudentT.Cdf(t, df), df), Is.EqualTo(t).Within(1e-9));
        }

        [TestCase(0.5)]
        [TestCase(1.0)]
        [TestCase(7.0)]
        [TestCase(1e6)]
        [TestCase(1e308)]
        public void ZeroIsTheMedianAtEveryDegreeOfFreedom(double df)
        {
            Assert.That(StudentT.Cdf(0, df), Is.EqualTo(0.5));
        }

        [Test]
        public void AHugeTAtAHugeDegreeOfFreedomIsCertain()
        {
            // t² overflows: ν/(ν + t²) is 0, the far end of the incomplete beta function.
            Assert.That(StudentT.Cdf(1e200, 1e308), Is.EqualTo(1.0));
            Assert.That(StudentT.Cdf(-1e200, 1e308), Is.EqualTo(0.0));
        }

        [Test]
        public void RefusalsSayWhatIsAllowed()
        {
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => StudentT.Quantile(1.5, 4)).Message, Does.StartWith("probability must be in (0, 1)"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => StudentT.TwoSidedCritical(0, 4)).Message, Does.StartWith("confidence must be in (0, 1)"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => StudentT.Cdf(1, -2)).Message, Does.StartWith("degrees of freedom must be positive"));
        }
    }
}
