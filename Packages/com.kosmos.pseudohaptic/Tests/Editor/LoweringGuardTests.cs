using System;
using Kosmos.PseudoHaptic.Simulation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>
    /// The lowering guard moves the base the lift is measured from down with the steady hand (a slack above it): below the
    /// base the object moves with the hand, the next lift is weighed from where it starts, and neither jitter, a one-pose
    /// glitch nor a motion that comes back moves the base.
    /// </summary>
    public class LoweringGuardTests
    {
        static WeightSolver Heavy(params WeightEffect[] more)
        {
            var effects = new System.Collections.Generic.List<WeightEffect> { new WeightGain(), new LoweringGuard() };
            effects.AddRange(more);
            return new WeightSolver(WeightModel.FromMass(2), new WeightProfile("guarded", effects));
        }

        [Test]
        public void LoweredBelowTheBaseTheObjectMovesWithTheHandAndTheNextLiftIsWeighedFromThere()
        {
            var s = Heavy();
            var frames = Run.Headset(frameRate: 90).Render(HandPath.StartAt(1.0).Hold(0.3).MoveTo(0.6, 0.8).Hold(0.5).MoveTo(0.9, 1).Hold(0.5));
            var y = new double[frames.Length];
            s.BeginHold(frames[0].HandY, frames[0].HandY, frames[0].PoseTime);
            double lowest = double.PositiveInfinity;
            for (int i = 1; i < frames.Length; i++)
            {
                y[i] = s.Step(frames[i].ToSample(), frames[i].Time - frames[i - 1].Time);
                if (frames[i].Time < 1.6) Assert.That(Math.Abs(frames[i].HandY - y[i]), Is.LessThanOrEqualTo(0.005 + 1e-12), "lowering: with the hand, frame " + i);
                if (frames[i].Time < 1.6) lowest = Math.Min(lowest, y[i]);
            }
            Assert.That(s.State.Base, Is.EqualTo(0.6 + 0.005).Within(1e-9), "the base is where the hand rested, plus the slack");
            double lift = 0.9 - 0.605, gain = s.Gain;
            Assert.That(Run.Last(y) - lowest, Is.EqualTo(gain * lift).Within(0.006), "the next lift weighed from where it started");
        }

        [Test]
        public void WithoutItAHeavyObjectLoweredFloatsAboveTheHand()
        {
            var frames = Run.Headset(frameRate: 90).Render(HandPath.StartAt(1.0).Hold(0.3).MoveTo(0.6, 0.8).Hold(0.5));
            var without = Run.Replay(new WeightSolver(WeightModel.FromMass(2), new WeightProfile("bare", new WeightEffect[] { new WeightGain() })), frames);
            var with = Run.Replay(Heavy(), frames);
            Assert.That(Run.Last(without) - 0.6, Is.GreaterThan(0.2), "Eq. 4 alone: G × the lowering");
            Assert.That(Run.Last(with), Is.EqualTo(0.6).Within(1e-9));
        }

        [Test]
        public void JitterAGlitchAndAHeftNeverMoveTheBase([Range(1, 40)] int seed)
        {
            var rng = new Random(seed);
            var path = HandPath.StartAt(1.0).Hold(0.5).MoveTo(1.3, 1).Hold(0.5).MoveTo(1.42, 0.3).MoveTo(1.3, 0.3).Hold(1);
            var headset = new HeadsetSimulator { FrameRate = 90, JitterSd = 0.0015, Seed = seed }.Glitch(0.2 + rng.NextDouble(), -0.2).Glitch(2.5 + rng.NextDouble(), -0.2);
            var s = Heavy();
            Run.Replay(s, headset.Render(path));
            Assert.That(s.State.Base, Is.EqualTo(1.0).Within(0.0045), "seed " + seed + ": within the jitter of where the hold began");
        }

        /// <summary>
        /// A glitch that stays for two or more poses passes the median of three: the hand rests, then 1–6 consecutive poses
        /// are 3 cm low (30 Hz poses over 90 Hz frames, clean), from the hold's third pose or after half a second, then it
        /// rests again; with and without the offset relaxation (which reads time, so that every frame runs the effects, not
        /// only those with a new pose). Up to four such poses leave the base where the hold began and a 2 kg object where
        /// it was; five or more are a lowering (the base follows, a slack above the hand). Before the guard undid a drop the
        /// hand came back up from within five steady poses, two poses lowered it for the rest of the hold.
        /// </summary>
        [Test]
        public void AHandBelowTheBaseForFewerThanFiveSteadyPosesLowersNothing([Range(1, 6)] int poses, [Values(15, 2)] int fromPose, [Values(false, true)] bool relaxing)
        {
            var path = HandPath.StartAt(1.0).Hold(1.5);
            var frames = Run.Headset(frameRate: 90).Offset((fromPose + 0.5) / 30, poses / 30.0, -0.03).Render(path);
            WeightSolver Solver() => relaxing ? Heavy(new OffsetRelaxation()) : Heavy();
            var still = Run.Replay(Solver(), Run.Headset(frameRate: 90).Render(path));
            var s = Solver();
            var y = Run.Replay(s, frames);
            if (poses <= 4)
            {
                Assert.That(s.State.Base, Is.EqualTo(1.0).Within(1e-12), "the base where the hold began");
                Assert.That(Run.Last(y), Is.EqualTo(Run.Last(still)).Within(1e-12), "the object where it was");
            }
            else if (!relaxing) Assert.That(s.State.Base, Is.EqualTo(0.975).Within(1e-12), "a lowering: the base a slack above the hand's lowest");
            else Assert.That(s.State.Base, Is.LessThan(0.999), "a lowering, the relaxation raising the base back toward the hand since");
        }

        /// <summary>
        /// A glitch of three poses right after a lowering: the hand lowers 5 cm in 0.5 s, rests 0–3 poses, then three poses
        /// are 3 cm low, then it rests 0.5 s (clean poses). The base ends a slack above where the hand rests, whichever pose
        /// the glitch began on: the glitch is not part of the lowering.
        /// </summary>
        [Test]
        public void AGlitchRightAfterALoweringLeavesTheBaseWhereTheHandRests([Range(0, 3)] int restPoses)
        {
            var path = HandPath.StartAt(1.0).Hold(0.3).MoveTo(0.95, 0.5);
            double at = (Math.Round(path.Duration * 30) + restPoses + 0.5) / 30;
            path.Hold(1);
            var s = Heavy();
            Run.Replay(s, Run.Headset(frameRate: 90).Offset(at, 3 / 30.0, -0.03).Render(path));
            Assert.That(s.State.Base, Is.EqualTo(0.955).Within(1e-9));
        }

        /// <summary>
        /// A gap that hides the way back up is no dip: the hand lowers 20 cm in 0.2 s, rests two poses at the bottom, and
        /// rises back in 0.2 s while tracking is lost (or low-confidence under the tracking-loss hold, whose poses are not
        /// remembered) for 0.25 s; found again at the top, the lift is weighed from the lowest point the hold saw, as it
        /// would be had the rise been seen: the base ends a slack above the lowest median of three poses before the gap. (Counted across the gap,
        /// the base five steady poses before the hand was found again lay on the way down, and the rise undid the lowering:
        /// 0.85–0.9 m.)
        /// </summary>
        [Test]
        public void AGapThatHidesTheWayBackUpLeavesTheBaseAtTheLowestPointSeen([Values(false, true)] bool lowConfidence)
        {
            var path = HandPath.StartAt(1.0).Hold(0.5).MoveTo(0.8, 0.2).Hold(2 / 30.0);
            double from = path.Duration;
            path.MoveTo(1.0, 0.2).Hold(1);
            var headset = Run.Headset(frameRate: 90);
            if (lowConfidence) headset.LowConfidence(from, 0.25);
            else headset.Drop(from, 0.25);
            var frames = headset.Render(path);
            var s = lowConfidence ? Heavy(new TrackingLossHold()) : Heavy();
            Run.Replay(s, frames);
            // The lowest point the hold saw: the lowest median of three consecutive poses before the gap, plus the slack.
            var poses = new System.Collections.Generic.List<double>();
            for (int i = 0; i < frames.Length && frames[i].Time < from; i++)
                if (i == 0 || frames[i].PoseTime != frames[i - 1].PoseTime) poses.Add(frames[i].HandY);
            double lowest = double.PositiveInfinity;
            for (int i = 2; i < poses.Count; i++)
                lowest = Math.Min(lowest, Math.Max(Math.Min(poses[i], poses[i - 1]), Math.Min(Math.Max(poses[i], poses[i - 1]), poses[i - 2])));
            Assert.That(lowest, Is.LessThan(0.815), "the hold saw the bottom");
            Assert.That(s.State.Base, Is.EqualTo(lowest + 0.005).Within(1e-9));
        }

        /// <summary>
        /// A grab on a pose 6–20 mm above where the hand then rests: the solver measures the lift from the first poses instead
        /// (a glitched grab pose), and the guard must not take that for a dip that came back. It did: it put the base back
        /// up within the slack of the grab's pose, 5 mm above the hand, and the next lift was weighed 5 mm short (a light
        /// object's lead, G − 1 times that, lost for the hold). With and without the light object's deadband, which measures
        /// the lift from the same poses: the base ends where the hand rests, and a 10 cm lift ends where the same lift from a
        /// clean grab does (P12's bounds).
        /// </summary>
        [Test]
        public void AGrabOnAGlitchedPoseAboveTheHandLeavesTheBaseWhereTheHandRests([Values(0.006, 0.008, 0.02)] double above,
            [Values(0.001, PhysicalConstants.StandardMassKg, 1.0)] double mass, [Values("paper", "gain")] string profile)
        {
            double Lift(double grabPose, out double baseAtRest)
            {
                var solver = new WeightSolver(WeightModel.FromMass(mass), NamedProfiles.Get(profile));
                double t = 0;
                solver.BeginHold(grabPose, grabPose, t);
                double Pose(double hand) { t += 1 / 30.0; return solver.Step(new HandSample(hand, true, true, t), 1 / 30.0); }
                for (int i = 0; i < 30; i++) Pose(1.0);
                baseAtRest = solver.State.Base;
                for (int i = 1; i <= 30; i++) Pose(1.0 + 0.1 * i / 30);
                double y = 0;
                for (int i = 0; i < 60; i++) y = Pose(1.1);
                return y;
            }
            double glitched = Lift(1.0 + above, out double glitchedBase), clean = Lift(1.0, out _);
            TestContext.Progress.WriteLine($"{profile}, {mass * 1000} g, grab {above * 1000} mm above: base {(glitchedBase - 1) * 1000:F2} mm, the lift ends {(glitched - clean) * 1000:F2} mm from the clean grab's");
            Assert.That(glitchedBase, Is.EqualTo(1.0).Within(1e-9), "the base is where the hand rests");
            // Placed at the hand in both (no grab offset), the object ends where the clean grab's does.
            double bound = mass == PhysicalConstants.StandardMassKg ? 0.001 : 0.01;
            Assert.That(glitched - clean, Is.EqualTo(0).Within(bound), "a lift after it ends where the same lift from a clean grab does");
        }

        [Test]
        public void TheSlackIsValidatedAndNamed()
        {
            Assert.That(new LoweringGuard().Slack, Is.EqualTo(0.005));
            Assert.That(() => new LoweringGuard(-0.001), Throws.InstanceOf<ArgumentOutOfRangeException>().With.Message.Contains("slack"));
            Assert.That(() => new LoweringGuard(double.NaN), Throws.InstanceOf<ArgumentOutOfRangeException>().With.Message.Contains("slack"));
            Assert.That(new LoweringGuard().Name, Is.EqualTo("lowering-guard"));
            Assert.That(new LoweringGuard().Stage, Is.EqualTo(EffectStage.Base));
        }
    }
}
