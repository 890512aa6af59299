using System;
using NUnit.Framework;
using Kosmos.PseudoHaptic.Simulation;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>The properties P1–P10 every reading must keep (shared/design/algorithm-reading.md), on Quest-like input.</summary>
    public class SolverPropertyTests
    {
        static readonly string[] Profiles = { "paper", "paper-experiment", "gain" };

        // P1: an object of gain 1 is rigid in the hand: within 5 mm of where the hand puts it while it moves and within
        // 1 mm once the hand has rested 0.5 s, at every frame clock and pose rate, poses 45 ms late, lifted at several
        // speeds by users of several standard speeds. The bounds are the property's (algorithm-reading.md), not a
        // constant of the solver. Up to a 0.4 m lift in 0.3 s (peak 2.5 m/s).
        [Test]
        public void P1_StandardWeightIsRigidInTheHand([ValueSource(nameof(Profiles))] string profile, [Values(0.3, 0.5, 1.5)] double standardSpeed)
        {
            foreach (var seconds in new[] { 0.3, 0.6, 1.2, 2.0 })
                foreach (var frameRate in new[] { 60.0, 72, 90, 120 })
                    foreach (var poseRate in new[] { 30.0, 60 })
                    {
                        var path = HandPath.StartAt(0.8).Hold(0.3).MoveTo(1.2, seconds).Hold(0.8).MoveTo(0.9, seconds).Hold(0.8);
                        var frames = Run.Headset(frameRate, poseRate, jitterSd: poseRate == 30 ? 0.0015 : 0, seed: (int)frameRate).Render(path);
                        var y = Run.Replay(Run.Solver(PhysicalConstants.StandardMassKg, NamedProfiles.Get(profile), standardSpeed), frames);
                        string at = profile + ", v_std " + standardSpeed + ", " + seconds + " s lift, " + frameRate + " Hz frames, " + poseRate + " Hz poses";
                        Assert.That(Run.MaxOffset(frames, y), Is.LessThanOrEqualTo(0.005), at + ": while it moves");
                        double restedUpTop = 0.3 + seconds + 0.045 + 0.5, restedAtEnd = path.Duration - 0.8 + 0.045 + 0.5;
                        for (int i = 0; i < frames.Length; i++)
                        {
                            double t = frames[i].Time;
                            bool rested = (t >= restedUpTop && t < 0.3 + seconds + 0.8) || t >= restedAtEnd;
                            if (rested) Assert.That(Math.Abs(frames[i].HandY - y[i]), Is.LessThanOrEqualTo(0.001), at + ": rested, frame " + i);
                        }
                    }
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

        // P4: no hand motion, no object motion; jitter at rest moves the object less than 1 cm in 10 s. Over 200 seeds
        // (a 5 g object at gain 3 crept up to 17.6 mm in 4 of them when the band ignored the gain).
        [Test]
        public void P4_NoCreepAtRest([ValueSource(nameof(Profiles))] string profile)
        {
            foreach (var m in new[] { 0.005, 0.045, 0.5, 5 })
            {
                var still = Run.Replay(Run.Solver(m, NamedProfiles.Get(profile)), Run.Headset().Render(HandPath.StartAt(1).Hold(10)));
                Assert.That(Run.MaxAbs(Array.ConvertAll(still, v => v - 1)), Is.EqualTo(0), "a still hand moves nothing");
                double worst = 0;
                int worstSeed = 0;
                for (int seed = 1; seed <= 200; seed++)
                {
                    var frames = Run.Headset(jitterSd: 0.0015, seed: seed).Render(HandPath.StartAt(1).Hold(10));
                    var y = Run.Replay(Run.Solver(m, NamedProfiles.Get(profile)), frames);
                    // Creep: where the object ends against where it began; and it never strays from its start by more
                    // than 1 cm or than the hand's own poses strayed from theirs (a golf ball is the hand).
                    double creep = Math.Abs(Run.Last(y) - y[0]), stray = 0, handStray = 0;
                    for (int i = 0; i < y.Length; i++)
                    {
                        stray = Math.Max(stray, Math.Abs(y[i] - y[0]));
                        handStray = Math.Max(handStray, Math.Abs(frames[i].HandY - frames[0].HandY));
                    }
                    Assert.That(stray, Is.LessThanOrEqualTo(Math.Max(0.01, handStray) + 1e-12), m + " kg, seed " + seed + ": strays from where it began");
                    if (creep > worst) { worst = creep; worstSeed = seed; }
                }
                Assert.That(worst, Is.LessThan(0.01), m + " kg: worst creep in 10 s over 200 seeds (seed " + worstSeed + ")");
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

        /// <summary>The ceiling ALGORITHM.md §6 states, from the paper's 0.2 m: the threshold grows with the mass by at most
        /// 30 % and the offset never grows past it by more than the paper's 0.02 m.</summary>
        internal const double StatedCeiling = 0.2 * 1.3 + 0.02;

        // P6: with the offset correction on, the offset stays bounded near its threshold.
        [TestCase(0.5), TestCase(2), TestCase(10), TestCase(1000)]
        public void P6_OffsetStaysNearTheThreshold(double massKg)
        {
            var path = HandPath.StartAt(0.5).Hold(0.2).MoveTo(1.3, 1.2).Hold(1).MoveTo(0.7, 1).MoveTo(1.6, 0.8).Hold(2);
            var frames = Run.Headset(frameRate: 72, jitterSd: 0.001).Render(path);
            var y = Run.Replay(Run.Solver(massKg, NamedProfiles.Paper), frames);
            Assert.That(Run.MaxOffset(frames, y), Is.LessThanOrEqualTo(StatedCeiling + 1e-12));
            var uncorrected = Run.Replay(Run.Solver(massKg, NamedProfiles.PaperExperiment), frames);
            Assert.That(Run.MaxOffset(frames, uncorrected), Is.GreaterThan(0.3), "without the correction the offset grows");
        }

        // P6: ... and heavier objects still settle lower: after a 0.5 m lift, 0.5, 1, 2 and 5 kg settle at least 5 mm
        // apart, in mass order, each offset within the stated ceiling (they all settled at exactly 0.22 m when the
        // threshold ignored the mass).
        [Test]
        public void P6_TheCorrectionKeepsWeightsApart([Values(0.5, 1.0, 2.0)] double liftSeconds, [Values(0.3, 0.5, 1.2)] double standardSpeed)
        {
            var path = HandPath.StartAt(0.6).Hold(0.3).MoveTo(1.1, liftSeconds).Hold(2);
            var frames = Run.Headset(frameRate: 90, jitterSd: 0.001, seed: 5).Render(path);
            double previous = double.NegativeInfinity;
            foreach (var m in new[] { 0.5, 1, 2, 5 })
            {
                var y = Run.Replay(Run.Solver(m, NamedProfiles.Paper, standardSpeed), frames);
                double offset = frames[frames.Length - 1].HandY - Run.Last(y);
                Assert.That(Run.MaxOffset(frames, y), Is.LessThanOrEqualTo(StatedCeiling + 1e-12), m + " kg: offset within the stated ceiling");
                Assert.That(offset, Is.GreaterThanOrEqualTo(previous + 0.005), m + " kg settles at least 5 mm below the next lighter");
                previous = offset;
            }
        }

        // P6b: offsets are measured from the grab: a hold that starts with hand and object apart behaves exactly as one
        // that starts together, shifted; a still hand moves nothing, whatever the grab offset.
        [Test]
        public void P6b_AHoldBegunApartBehavesAsOneBegunTogetherShifted([ValueSource(nameof(Profiles))] string profile, [Values(0.12, 0.3, -0.1)] double grabOffset)
        {
            var path = HandPath.StartAt(1.0).Hold(1.0).MoveTo(1.3, 1.0).Hold(1.0).MoveTo(0.9, 0.8).Hold(1);
            var frames = Run.Headset(frameRate: 90, jitterSd: 0.0015, seed: 3).Render(path);
            foreach (var m in new[] { 0.01, 0.5, 2, 5 })
            {
                var together = Run.Replay(Run.Solver(m, NamedProfiles.Get(profile)), frames);
                var solver = Run.Solver(m, NamedProfiles.Get(profile));
                var apart = new double[frames.Length];
                solver.BeginHold(frames[0].HandY, frames[0].HandY - grabOffset, frames[0].PoseTime);
                apart[0] = solver.ObjectY;
                for (int i = 1; i < frames.Length; i++) apart[i] = solver.Step(frames[i].ToSample(), frames[i].Time - frames[i - 1].Time);
                for (int i = 0; i < frames.Length; i++)
                    Assert.That(apart[i], Is.EqualTo(together[i] - grabOffset).Within(1e-9), m + " kg, frame " + i);
                int oneSecond = Array.FindIndex(frames, f => f.Time >= 1.0);
                Assert.That(Math.Abs(apart[oneSecond] - apart[0]), Is.LessThan(0.005), m + " kg: a still hand for 1 s after the grab (jitter only)");
            }
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

        // P8: no input ever yields NaN, infinity or a jump: no frame's step beyond max(G, 1) times how far apart the
        // hand's usable poses of the last ten frames lie, plus 1 cm (issue 22's rule: what the hand does not do, the
        // object does not do either; a light object leads the hand by its gain).
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
                var poses = new double[10];
                for (int k = 0; k < poses.Length; k++) poses[k] = 0.8;
                for (int i = 0; i < 5000; i++)
                {
                    var sample = new HandSample(rng.Next(4) == 0 ? ys[rng.Next(ys.Length)] : 0.8 + 0.3 * rng.NextDouble(),
                        rng.Next(5) != 0, rng.Next(3) != 0, rng.Next(2) == 0 ? double.NaN : i * 0.011);
                    double y = solver.Step(sample, dts[rng.Next(dts.Length)]);
                    Assert.That(double.IsNaN(y) || double.IsInfinity(y), Is.False);
                    if (sample.IsUsable) poses[i % 10] = sample.Y;
                    double near = 0;
                    foreach (var a in poses)
                        foreach (var b in poses) near = Math.Max(near, Math.Abs(a - b));
                    Assert.That(Math.Abs(y - last), Is.LessThanOrEqualTo(Math.Max(1, solver.Gain) * near + 0.01), "step " + i);
                    last = y;
                }
            }
        }

        // P8 and P12: lost for 2.5 s while the hand moves 1.4 m, then regained: never NaN, the object comes back with the
        // hand (no step beyond the hand's own), and ends where the same motion without the loss ends. A light object's lead on
        // the hand's motion across the loss glides instead of jumping (issue 32): under `gain` the 10 g object's, 2 × 0.88 m,
        // takes about 6 s at the glide's speed, so the hand rests 4 s at the end.
        [Test]
        public void P8_LostForSecondsAndRegainedFarAwayDoesNotJump([ValueSource(nameof(Profiles))] string profile)
        {
            var path = Run.Lift(0.3, 1).MoveTo(0.2, 0.6).Hold(3).MoveTo(1.6, 1.2).Hold(4);
            var frames = Run.Headset(frameRate: 90).Drop(1.4, 2.5).Render(path);
            var clean = Run.Headset(frameRate: 90).Render(path);
            foreach (var m in new[] { 0.01, 0.5, 5 })
            {
                var solver = Run.Solver(m, NamedProfiles.Get(profile));
                var y = Run.Replay(solver, frames);
                Assert.That(Run.AllFinite(y), Is.True);
                int back = Array.FindIndex(frames, f => f.Time > 3.9);
                double handStep = Math.Abs(frames[back].HandY - frames[Array.FindLastIndex(frames, f => f.Time < 1.4)].HandY);
                Assert.That(Math.Abs(y[back] - y[back - 1]), Is.LessThanOrEqualTo(Math.Max(1, solver.Gain) * handStep + 0.01), m + " kg: back with the hand");
                Assert.That(Run.Last(y), Is.EqualTo(Run.Last(Run.Replay(Run.Solver(m, NamedProfiles.Get(profile)), clean))).Within(0.01), m + " kg: where it ends without the loss");
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
            Assert.That(Math.Abs(hand - solver.ObjectY), Is.LessThan(0.01), "within one pose of the hand");
            Assert.That(solver.State.Time, Is.EqualTo(600).Within(1e-6), "the hold's clock keeps the millisecond");
        }

        // P11: faster moves further (paper §3.1): the same 0.4 m lift done faster, or by a user whose v_std is lower,
        // leaves an object heavier than the standard higher once the hand has rested; the standard weight is unaffected.
        // Today's reading without it: a 2 kg object rose 12.8 cm whether the lift took 2 s or 0.3 s.
        [Test]
        public void P11_FasterMovesFurther([Values("paper", "paper-experiment")] string profile, [Values(0.5, 1, 2, 5)] double massKg)
        {
            // Under the offset correction a lift whose offset would pass 0.2 m is held at the threshold whatever its speed:
            // the paper profile is judged on a lift that stays below it.
            double lift = profile == "paper" ? 0.25 : 0.4;
            double Rise(double seconds, double standardSpeed, double m)
            {
                var frames = Run.Headset(frameRate: 90, jitterSd: 0.001, seed: 11).Render(HandPath.StartAt(0.7).Hold(0.3).MoveTo(0.7 + lift, seconds).Hold(2.5));
                var y = Run.Replay(Run.Solver(m, NamedProfiles.Get(profile), standardSpeed), frames);
                return Run.Last(y) - y[0];
            }
            double previous = double.NegativeInfinity;
            foreach (var seconds in new[] { 2.0, 1.0, 0.6, 0.3 })
            {
                double rise = Rise(seconds, 0.5, massKg);
                Assert.That(rise, Is.GreaterThan(previous + 0.002), massKg + " kg: a " + lift + " m lift in " + seconds + " s rises further than a slower one");
                previous = rise;
            }
            Assert.That(Rise(1.0, 0.3, massKg), Is.GreaterThan(Rise(1.0, 0.8, massKg) + 0.002), massKg + " kg: the same lift by a user with a lower v_std rises further");
            foreach (var seconds in new[] { 2.0, 0.3 })
                Assert.That(Rise(seconds, 0.5, PhysicalConstants.StandardMassKg), Is.EqualTo(lift).Within(0.003), "the golf ball rises with the hand");
        }

        // P11b: ... where the offset correction binds (paper profile, lifts whose offset would pass its threshold) the
        // ceiling erases the difference once a lift reaches it (the offset is a function of the lift, and the ceiling's
        // slope vanishes): a faster lift, or a user with a lower v_std, never ends lower than a slower one (issue 22, rule 4:
        // bounded here by 1 mm, the 5 mm under Quest-like input in WeightCueRuleTests), and nothing moves at rest.
        // Below the ceiling P11 holds strictly.
        [Test]
        public void P11b_FasterMovesFurtherUnderTheOffsetCorrection([Values(2.0, 5.0)] double massKg, [Values(0.4, 0.5)] double lift)
        {
            double Rise(double seconds, double standardSpeed)
            {
                var frames = Run.Headset(frameRate: 90, jitterSd: 0.001, seed: 11).Render(HandPath.StartAt(0.8).Hold(0.3).MoveTo(0.8 + lift, seconds).Hold(11));
                var y = Run.Replay(Run.Solver(massKg, NamedProfiles.Paper, standardSpeed), frames);
                // At rest: the median over the second after the hand stopped (in the correction's ceiling the object moves with
                // the hand's millimetre jitter, which would decide a comparison of single frames).
                double stop = 0.3 + seconds + 0.1;
                double atRest = QuestLikeInput.MedianOver(frames, i => y[i], stop, stop + 1);
                // P4's bound for a hand at rest with jitter: under 1 cm in 10 s (the object may follow the jitter, not creep).
                Assert.That(Math.Abs(Run.Last(y) - atRest), Is.LessThan(0.01), massKg + " kg, " + seconds + " s lift: still after 10 s at rest");
                Assert.That(Run.MaxOffset(frames, y), Is.LessThanOrEqualTo(StatedCeiling + 1e-12), massKg + " kg: offset within the stated ceiling");
                return atRest - y[0];
            }
            double previous = double.NegativeInfinity;
            foreach (var seconds in new[] { 2.0, 1.0, 0.6, 0.3 })
            {
                double rise = Rise(seconds, 0.5);
                Assert.That(rise, Is.GreaterThan(previous - 0.001), massKg + " kg: a " + lift + " m lift in " + seconds + " s ends no lower than a slower one");
                previous = rise;
            }
            Assert.That(Rise(1.0, 0.3), Is.GreaterThan(Rise(1.0, 1.0) - 0.001), massKg + " kg: the same lift by a user with a lower v_std ends no lower");
        }

        // P11c: ... and where the speed cap binds too (a slow user, v_std 0.3 m/s): the cap only measures how far the hand
        // pulls beyond what the weight allows, so a faster lift still ends no lower (within 1 mm), 1 s after the hand stops.
        [Test]
        public void P11c_TheSpeedCapNeverReversesItUnderTheCorrection([Values(0.1, 1.0, 2.0)] double massKg)
        {
            double previous = double.NegativeInfinity;
            foreach (var seconds in new[] { 0.6, 0.4, 0.3, 0.2 })
            {
                var frames = Run.Headset(frameRate: 90, jitterSd: 0.001, seed: 3).Render(HandPath.StartAt(0.8).Hold(0.3).MoveTo(1.1, seconds).Hold(1.5));
                var y = Run.Replay(Run.Solver(massKg, NamedProfiles.Paper, 0.3), frames);
                double stop = 0.3 + seconds + 0.1;
                double rise = QuestLikeInput.MedianOver(frames, i => y[i], stop + 0.5, stop + 1.4) - y[0];
                Assert.That(rise, Is.GreaterThan(previous - 0.001), massKg + " kg: a 0.3 m lift in " + seconds + " s ends no lower than a slower one");
                previous = rise;
            }
        }
    }
}