using System;
using NUnit.Framework;
using Kosmos.PseudoHaptic.Simulation;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>The properties P1–P10 every reading must keep (shared/design/algorithm-reading.md), on Quest-like input.</summary>
    public class SolverPropertyTests
    {
        static readonly string[] Profiles = { "paper", "paper-experiment", "gain" };

        // P1: the golf ball, lifted at up to the user's standard speed, stays with the hand (up to the deadband's
        // width, max(v_std × 6 ms, 4 mm)). Up to v_std = 1.6 m/s: beyond, a smooth lift's peak exceeds the 10 cm-per-pose limit.
        [TestCase("paper", 0.3), TestCase("paper", 0.5), TestCase("paper", 1.2)]
        [TestCase("paper-experiment", 0.5), TestCase("gain", 0.5), TestCase("gain", 1.5)]
        public void P1_StandardWeightStaysWithTheHand(string profile, double standardSpeed)
        {
            double rise = 0.3, duration = rise / standardSpeed; // mean speed = v_std, peak 1.875 × v_std
            var frames = Run.Headset(frameRate: 90).Render(Run.Lift(rise, duration));
            var y = Run.Replay(Run.Solver(PhysicalConstants.StandardMassKg, NamedProfiles.Get(profile), standardSpeed), frames);
            var band = NamedProfiles.Get(profile).Find<MotionDeadband>();
            double deadband = band != null ? band.WidthFor(standardSpeed) : 0;
            Assert.That(Run.MaxOffset(frames, y), Is.LessThanOrEqualTo(deadband + 1e-9), "max offset during the lift");
            Assert.That(Math.Abs(frames[frames.Length - 1].HandY - Run.Last(y)), Is.LessThanOrEqualTo(deadband + 1e-9), "offset at the end");
        }

        // P2: after the same lift, heavier is never higher.
        [Test]
        public void P2_HeavierLagsMore([ValueSource(nameof(Profiles))] string profile)
        {
            double[] masses = { 0.001, 0.01, 0.045, 0.1, 0.3, 0.5, 1, 2, 5, 10, 100, 1e4, 1e6 };
            var frames = Run.Headset(frameRate: 72, jitterSd: 0.001, seed: 7).Render(Run.Lift(0.35, 0.9));
            double previousEnd = double.PositiveInfinity, previousMax = double.PositiveInfinity;
            foreach (var m in masses)
            {
                var y = Run.Replay(Run.Solver(m, NamedProfiles.Get(profile)), frames);
                double max = double.NegativeInfinity;
                foreach (var v in y) max = Math.Max(max, v);
                Assert.That(Run.Last(y), Is.LessThanOrEqualTo(previousEnd + P2Tolerance(profile)), "end height at " + m + " kg");
                Assert.That(max, Is.LessThanOrEqualTo(previousMax + P2Tolerance(profile)), "peak height at " + m + " kg");
                previousEnd = Run.Last(y);
                previousMax = max;
            }
        }

        /// <summary>
        /// Where two masses tie, only the dynamics of the tie differ: 1 g and 10 g both sit at the gain cap; and
        /// with the offset correction every object that lags past 0.2 m is held near 0.2–0.22 m below the hand,
        /// where the one with the larger offset is corrected harder and may end a few millimetres higher
        /// (ALGORITHM.md, §6). Measured worst case over the stability suite's seeds: under 5 mm.
        /// </summary>
        internal static double P2Tolerance(string profile) => NamedProfiles.Get(profile).Has<OffsetCorrection>() ? 0.005 : 1e-4;

        // P3: lighter than the golf ball leads, within the gain cap, in every profile.
        [Test]
        public void P3_LighterLeadsWithinTheGainCap([ValueSource(nameof(Profiles))] string profile)
        {
            var frames = Run.Headset().Render(Run.Lift(0.2, 1.0));
            double handRise = frames[frames.Length - 1].HandY - frames[0].HandY;
            foreach (var m in new[] { 1e-6, 0.001, 0.01, 0.03 })
            {
                var solver = Run.Solver(m, NamedProfiles.Get(profile));
                var y = Run.Replay(solver, frames);
                double rise = Run.Last(y) - y[0];
                Assert.That(rise, Is.GreaterThan(handRise), m + " kg leads");
                Assert.That(rise, Is.LessThanOrEqualTo(SolverLimits.Default.MaxGain * handRise + 1e-9), m + " kg within the cap");
            }
        }

        // P4: no hand motion, no object motion; jitter at rest creeps less than 1 cm in 10 s.
        [Test]
        public void P4_NoCreepAtRest([ValueSource(nameof(Profiles))] string profile, [Values(1, 2, 3)] int seed)
        {
            foreach (var m in new[] { 0.005, 0.045, 0.5, 5 })
            {
                var still = Run.Replay(Run.Solver(m, NamedProfiles.Get(profile)), Run.Headset().Render(HandPath.StartAt(1).Hold(10)));
                Assert.That(Run.MaxAbs(Array.ConvertAll(still, v => v - 1)), Is.EqualTo(0), "a still hand moves nothing");

                var frames = Run.Headset(jitterSd: 0.0015, seed: seed).Render(HandPath.StartAt(1).Hold(10));
                var y = Run.Replay(Run.Solver(m, NamedProfiles.Get(profile)), frames);
                Assert.That(Math.Abs(Run.Last(y) - y[0]), Is.LessThan(0.01), m + " kg creep in 10 s");
            }
        }

        // P5: local y never below 0.
        [Test]
        public void P5_NeverBelowTheFloor([ValueSource(nameof(Profiles))] string profile)
        {
            var path = HandPath.StartAt(0.05).MoveTo(-0.3, 0.5).Hold(0.5).MoveTo(0.2, 0.5).MoveTo(-0.5, 0.3);
            foreach (var m in new[] { 0.001, 0.045, 2.0 })
            {
                var y = Run.Replay(Run.Solver(m, NamedProfiles.Get(profile)), Run.Headset(jitterSd: 0.002).Render(path));
                foreach (var v in y) Assert.That(v, Is.GreaterThanOrEqualTo(0.0));
            }
            var below = Run.Solver(1, NamedProfiles.Get(profile));
            below.BeginHold(-0.2, -0.2);
            Assert.That(below.ObjectY, Is.EqualTo(0.0), "a hold that begins below the floor starts on it");
        }

        // P6: with the offset correction on, the offset stays bounded near its threshold.
        [TestCase(0.5), TestCase(2), TestCase(10), TestCase(1000)]
        public void P6_OffsetStaysNearTheThreshold(double massKg)
        {
            var path = HandPath.StartAt(0.5).Hold(0.2).MoveTo(1.3, 1.2).Hold(1).MoveTo(0.7, 1).MoveTo(1.6, 0.8).Hold(2);
            var frames = Run.Headset(frameRate: 72, jitterSd: 0.001).Render(path);
            var y = Run.Replay(Run.Solver(massKg, NamedProfiles.Paper), frames);
            Assert.That(Run.MaxOffset(frames, y), Is.LessThan(0.25));
            var uncorrected = Run.Replay(Run.Solver(massKg, NamedProfiles.PaperExperiment), frames);
            Assert.That(Run.MaxOffset(frames, uncorrected), Is.GreaterThan(0.3), "without the correction the offset grows");
        }

        // P7: the same motion on any frame clock ends in the same place.
        [Test]
        public void P7_FrameClockDoesNotMatter([ValueSource(nameof(Profiles))] string profile, [Values(0.045, 0.4, 3)] double massKg)
        {
            var path = Run.Lift(0.3, 0.8).MoveTo(0.9, 0.7).MoveTo(1.2, 0.6).Hold(0.5);
            double? reference = null;
            foreach (var rate in new[] { 30.0, 60, 72, 90, 120 })
                foreach (var wobble in new[] { 0.0, 0.3 })
                {
                    var y = Run.Replay(Run.Solver(massKg, NamedProfiles.Get(profile)), Run.Headset(frameRate: rate, wobble: wobble, seed: (int)rate).Render(path));
                    reference = reference ?? Run.Last(y);
                    Assert.That(Run.Last(y), Is.EqualTo(reference.Value).Within(0.01), rate + " Hz, wobble " + wobble);
                }
        }

        // P8: no input ever yields NaN, infinity or a jump.
        [Test]
        public void P8_GarbageInNeverBecomesNaNOrAJump([ValueSource(nameof(Profiles))] string profile)
        {
            double[] ys = { double.NaN, double.PositiveInfinity, double.NegativeInfinity, 1e300, -1e300, 0.8, 0.81, 5, -5 };
            double[] dts = { 0, -0.01, double.NaN, double.PositiveInfinity, 10, 1.0 / 90, 1e-9 };
            var rng = new Random(11);
            foreach (var m in new[] { 0.001, 0.045, 1, 1e6 })
            {
                var solver = Run.Solver(m, NamedProfiles.Get(profile));
                solver.BeginHold(0.8, 0.8);
                double last = solver.ObjectY;
                for (int i = 0; i < 5000; i++)
                {
                    var sample = new HandSample(rng.Next(4) == 0 ? ys[rng.Next(ys.Length)] : 0.8 + 0.3 * rng.NextDouble(),
                        rng.Next(5) != 0, rng.Next(3) != 0, rng.Next(2) == 0 ? double.NaN : i * 0.011);
                    double y = solver.Step(sample, dts[rng.Next(dts.Length)]);
                    Assert.That(double.IsNaN(y) || double.IsInfinity(y), Is.False);
                    Assert.That(Math.Abs(y - last), Is.LessThanOrEqualTo(0.1 + 1e-12), "step " + i);
                    last = y;
                }
            }
        }

        [Test]
        public void P8_LostForSecondsAndRegainedFarAwayDoesNotJump([ValueSource(nameof(Profiles))] string profile)
        {
            var path = Run.Lift(0.3, 1).MoveTo(0.2, 0.6).Hold(3).MoveTo(1.6, 1.2).Hold(1);
            var frames = Run.Headset(frameRate: 90).Drop(1.4, 2.5).Render(path);
            foreach (var m in new[] { 0.01, 0.5, 5 })
            {
                var y = Run.Replay(Run.Solver(m, NamedProfiles.Get(profile)), frames);
                Assert.That(Run.AllFinite(y), Is.True);
                Assert.That(Run.MaxStep(y), Is.LessThanOrEqualTo(0.1 + 1e-12), m + " kg");
                int back = Array.FindIndex(frames, f => f.Time > 3.9);
                Assert.That(Math.Abs(y[back] - y[back - 1]), Is.LessThan(0.01), m + " kg: no jump when tracking returns");
            }
        }

        // P9: hours of use do not drift. A 10-minute back-and-forth of the golf ball ends where the hand is.
        [Test]
        public void P9_NoDriftOverLongHolds([ValueSource(nameof(Profiles))] string profile)
        {
            var solver = Run.Solver(PhysicalConstants.StandardMassKg, NamedProfiles.Get(profile));
            double dt = 1.0 / 120, hand = 1.0, offsetAtOneMinute = double.NaN;
            solver.BeginHold(hand, hand, 0);
            for (long i = 1; i <= 120L * 600; i++)
            {
                double t = i * dt, poseT = Math.Floor(t * 30) / 30;
                hand = 1.0 + 0.2 * Math.Sin(2 * Math.PI * 0.5 * poseT);
                solver.Step(new HandSample(hand, true, true, poseT + 3600.0 * 5), dt); // a clock five hours in
                if (i == 120L * 60) offsetAtOneMinute = hand - solver.ObjectY;
            }
            Assert.That(hand - solver.ObjectY, Is.EqualTo(offsetAtOneMinute).Within(1e-9), "same phase, nine minutes later");
            Assert.That(Math.Abs(hand - solver.ObjectY), Is.LessThan(0.01), "bounded by the deadband and one pose");
            Assert.That(solver.State.Time, Is.EqualTo(600).Within(1e-6), "the hold's clock keeps the millisecond");
        }
    }
}
