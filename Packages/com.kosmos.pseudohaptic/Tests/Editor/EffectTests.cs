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
            Assert.That(cap.CapFor(WeightModel.FromMass(PhysicalConstants.StandardMassKg), 0.4), Is.EqualTo(double.PositiveInfinity), "the golf ball is not capped: it is rigid in the hand");
            Assert.That(cap.CapFor(WeightModel.FromMass(0.046), 0.4), Is.EqualTo(1.0).Within(1e-3), "just heavier: about headroom × v_std");
            // 2 kg at gain 1 (the cap alone), lifted 0.4 m in 0.4 s (peak 1.9 m/s) by a user of v_std 0.5 m/s.
            var frames = Run.Headset(frameRate: 120).Render(Run.Lift(0.4, 0.4).Hold(3));
            var solver = new WeightSolver(WeightModel.FromMass(2), Only(cap), 0.5);
            var y = Run.Replay(solver, frames);
            double capSpeed = 2.5 * 0.5 * Math.Exp(-0.24 * (2 - 0.045));
            for (int i = 4; i < y.Length; i++)
                Assert.That(y[i] - y[i - 4], Is.LessThanOrEqualTo(capSpeed * (frames[i].Time - frames[i - 4].Time + 0.05) + 1e-9), "mean speed over 4 frames, frame " + i);
            int handStops = Array.FindIndex(frames, f => f.Time >= 0.3 + 0.4 + 0.05);
            Assert.That(y[handStops] - y[0], Is.LessThan(0.39), "held back while the hand moves");
            Assert.That(Run.Last(y) - y[0], Is.EqualTo(0.4).Within(1e-9), "deferred, not lost: it ends where the hand put it");
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
        public void DeadbandSwallowsJitterOfALightObjectAndLosesNothingAtGainOne()
        {
            var db = Only(new MotionDeadband(), new WeightGain());
            var solver = new WeightSolver(WeightModel.FromMass(0.01), db, 0.5); // gain 3 (the cap)
            solver.BeginHold(1, 1);
            for (int i = 0; i < 100; i++) solver.Step(new HandSample(1 + (i % 2 == 0 ? 0.003 : -0.003)), 1 / 30.0);
            Assert.That(solver.ObjectY, Is.EqualTo(1.0), "±3 mm of jitter moves a gain-3 object not at all");
            var y = Lift(db, 0.045);
            Assert.That(Run.Last(y) - y[0], Is.EqualTo(0.3).Within(1e-12), "at gain 1 a lift passes whole: nothing to suppress, nothing lost");
            var heavy = Lift(db, 0.09);
            Assert.That(Run.Last(heavy) - heavy[0], Is.EqualTo(0.15).Within(1e-12), "below gain 1 too (gain 0.5)");
            Assert.That(new MotionDeadband().WidthFor(0.5, 1.0), Is.EqualTo(0.0), "no band at gain 1");
            Assert.That(new MotionDeadband().WidthFor(0.5, 0.5), Is.EqualTo(0.0), "none for a heavier object (not a negative width)");
            Assert.That(new MotionDeadband().WidthFor(0.5, 3.0), Is.EqualTo(0.012 * 2 / 3.0).Within(1e-12), "span × (1 − 1/G)");
            Assert.That(new MotionDeadband().WidthFor(3.0, 3.0), Is.EqualTo(0.018 * 2 / 3.0).Within(1e-12), "a fast user: v_std × 6 ms");
            var light = Lift(db, 0.01);
            Assert.That(Run.Last(light) - light[0], Is.EqualTo(3 * (0.3 - 0.008)).Within(1e-9), "a light object's lift passes less the band");
        }

        [Test]
        public void TheDeadbandFollowsTheHandOnlyPastItsWidthInEitherDirection()
        {
            // Gain 3 (10 g) for a user of 0.5 m/s: width 12 mm × (1 − 1/3) = 8 mm. The band's reference stays put while
            // the hand moves within 8 mm of it and is dragged along at 8 mm beyond; the object moves 3 × the reference.
            var solver = new WeightSolver(WeightModel.FromMass(0.01), Only(new MotionDeadband(), new WeightGain()), 0.5);
            Assert.That(solver.Gain, Is.EqualTo(3.0));
            Assert.That(solver.Constants.DeadbandWidth, Is.EqualTo(0.008).Within(1e-15));
            double t = 0;
            solver.BeginHold(1.0, 1.0, t);
            double[] hand = { 1.005, 1.010, 1.005, 1.002, 0.990, 0.995, 1.003, 1.010 };
            double[] reference = { 1.000, 1.002, 1.002, 1.002, 0.998, 0.998, 0.998, 1.002 }; // held, dragged up, held, dragged down, held, dragged up
            for (int i = 0; i < hand.Length; i++)
            {
                t += 1 / 30.0;
                double y = solver.Step(new HandSample(hand[i], true, true, t), 1 / 30.0);
                Assert.That(y, Is.EqualTo(1.0 + 3 * (reference[i] - 1.0)).Within(1e-12), "pose " + i);
                Assert.That(solver.State.DeadbandReference, Is.EqualTo(reference[i]).Within(1e-12), "pose " + i);
            }
            Assert.That(new MotionDeadband().Name, Is.EqualTo("motion-deadband"));
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
            Assert.That(Run.MaxOffset(frames, y), Is.InRange(0.2, 0.25), "held near the paper's 0.2 m, never past a quarter metre");
            double maxSpeedChange = 0;
            for (int i = 2; i < y.Length; i++) maxSpeedChange = Math.Max(maxSpeedChange, Math.Abs((y[i] - y[i - 1]) - (y[i - 1] - y[i - 2])));
            Assert.That(maxSpeedChange, Is.LessThan(0.005), "per-frame change of the per-frame step, m: (1 − G)·v_hand spread over the 2 cm band");
        }

        [Test]
        public void OffsetCorrectionPaceShiftIsBoundedContinuousAndMonotone()
        {
            var c = new OffsetCorrection();
            Assert.That(c.PaceShiftAt(0, 0.5), Is.EqualTo(0), "nothing at rest");
            double previous = 0;
            for (double pace = 0.01; pace < 20; pace *= 1.1)
            {
                double shift = c.PaceShiftAt(pace, 0.5);
                Assert.That(shift, Is.GreaterThan(previous), "strictly more for a faster pace");
                Assert.That(shift - previous, Is.LessThan(0.01), "no jump");
                Assert.That(shift, Is.LessThan(0.1), "bounded");
                previous = shift;
            }
            Assert.That(c.PaceShiftAt(1, 0.3), Is.GreaterThan(c.PaceShiftAt(1, 1.0)), "a lower v_std reads the same pace as faster");
            Assert.That(c.ThresholdFor(0.045) - c.PaceShiftAt(1e9, 0.01), Is.GreaterThan(0), "the threshold stays positive");
            Assert.That(c.PaceShiftAt(double.PositiveInfinity, 0.5), Is.EqualTo(c.PaceShift).Within(1e-15), "an infinite pace: the whole shift, not NaN");
            Assert.That(c.PaceShiftAt(-1, 0.5), Is.EqualTo(c.PaceShiftAt(1, 0.5)), "lowering counts like lifting");
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => new OffsetCorrection(paceShift: -0.01)).ParamName, Is.EqualTo("paceShift"));
        }

        [Test]
        public void AnObjectMadeLighterThanTheStandardMidHoldKeepsItsMassThresholdWhateverThePaceBefore()
        {
            // A fast heavy lift leaves a held pace of about 1 m/s, which would lower a heavy object's threshold by 4 cm.
            // Made light mid-hold (a scene changing the weight), the object leads the hand and its offset stops at its own
            // threshold and band, 0.15 + 0.02 m: the pace shift is for objects heavier than the standard only.
            var profile = Only(new WeightGain(), new FasterMovesFurther(), new OffsetCorrection());
            var s = new WeightSolver(WeightModel.FromMass(5), profile, 0.5);
            double t = 0, hand = 1.0;
            s.BeginHold(hand, hand, t);
            for (int i = 0; i < 9; i++) s.Step(new HandSample(hand += 1.0 / 30, true, true, t += 1 / 30.0), 1 / 30.0);
            Assert.That(s.State.HeldPace, Is.GreaterThan(0.9));
            s.Configure(WeightModel.FromMass(0.01), profile, 0.5);
            Assert.That(s.Gain, Is.GreaterThan(1));
            for (int i = 0; i < 150; i++) s.Step(new HandSample(hand += 0.1 / 30, true, true, t += 1 / 30.0), 1 / 30.0);
            Assert.That(s.State.HeldPace, Is.GreaterThan(0.9), "still held: the light object has no pace rule");
            Assert.That(s.Offset, Is.EqualTo(-(0.15 + 0.02)).Within(0.002), "the object leads by its own threshold and band");
        }

        [Test]
        public void OffsetCorrectionThresholdGrowsWithTheMass()
        {
            var c = new OffsetCorrection();
            Assert.That(c.ThresholdFor(1), Is.EqualTo(0.2).Within(1e-12), "the paper's 0.2 m at 1 kg");
            Assert.That(c.ThresholdFor(2) - c.ThresholdFor(1), Is.EqualTo(0.01).Within(1e-12), "1 cm per doubling");
            Assert.That(c.ThresholdFor(0.5), Is.EqualTo(0.19).Within(1e-12));
            Assert.That(c.ThresholdFor(1e6) + c.Band, Is.LessThanOrEqualTo(0.25), "the visible offset stays within a quarter metre");
            Assert.That(c.ThresholdFor(0.001), Is.EqualTo(0.15).Within(1e-12));
            Assert.That(c.ThresholdFor(0), Is.EqualTo(0.15).Within(1e-12), "no mass: the least");
            var flat = new OffsetCorrection(perDoubling: 0);
            Assert.That(flat.ThresholdFor(0), Is.EqualTo(0.15).Within(1e-12), "no mass, no growth per doubling: still the least, not NaN");
            Assert.That(flat.ThresholdFor(5), Is.EqualTo(0.2).Within(1e-12));
        }

        [Test]
        public void OffsetCorrectionPullsABigOffsetBackGradually()
        {
            // A big offset the hand's motion did not make: tracking lost for a second, the hand back 0.5 m higher.
            var solver = new WeightSolver(WeightModel.FromMass(1), Only(new OffsetCorrection()));
            solver.BeginHold(1.0, 1.0, 0);
            double t = 0;
            for (int i = 0; i < 90; i++) { t += 1 / 90.0; solver.Step(HandSample.Lost, 1 / 90.0); }
            double last = solver.ObjectY;
            for (int i = 0; i < 600; i++)
            {
                t += 1 / 90.0;
                double y = solver.Step(new HandSample(1.5, true, true, t), 1 / 90.0);
                Assert.That(y - last, Is.InRange(0.0, 0.5 / 90 + 1e-12));
                last = y;
            }
            Assert.That(solver.Offset, Is.EqualTo(0.22).Within(0.001), "drawn back to the band's end (1 kg: 0.2 + 0.02 m)");
        }

        // (offset at the start d0, change the hand alone would make Δ), m; 1 kg: threshold T = 0.2, band B = 0.02.
        [TestCase(0.210, +0.005)]  // growth inside the band
        [TestCase(0.190, +0.020)]  // growth into the band from below it
        [TestCase(0.195, +0.020)]  // …with the free step's midpoint past T: resisted from where it crosses T
        [TestCase(0.210, +0.020)]  // growth toward the band's end
        [TestCase(0.225, +0.010)]  // growth past the band: none (then the pull, pinned above, draws it back a little)
        [TestCase(0.210, +0.100)]  // one huge step: the rule alone would end at 0.224 m; the visible ceiling holds it at T + B
        [TestCase(0.219, -0.010)]  // shrinks inside the band
        [TestCase(0.215, -0.025)]
        [TestCase(0.219, -0.034)]  // very large shrinks (|Δ| ≥ 1.5 B): judged at the start…
        [TestCase(0.210, -0.035)]  // …unless the free step's midpoint is at or below T: then the hand's whole motion
        public void OffsetCorrectionSharesOneStepByTheImplicitMidpointRule(double d0, double delta)
        {
            // One pose changes the offset: the object's share s of the hand's motion is judged at the step's midpoint,
            // d = d0 + (1 − s((d0 + d)/2))·Δ, s(m) = clamp((m − T)/B, 0, 1), solved here by bisection, independently
            // of the solver's closed form. A single step shrinking the offset by 1.5 band widths or more from inside the
            // band has no unique such d; it is judged at the start, d = d0 + (1 − s(d0))·Δ, unless d = d0 + Δ is itself
            // consistent (midpoint ≤ T).
            const double T = 0.2, B = 0.02;
            var solver = new WeightSolver(WeightModel.FromMass(1), Only(new WeightGain(), new OffsetCorrection()));
            double G = solver.Gain, t = 0;
            Assert.That(G, Is.LessThan(0.5), "a heavy object: the hand's step changes the offset");
            solver.BeginHold(1.0, 1.0, 0);
            for (int i = 0; i < 45; i++) { t += 1 / 90.0; solver.Step(HandSample.Lost, 1 / 90.0); }
            double hand = 1.0 + d0; // the hand comes back d0 higher: an offset no motion made
            for (int i = 0; i < 3; i++) { t += 1 / 90.0; solver.Step(new HandSample(hand, true, true, t), 1 / 90.0); }
            Assert.That(hand - solver.ObjectY, Is.EqualTo(d0).Within(1e-3), "re-anchored at about the offset d0");
            d0 = hand - solver.ObjectY; // exactly, after what the pull did past the band

            hand += delta / (1 - G); // the object follows G of it, so the offset alone would change by Δ
            t += 1 / 90.0;
            // Where the object is headed: a step too big for the solver's speed limit (4 m/s) is partly carried.
            double d = hand - solver.Step(new HandSample(hand, true, true, t), 1 / 90.0) - solver.State.Carry;

            Func<double, double> s = m => Math.Max(0, Math.Min(1, (m - T) / B));
            double expected;
            if (delta < -1.5 * B && d0 + delta / 2 > T) expected = d0 + (1 - s(d0)) * delta;
            else
            {
                double lo = Math.Min(d0, d0 + delta), hi = Math.Max(d0, d0 + delta);
                for (int i = 0; i < 200; i++)
                {
                    double mid = (lo + hi) / 2, g = d0 + (1 - s((d0 + mid) / 2)) * delta - mid; // decreasing in mid
                    if (g > 0) lo = mid; else hi = mid;
                }
                expected = (lo + hi) / 2;
            }
            if (d0 <= T + B && expected > T + B) expected = T + B; // the visible ceiling: no step grows it past the band's end
            double beyond = expected - (T + B); // the pull past the band's end (pinned by the test below)
            if (beyond > 0) expected -= Math.Min(beyond, 0.5 * Math.Min(1, beyond / (5 * B)) / 90.0);
            Assert.That(d, Is.EqualTo(expected).Within(1e-9));
        }

        [TestCase(+0.5)]
        [TestCase(-0.5)]
        public void OffsetCorrectionPullsAtFullSpeedFarOutThenSlowsOverFiveBandsInEitherDirection(double jump)
        {
            // The hand comes back `jump` m away after a second's loss: an offset no motion made. Beyond the band's end
            // (1 kg: 0.2 + 0.02 m) the object is drawn toward the hand at 0.5 m/s while more than five band widths
            // (0.1 m) out, then at 0.5 m/s × beyond / 0.1 m, each frame's time counting at most the longest frame.
            var c = new OffsetCorrection();
            var solver = new WeightSolver(WeightModel.FromMass(1), Only(c));
            solver.BeginHold(1.0, 1.0, 0);
            double t = 0;
            for (int i = 0; i < 90; i++) { t += 1 / 90.0; solver.Step(HandSample.Lost, 1 / 90.0); }
            double hand = 1.0 + jump, y = solver.ObjectY, fullSpeedFrames = 0;
            for (int i = 0; i < 400; i++)
            {
                double dt = i % 50 == 7 ? 0.05 : 1 / 90.0; // now and then a 20 Hz hitch: it counts as 25 ms
                t += dt;
                double offset = hand - y, beyond = Math.Abs(offset) - 0.22;
                double speed = beyond >= 0.1 ? 0.5 : 0.5 * beyond / 0.1;
                double expected = y + Math.Sign(offset) * Math.Max(0, Math.Min(beyond, speed * Math.Min(dt, 0.025)));
                if (beyond >= 0.1) fullSpeedFrames++;
                y = solver.Step(new HandSample(hand, true, true, t), dt);
                Assert.That(y, Is.EqualTo(expected).Within(1e-12), "frame " + i);
            }
            Assert.That(fullSpeedFrames, Is.GreaterThan(20), "the pull ran at full speed first");
            Assert.That(Math.Abs(hand - y) - 0.22, Is.InRange(0.0, 1e-3), "and ended near the band's end");
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

        [TestCase(0.02, 0)]  // gain 3: the speed limit carries what the floor stops
        [TestCase(5.0, 1)]   // heavy: the speed cap owes it
        public void MotionTheFloorStoppedIsNotOwedAfterwards(double massKg, int capped)
        {
            // The hand drives the object fast into the floor, waits there and lifts again. What the speed limit or the
            // speed cap still owed downward when the floor stopped the object is dropped: the first lifting pose lifts
            // it, instead of the object sitting on the floor paying a debt into it.
            var effects = capped == 1
                ? new WeightEffect[] { new WeightGain(), new ExperimentalBlend(), new SpeedCap(), new FloorClamp() }
                : new WeightEffect[] { new WeightGain(), new ExperimentalBlend(), new FloorClamp() };
            var solver = new WeightSolver(WeightModel.FromMass(massKg), Only(effects), 0.3);
            const double dt = 1 / 90.0;
            double hand = 0.05, t = 0, y = 0.05;
            solver.BeginHold(hand, hand, t);
            for (int i = 0; i < 30; i++) { t += dt; hand -= 4.0 * dt; y = solver.Step(new HandSample(hand, true, true, t), dt); }
            Assert.That(y, Is.EqualTo(0.0), "on the floor");
            Assert.That(capped == 1 ? solver.State.CapDeferred : solver.State.Carry, Is.EqualTo(0.0), "nothing owed into it");
            t += dt; hand += 0.01;
            double lifted = solver.Step(new HandSample(hand, true, true, t), dt);
            Assert.That(lifted, Is.GreaterThan(0.0), "the first lifting pose lifts it");
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
