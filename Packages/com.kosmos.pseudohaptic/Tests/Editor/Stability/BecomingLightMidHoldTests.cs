using System;
using Kosmos.PseudoHaptic.Simulation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests.Stability
{
    /// <summary>
    /// An object that becomes lighter than the standard during a hold: <see cref="WeightSolver.Configure"/> from a mass whose
    /// gain is at most 1 (heavier than the standard golf ball, 45 g: no band, the object is the hand's) down to 1 g or 10 g,
    /// where the motion deadband (<see cref="MotionDeadband"/>) opens. What a user expects: the object behaves as a light
    /// object held from the grab does (jitter at rest moves it no more; a small lift ends where the weight puts it), and
    /// nothing becomes NaN.
    /// </summary>
    public class BecomingLightMidHoldTests
    {
        /// <summary>The mass held until the change, kg: heavier than the standard, gain below 1 in every named profile.</summary>
        const double HeavyMass = 0.1;

        /// <summary>Replays <paramref name="frames"/> as <see cref="TraceReplay"/> does, the object held as
        /// <paramref name="fromMass"/> until the first frame at or after <paramref name="changeAt"/> (s), then as
        /// <paramref name="toMass"/> (the same profile and user).</summary>
        internal static double[] Replay(double fromMass, double toMass, WeightProfile profile, TraceFrame[] frames, double changeAt)
        {
            var solver = Run.Solver(fromMass, profile);
            var y = new double[frames.Length];
            int first = TraceReplay.FirstUsable(frames);
            solver.BeginHold(frames[first].HandY, frames[first].HandY, frames[first].PoseTime);
            bool changed = false;
            for (int i = 0; i < frames.Length; i++)
            {
                if (!changed && frames[i].Time >= changeAt - 1e-9)
                {
                    solver.Configure(WeightModel.FromMass(toMass), profile, solver.StandardSpeed);
                    changed = true;
                }
                y[i] = i <= first ? solver.ObjectY : solver.Step(frames[i].ToSample(), frames[i].Time - frames[i - 1].Time);
            }
            return y;
        }

        [Test]
        public void TheHeavyMassHasNoBand([Values("paper", "paper-experiment", "gain", "xyz")] string p)
        {
            var solver = Run.Solver(HeavyMass, NamedProfiles.Get(p));
            Assert.That(solver.Gain, Is.LessThanOrEqualTo(1));
            Assert.That(solver.Constants.DeadbandWidth, Is.EqualTo(0));
        }

        /// <summary>
        /// After the change the band adds nothing to where the weight puts the object but the lack of jitter: the hand rests
        /// with 1.5 mm of jitter (30 Hz poses over 90 Hz frames), held as 100 g for 1 s, then as 1 g or 10 g for 10 s more, over
        /// 200 seeds; the object's median just after the change (1.1–1.5 s) and over the last second is within 1 cm (P4's
        /// bound) of the weight's without a band (the profile without <see cref="MotionDeadband"/>, the same poses and change).
        /// The weight itself moves the object at such a change, by (G_light − G_heavy) × (hand − base), which a comparison
        /// with where the 100 g object sat would count as creep. Measured at most 5.06 mm (the steady hand's mean is where the
        /// band restarts); restarted on the grab's own pose, 17.10 mm (seed 47, whose grab pose lay 5.6 mm above where the hand
        /// rests); started closed at the hand, the rest rule's mean drifting from that one pose, see the print on a mutant.
        /// </summary>
        [Test]
        public void AfterBecomingLightAtRestTheBandAddsNoOffsetToWhereTheWeightPutsIt([Values("paper", "gain")] string p, [Values(0.001, 0.01)] double m)
        {
            double worst = WorstAddedByTheBand(p, m, seed => HandPath.StartAt(1).Hold(11), 1, new[] { (1.1, 1.5), (10.0, 11.0) }, seed => $"seed {seed}", out string worstCase);
            TestContext.Progress.WriteLine($"{m * 1000} g, {p}: after becoming light at rest the band puts the object at most {Math.Abs(worst) * 1000:F2} mm from where the weight without a band does ({worstCase})");
            Assert.That(worst, Is.EqualTo(0).Within(0.01), worstCase);
        }

        /// <summary>Over seeds 1–200 of 1.5 mm jitter on <paramref name="pathOf"/>'s path, held as 100 g until
        /// <paramref name="changeAt"/> (s) and then as <paramref name="m"/>: the object's median less the weight without a
        /// band's (the same poses and change) over each of <paramref name="windows"/> (s), the one of largest size; every
        /// height finite.</summary>
        static double WorstAddedByTheBand(string p, double m, Func<int, HandPath> pathOf, double changeAt, (double From, double To)[] windows,
            Func<int, string> name, out string worstCase)
        {
            var profile = NamedProfiles.Get(p);
            var without = profile.Without<MotionDeadband>();
            double worst = 0;
            worstCase = "";
            for (int seed = 1; seed <= 200; seed++)
            {
                var frames = Run.Headset(jitterSd: 0.0015, seed: seed).Render(pathOf(seed));
                var y = Replay(HeavyMass, m, profile, frames, changeAt);
                var n = Replay(HeavyMass, m, without, frames, changeAt);
                Assert.That(Run.AllFinite(y), Is.True, $"seed {seed}: finite");
                foreach (var (from, to) in windows)
                {
                    double added = QuestLikeInput.MedianOver(frames, i => y[i] - n[i], from, to);
                    if (Math.Abs(added) > Math.Abs(worst)) { worst = added; worstCase = $"{name(seed)}, {from}-{to} s"; }
                }
            }
            return worst;
        }

        /// <summary>
        /// A band opened after a long heavy hold starts where the hand rests now, not where it rested before: held as 100 g,
        /// the hand rests 2 s at the grab's pose, settles up or down by half the light object's band width in 0.5 s (staying
        /// within the band of the grab's pose, so the band starts as at a grab), rests 2.5 s, and the object becomes 1 g or
        /// 10 g at 5 s, the hand resting 6 s more, with 1.5 mm of jitter throughout, 200 seeds. The object's median just
        /// after the change (5.1–5.5 s) and over the last second is within 1 cm (P4's bound) of the weight's without a band.
        /// Measured at most 6.14 mm (4.44–4.87 mm under <c>paper</c>); had the steady hand's mean stopped taking poses once
        /// it fades over 30 (a second and more into the hold, where it multiplies by the reciprocal), 14.52–17.09 mm: the
        /// band started where the hand rested before.
        /// </summary>
        [Test]
        public void AfterALongHeavyHoldTheBandStartsWhereTheHandNowRests([Values("paper", "gain")] string p, [Values(0.001, 0.01)] double m)
        {
            double w = Run.Solver(m, NamedProfiles.Get(p)).Constants.DeadbandWidth;
            double Settle(int seed) => (seed % 2 == 0 ? 0.5 : -0.5) * w;
            double worst = WorstAddedByTheBand(p, m, seed => HandPath.StartAt(1).Hold(2).MoveTo(1 + Settle(seed), 0.5).Hold(8.5), 5,
                new[] { (5.1, 5.5), (10.0, 11.0) }, seed => $"seed {seed}, settled {Settle(seed) * 1000:F1} mm", out string worstCase);
            TestContext.Progress.WriteLine($"{m * 1000} g, {p} (band width {w * 1000:F2} mm): after a long heavy hold the band puts the object at most {Math.Abs(worst) * 1000:F2} mm from where the weight without a band does ({worstCase})");
            Assert.That(worst, Is.EqualTo(0).Within(0.01), worstCase);
        }

        /// <summary>
        /// The mass switched back and forth during a hold (a study toggling the condition, a scene swapping the object's mass):
        /// the hand rests with 1.5 mm of jitter, held as 100 g for 1 s, then as 1 g or 10 g and 100 g in turn, half a second
        /// each, to 11 s (twenty changes), over 200 seeds. Every height is finite, and over the last light half second
        /// (10–10.5 s) the object's median is within 1 cm (P4's bound) of the weight's without a band, the same poses and
        /// changes: the changes leave the band nothing of their own.
        /// </summary>
        [Test]
        public void TheMassSwitchedBackAndForthAtRestLeavesTheBandNothing([Values("paper", "gain")] string p, [Values(0.001, 0.01)] double m)
        {
            var profile = NamedProfiles.Get(p);
            double worst = 0;
            string worstCase = "";
            for (int seed = 1; seed <= 200; seed++)
            {
                var frames = Run.Headset(jitterSd: 0.0015, seed: seed).Render(HandPath.StartAt(1).Hold(11));
                var y = Toggled(profile, m, frames);
                var n = Toggled(profile.Without<MotionDeadband>(), m, frames);
                Assert.That(Run.AllFinite(y), Is.True, $"seed {seed}: finite");
                double added = QuestLikeInput.MedianOver(frames, i => y[i] - n[i], 10, 10.5);
                if (Math.Abs(added) > Math.Abs(worst)) { worst = added; worstCase = $"seed {seed}"; }
            }
            TestContext.Progress.WriteLine($"{m * 1000} g and 100 g in turn, {p}: the band puts the object at most {Math.Abs(worst) * 1000:F2} mm from where the weight without a band does ({worstCase})");
            Assert.That(worst, Is.EqualTo(0).Within(0.01), worstCase);
        }

        /// <summary>Replays <paramref name="frames"/> held as 100 g until 1 s, then as <paramref name="m"/> from 1 s to 1.5 s,
        /// 2 s to 2.5 s, …, 10 s to 10.5 s and as 100 g between (twenty changes).</summary>
        static double[] Toggled(WeightProfile profile, double m, TraceFrame[] frames)
        {
            var solver = Run.Solver(HeavyMass, profile);
            var y = new double[frames.Length];
            int first = TraceReplay.FirstUsable(frames);
            solver.BeginHold(frames[first].HandY, frames[first].HandY, frames[first].PoseTime);
            int switched = 0;
            for (int i = 0; i < frames.Length; i++)
            {
                int due = frames[i].Time < 1 - 1e-9 ? 0 : 1 + (int)Math.Floor((frames[i].Time - 1 + 1e-9) / 0.5);
                if (due != switched)
                {
                    switched = due;
                    solver.Configure(WeightModel.FromMass(due % 2 == 1 ? m : HeavyMass), profile, solver.StandardSpeed);
                }
                y[i] = i <= first ? solver.ObjectY : solver.Step(frames[i].ToSample(), frames[i].Time - frames[i - 1].Time);
            }
            Assert.That(switched, Is.InRange(20, 21), "ten changes to light and ten back");
            return y;
        }

        /// <summary>
        /// A slow small lift after the change is a lift: held as 100 g for 0.5 s at rest, then as 1 g or 10 g, the hand rises
        /// 5–20 mm in 0.5–2 s (at once or after 0.3 s) and rests 3 s; the object ends where the weight without a band puts
        /// it (the same poses and the same change, the profile without <see cref="MotionDeadband"/>), within P1's millimetre
        /// (measured 0.54–0.59 mm, as from the grab; with the band started closed at the hand at the change, up to 1.02 mm).
        /// </summary>
        [Test]
        public void ASlowSmallLiftAfterBecomingLightEndsWhereTheWeightPutsIt([Values("paper", "gain")] string p, [Values(0.001, 0.01)] double m)
        {
            double worst = 0;
            string worstCase = "";
            var noBand = NamedProfiles.Get(p).Without<MotionDeadband>(p + "-without-band");
            foreach (double rest in new[] { 0, 0.3 })
                foreach (double seconds in new[] { 0.5, 1, 2 })
                    foreach (double lift in new[] { 0.005, 0.008, 0.012, 0.016, 0.02 })
                    {
                        var path = HandPath.StartAt(1).Hold(0.5 + rest).MoveTo(1 + lift, seconds).Hold(3);
                        var frames = Run.Headset().Render(path);
                        var y = Replay(HeavyMass, m, NamedProfiles.Get(p), frames, 0.5);
                        Assert.That(Run.AllFinite(y), Is.True);
                        double d = Run.Last(y) - Run.Last(Replay(HeavyMass, m, noBand, frames, 0.5));
                        if (Math.Abs(d) > Math.Abs(worst)) { worst = d; worstCase = $"{lift * 1000} mm in {seconds} s after {rest} s"; }
                    }
            TestContext.Progress.WriteLine($"{m * 1000} g, {p}: a slow small lift after becoming light ends at most {Math.Abs(worst) * 1000:F2} mm from where the weight puts it ({worstCase})");
            Assert.That(worst, Is.EqualTo(0).Within(0.001), worstCase);
        }

        /// <summary>
        /// The same on Quest-like input (<see cref="QuestLikeInput"/>), 200 seeds for each profile: held as 100 g for 0.3–1 s,
        /// then as 1–20 g, a lift of 5–20 mm in 0.5–2 s after 0–0.5 s, then 3 s at rest; the object's median over the last
        /// second is within 1 cm (the light-object properties' bound) of the median the weight without a band gives
        /// (measured 3.72 mm in every profile).
        /// </summary>
        [Test]
        public void ASlowSmallLiftAfterBecomingLightEndsWhereTheWeightPutsItOnQuestLikeInput([Values("paper", "paper-experiment", "gain", "xyz")] string profile)
        {
            double worst = BandEndOverSeeds.Worst(profile, (seed, rng, mass) =>
            {
                double changeAt = QuestLikeInput.Uniform(rng, 0.3, 1), lift = QuestLikeInput.Uniform(rng, 0.005, 0.02);
                double seconds = QuestLikeInput.Uniform(rng, 0.5, 2), rest = QuestLikeInput.Uniform(rng, 0, 0.5);
                var path = HandPath.StartAt(1).Hold(changeAt + rest).MoveTo(1 + lift, seconds).Hold(3);
                var frames = QuestLikeInput.Headset(new Random(seed * 7919), seed).Render(path);
                return new BandEndOverSeeds.Scene
                {
                    Frames = frames, End = path.Duration, Replay = pr => Replay(HeavyMass, mass, pr, frames, changeAt),
                    Description = $"{mass * 1000} g at {changeAt:F2} s, lift {lift * 1000:F1} mm in {seconds:F2} s after {rest:F2} s",
                };
            }, out string worstCase);
            Assert.That(Run.AllFinite(Replay(HeavyMass, 0.001, NamedProfiles.Get(profile), QuestLikeInput.Headset(new Random(7919), 1).Render(HandPath.StartAt(1).Hold(0.5).MoveTo(1.01, 0.5).Hold(1)), 0.5)), Is.True);
            TestContext.Progress.WriteLine($"{profile}: a slow small lift after becoming light ends at most {Math.Abs(worst) * 1000:F2} mm from where the weight puts it over 200 seeds ({worstCase})");
            Assert.That(worst, Is.EqualTo(0).Within(0.01), worstCase);
        }

        /// <summary>
        /// After a lift, the change moves the object only as the weight does: held as 100 g, the hand lifts 1–5 cm in 0.5 s,
        /// rests 1 s, and the object becomes 1 g or 10 g (on a tracked pose, or 0.1 s into a 0.2 s loss); over the 2 s after
        /// the change the object is never more than 1 cm (the light-object properties' bound) from where the weight without a
        /// band puts it (the same poses and change), every height is finite, and it ends within P1's millimetre of it.
        /// </summary>
        [Test]
        public void AfterALiftTheChangeMovesTheObjectAsTheWeightDoes([Values("paper", "gain")] string p, [Values(0.001, 0.01)] double m,
            [Values(0.01, 0.015, 0.02, 0.03, 0.05, -0.02)] double lift, [Values(false, true)] bool inALoss)
        {
            var noBand = NamedProfiles.Get(p).Without<MotionDeadband>(p + "-without-band");
            var headset = Run.Headset();
            if (inALoss) headset.Drop(1.7, 0.2);
            var frames = headset.Render(HandPath.StartAt(1).Hold(0.3).MoveTo(1 + lift, 0.5).Hold(3));
            var a = Replay(HeavyMass, m, NamedProfiles.Get(p), frames, 1.8);
            var b = Replay(HeavyMass, m, noBand, frames, 1.8);
            double largest = 0;
            for (int i = QuestLikeInput.FrameAt(frames, 1.8); i < frames.Length; i++) largest = Math.Max(largest, Math.Abs(a[i] - b[i]));
            TestContext.Progress.WriteLine($"{m * 1000} g, {p}, lift {lift * 1000} mm: after the change at most {largest * 1000:F2} mm from the weight without a band, at the end {(Run.Last(a) - Run.Last(b)) * 1000:F2} mm");
            Assert.That(Run.AllFinite(a), Is.True);
            Assert.That(largest, Is.LessThanOrEqualTo(0.01), "largest");
            Assert.That(Run.Last(a) - Run.Last(b), Is.EqualTo(0).Within(0.001), "at the end");
        }
    }
}
