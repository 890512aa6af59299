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
        public void DeadbandSwallowsJitterOfALightObjectAndLosesNothingAtGainOne()
        {
            var db = Only(new MotionDeadband(), new WeightGain());
            var solver = new WeightSolver(WeightModel.FromMass(0.01), db, 0.5); // gain 3 (the cap)
            solver.BeginHold(1, 1);
            double settled = 0;
            for (int i = 0; i < 100; i++)
            {
                solver.Step(new HandSample(1 + (i % 2 == 0 ? 0.003 : -0.003)), 1 / 30.0);
                if (i == 10) settled = solver.ObjectY;
            }
            // The first steady poses move the lift's base and the band to their mean (where the hand rests): the object moves
            // there once, by less than the jitter (not G times it), and then not at all.
            Assert.That(settled, Is.EqualTo(1.0).Within(0.003), "±3 mm of jitter moves a gain-3 object less than the jitter, once");
            Assert.That(solver.ObjectY, Is.EqualTo(settled), "…and then not at all");
            var y = Lift(db, 0.045);
            Assert.That(Run.Last(y) - y[0], Is.EqualTo(0.3).Within(1e-12), "at gain 1 a lift passes whole: nothing to suppress, nothing lost");
            var heavy = Lift(db, 0.09);
            Assert.That(Run.Last(heavy) - heavy[0], Is.EqualTo(0.15).Within(1e-12), "below gain 1 too (gain 0.5)");
            Assert.That(new MotionDeadband().WidthFor(0.5, 1.0), Is.EqualTo(0.0), "no band at gain 1");
            Assert.That(new MotionDeadband().WidthFor(0.5, 0.5), Is.EqualTo(0.0), "none for a heavier object (not a negative width)");
            Assert.That(new MotionDeadband().WidthFor(0.5, 3.0), Is.EqualTo(0.012 * 2 / 3.0).Within(1e-12), "span × (1 − 1/G)");
            Assert.That(new MotionDeadband().WidthFor(3.0, 3.0), Is.EqualTo(0.018 * 2 / 3.0).Within(1e-12), "a fast user: v_std × 6 ms");
            var light = Lift(db, 0.01);
            Assert.That(Run.Last(light) - light[0], Is.EqualTo(3 * 0.3).Within(0.001), "a light object's lift passes whole once the hand rests: the band costs no lasting lift");
        }

        [Test]
        public void TheDeadbandFollowsTheHandOnlyPastItsWidthInEitherDirection()
        {
            // Gain 3 (10 g) for a user of 0.5 m/s: width 12 mm × (1 − 1/3) = 8 mm. At the grab the band's reference stays put
            // while the hand moves within 8 mm of it and is dragged along at 8 mm beyond (pushes jitter could make close
            // nothing); the object moves 3 × the reference.
            var solver = new WeightSolver(WeightModel.FromMass(0.01), Only(new MotionDeadband(), new WeightGain()), 0.5);
            Assert.That(solver.Gain, Is.EqualTo(3.0));
            Assert.That(solver.Constants.DeadbandWidth, Is.EqualTo(0.008).Within(1e-15));
            double t = 0;
            solver.BeginHold(1.0, 1.0, t);
            double Pose(double hand) { t += 1 / 30.0; return solver.Step(new HandSample(hand, true, true, t), 1 / 30.0); }
            for (int i = 0; i < 3; i++) Pose(1.0); // the grab settles
            double[] hand = { 1.005, 1.010, 1.005, 1.002, 0.995, 0.993, 1.003, 1.011 };
            double[] reference = { 1.000, 1.002, 1.002, 1.002, 1.002, 1.001, 1.001, 1.003 }; // held, dragged up, held, dragged down, held, dragged up
            for (int i = 0; i < hand.Length; i++)
            {
                double y = Pose(hand[i]);
                Assert.That(y, Is.EqualTo(1.0 + 3 * (reference[i] - 1.0)).Within(1e-12), "pose " + i);
                Assert.That(solver.State.DeadbandReference, Is.EqualTo(reference[i]).Within(1e-12), "pose " + i);
            }
            // Sustained motion closes the band (at most 4 mm / G a pose beyond the hand's own step): a 4 cm rise in 5 mm steps
            // leaves the reference at the hand, not 8 mm behind it, and at rest it stays there.
            for (int i = 1; i <= 8; i++) Pose(1.011 + 0.005 * i);
            Assert.That(solver.State.DeadbandHalfWidth, Is.LessThan(0.001), "closed by the rise");
            for (int i = 0; i < 60; i++) Pose(1.051);
            Assert.That(solver.State.DeadbandReference, Is.EqualTo(1.051).Within(1e-4), "at the hand after the rise");
            Assert.That(solver.State.DeadbandHalfWidth, Is.EqualTo(0.008).Within(1e-12), "regrown at rest");
            double before = solver.ObjectY;
            // A heft of 2 cm and back leaves the object where it was (a plain backlash moved it 3 × 2 × 8 mm = 48 mm).
            for (int i = 1; i <= 4; i++) Pose(1.051 + 0.005 * i);
            for (int i = 3; i >= 0; i--) Pose(1.051 + 0.005 * i);
            for (int i = 0; i < 60; i++) Pose(1.051);
            Assert.That(solver.ObjectY, Is.EqualTo(before).Within(0.001), "a heft leaves the object where it was");
            Assert.That(new MotionDeadband().Name, Is.EqualTo("motion-deadband"));
        }

        [Test]
        public void TheFirstPosesAtRestSetWhereALightObjectsLiftIsMeasuredFrom([Values(false, true)] bool begunUntracked)
        {
            // Gain 3, band 8 mm. The grab's pose is 4 mm above where the hand then rests (jitter, not a glitch: within the
            // solver's 5 mm). The hold's first six steady poses move the base and the band to their mean: the object moves
            // there with them (once, 4 mm: not G times it), and a lift is measured from where the hand rests. A hold begun
            // untracked starts at its first pose, however long after (the first poses' 0.3 s count from there).
            var solver = new WeightSolver(WeightModel.FromMass(0.01), Only(new MotionDeadband(), new WeightGain()), 0.5);
            double t = 0;
            double Pose(double hand) { t += 1 / 30.0; return solver.Step(new HandSample(hand, true, true, t), 1 / 30.0); }
            if (begunUntracked)
            {
                solver.BeginHold(double.NaN, 1.004, double.NaN);
                for (int i = 0; i < 30; i++) { t += 1 / 30.0; solver.Step(new HandSample(double.NaN, false, false, double.NaN), 1 / 30.0); }
                Pose(1.004); // the hold's first pose: the grab
            }
            else solver.BeginHold(1.004, 1.004, t);
            for (int i = 0; i < 8; i++) Pose(1.0);
            Assert.That(solver.State.Base, Is.EqualTo(1.0).Within(1e-12), "the base is where the hand rests");
            Assert.That(solver.ObjectY, Is.EqualTo(1.0).Within(1e-12), "the object moved with it, 1 × the grab pose's error");
            Assert.That(solver.State.DeadbandMoved, Is.EqualTo(0), "nothing moved");
            // Settled, a push is motion (or a glitch), not jitter about an unlucky grab pose: the rule after motion takes
            // over, whose reference goes back to where the hand rests once it does.
            Pose(1.011);
            Assert.That(solver.State.DeadbandMoved, Is.EqualTo(1), "a push once the first poses have settled is motion");
            for (int i = 0; i < 90; i++) Pose(1.0);
            Assert.That(solver.ObjectY, Is.EqualTo(1.0).Within(0.001), "a one-pose push and back leaves the object where the hand rests");
            // Measured from the grab's own pose, the same hold would leave it G × 4 mm: 12 mm below the hand after any motion.
        }

        /// <summary>What ends the settling of the first poses before they are all taken: a steady pose more than 5 mm from
        /// their mean (a glitch of two or three poses, which the median of three passes), a gap (the hand may have moved
        /// while unseen), and the settling base more than the lowering guard's slack below the grab's pose is no dip for the
        /// guard to undo. Gain 3, band 8 mm: none of these hands pushes the band.</summary>
        [Test]
        public void TheFirstPosesSetWhereTheHandRestsOnlyFromPosesAtRest([Values("glitch", "gap", "below")] string what)
        {
            var profile = what == "below" ? NamedProfiles.Paper : Only(new MotionDeadband(), new WeightGain());
            var solver = new WeightSolver(WeightModel.FromMass(0.01), profile, 0.5);
            double t = 0, grab = what == "below" ? 1.0045 : 1.0;
            solver.BeginHold(grab, grab, t);
            void Pose(double hand) { t += 1 / 30.0; solver.Step(new HandSample(hand, true, true, t), 1 / 30.0); }
            void Lost() { t += 1 / 30.0; solver.Step(new HandSample(double.NaN, false, false, double.NaN), 1 / 30.0); }
            Pose(1.0);
            Pose(1.0);
            if (what == "glitch")
            {
                Pose(0.9935); // two poses 6.5 mm low: within the band, past 5 mm
                Pose(0.9935);
                for (int i = 0; i < 10; i++) Pose(1.0);
                Assert.That(solver.State.Base, Is.EqualTo(1.0).Within(1e-9), "a glitch of two poses is not where the hand rests");
            }
            else if (what == "gap")
            {
                for (int i = 0; i < 2; i++) Lost();
                for (int i = 0; i < 10; i++) Pose(1.004); // the hand 4 mm higher after the gap: within the band and the 5 mm
                Assert.That(solver.State.Base, Is.EqualTo(1.0).Within(1e-9), "poses after a gap say nothing of where the hand rested");
            }
            else
            {
                // The grab's pose 4.5 mm above the first poses (within the solver's 5 mm), the hand then resting 2.5 mm lower:
                // the settling base ends more than the guard's slack below the grab's pose.
                for (int i = 0; i < 20; i++) Pose(0.9975);
                Assert.That(solver.State.Base, Is.EqualTo(0.9975).Within(0.001), "the guard leaves the settled base where the hand rests");
            }
        }

        [Test]
        public void LoweringGuardKeepsTheOffsetFromGrowingWhileLowering()
        {
            var path = HandPath.StartAt(1).Hold(0.2).MoveTo(0.7, 0.6).Hold(0.3);
            var frames = Run.Headset().Render(path);
            var unguarded = Run.Replay(new WeightSolver(WeightModel.FromMass(5), Only(new WeightGain())), frames);
            var guarded = Run.Replay(new WeightSolver(WeightModel.FromMass(5), Only(new WeightGain(), new LoweringGuard())), frames);
            Assert.That(Run.MaxOffset(frames, unguarded), Is.GreaterThan(0.25), "Eq. 4 alone leaves a heavy object hanging above a lowered hand");
            Assert.That(Run.MaxOffset(frames, guarded), Is.LessThan(0.015), "the guard brings it down with the hand (within a jitter-size slack)");
        }

        [Test]
        public void OffsetCorrectionStopsGrowthPastTheThresholdWithoutJumps()
        {
            // Poses every frame, so the hand itself is smooth and any kink in the object's motion is the correction's.
            var frames = Run.Headset(frameRate: 90, poseRate: 90).Render(HandPath.StartAt(0.5).Hold(0.2).MoveTo(1.5, 1.5).Hold(0.5));
            var profile = Only(new WeightGain(), new OffsetCorrection());
            var y = Run.Replay(new WeightSolver(WeightModel.FromMass(3), profile), frames);
            Assert.That(Run.MaxOffset(frames, y), Is.InRange(0.2, SolverPropertyTests.StatedCeiling), "held near the paper's 0.2 m, never past the stated ceiling");
            double maxSpeedChange = 0;
            for (int i = 2; i < y.Length; i++) maxSpeedChange = Math.Max(maxSpeedChange, Math.Abs((y[i] - y[i - 1]) - (y[i - 1] - y[i - 2])));
            Assert.That(maxSpeedChange, Is.LessThan(0.005), "per-frame change of the per-frame step, m: (1 − G)·v_hand spread over the 2 cm band");
        }



        [Test]
        public void OffsetCorrectionThresholdGrowsWithTheMass()
        {
            var c = new OffsetCorrection();
            Assert.That(c.ThresholdFor(1), Is.EqualTo(0.2).Within(1e-12), "the paper's 0.2 m at 1 kg");
            Assert.That(c.ThresholdFor(2) - c.ThresholdFor(1), Is.EqualTo(0.02).Within(1e-12), "2 cm per doubling");
            Assert.That(c.ThresholdFor(0.5), Is.EqualTo(0.18).Within(1e-12));
            Assert.That(c.ThresholdFor(1e6) + c.Band, Is.EqualTo(SolverPropertyTests.StatedCeiling).Within(1e-12), "the visible offset's ceiling");
            Assert.That(c.Ceiling, Is.EqualTo(SolverPropertyTests.StatedCeiling).Within(1e-12));
            Assert.That(c.ThresholdFor(0.001), Is.EqualTo(0.15).Within(1e-12));
            Assert.That(c.ThresholdFor(0), Is.EqualTo(0.15).Within(1e-12), "no mass: the least");
            var flat = new OffsetCorrection(perDoubling: 0);
            Assert.That(flat.ThresholdFor(0), Is.EqualTo(0.15).Within(1e-12), "no mass, no growth per doubling: still the least, not NaN");
            Assert.That(flat.ThresholdFor(5), Is.EqualTo(0.2).Within(1e-12));
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
        public void AFloorBeyondTheSolversCoordinatesIsRefusedWhenSet()
        {
            // P8: 1e39 was accepted, and the first frame of a hold then put the object there (a float's infinity on the
            // transform): the hold's ±1e5 m guard covers later frames only.
            foreach (double floor in new[] { 1e39, -1e39, 1.0000001e5, double.MaxValue })
                Assert.That(() => new FloorClamp(floor), Throws.InstanceOf<ArgumentOutOfRangeException>().With.Message.Contains("floor"), floor.ToString());
            foreach (double floor in new[] { -1e5, 1e5, -2.5, 0 })
            {
                var solver = new WeightSolver(WeightModel.FromMass(1), Only(new FloorClamp(floor)));
                solver.BeginHold(1, 1);
                double y = solver.Step(new HandSample(1, true, true, 0), 1 / 90.0);
                Assert.That(y, Is.EqualTo(Math.Max(1, floor)), "the floor holds, finite: " + floor);
            }
        }

        [Test]
        public void TheFloorKeepsTheObjectsBottomAboveTheSupport()
        {
            var solver = new WeightSolver(WeightModel.FromMass(0.5), NamedProfiles.Paper) { BottomBelowPivot = 0.06 };
            Assert.That(solver.BottomBelowPivot, Is.EqualTo(0.06));
            solver.BeginHold(0.3, 0.2, 0); // grabbed 10 cm above its pivot
            double lowest = double.PositiveInfinity;
            for (int i = 1; i <= 180; i++)
            {
                double t = i / 90.0, hand = 0.3 - 0.5 * Math.Min(1, t); // the hand pushes 0.5 m down, through the table
                lowest = Math.Min(lowest, solver.Step(new HandSample(hand, true, true, Math.Floor(t * 30) / 30), 1 / 90.0));
            }
            Assert.That(lowest, Is.EqualTo(0.06).Within(1e-12), "the pivot stops 6 cm above the floor: the bottom rests on it");
            var below = new WeightSolver(WeightModel.FromMass(0.5), NamedProfiles.Paper) { BottomBelowPivot = 0.05 };
            below.BeginHold(0.1, 0.01);
            Assert.That(below.ObjectY, Is.EqualTo(0.05), "a hold that begins with the bottom below the floor starts on it");
            foreach (var bad in new[] { -0.01, double.NaN, double.PositiveInfinity })
                Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => solver.BottomBelowPivot = bad).ParamName, Is.EqualTo("BottomBelowPivot"));
        }

        [Test]
        public void ABottomSetMidHoldLiftsTheObjectOffTheFloorOnTheNextFrameThoughTheHandHasNotMoved()
        {
            // The scene swaps in a bigger collider while the object rests on the table in a still hand (the same pose, frame
            // after frame: still frames, which reuse the last frame). The next frame already keeps the new bottom above the floor.
            var solver = new WeightSolver(WeightModel.FromMass(0.5), NamedProfiles.Paper);
            var still = new HandSample(0.05, true, true, 0.0);
            solver.BeginHold(0.05, 0.05, 0.0);
            for (int i = 0; i < 30; i++) solver.Step(still, 1 / 90.0);
            Assert.That(solver.ObjectY, Is.EqualTo(0.05), "resting where it was grabbed");
            solver.BottomBelowPivot = 0.1;
            Assert.That(solver.Step(still, 1 / 90.0), Is.EqualTo(0.1).Within(1e-12), "its bottom on the floor, not 5 cm through it");
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
