using System;
using NUnit.Framework;
using static Kosmos.PseudoHaptic.Tests.Run3D;

namespace Kosmos.PseudoHaptic.Tests.ThreeDimensions
{
    /// <summary>Issue 10, break-away: off by default; with a distance, the hold ends by itself once the hand is that far
    /// from where it grabbed, reported in the solver's state; the object stays where it was let go.</summary>
    public class BreakAwayTests
    {
        // A fast, high lift of a heavy object: the object lags up to the offset correction's 0.22 m below the hand.
        static HandPath3D HighLift => (double t, out double x, out double y, out double z) =>
        {
            x = 0.1;
            y = 0.9 + 0.8 * Headset3D.MinJerk(t, 0.3, 0.8, 0, 1);
            z = 0.2;
        };

        [Test]
        public void OffByDefaultInEveryNamedProfile([Values("paper", "paper-experiment", "gain", "xyz")] string name)
        {
            Assert.That(NamedProfiles.Get(name).Has<BreakAway>(), Is.False);
            var f = new Headset3D().Render(HighLift, null, 2);
            var r = Run3D.Of(new WeightSolver3D(WeightModel.FromMass(10), NamedProfiles.Get(name)), f);
            Assert.That(r.Holding, Has.All.True);
        }

        [Test]
        public void PulledTooFarTheHoldEndsAndTheObjectStays()
        {
            var solver = new WeightSolver3D(WeightModel.FromMass(10), NamedProfiles.Paper.With(new BreakAway(0.15)));
            var f = new Headset3D().Render(HighLift, null, 2);
            var r = Run3D.Of(solver, f);
            int ended = Array.IndexOf(r.Holding, false);
            Assert.That(ended, Is.GreaterThan(0), "the hold ended");
            Assert.That(solver.BrokeAway, Is.True);
            Assert.That(solver.IsHolding, Is.False);
            for (int i = ended; i < r.Y.Length; i++)
            {
                Assert.That(r.Holding[i], Is.False, "it does not restart");
                Assert.That(r.Y[i], Is.EqualTo(r.Y[ended]), "the object stays where it was let go");
                Assert.That(r.X[i], Is.EqualTo(r.X[ended]));
            }
            double dy = f.A[ended].Y - r.Y[ended] - (f.A[0].Y - r.Y[0]);
            Assert.That(dy, Is.GreaterThan(0.15), "it broke away beyond the distance, not before");
            int beyond = 0;
            while (f.A[beyond].Y - r.Y[beyond] - (f.A[0].Y - r.Y[0]) <= 0.15) beyond++;
            // After the default dwell of 0.1 s beyond it (a frame where the object catches up restarts the dwell: at most one 30 Hz pose).
            Assert.That(f.T[ended] - f.T[beyond], Is.InRange(0.1 - 1.01 / 90, 0.1 + 1 / 30.0 + 1.01 / 90));
        }

        [Test]
        public void ALightObjectOrAGentleLiftDoesNotBreakAway()
        {
            var f = new Headset3D().Render(HighLift, null, 2);
            var r = Run3D.Of(new WeightSolver3D(WeightModel.FromMass(0.045), NamedProfiles.Paper.With(new BreakAway(0.15))), f);
            Assert.That(r.Holding, Has.All.True);
        }

        [Test]
        public void AOnePoseGlitchDoesNotDropIt()
        {
            var solver = new WeightSolver3D(WeightModel.FromMass(2), NamedProfiles.Xyz.With(new BreakAway(0.1)));
            solver.BeginHold(new HandPose(0, 1, 0, true, true, 0), 0, 1, 0);
            for (int i = 1; i <= 90; i++)
            {
                long pose = i / 3;
                bool glitch = pose == 10; // one 30 Hz pose, three frames, 0.5 m off
                solver.Step(new HandPose(glitch ? 0.5 : 0, 1, 0, true, true, pose / 30.0), 1 / 90.0);
                Assert.That(solver.IsHolding, Is.True, $"frame {i}");
            }
            Assert.That(() => new BreakAway(0), Throws.InstanceOf<ArgumentOutOfRangeException>().With.Message.Contains("distance"));
            Assert.That(() => new BreakAway(double.NaN), Throws.InstanceOf<ArgumentOutOfRangeException>().With.Message.Contains("distance"));
            Assert.That(() => new BreakAway(0.1, -1), Throws.InstanceOf<ArgumentOutOfRangeException>().With.Message.Contains("dwell"));
        }

        [Test]
        public void AGrabOffsetInHeightIsNoDistance()
        {
            // Grabbed 12 cm below (and beside) the hand, held still for two seconds: it never was 0.1 m from where it was grabbed.
            var solver = new WeightSolver3D(WeightModel.FromMass(2), NamedProfiles.Xyz.With(new BreakAway(0.1)));
            solver.BeginHold(At(0, 1, 0, 0), 0.08, 0.88, -0.06);
            for (int i = 1; i <= 64; i++) solver.Step(At(0, 1, 0, i / 32.0), 1 / 32.0);
            Assert.That(solver.IsHolding, Is.True);
            Assert.That(solver.ObjectY, Is.EqualTo(0.88).Within(1e-9));
        }

