using System;
using NUnit.Framework;
using static Kosmos.PseudoHaptic.Tests.Run3D;

namespace Kosmos.PseudoHaptic.Tests.ThreeDimensions
{
    /// <summary>
    /// The 3D solver's x/z, pose by pose (1/32 s poses, so every sum is exact): after a long loss the tracking-loss hold
    /// waits SettleTime before x/z follow again; a sideways step no hand can make re-anchors (the object stays); with
    /// the offset correction, what re-anchoring left sideways is pulled back at its pull speed, ramping over five band
    /// widths, each frame counting at most the longest frame. As y does in the 1D solver.
    /// </summary>
    public class HorizontalTrackingTests
    {
        const double Pose = 1 / 32.0;

        // Paper without the correction: x/z follow the hand 1:1 (no lateral inertia), the hold settles after losses.
        static WeightSolver3D Solver(WeightProfile profile = null, double massKg = 1)
            => new WeightSolver3D(WeightModel.FromMass(massKg), profile ?? NamedProfiles.PaperExperiment);

        [Test]
        public void AfterALongLossXAndZWaitForSteadyTrackingThenFollowFromWhereTheObjectIs()
        {
            var s = Solver();
            double t = 0;
            s.BeginHold(At(0, 1, 0, t), 0, 1, 0);
            for (int i = 0; i < 4; i++) { t += Pose; s.Step(At(0.01 * (i + 1), 1, 0, t), Pose); }
            Assert.That(s.ObjectX, Is.EqualTo(0.04).Within(1e-12), "followed 1:1 while tracked");
            for (int i = 0; i < 10; i++) { t += Pose; s.Step(HandPose.Lost, Pose); }            // 0.31 s lost
            double x = 0.34;
            for (int i = 0; i < 4; i++)
            {
                t += Pose; x += 0.01;
                s.Step(At(x, 1, -0.2, t), Pose);
                Assert.That(s.ObjectX, Is.EqualTo(0.04).Within(1e-12), "settling (0.1 s = 4 poses of 1/32 s), pose " + i);
                Assert.That(s.ObjectZ, Is.EqualTo(0.0).Within(1e-12));
            }
            t += Pose; x += 0.01;
            s.Step(At(x, 1, -0.21, t), Pose);
            Assert.That(s.ObjectX, Is.EqualTo(0.05).Within(1e-12), "then the hand's next step, from where the object was");
            Assert.That(s.ObjectZ, Is.EqualTo(-0.01).Within(1e-12));
        }

        [Test]
        public void AfterAShortLossXAndZDoNotJumpTheySettleAndFollowFromWhereTheObjectIs()
        {
            // Unlike y (caught up through the speed limit), x/z have no speed limit to spread a catch-up over frames, so
            // with the tracking-loss hold they settle after any loss; what the hand moved sideways during the blink is
            // left as an offset (stability.md, known limits).
            var s = Solver();
            double t = 0;
            s.BeginHold(At(0, 1, 0, t), 0, 1, 0);
            t += Pose; s.Step(At(0.01, 1, 0, t), Pose);
            for (int i = 0; i < 6; i++) { t += Pose; s.Step(HandPose.Lost, Pose); }              // 0.19 s lost
            for (int i = 0; i < 4; i++)
            {
                t += Pose; s.Step(At(0.41, 1, 0.05, t), Pose);
                Assert.That(s.ObjectX, Is.EqualTo(0.01).Within(1e-12), "no jump: settling, pose " + i);
            }
            t += Pose; s.Step(At(0.42, 1, 0.05, t), Pose);
            Assert.That(s.ObjectX, Is.EqualTo(0.02).Within(1e-12), "then the hand's next step");
            Assert.That(s.ObjectZ, Is.EqualTo(0.0).Within(1e-12));
        }

