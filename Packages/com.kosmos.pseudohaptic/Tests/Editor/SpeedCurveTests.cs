using System;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>
    /// Eq. 5's curve and the gain built from it, term by term: each switch of <see cref="WeightModel.Gain"/> on
    /// its own, the curve relative to the golf ball, and the least-squares refit from a user's lifts checked
    /// against the closed form of a two-point line and against data that heavier lifts faster.
    /// </summary>
    public class SpeedCurveTests
    {
        const double Golf = 0.045; // kg, the paper's standard object

        [TestCase(0.5)]
        [TestCase(2.0)]
        [TestCase(7.5)]
        public void EachTermOfTheGainAlone(double massKg)
        {
            var m = WeightModel.FromMass(massKg);
            double weightRatio = Golf / massKg;                      // Eq. 4: W_std / W
            double experimental = Math.Exp(-0.24 * (massKg - Golf)); // Eq. 5 relative to the golf ball
            Assert.That(m.StandardWeightRatio, Is.EqualTo(weightRatio).Within(1e-15));
            Assert.That(m.ExperimentalRatio, Is.EqualTo(experimental).Within(1e-15));
            Assert.That(m.Gain(true, false, 100), Is.EqualTo(weightRatio).Within(1e-15));
            Assert.That(m.Gain(false, true, 100), Is.EqualTo(experimental).Within(1e-15));
            Assert.That(m.Gain(true, true, 100), Is.EqualTo(0.5 * (weightRatio + experimental)).Within(1e-15));
            Assert.That(m.Gain(false, false, 100), Is.EqualTo(1.0));
            Assert.That(m.WeightNewtons, Is.EqualTo(massKg * 9.80665).Within(1e-12));
        }

        [Test]
        public void TheCapAppliesToEveryCombinationAndOnlyAboveIt()
        {
            var light = WeightModel.FromMass(0.009); // W_std / W = 5, experimental ratio just above 1
            Assert.That(light.Gain(true, false, 2), Is.EqualTo(2));
            Assert.That(light.Gain(true, true, 2), Is.EqualTo(2));
            Assert.That(light.Gain(false, true, 1.005), Is.EqualTo(1.005), "e^(0.24·0.036) = 1.0087 capped");
            Assert.That(light.Gain(false, false, 1), Is.EqualTo(1));
            Assert.That(light.Gain(true, false, 5.5), Is.EqualTo(5).Within(1e-12), "below the cap: untouched");
        }

        [Test]
        public void AModelKeepsItsOwnCurve()
        {
            var flat = new ExperimentalSpeedCurve(1.0, 0);
            Assert.That(WeightModel.FromMass(3, flat).Curve, Is.SameAs(flat));
            Assert.That(WeightModel.FromMass(3, flat).ExperimentalRatio, Is.EqualTo(1), "b = 0: speed does not depend on mass");
            Assert.That(WeightModel.FromMass(3).Curve, Is.SameAs(ExperimentalSpeedCurve.Paper));
            Assert.That(WeightModel.FromDensity(1000, 0.002, flat).Curve, Is.SameAs(flat));
            Assert.That(WeightModel.FromDensity(1000, 0.002).Curve, Is.SameAs(ExperimentalSpeedCurve.Paper));
            Assert.That(WeightModel.FromDensity(1000, 0.002).MassKg, Is.EqualTo(2).Within(1e-15));
            var e = Assert.Throws<ArgumentOutOfRangeException>(() => WeightModel.FromDensity(1e-300, 1e-300));
            Assert.That(e.ParamName, Is.EqualTo("massKg (density × volume)"), "underflows to 0 kg");
        }

        [Test]
        public void TheCurveAtAndAwayFromTheGolfBall()
        {
            var c = new ExperimentalSpeedCurve(2.0, 0.5);
            Assert.That(c.Speed(0), Is.EqualTo(2.0));
            Assert.That(c.Speed(2), Is.EqualTo(2.0 * Math.Exp(-1)).Within(1e-15));
            Assert.That(c.RatioToStandard(Golf), Is.EqualTo(1));
            Assert.That(c.RatioToStandard(2.045), Is.EqualTo(Math.Exp(-1)).Within(1e-15));
            Assert.That(c.RatioToStandard(0.0), Is.EqualTo(Math.Exp(0.5 * Golf)).Within(1e-15), "lighter than the ball: above 1");
            Assert.That(ExperimentalSpeedCurve.Paper.A, Is.EqualTo(1.6793));
            Assert.That(ExperimentalSpeedCurve.Paper.B, Is.EqualTo(0.24));
        }

        [Test]
        public void FitThroughTwoLiftsIsTheLineThroughThem()
        {
            // ln v = ln a − b·m through (1 kg, 1.2 m/s) and (3 kg, 0.6 m/s): b = ln 2 / 2, a = 1.2·e^b.
            var fit = ExperimentalSpeedCurve.Fit(new[] { 1.0, 3.0 }, new[] { 1.2, 0.6 });
            Assert.That(fit.B, Is.EqualTo(Math.Log(2) / 2).Within(1e-14));
            Assert.That(fit.A, Is.EqualTo(1.2 * Math.Exp(Math.Log(2) / 2)).Within(1e-14));
            Assert.That(fit.Speed(1), Is.EqualTo(1.2).Within(1e-14));
            Assert.That(fit.Speed(3), Is.EqualTo(0.6).Within(1e-14));
        }

        [Test]
        public void FitOfScatteredLiftsIsTheLeastSquaresLine()
        {
            // Four lifts off any one exponential; the least-squares line of (m, ln v) by the normal equations.
            double[] m = { 0.5, 1.5, 2.0, 4.0 }, v = { 1.5, 1.1, 1.2, 0.55 };
            double n = m.Length, sx = 0, sy = 0, sxx = 0, sxy = 0;
            for (int i = 0; i < m.Length; i++) { sx += m[i]; sy += Math.Log(v[i]); sxx += m[i] * m[i]; sxy += m[i] * Math.Log(v[i]); }
            double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
            double intercept = (sy - slope * sx) / n;
            var fit = ExperimentalSpeedCurve.Fit(m, v);
            Assert.That(fit.B, Is.EqualTo(-slope).Within(1e-12));
            Assert.That(fit.A, Is.EqualTo(Math.Exp(intercept)).Within(1e-12));
        }

        [Test]
        public void LiftsThatGetFasterWithMassGiveAFlatCurveAtTheirMeanSpeed()
        {
            // Heavier-is-faster is no weight cue: b is held at 0 and a is the geometric mean of the speeds.
            var fit = ExperimentalSpeedCurve.Fit(new[] { 1.0, 2.0, 4.0 }, new[] { 0.5, 0.8, 1.0 });
            Assert.That(fit.B, Is.EqualTo(0));
            Assert.That(fit.A, Is.EqualTo(Math.Pow(0.5 * 0.8 * 1.0, 1.0 / 3)).Within(1e-12));
        }

        [Test]
        public void FitRefusesWhatCannotGiveACurveNamingTheArgument()
        {
            var lengths = Assert.Throws<ArgumentException>(() => ExperimentalSpeedCurve.Fit(new[] { 1.0, 2.0 }, new[] { 1.0 }));
            Assert.That(lengths.ParamName, Is.EqualTo("speeds"));
            Assert.That(lengths.Message, Does.Contain("massesKg and speeds must have the same length."));
            var one = Assert.Throws<ArgumentException>(() => ExperimentalSpeedCurve.Fit(new[] { 1.0 }, new[] { 1.0 }));
            Assert.That(one.ParamName, Is.EqualTo("massesKg"));
            Assert.That(one.Message, Does.Contain("at least two (mass, speed) pairs are needed."));
            Assert.That(Assert.Throws<ArgumentException>(() => ExperimentalSpeedCurve.Fit(new double[0], new double[0])).ParamName, Is.EqualTo("massesKg"));
            var equal = Assert.Throws<ArgumentException>(() => ExperimentalSpeedCurve.Fit(new[] { 2.0, 2.0, 2.0 }, new[] { 1.0, 0.9, 1.1 }));
            Assert.That(equal.ParamName, Is.EqualTo("massesKg"));
            Assert.That(equal.Message, Does.Contain("must not all be equal"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => ExperimentalSpeedCurve.Fit(new[] { 1.0, 0.0 }, new[] { 1.0, 1.0 })).ParamName, Is.EqualTo("massesKg[1]"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => ExperimentalSpeedCurve.Fit(new[] { 1.0, 2.0 }, new[] { -1.0, 1.0 })).ParamName, Is.EqualTo("speeds[0]"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => ExperimentalSpeedCurve.Fit(new[] { 1.0, 2.0 }, new[] { 1.0, double.NaN })).ParamName, Is.EqualTo("speeds[1]"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => new ExperimentalSpeedCurve(double.PositiveInfinity, 0)).ParamName, Is.EqualTo("a"));
            Assert.That(new ExperimentalSpeedCurve(1, 0).B, Is.EqualTo(0), "b = 0 is allowed");
        }
    }
}
