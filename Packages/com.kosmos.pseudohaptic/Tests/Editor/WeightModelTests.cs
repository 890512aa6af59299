using System;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests
{
    public class WeightModelTests
    {
        [Test]
        public void StandardWeightIsAGolfBall()
        {
            Assert.That(PhysicalConstants.StandardWeightNewtons, Is.EqualTo(0.4413).Within(1e-4));
            Assert.That(WeightModel.FromMass(2).WeightNewtons, Is.EqualTo(19.6133).Within(1e-4));
        }

        // The design note's sample gains for the adopted reading of Eq. 4–6.
        [TestCase(0.010, 2.75)]
        [TestCase(0.100, 0.72)]
        [TestCase(0.500, 0.49)]
        [TestCase(1.000, 0.42)]
        [TestCase(2.000, 0.32)]
        [TestCase(5.000, 0.16)]
        public void BlendedGainMatchesTheAdoptedReading(double massKg, double gain)
        {
            Assert.That(WeightModel.FromMass(massKg).Gain(true, true, 100), Is.EqualTo(gain).Within(0.005));
        }

        [Test]
        public void GolfBallGainIsExactlyOneInEveryCombination()
        {
            var m = WeightModel.FromMass(PhysicalConstants.StandardMassKg);
            Assert.That(m.Gain(true, true, 3), Is.EqualTo(1.0).Within(1e-12));
            Assert.That(m.Gain(true, false, 3), Is.EqualTo(1.0).Within(1e-12));
            Assert.That(m.Gain(false, true, 3), Is.EqualTo(1.0).Within(1e-12));
            Assert.That(m.Gain(false, false, 3), Is.EqualTo(1.0));
        }

        [Test]
        public void GainNeverExceedsTheCap()
        {
            Assert.That(WeightModel.FromMass(0.001).Gain(true, false, 3), Is.EqualTo(3.0)); // Eq. 4 alone: 45
            Assert.That(WeightModel.FromMass(1e6).Gain(true, true, 3), Is.GreaterThanOrEqualTo(0).And.LessThan(1e-6));
        }

        [Test]
        public void ExperimentalSpeedIsPlausibleInKilograms()
        {
            var c = ExperimentalSpeedCurve.Paper;
            Assert.That(c.Speed(1.25), Is.EqualTo(1.24).Within(0.01));
            Assert.That(c.Speed(5.0), Is.EqualTo(0.51).Within(0.01));
            Assert.That(c.Speed(1e6), Is.EqualTo(0.0)); // underflows, never NaN
        }

        [Test]
        public void MassFromDensityAndVolume()
        {
            var m = WeightModel.FromDensity(700, 0.001); // a litre of wood
            Assert.That(m.MassKg, Is.EqualTo(0.7).Within(1e-12));
        }

        [Test]
        public void FitRecoversTheCurve()
        {
            double[] masses = { 1.25, 2.0, 2.5, 4.0, 5.0 };
            var speeds = new double[masses.Length];
            for (int i = 0; i < masses.Length; i++) speeds[i] = 1.2 * Math.Exp(-0.3 * masses[i]);
            var fit = ExperimentalSpeedCurve.Fit(masses, speeds);
            Assert.That(fit.A, Is.EqualTo(1.2).Within(1e-9));
            Assert.That(fit.B, Is.EqualTo(0.3).Within(1e-9));
        }

        [TestCase(0.0, "massKg")]
        [TestCase(-1.0, "massKg")]
        [TestCase(double.NaN, "massKg")]
        [TestCase(double.PositiveInfinity, "massKg")]
        public void InvalidMassThrowsNamingTheField(double mass, string field)
        {
            var e = Assert.Throws<ArgumentOutOfRangeException>(() => WeightModel.FromMass(mass));
            Assert.That(e.ParamName, Is.EqualTo(field));
            Assert.That(e.Message, Does.Contain(field));
        }

        [Test]
        public void InvalidCurveAndDensityThrowNamingTheField()
        {
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => new ExperimentalSpeedCurve(0, 0.24)).ParamName, Is.EqualTo("a"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => new ExperimentalSpeedCurve(1.6, -1)).ParamName, Is.EqualTo("b"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => new ExperimentalSpeedCurve(double.NaN, 0.2)).ParamName, Is.EqualTo("a"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => WeightModel.FromDensity(-5, 1)).ParamName, Is.EqualTo("densityKgPerCubicMetre"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => WeightModel.FromDensity(5, double.PositiveInfinity)).ParamName, Is.EqualTo("volumeCubicMetres"));
            Assert.Throws<ArgumentOutOfRangeException>(() => WeightModel.FromDensity(1e300, 1e300)); // overflows to infinity
        }

        [Test]
        public void InvalidSolverConfigurationThrowsNamingTheField()
        {
            var m = WeightModel.FromMass(1);
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => new WeightSolver(m, NamedProfiles.Paper, 0)).ParamName, Is.EqualTo("standardSpeed"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => new WeightSolver(m, NamedProfiles.Paper, double.NaN)).ParamName, Is.EqualTo("standardSpeed"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => new SolverLimits(maxGain: 0.5)).ParamName, Is.EqualTo("maxGain"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => new SolverLimits(glideSpeed: double.NaN)).ParamName, Is.EqualTo("glideSpeed"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => new SolverLimits(workspaceRadius: 0.5)).ParamName, Is.EqualTo("workspaceRadius"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => new SolverLimits(workspaceRadius: double.NaN)).ParamName, Is.EqualTo("workspaceRadius"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => new SolverLimits(workspaceRadius: double.PositiveInfinity)).ParamName, Is.EqualTo("workspaceRadius"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => new OffsetCorrection(threshold: -0.2)).ParamName, Is.EqualTo("threshold"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => new SpeedCap(headroom: 0.5)).ParamName, Is.EqualTo("headroom"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => new MotionDeadband(lagTime: double.NaN)).ParamName, Is.EqualTo("lagTime"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => new FloorClamp(double.NegativeInfinity)).ParamName, Is.EqualTo("floor"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => new TrackingLossHold(settleTime: -1)).ParamName, Is.EqualTo("settleTime"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => new OffsetRelaxation(timeConstant: 0)).ParamName, Is.EqualTo("timeConstant"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => new WeightSolver(m).BeginHold(0, double.NaN)).ParamName, Is.EqualTo("objectY"));
        }
    }
}
