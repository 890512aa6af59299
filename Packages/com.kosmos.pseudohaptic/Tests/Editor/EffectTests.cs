using System;
using NUnit.Framework;
using Kosmos.PseudoHaptic.Simulation;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>Each effect alone, against a profile without it.</summary>
    public class EffectTests
    {
        static WeightProfile Only(params WeightEffect[] effects) => new WeightProfile("test", effects);

        static double[] Lift(WeightProfile profile, double massKg, double rise = 0.3, double seconds = 1, double standardSpeed = 0.5)
            => Run.Replay(new WeightSolver(WeightModel.FromMass(massKg), profile, standardSpeed), Run.Headset().Render(Run.Lift(rise, seconds)));

        [Test]
        public void NoEffectsFollowsTheHand()
        {
            var y = Lift(Only(), 5);
            Assert.That(Run.Last(y) - y[0], Is.EqualTo(0.3).Within(1e-9));
        }

        [Test]
        public void WeightGainScalesTheLiftByWstdOverW()
        {
            var y = Lift(Only(new WeightGain()), 0.09);
            Assert.That(Run.Last(y) - y[0], Is.EqualTo(0.3 * 0.5).Within(1e-9));
        }

        [Test]
        public void ExperimentalBlendAveragesEq4WithTheExperimentalRatio()
        {
            var y = Lift(Only(new WeightGain(), new ExperimentalBlend()), 1);
            double g = 0.5 * (0.045 + Math.Exp(-0.24 * (1 - 0.045)));
            Assert.That(Run.Last(y) - y[0], Is.EqualTo(0.3 * g).Within(1e-9));
        }

        [Test]
        public void SpeedCapHoldsBackAHeavyObjectLiftedFast()
        {
            var cap = new SpeedCap();
            var model = WeightModel.FromMass(20);
            Assert.That(cap.CapFor(WeightModel.FromMass(PhysicalConstants.StandardMassKg), 0.4), Is.EqualTo(1.0).Within(1e-12), "never below v_std at the golf ball");
            var frames = Run.Headset(frameRate: 120).Render(Run.Lift(0.4, 0.4));
            var solver = new WeightSolver(model, Only(cap), 0.2);
            var y = Run.Replay(solver, frames);
            for (int i = 1; i < y.Length; i++)
                Assert.That(Math.Abs(y[i] - y[i - 1]), Is.LessThanOrEqualTo(solver.Constants.CapSpeed / 30 + 1e-12), "frame " + i);
            Assert.That(Run.Last(y) - y[0], Is.LessThan(0.4));
        }

        [Test]
        public void SpeedCapJudgesSpeedOverThePoseIntervalNotTheFrame()
        {
            // A golf ball lifted at its user's standard speed under 120 Hz frames: a per-frame judgement would
            // see fourfold spikes and cap them.
            var frames = Run.Headset(frameRate: 120).Render(Run.Lift(0.3, 0.6));
            var y = Run.Replay(new WeightSolver(WeightModel.FromMass(PhysicalConstants.StandardMassKg), Only(new SpeedCap()), 0.5), frames);
            Assert.That(Run.Last(y) - y[0], Is.EqualTo(0.3).Within(1e-9));
        }

        [Test]
        public void DeadbandSwallowsJitterAndPassesMotion()
        {
            var db = Only(new MotionDeadband());
            var solver = new WeightSolver(WeightModel.FromMass(0.01), db, 0.5); // half-width max(3 mm, 4 mm)
            solver.BeginHold(1, 1);
            for (int i = 0; i < 100; i++) solver.Step(new HandSample(1 + (i % 2 == 0 ? 0.003 : -0.003)), 1 / 30.0);
            Assert.That(solver.ObjectY, Is.EqualTo(1.0), "±3 mm of jitter moves nothing");
            var y = Lift(db, 0.045);
            Assert.That(Run.Last(y) - y[0], Is.EqualTo(0.3 - 0.004).Within(1e-9), "a lift passes, less the band");
            Assert.That(new MotionDeadband().WidthFor(2.0), Is.EqualTo(0.012).Within(1e-12), "a fast user: v_std × 6 ms");
        }

        [Test]
        public void LoweringGuardKeepsTheOffsetFromGrowingWhileLowering()
        {
            var path = HandPath.StartAt(1).Hold(0.2).MoveTo(0.7, 0.6).Hold(0.3);
            var frames = Run.Headset().Render(path);
            var unguarded = Run.Replay(new WeightSolver(WeightModel.FromMass(5), Only(new WeightGain())), frames);
            var guarded = Run.Replay(new WeightSolver(WeightModel.FromMass(5), Only(new WeightGain(), new LoweringGuard())), frames);
            Assert.That(Run.MaxOffset(frames, unguarded), Is.GreaterThan(0.25), "Eq. 4 alone leaves a heavy object hanging above a lowered hand");
            Assert.That(Run.MaxOffset(frames, guarded), Is.LessThan(1e-9), "the guard brings it down with the hand");
        }

        [Test]
        public void OffsetCorrectionStopsGrowthPastTheThresholdWithoutJumps()
        {
            // Poses every frame, so the hand itself is smooth and any kink in the object's motion is the correction's.
            var frames = Run.Headset(frameRate: 90, poseRate: 90).Render(HandPath.StartAt(0.5).Hold(0.2).MoveTo(1.5, 1.5).Hold(0.5));
            var profile = Only(new WeightGain(), new OffsetCorrection());
            var y = Run.Replay(new WeightSolver(WeightModel.FromMass(3), profile), frames);
            Assert.That(Run.MaxOffset(frames, y), Is.InRange(0.2, 0.23), "the band ends at 0.22 m; one pose of growth may pass it");
            double maxSpeedChange = 0;
            for (int i = 2; i < y.Length; i++) maxSpeedChange = Math.Max(maxSpeedChange, Math.Abs((y[i] - y[i - 1]) - (y[i - 1] - y[i - 2])));
            Assert.That(maxSpeedChange, Is.LessThan(0.005), "per-frame change of the per-frame step, m: (1 − G)·v_hand spread over the 2 cm band");
        }

        [Test]
        public void OffsetCorrectionPullsABigOffsetBackGradually()
        {
            var solver = new WeightSolver(WeightModel.FromMass(1), Only(new OffsetCorrection()));
            solver.BeginHold(1.5, 1.0); // 0.5 m below the hand from the start
            double last = solver.ObjectY;
            for (int i = 0; i < 600; i++)
            {
                double y = solver.Step(new HandSample(1.5), 1 / 90.0);
                Assert.That(y - last, Is.InRange(0.0, 0.5 / 90 + 1e-12));
                last = y;
            }
            Assert.That(solver.Offset, Is.EqualTo(0.22).Within(0.001));
        }

        [Test]
        public void OffsetRelaxationReturnsAHeldOffsetToZeroOnlyWhenOn()
        {
            var frames = Run.Headset().Render(Run.Lift(0.3, 1).Hold(8));
            var off = Run.Replay(new WeightSolver(WeightModel.FromMass(2), Only(new WeightGain())), frames);
            var on = Run.Replay(new WeightSolver(WeightModel.FromMass(2), Only(new WeightGain(), new OffsetRelaxation())), frames);
            double hand = frames[frames.Length - 1].HandY;
            Assert.That(hand - Run.Last(off), Is.GreaterThan(0.25), "off: the offset is held");
            Assert.That(hand - Run.Last(on), Is.LessThan(0.01), "on: it relaxes (τ = 1.5 s, 8 s of rest)");
        }

        [Test]
        public void FloorClampHoldsLocalYAtZero()
        {
            var frames = Run.Headset().Render(HandPath.StartAt(0.1).MoveTo(-0.4, 0.5).MoveTo(0.1, 0.5));
            var y = Run.Replay(new WeightSolver(WeightModel.FromMass(0.01), Only(new FloorClamp())), frames);
            foreach (var v in y) Assert.That(v, Is.GreaterThanOrEqualTo(0.0));
            var free = Run.Replay(new WeightSolver(WeightModel.FromMass(0.01), Only()), frames);
            Assert.That(Array.Exists(free, v => v < -0.1), Is.True, "without it the object goes through");
        }

        [Test]
        public void TrackingLossHoldWaitsForSteadyTrackingThenReanchors()
        {
            var hold = Only(new TrackingLossHold(settleTime: 0.1));
            var solver = new WeightSolver(WeightModel.FromMass(0.045), hold);
            solver.BeginHold(1, 1, 0);
            double t = 0;
            for (int i = 0; i < 30; i++) { t += 1 / 90.0; solver.Step(HandSample.Lost, 1 / 90.0); }
            Assert.That(solver.ObjectY, Is.EqualTo(1.0), "held while lost");
            for (int i = 0; i < 5; i++) { t += 1 / 90.0; solver.Step(new HandSample(1.1, true, true, t), 1 / 90.0); }
            Assert.That(solver.ObjectY, Is.EqualTo(1.0), "still settling");
            for (int i = 0; i < 20; i++) { t += 1 / 90.0; solver.Step(new HandSample(1.1 + 0.001 * i, true, true, t), 1 / 90.0); }
            Assert.That(solver.ObjectY, Is.GreaterThan(1.0).And.LessThan(1.02), "follows from where the hand came back, no catch-up jump");
            solver.Step(new HandSample(1.5, true, false, t + 0.01), 1 / 90.0);
            Assert.That(solver.ObjectY, Is.LessThan(1.02), "a low-confidence pose counts as lost");
        }

        [Test]
        public void WithoutTrackingLossHoldAShortLossIsCaughtUpSmoothly()
        {
            var frames = Run.Headset(frameRate: 90).Drop(0.6, 0.15).Render(Run.Lift(0.3, 1));
            var y = Run.Replay(new WeightSolver(WeightModel.FromMass(0.045), Only()), frames);
            Assert.That(Run.Last(y) - y[0], Is.EqualTo(0.3).Within(1e-9), "nothing lost");
            Assert.That(Run.MaxStep(y), Is.LessThanOrEqualTo(0.1));
        }

        [Test]
        public void RepeatedPosesWithoutTimestampsAreNotStops()
        {
            var headset = Run.Headset(frameRate: 120);
            headset.WritePoseTime = false;
            var frames = headset.Render(Run.Lift(0.3, 0.6));
            var y = Run.Replay(new WeightSolver(WeightModel.FromMass(PhysicalConstants.StandardMassKg), NamedProfiles.Paper), frames);
            Assert.That(Run.Last(y) - y[0], Is.EqualTo(0.3).Within(0.004));
        }

        [Test]
        public void AnEffectOffIsNeverCalled()
        {
            Assert.That(NamedProfiles.Gain.Effects.Count, Is.EqualTo(3));
            Assert.That(NamedProfiles.PaperExperiment.Has<OffsetCorrection>(), Is.False);
            Assert.That(NamedProfiles.Paper.Has<OffsetCorrection>(), Is.True);
        }

        [Test]
        public void AHandFilterSmoothsJitterAndEndsWhereTheHandEnds()
        {
            var frames = Run.Headset(frameRate: 90, jitterSd: 0.002, seed: 3).Render(Run.Lift(0.3, 1).Hold(1));
            var raw = Run.Replay(new WeightSolver(WeightModel.FromMass(0.045), Only()), frames);
            var smooth = Run.Replay(new WeightSolver(WeightModel.FromMass(0.045), Only().WithHandFilter(new ExponentialSmoothing(0.05))), frames);
            double Roughness(double[] y) { double r = 0; for (int i = 2; i < y.Length; i++) r += Math.Abs(y[i] - 2 * y[i - 1] + y[i - 2]); return r; }
            Assert.That(Roughness(smooth), Is.LessThan(0.5 * Roughness(raw)));
            Assert.That(Run.Last(smooth), Is.EqualTo(1.1).Within(0.003), "the filter converges at rest, to the hand's height without its jitter");
        }

        [Test]
        public void EachSolverGetsItsOwnFilterInstance()
        {
            var profile = NamedProfiles.Gain.WithHandFilter(new ExponentialSmoothing(0.05));
            var a = new WeightSolver(WeightModel.FromMass(0.045), profile);
            var b = new WeightSolver(WeightModel.FromMass(0.045), profile);
            a.BeginHold(1, 1, 0);
            b.BeginHold(0, 0, 0);
            for (int i = 1; i < 50; i++) { a.Step(new HandSample(1.2, true, true, i / 30.0), 1 / 30.0); b.Step(new HandSample(0, true, true, i / 30.0), 1 / 30.0); }
            Assert.That(a.ObjectY, Is.EqualTo(1.2).Within(0.01));
            Assert.That(b.ObjectY, Is.EqualTo(0.0));
        }
    }
}
