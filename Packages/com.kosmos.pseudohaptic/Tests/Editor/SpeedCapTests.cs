using System;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>
    /// The speed cap pose by pose (1/32 s poses, gain 1 so only the cap shapes the motion): over each new pose the
    /// object moves at most v_cap × the pose's interval; what it held back is owed (at most the carry limit) and paid
    /// at v_cap over the following poses, cancelled by motion the other way; frames without a new pose pay nothing.
    /// </summary>
    public class SpeedCapTests
    {
        const double Pose = 1 / 32.0;

        static WeightSolver Capped(double massKg, SolverLimits limits = null)
        {
            var cap = new SpeedCap();
            var s = new WeightSolver(WeightModel.FromMass(massKg), new WeightProfile("test", new WeightEffect[] { cap }, limits), 0.5);
            Assert.That(s.Gain, Is.EqualTo(1.0), "the cap alone: gain 1");
            Assert.That(s.Constants.CapSpeed, Is.EqualTo(cap.CapFor(s.Model, 0.5)), "the solver's cap is the effect's");
            return s;
        }

        [Test]
        public void OverEachPoseTheObjectMovesAtMostTheCapAndPaysWhatItOwesAfterwards()
        {
            var s = Capped(2);
            double perPose = s.Constants.CapSpeed * Pose;
            Assert.That(perPose, Is.InRange(0.005, 0.04), "2 kg for a user of 0.5 m/s");
            double t = 0, hand = 1.0, y = 1.0, owed = 0;
            s.BeginHold(hand, hand, t);
            for (int i = 0; i < 4; i++)
            {
                t += Pose; hand += 0.05;
                double next = s.Step(new HandSample(hand, true, true, t), Pose);
                Assert.That(next - y, Is.EqualTo(perPose).Within(1e-12), "lifting, pose " + i);
                owed += 0.05 - perPose;
                Assert.That(s.State.CapDeferred, Is.EqualTo(owed).Within(1e-12));
                y = next;
            }
            // The same pose again (same timestamp) is no new pose: nothing is paid, however long the frame.
            Assert.That(s.Step(new HandSample(hand, true, true, t), Pose), Is.EqualTo(y));
            int poses = 0;
            while (s.State.CapDeferred > 0 && poses < 100)
            {
                t += Pose;
                double next = s.Step(new HandSample(hand, true, true, t), Pose);
                Assert.That(next - y, Is.EqualTo(Math.Min(perPose, owed)).Within(1e-12), "the hand still, pose " + poses);
                owed -= next - y;
                y = next;
                poses++;
            }
            Assert.That(y, Is.EqualTo(hand).Within(1e-12), "deferred, not lost");
            Assert.That(poses, Is.EqualTo((int)Math.Ceiling((0.2 - 4 * perPose) / perPose - 1e-9)));
        }

        [Test]
        public void TheHandTurningBackCancelsWhatIsOwed()
        {
            var s = Capped(2);
            double perPose = s.Constants.CapSpeed * Pose, t = 0, hand = 1.0;
            s.BeginHold(hand, hand, t);
            t += Pose; hand += 0.05;
            double y = s.Step(new HandSample(hand, true, true, t), Pose);
            double owed = 0.05 - perPose;
            t += Pose; hand -= 0.04; // down by less than is owed: the object still rises, by what is left
            double next = s.Step(new HandSample(hand, true, true, t), Pose);
            Assert.That(next - y, Is.EqualTo(Math.Min(perPose, owed - 0.04)).Within(1e-12));
            Assert.That(s.State.CapDeferred, Is.EqualTo(Math.Max(0, owed - 0.04 - perPose)).Within(1e-12));
        }

        [Test]
        public void WhatIsOwedIsLimitedToTheCarryLimitAndLoweringIsCappedToo()
        {
            var s = Capped(5, new SolverLimits(maxCarry: 0.03));
            double perPose = s.Constants.CapSpeed * Pose, t = 0, hand = 1.0;
            s.BeginHold(hand, hand, t);
            for (int i = 0; i < 6; i++) { t += Pose; hand += 0.1; s.Step(new HandSample(hand, true, true, t), Pose); }
            Assert.That(s.State.CapDeferred, Is.EqualTo(0.03), "at most the carry limit is owed");
            for (int i = 0; i < 6; i++) { t += Pose; hand -= 0.1; s.Step(new HandSample(hand, true, true, t), Pose); }
            Assert.That(s.State.CapDeferred, Is.EqualTo(-0.03), "lowering fast is owed downward, within the same limit");
            double y = s.ObjectY;
            t += Pose; hand -= 0.1;
            Assert.That(s.Step(new HandSample(hand, true, true, t), Pose) - y, Is.EqualTo(-perPose).Within(1e-12), "lowered at the cap too");
        }

        [TestCase(0.02)] // 0.64 m/s: the filtered hand outruns v_cap (0.78 m/s) only at its peaks
        [TestCase(0.06)] // 1.92 m/s: capped throughout, the rest owed
        public void WithAHandFilterTheObjectNeverOutrunsTheCapOverAnyFrame(double perPoseRise)
        {
            // A filter spreads each pose's motion over the frames after it (90 Hz frames, 30 Hz poses): the object
            // moves on frames without a new pose too, so the cap judges every frame over its own time. Judged over
            // the pose's interval on the pose's frame and again on the frames between, it would move up to 5/3 of v_cap.
            const double frame = 1 / 96.0;
            var cap = new SpeedCap();
            var s = new WeightSolver(WeightModel.FromMass(2),
                new WeightProfile("test", new WeightEffect[] { cap }).WithHandFilter(new ExponentialSmoothing(0.03)), 0.5);
            double v = s.Constants.CapSpeed, t = 0, hand = 1.0, y = 1.0, owed = 0, moved = 0;
            s.BeginHold(hand, hand, t);
            int framesBetweenPosesThatMoved = 0;
            for (int i = 0; i < 96; i++)
            {
                bool pose = i % 3 == 0 && i < 24; // lift for a quarter of a second, then hold still
                if (pose) { t += Pose; hand += perPoseRise; }
                double before = s.State.HandY, next = s.Step(new HandSample(hand, true, true, t), frame);
                double wanted = s.State.HandY - before + owed; // the filtered hand's motion (gain 1) plus what was owed
                double expected = Math.Min(wanted, v * frame);
                Assert.That(next - y, Is.EqualTo(expected).Within(1e-12), "frame " + i + ": the filtered hand's motion, at most v_cap over the frame");
                owed = wanted - expected;
                if (!pose && next != y) framesBetweenPosesThatMoved++;
                moved += next - y;
                y = next;
            }
            Assert.That(framesBetweenPosesThatMoved, Is.GreaterThan(40), "the filter moves the object between poses");
            Assert.That(moved, Is.LessThanOrEqualTo(v * 96 * frame + 1e-12), "over the second, no faster than v_cap");
            Assert.That(s.State.CapDeferred, Is.EqualTo(owed).Within(1e-12), "the rest is owed");
        }

        /// <summary>A scene's own hand-motion effect that moves the followed hand up on every frame, new pose or not.</summary>
        sealed class Drift : WeightEffect
        {
            public override string Name => "drift";
            public override EffectStage Stage => EffectStage.HandMotion;
            protected override void Apply(ref MotionFrame frame, ref HoldState state, in SolverConstants constants) => frame.HandDelta += 1.0 * frame.Dt;
        }

        [Test]
        public void MotionAnEffectMakesBetweenPosesIsJudgedOverTheFrame()
        {
            const double frame = 1 / 90.0;
            var s = new WeightSolver(WeightModel.FromMass(2), new WeightProfile("test", new WeightEffect[] { new Drift(), new SpeedCap() }), 0.5);
            double v = s.Constants.CapSpeed;
            Assert.That(v, Is.InRange(0.5, 0.9), "the drift's 1 m/s outruns the cap");
            s.BeginHold(1.0, 1.0, 0);
            double y = 1.0;
            for (int i = 0; i < 9; i++)
            {
                double next = s.Step(new HandSample(1.0, true, true, 0), frame); // the same pose: no new one
                Assert.That(next - y, Is.EqualTo(v * frame).Within(1e-12), "frame " + i);
                y = next;
            }
            Assert.That(s.State.CapDeferred, Is.EqualTo(9 * (1.0 - v) * frame).Within(1e-12), "the rest is owed");
        }

        [Test]
        public void TheStandardWeightAndLighterAreNeverCapped()
        {
            var s = Capped(PhysicalConstants.StandardMassKg);
            Assert.That(s.Constants.CapSpeed, Is.EqualTo(double.PositiveInfinity));
            double t = Pose;
            s.BeginHold(1.0, 1.0, 0);
            Assert.That(s.Step(new HandSample(1.09, true, true, t), Pose), Is.EqualTo(1.09).Within(1e-12), "2.9 m/s: rigid in the hand");
            Assert.That(new SpeedCap().Name, Is.EqualTo("speed-cap"));
            Assert.That(new SpeedCap(4).Headroom, Is.EqualTo(4));
            Assert.That(new SpeedCap(4).CapFor(WeightModel.FromMass(2), 0.5), Is.EqualTo(1.6 * new SpeedCap().CapFor(WeightModel.FromMass(2), 0.5)).Within(1e-12));
        }
    }
}