        [TestCase(0.15, 0.10, false)] // 0.18 m in a 1/32 s pose: under 6 m/s × 1/30 s = 0.2 m, followed
        [TestCase(0.15, 0.15, true)]  // 0.21 m: no hand moves so fast, re-anchored
        public void ASidewaysStepNoHandCanMakeReanchors(double dx, double dz, bool reanchors)
        {
            var s = Solver();
            double t = 0;
            s.BeginHold(At(0, 1, 0, t), 0, 1, 0);
            t += Pose; s.Step(At(0.01, 1, 0, t), Pose);
            t += Pose; s.Step(At(0.01 + dx, 1, dz, t), Pose);
            Assert.That(s.ObjectX, Is.EqualTo(reanchors ? 0.01 : 0.01 + dx).Within(1e-12));
            Assert.That(s.ObjectZ, Is.EqualTo(reanchors ? 0 : dz).Within(1e-12));
            t += Pose; s.Step(At(0.02 + dx, 1, dz, t), Pose);
            Assert.That(s.ObjectX, Is.EqualTo((reanchors ? 0.02 : 0.02 + dx)).Within(1e-12), "then followed");
        }

        [TestCase(0.04, 0.23, false)] // a 40 ms frame right after motion: judged over it, 6 m/s × 0.04 s = 0.24 m
        [TestCase(0.04, 0.25, true)]
        [TestCase(0.01, 0.19, false)] // a 10 ms frame (two poses in one short frame): over a 30 Hz pose at least, 0.2 m
        [TestCase(0.01, 0.21, true)]
        public void ASidewaysStepIsJudgedOverTheTimeSinceTheLastSidewaysMotion(double frame, double dx, bool reanchors)
        {
            var s = Solver();
            double t = 0;
            s.BeginHold(At(0, 1, 0, t), 0, 1, 0);
            t += Pose; s.Step(At(0.01, 1, 0, t), Pose);
            t += frame; s.Step(At(0.01 + dx, 1, 0, t), frame);
            Assert.That(s.ObjectX, Is.EqualTo(reanchors ? 0.01 : 0.01 + dx).Within(1e-12));
        }

        [TestCase(0.29, false)] // still for 0.1 s, then a 10 ms frame: judged over at most 50 ms, 6 m/s × 0.05 s = 0.3 m
        [TestCase(0.31, true)]
        public void AfterStillnessASidewaysStepIsJudgedOverTheLongestWindow(double dx, bool reanchors)
        {
            // Still frames (new poses, no sideways motion) do not restart the window; a sideways step does.
            var s = Solver();
            double t = 0;
            s.BeginHold(At(0, 1, 0, t), 0, 1, 0);
            t += Pose; s.Step(At(0, 1, 0.01, t), Pose);
            for (int i = 0; i < 9; i++) { t += 0.01; s.Step(At(0, 1, 0.01, t), 0.01); }
            t += 0.01; s.Step(At(dx, 1, 0.01, t), 0.01);
            Assert.That(s.ObjectX, Is.EqualTo(reanchors ? 0 : dx).Within(1e-12));
            t += 0.01; s.Step(At(dx, 1, 0.01 + 0.21, t), 0.01);
            Assert.That(s.ObjectZ, Is.EqualTo(0.01).Within(1e-12), "10 ms after the step in x, a 0.21 m step in z is judged over 1/30 s: re-anchored (the object stays)");
        }

        // Without the tracking-loss hold, x/z treat a loss as y's estimator does: a short one is caught up, a longer one
        // than the catch-up gap (0.25 s = 8 poses) re-anchors, whatever the hand did meanwhile.
        [TestCase(8, false)]
        [TestCase(9, true)]
        public void WithoutTheLossHoldAShortLossIsCaughtUpInEveryAxisAndALongOneReanchors(int lostPoses, bool reanchors)
        {
            var s = Solver(NamedProfiles.PaperExperiment.Without<TrackingLossHold>(), PhysicalConstants.StandardMassKg);
            double t = 0;
            s.BeginHold(At(0, 1, 0, t), 0, 1, 0);
            for (int i = 0; i < 3; i++) { t += Pose; s.Step(At(0, 1, 0, t), Pose); }
            for (int i = 0; i < lostPoses; i++) { t += Pose; s.Step(HandPose.Lost, Pose); }
            t += Pose; s.Step(At(0.05, 1.05, 0.05, t), Pose);
            double expected = reanchors ? 0 : 0.05;
            Assert.That(new[] { s.ObjectX, s.ObjectY - 1, s.ObjectZ }, Is.EqualTo(new[] { expected, expected, expected }).Within(1e-12));
        }

