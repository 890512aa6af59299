using System;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests.ThreeDimensions
{
    /// <summary>
    /// The steady followed point that drives lateral inertia (the median of the last three followed points), for survivors
    /// of the 3d-2 mutation run (quality.md, "In pieces"): it takes new poses only, never a frame that repeats one
    /// (30 Hz poses over 90 Hz frames), so a one-pose glitch of a still hand leaves the object exactly where it was; it
    /// stands still while no hand is followed, so the hand's lead on it is kept through a loss; and a pose repeated
    /// unchanged for exactly <c>SolverLimits.RepeatTime</c> (0.1 s) enters it again, as the same pose re-stamped would.
    /// </summary>
    public class SteadyPointTests
    {
        static readonly LateralInertia Inertia = new LateralInertia();
        static readonly WeightProfile Profile = NamedProfiles.Paper.With(Inertia, "paper+lateral");

        static WeightSolver3D Solver() => new WeightSolver3D(WeightModel.FromMass(2), Profile);

        [Test]
        public void AOnePoseGlitchOfAStillHandShownOverThreeFramesLeavesTheObjectExactlyWhereItWas([Values(0.05, -0.05, 0.2)] double glitch)
        {
            WeightSolver3D clean = Solver(), glitched = Solver();
            clean.BeginHold(Run3D.At(0.2, 1, 0.3, 0), 0.2, 1, 0.3);
            glitched.BeginHold(Run3D.At(0.2, 1, 0.3, 0), 0.2, 1, 0.3);
            bool moved = false;
            for (int frame = 1; frame <= 270; frame++)
            {
                int pose = frame / 3; // 30 Hz poses over 90 Hz frames: each shown for three frames
                double t = pose / 30.0, x = pose == 30 ? 0.2 + glitch : 0.2;
                clean.Step(Run3D.At(0.2, 1, 0.3, t), 1 / 90.0);
                glitched.Step(Run3D.At(x, 1, 0.3, t), 1 / 90.0);
                if (pose == 30) moved |= glitched.ObjectX != clean.ObjectX;
                if (pose > 30)
                {
                    Assert.That(glitched.ObjectX, Is.EqualTo(clean.ObjectX), "x at frame " + frame);
                    Assert.That(glitched.ObjectZ, Is.EqualTo(clean.ObjectZ), "z at frame " + frame);
                }
            }
            Assert.That(moved, Is.True, "the glitch itself is shown, as the hand's pose is");
        }

        [Test]
        public void WhereTheHandWasBeforeALossDoesNotReachTheSteadyPointAfterIt()
        {
            // Two holds begun still, one at x = +0.3 and one at −0.3 (no lag in either), lose the hand for half a second and
            // find it at x = 0, moving right 2 cm a pose: from there on the object moves the same in both, to the bit. The
            // steady point starts over after the loss: until three poses are back it is the first of them, whatever the
            // points before the loss were (a median over them would take +0.3's side and not −0.3's).
            WeightSolver3D right = Solver(), left = Solver();
            right.BeginHold(Run3D.At(0.3, 1, 0, 0), 0.3, 1, 0);
            left.BeginHold(Run3D.At(-0.3, 1, 0, 0), -0.3, 1, 0);
            double t = 0;
            for (int i = 0; i < 30; i++)
            {
                t += 1 / 30.0;
                right.Step(Run3D.At(0.3, 1, 0, t), 1 / 30.0);
                left.Step(Run3D.At(-0.3, 1, 0, t), 1 / 30.0);
            }
            Assert.That(right.LagX, Is.EqualTo(0.0));
            Assert.That(left.LagX, Is.EqualTo(0.0));
            for (int i = 0; i < 15; i++) { t += 1 / 30.0; right.Step(HandPose.Lost, 1 / 30.0); left.Step(HandPose.Lost, 1 / 30.0); }
            for (int i = 0; i < 30; i++)
            {
                t += 1 / 30.0;
                right.Step(Run3D.At(0.02 * i, 1, 0, t), 1 / 30.0);
                left.Step(Run3D.At(0.02 * i, 1, 0, t), 1 / 30.0);
                Assert.That(right.LagX, Is.EqualTo(left.LagX), "the lag, pose " + (i + 1) + " after the loss");
                Assert.That(right.ObjectX, Is.EqualTo(left.ObjectX), "the object (grabbed where the hand was, taken rigidly across the loss), pose " + (i + 1) + " after the loss");
            }
            Assert.That(right.LagX, Is.GreaterThan(0.001), "the carry after the loss left a lag");
        }

        [Test]
        public void WhileNoHandIsFollowedTheHandsLeadOnTheSteadyPointIsKept()
        {
            // 1 cm per pose sideways, a pose every frame: the steady point (the median of the last three) is one pose behind,
            // a lead of 1 cm. Then a loss of 6 s: the lag proper decays to nothing (twenty time constants), the lead stays,
            // and the object shows it through the saturating curve, M·tanh(lead/M).
            var s = Solver();
            s.BeginHold(Run3D.At(0, 1, 0, 0), 0, 1, 0);
            int i = 1;
            for (; i <= 30; i++) s.Step(Run3D.At(0.01 * i, 1, 0, i / 30.0), 1 / 30.0);
            Assert.That(s.LagX, Is.GreaterThan(0.01), "the carry left a lag behind the hand");
            for (int k = 0; k < 180; k++) s.Step(HandPose.Lost, 1 / 30.0);
            double m = Inertia.MaxOffset;
            Assert.That(s.LagX, Is.EqualTo(m * Math.Tanh(0.01 / m)).Within(1e-6));
            Assert.That(s.LagZ, Is.EqualTo(0.0));
        }

        [Test]
        public void APoseRepeatedForExactlyTheRepeatTimeEntersTheSteadyPointAsTheSamePoseReStampedWould()
        {
            // Frames of 0.05 s: two add up to 0.1 s exactly. One source repeats its last pose without a time stamp; the
            // other shows the same place with a new time stamp every 0.1 s. Sideways, the object must move the same.
            WeightSolver3D repeated = Solver(), stamped = Solver();
            repeated.BeginHold(Run3D.At(0, 1, 0, 0), 0, 1, 0);
            stamped.BeginHold(Run3D.At(0, 1, 0, 0), 0, 1, 0);
            const double dt = 0.05;
            double x = 0, t = 0;
            for (int i = 1; i <= 10; i++)
            {
                x = 0.01 * i;
                t = i * dt;
                repeated.Step(Run3D.At(x, 1, 0, t), dt);
                stamped.Step(Run3D.At(x, 1, 0, t), dt);
                Assert.That(repeated.ObjectX, Is.EqualTo(stamped.ObjectX));
            }
            Assert.That(0.0 + dt + dt, Is.EqualTo(0.1), "the repeat time is met exactly");
            for (int j = 1; j <= 12; j++)
            {
                repeated.Step(new HandPose(x, 1, 0, true, true, double.NaN), dt);
                stamped.Step(Run3D.At(x, 1, 0, t + 0.1 * (j / 2)), dt);
                Assert.That(repeated.ObjectX, Is.EqualTo(stamped.ObjectX), "x at rest frame " + j);
                Assert.That(repeated.ObjectZ, Is.EqualTo(stamped.ObjectZ), "z at rest frame " + j);
            }
            Assert.That(repeated.LagX, Is.Not.EqualTo(0.0), "the lag is still decaying: the two are compared where it tells");
        }
    }
}
