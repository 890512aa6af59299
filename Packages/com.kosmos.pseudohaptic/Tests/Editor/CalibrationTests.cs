using System;
using System.Collections.Generic;
using NUnit.Framework;
using Kosmos.PseudoHaptic.Simulation;

namespace Kosmos.PseudoHaptic.Tests
{
    public class CalibrationTests
    {
        /// <summary>A golf-ball lift recorded at 30 Hz: rest, a minimum-jerk rise, rest; optional jitter.</summary>
        static (double[] t, double[] y) Recording(double rise, double seconds, double jitterSd = 0, int seed = 1)
        {
            var path = HandPath.StartAt(0.9).Hold(0.5).MoveTo(0.9 + rise, seconds).Hold(0.5);
            var rng = new Random(seed);
            int n = (int)(path.Duration * 30) + 1;
            var t = new double[n];
            var y = new double[n];
            for (int i = 0; i < n; i++)
            {
                t[i] = i / 30.0;
                y[i] = path.HeightAt(t[i]) + jitterSd * (rng.NextDouble() * 2 - 1) * 1.732;
            }
            return (t, y);
        }

        // Mean speed over 10–90 % of a minimum-jerk rise: 0.8·R over the time between s(τ)=0.1 and 0.9.
        static double MinimumJerkMeasuredSpeed(double rise, double seconds)
        {
            double Tau(double s) { double lo = 0, hi = 1; for (int i = 0; i < 60; i++) { double m = (lo + hi) / 2; double v = m * m * m * (10 + m * (-15 + 6 * m)); if (v < s) lo = m; else hi = m; } return lo; }
            return 0.8 * rise / ((Tau(0.9) - Tau(0.1)) * seconds);
        }

        [Test]
        public void MeasuresTheMeanSpeedOfTheLift()
        {
            var (t, y) = Recording(0.4, 0.8);
            var lift = StandardSpeedCalibration.MeasureLift(t, y);
            Assert.That(lift.IsAccepted, Is.True, lift.Reason);
            Assert.That(lift.Rise, Is.EqualTo(0.4).Within(1e-9));
            Assert.That(lift.Speed, Is.EqualTo(MinimumJerkMeasuredSpeed(0.4, 0.8)).Within(0.01));
        }

        [Test]
        public void ToleratesMillimetreJitter()
        {
            var (t, y) = Recording(0.3, 0.6, jitterSd: 0.002, seed: 5);
            var lift = StandardSpeedCalibration.MeasureLift(t, y);
            Assert.That(lift.IsAccepted, Is.True, lift.Reason);
            Assert.That(lift.Speed, Is.EqualTo(MinimumJerkMeasuredSpeed(0.3, 0.6)).Within(0.05 * lift.Speed));
        }

        [TestCase(0.05, 0.5, "too short")]
        [TestCase(0.3, 20, "too slow")]
        [TestCase(1.5, 0.25, "too fast")]
        public void RejectsWhatIsNotADeliberateLift(double rise, double seconds, string reason)
        {
            var (t, y) = Recording(rise, seconds);
            var lift = StandardSpeedCalibration.MeasureLift(t, y);
            Assert.That(lift.IsAccepted, Is.False);
            Assert.That(lift.Reason, Does.StartWith(reason));
        }

        [Test]
        public void RejectsNonFiniteAndBackwardSamples()
        {
            var (t, y) = Recording(0.3, 0.6);
            y[10] = double.NaN;
            Assert.That(StandardSpeedCalibration.MeasureLift(t, y).Reason, Does.Contain("non-finite sample at index 10"));
            (t, y) = Recording(0.3, 0.6);
            t[12] = t[11];
            Assert.That(StandardSpeedCalibration.MeasureLift(t, y).Reason, Does.Contain("time does not increase at index 12"));
            Assert.That(StandardSpeedCalibration.MeasureLift(new double[2], new double[2]).Reason, Does.StartWith("too short"));
        }

        [Test]
        public void CombinesSeveralLiftsByTheirMedianAndDropsOutliers()
        {
            var lifts = new List<LiftMeasurement>();
            foreach (var s in new[] { 0.50, 0.52, 0.48, 0.51, 1.90 })
                lifts.Add(new LiftMeasurement(true, s, 0.3, 0.3 / s, null));
            lifts.Add(StandardSpeedCalibration.MeasureLift(new double[] { 0, 1, 2 }, new double[] { 0, 0, 0 }));
            var r = StandardSpeedCalibration.Combine(lifts);
            Assert.That(r.IsAccepted, Is.True, r.Reason);
            Assert.That(r.StandardSpeed, Is.EqualTo(0.505).Within(1e-12));
            Assert.That(r.LiftsUsed, Is.EqualTo(4));
            Assert.That(r.LiftsOffered, Is.EqualTo(6));
        }

        [Test]
        public void RejectsInconsistentOrMissingLifts()
        {
            var wild = new List<LiftMeasurement>();
            foreach (var s in new[] { 0.2, 0.5, 1.0, 1.6 }) wild.Add(new LiftMeasurement(true, s, 0.3, 0.3 / s, null));
            Assert.That(StandardSpeedCalibration.Combine(wild).Reason, Does.StartWith("inconsistent lifts"));
            Assert.That(StandardSpeedCalibration.Combine(new List<LiftMeasurement>()).Reason, Is.EqualTo("no lifts recorded"));
            var bad = StandardSpeedCalibration.FromLifts(new[] { new double[] { 0, 1, 2 } }, new[] { new double[] { 0, 0.01, 0 } });
            Assert.That(bad.IsAccepted, Is.False);
            Assert.That(bad.Reason, Does.Contain("too short"));
        }

        [Test]
        public void CalibratedSpeedFeedsTheSolver()
        {
            var (t, y) = Recording(0.35, 0.7);
            var r = StandardSpeedCalibration.FromLifts(new[] { t }, new[] { y });
            var solver = new WeightSolver(WeightModel.FromMass(1), NamedProfiles.Paper, r.StandardSpeed);
            Assert.That(solver.StandardSpeed, Is.EqualTo(r.StandardSpeed));
            Assert.That(solver.Constants.CapSpeed, Is.EqualTo(2.5 * r.StandardSpeed * Math.Exp(-0.24 * (1 - 0.045))).Within(1e-12));
        }
    }
}