        [Test]
        public void AHoldBegunBeforeAnyHandIsTrackedMeasuresFromWhereTheFirstHandGrabbed()
        {
            // No hand at the start; the hand appears 0.3 m beside and 0.1 m above the object: that is where it grabbed,
            // no distance. Carried 0.6 m sideways in 0.3 s, the 10 kg object trails by up to 0.1 m (as above).
            foreach (double distance in new[] { 0.05, 0.12 })
            {
                var solver = new WeightSolver3D(WeightModel.FromMass(10), NamedProfiles.Xyz.With(new BreakAway(distance)));
                double t = 0;
                solver.BeginHold(HandPose.Lost, 0, 1, 0);
                for (int i = 0; i < 4; i++) { t += 1 / 32.0; solver.Step(HandPose.Lost, 1 / 32.0); }
                for (int i = 0; i < 16; i++) { t += 1 / 32.0; solver.Step(At(0.3, 1.1, 0, t), 1 / 32.0); }
                Assert.That(solver.IsHolding, Is.True, "where the first hand grabbed is no distance, at " + distance + " m");
                Assert.That(new[] { solver.ObjectX, solver.ObjectY, solver.ObjectZ }, Is.EqualTo(new[] { 0, 1.0, 0 }).Within(1e-9), "the object stayed");
                for (int i = 0; i < 40; i++)
                {
                    t += 1 / 32.0;
                    solver.Step(At(0.3 + 0.6 * Math.Min(1, i / 10.0), 1.1, 0, t), 1 / 32.0);
                }
                Assert.That(solver.BrokeAway, Is.EqualTo(distance < 0.1), "break-away at " + distance + " m");
            }
        }

        [Test]
        public void TimeWithoutAFollowedHandDoesNotCountTowardTheDwell()
        {
            // 10 kg lifted 0.8 m in half a second settles about 0.22 m below the hand: past a 0.15 m break-away for good.
            // With a 1 s dwell, tracking lost 0.25 s after it went past: the two seconds of loss do not drop it; back,
            // the hold ends once the dwell is complete, counting the time before the loss.
            var solver = new WeightSolver3D(WeightModel.FromMass(10), NamedProfiles.Paper.With(new BreakAway(0.15, 1.0)));
            double t = 0, hand = 0.9;
            solver.BeginHold(At(0.1, hand, 0.2, t), 0.1, hand, 0.2);
            int pose = 0, pastFrom = -1;
            while (pastFrom < 0 || pose - pastFrom < 8)
            {
                pose++; t += 1 / 32.0;
                hand = 0.9 + 0.8 * Math.Min(1, pose / 16.0);
                solver.Step(At(0.1, hand, 0.2, t), 1 / 32.0);
                if (pastFrom < 0 && hand - solver.ObjectY > 0.15) pastFrom = pose;
                Assert.That(pose, Is.LessThan(64), "the lift takes the object past 0.15 m");
            }
            for (int i = 0; i < 64; i++)
            {
                t += 1 / 32.0;
                solver.Step(HandPose.Lost, 1 / 32.0);
                Assert.That(solver.IsHolding, Is.True, "lost for " + (i + 1) + " / 32 s");
            }
            int back = 0;
            while (solver.IsHolding && back < 64) { back++; t += 1 / 32.0; solver.Step(At(0.1, hand, 0.2, t), 1 / 32.0); }
            Assert.That(solver.BrokeAway, Is.True, "past it still, once back");
            Assert.That(back, Is.InRange(22, 26), "after the rest of the dwell, 0.75 s = 24 poses, not a whole new second");
        }

        [Test]
        public void ASidewaysPullBeyondTheLateralBoundBreaksAway()
        {
            // Lateral inertia keeps a heavy object up to 0.10 m behind a fast sideways swing: a 0.08 m break-away trips.
            HandPath3D swing = (double t, out double x, out double y, out double z) => { x = 0.8 * Headset3D.MinJerk(t, 0.3, 0.4, 0, 1); y = 1; z = 0; };
            var solver = new WeightSolver3D(WeightModel.FromMass(20), NamedProfiles.Xyz.With(new BreakAway(0.08, 0)));
            var r = Run3D.Of(solver, new Headset3D().Render(swing, null, 2));
            Assert.That(solver.BrokeAway, Is.True);
            var kept = new WeightSolver3D(WeightModel.FromMass(20), NamedProfiles.Xyz.With(new BreakAway(0.12, 0)));
            Run3D.Of(kept, new Headset3D().Render(swing, null, 2));
            Assert.That(kept.BrokeAway, Is.False, "the lateral lag never exceeds 0.10 m");
        }

        [TestCase(0)] // x
        [TestCase(2)] // z
        public void TheDistanceIsMeasuredSidewaysTooFromWhereTheHandGrabbed(int axis)
        {
            // 10 kg on xyz (lateral inertia), grabbed 8 cm beside and 6 cm behind the hand: at rest that grab offset is
            // no distance. Carried 0.6 m sideways in 0.3 s, the object trails the hand by up to 0.1 m: past 5 cm for
            // more than the 0.1 s dwell, the hold ends; with 0.12 m to go it does not.
            foreach (double distance in new[] { 0.05, 0.12 })
            {
                var solver = new WeightSolver3D(WeightModel.FromMass(10), NamedProfiles.Xyz.With(new BreakAway(distance)));
                double t = 0;
                solver.BeginHold(new HandPose(0, 1, 0, true, true, t), 0.08, 1, -0.06);
                for (int i = 0; i < 40; i++)
                {
                    t += 1 / 32.0;
                    double side = 0.6 * Math.Min(1, i / 10.0);
                    solver.Step(new HandPose(axis == 0 ? side : 0, 1, axis == 2 ? side : 0, true, true, t), 1 / 32.0);
                    if (i < 2) Assert.That(solver.IsHolding, Is.True, "the grab offset itself is no distance, pose " + i);
                }
                Assert.That(solver.BrokeAway, Is.EqualTo(distance < 0.1), "break-away at " + distance + " m");
                Assert.That(solver.IsHolding, Is.EqualTo(distance > 0.1));
            }
        }
    }
}