        // (where the object was grabbed beside the hand, x and z), m: the pull draws it back to that grab offset, not onto the hand.
        [TestCase(0.0, 0.0)]
        [TestCase(0.08, -0.06)]
        public void WithTheCorrectionWhatReanchoringLeftSidewaysIsPulledBack(double grabX, double grabZ)
        {
            var s = Solver(NamedProfiles.Paper);
            double t = 0;
            s.BeginHold(At(0, 1, 0, t), grabX, 1, grabZ);
            t += Pose; s.Step(At(0, 1, 0, t), Pose);
            for (int i = 0; i < 10; i++) { t += Pose; s.Step(HandPose.Lost, Pose); }
            for (int i = 0; i < 4; i++) { t += Pose; s.Step(At(0.3, 1, 0.4, t), Pose); }         // back 0.5 m away: settles
            double x = s.ObjectX, z = s.ObjectZ, goalX = 0.3 + grabX, goalZ = 0.4 + grabZ;
            Assert.That(Math.Sqrt((x - grabX) * (x - grabX) + (z - grabZ) * (z - grabZ)), Is.LessThan(0.02), "re-anchored: the object stayed (the pull began)");
            for (int i = 0; i < 80; i++)
            {
                t += Pose;
                s.Step(At(0.3, 1, 0.4, t), Pose);
                double r = Math.Sqrt((goalX - x) * (goalX - x) + (goalZ - z) * (goalZ - z));
                double pull = Math.Min(r, 0.5 * Math.Min(1, r / 0.1) * 0.025); // 1/32 s counts as 25 ms
                Assert.That(s.ObjectX, Is.EqualTo(x + (goalX - x) / r * pull).Within(1e-12), "pose " + i);
                Assert.That(s.ObjectZ, Is.EqualTo(z + (goalZ - z) / r * pull).Within(1e-12), "pose " + i);
                x = s.ObjectX; z = s.ObjectZ;
            }
            Assert.That(Math.Sqrt((goalX - x) * (goalX - x) + (goalZ - z) * (goalZ - z)), Is.LessThan(0.01), "drawn back to where it was grabbed");
        }

        [Test]
        public void APullFastEnoughToCloseTheGapInOneFrameLandsOnTheGrabOffsetNeverPastIt()
        {
            // 10 m/s ramped over 0.1 m: 10 × (r / 0.1) × 25 ms = 2.5 r, more than the gap, for any gap under 0.25 m.
            var s = Solver(NamedProfiles.Paper.With(new OffsetCorrection(pullSpeed: 10)));
            double t = 0;
            s.BeginHold(At(0, 1, 0, t), 0.08, 1, -0.06);
            t += Pose; s.Step(At(0, 1, 0, t), Pose);
            for (int i = 0; i < 10; i++) { t += Pose; s.Step(HandPose.Lost, Pose); }
            for (int i = 0; i < 4; i++) { t += Pose; s.Step(At(0.12, 1, 0.16, t), Pose); }      // back 0.2 m away: settles
            Assert.That(s.ObjectX, Is.EqualTo(0.12 + 0.08).Within(1e-12), "at the grab offset beside the hand at once");
            Assert.That(s.ObjectZ, Is.EqualTo(0.16 - 0.06).Within(1e-12));
            t += Pose; s.Step(At(0.12, 1, 0.16, t), Pose);
            Assert.That(new[] { s.ObjectX, s.ObjectZ }, Is.EqualTo(new[] { 0.2, 0.1 }).Within(1e-12), "and stays there");
        }
    }
}
