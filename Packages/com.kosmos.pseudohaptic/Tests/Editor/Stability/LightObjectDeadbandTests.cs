using System;
using Kosmos.PseudoHaptic.Simulation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests.Stability
{
    /// <summary>
    /// Objects lighter than the standard (1–40 g, gains up to the cap) are as safe as heavier ones: P12 (a tracking artifact
    /// leaves nothing), P13 (a heft leaves nothing) and P4 (jitter at rest after a lift does not creep), through the motion
    /// deadband (<see cref="MotionDeadband"/>), whose band absorbs jitter at rest only. Found by an audit: the band was a plain
    /// backlash on the raw hand, so anything that pushed the hand past the band's far edge and back (a one-pose glitch, a
    /// re-acquisition snap, a heft) moved its reference by twice its half-width, and the object by G × that: 1 g and 10 g
    /// ended 42–48 mm from where the clean path put them. Bounds are the properties', not the code's: 10 mm.
    /// </summary>
    public class LightObjectDeadbandTests
    {
        static readonly string[] Profiles = { "paper", "paper-experiment", "gain", "xyz" };

        /// <summary>The light masses the properties weigh, kg (gains from about 1.06 to the cap of 3).</summary>
        static readonly double[] Masses = { 0.001, 0.005, 0.01, 0.02, 0.04 };

        static double Settle(WeightSolver s, TraceFrame[] frames) => Run.Last(Run.Replay(s, frames));

        /// <summary>The audit's reproducer: 30 Hz poses over 90 Hz frames, no jitter, the hand lifts 5 cm in 0.4 s and rests;
        /// a one-pose glitch of +3 cm at rest, a 0.3 s loss and 0.1 s of poses 4 cm high, a heft of +3 cm and back each end
        /// within 1 cm of the clean path (they ended 42.1 mm (10 g) and 48.0 mm (1 g) off).</summary>
        [Test]
        public void TheAuditsGlitchSnapAndHeftLeaveNothing([Values("paper", "paper-experiment", "gain", "xyz")] string p, [Values(0.001, 0.01)] double m)
        {
            var path = HandPath.StartAt(1).Hold(0.3).MoveTo(1.05, 0.4).Hold(2.5);
            double R(HeadsetSimulator h, HandPath q) => Settle(Run.Solver(m, NamedProfiles.Get(p)), h.Render(q));
            double clean = R(Run.Headset(), path);
            double glitch = R(Run.Headset().Glitch(1.5, 0.03), path);
            double snap = R(Run.Headset().Drop(1.5, 0.3).Offset(1.8, 0.1, 0.04), path);
            double heft = R(Run.Headset(), HandPath.StartAt(1).Hold(0.3).MoveTo(1.05, 0.4).Hold(0.5).MoveTo(1.08, 0.3).MoveTo(1.05, 0.3).Hold(2.0));
            double heftClean = R(Run.Headset(), HandPath.StartAt(1).Hold(0.3).MoveTo(1.05, 0.4).Hold(3.1));
            TestContext.Progress.WriteLine($"{m * 1000} g, {p}: glitch {(glitch - clean) * 1000:F3} mm, snap {(snap - clean) * 1000:F3} mm, heft {(heft - heftClean) * 1000:F3} mm from the clean path");
            // Within P1's millimetre (the old band left 42–48 mm).
            Assert.Multiple(() =>
            {
                Assert.That(glitch - clean, Is.EqualTo(0).Within(0.001), "glitch");
                Assert.That(snap - clean, Is.EqualTo(0).Within(0.001), "snap");
                Assert.That(heft - heftClean, Is.EqualTo(0).Within(0.001), "heft");
            });
        }

        /// <summary>A light object's lift ends where the weight puts it: G × the hand's lift above where it began (the band
        /// costs no lasting lift; a backlash left it G × the half-width short, 24 mm at 1 g), and lowered it ends where
        /// the weight puts it too (1 g lowered 0.2 m under <c>paper</c> ended 14 mm above where the weight puts it).</summary>
        [Test]
        public void ALightObjectEndsWhereTheWeightPutsIt([Values("paper", "paper-experiment", "gain", "xyz")] string p, [Values(0.001, 0.01, 0.02)] double m)
        {
            var up = Run.Headset().Render(HandPath.StartAt(1).Hold(0.3).MoveTo(1.05, 0.4).Hold(1.5));
            var solver = Run.Solver(m, NamedProfiles.Get(p));
            double rise = Settle(solver, up) - 1;
            Assert.That(rise, Is.EqualTo(solver.Gain * 0.05).Within(0.001), "lifted 5 cm");
            var down = Run.Headset().Render(HandPath.StartAt(1).Hold(0.3).MoveTo(1.05, 0.4).Hold(0.5).MoveTo(0.85, 0.8).Hold(1.5));
            var noBand = NamedProfiles.Get(p).Without<MotionDeadband>(p + "-without-band");
            double expected = Settle(Run.Solver(m, noBand), down);
            Assert.That(Settle(Run.Solver(m, NamedProfiles.Get(p)), down), Is.EqualTo(expected).Within(0.002), "lowered 0.2 m: where the weight without a band puts it");
        }

        /// <summary>A brisk small lift from the grab is a lift, not jitter: the hand rises 14 mm within one 30 Hz pose (less
        /// than two band widths, 8 mm each at 1 g) and rests; the object ends G × 14 mm above where it began, as the weight puts
        /// it (measured 0.07–0.12 mm short; had every push at the grab dragged the band as jitter does, it stayed G × the band
        /// width short: 21–24 mm).</summary>
        [Test]
        public void ABriskSmallLiftFromTheGrabEndsWhereTheWeightPutsIt([Values("paper", "gain")] string p, [Values(0.001, 0.01)] double m)
        {
            var solver = Run.Solver(m, NamedProfiles.Get(p));
            double rise = Settle(solver, Run.Headset().Render(HandPath.StartAt(1).Hold(0.3).MoveTo(1.014, 1 / 30.0).Hold(1.5))) - 1;
            Assert.That(rise, Is.EqualTo(solver.Gain * 0.014).Within(0.001));
        }

        /// <summary>The same brisk small lift made at once: the hand rises 14 mm within one 30 Hz pose that starts at the grab's
        /// pose or one or two poses after it (no latency before the first frame: the headset's delays the grab's pose and the
        /// lift alike), and rests; the object ends G × 14 mm above where it began, as the weight without a band puts it, within
        /// P1's millimetre (measured 0.08–0.43 mm short). Here the steady hand's mean since the grab has the lift in it from
        /// the start, so it tells nothing: a push beyond half a band width closing the band at the grab, and the reference
        /// dragged half a width to a width from the grab's pose counting as motion, are what end the lift where the weight
        /// puts it (without the first, up to 12.0 mm short; without the second, up to 7.5 mm).</summary>
        [Test]
        public void ABriskSmallLiftRightAfterTheGrabEndsWhereTheWeightPutsIt([Values("paper", "gain")] string p, [Values(0.001, 0.01)] double m, [Values(0, 1, 2)] int poses)
        {
            var path = HandPath.StartAt(1);
            if (poses > 0) path.Hold(poses / 30.0);
            var headset = Run.Headset();
            headset.Latency = 0;
            var frames = headset.Render(path.MoveTo(1.014, 1 / 30.0).Hold(1.5));
            double d = BandMinusWithout(m, p, frames, frames.Length - 1);
            TestContext.Progress.WriteLine($"{m * 1000} g, {p}, lift {poses} pose(s) after the grab: ends {d * 1000:F2} mm from where the weight puts it");
            Assert.That(d, Is.EqualTo(0).Within(0.001));
        }

        /// <summary>
        /// The same on Quest-like input (<see cref="QuestLikeInput"/>: 1–2 mm jitter, one-pose glitches, low confidence at
        /// speed), over 200 seeds for each profile: the hand rises or lowers 13–18 mm within one 30 Hz pose, 0–70 ms after
        /// the grab's pose, 1–20 g, then rests 3 s; the object's median over the last second adds at most 1 cm (the
        /// light-object properties' bound) to what the same poses cost the weight without a band, both measured against that
        /// weight on the hand's real poses (the same headset without its jitter): a lift this soon can be measured only from
        /// the poses seen before it, and G times their error is the weight's own, not the band's. The headset's latency is
        /// left out: it delays the grab's pose and the lift alike, and a latency before the first frame would add 45 ms of
        /// rest at the grab, after which the steady hand's mean tells the lift on its own. Measured at most 2.03 mm (6.13 mm
        /// under <c>gain</c>); against the weight without a band on the same poses, before the hold's first poses set the
        /// base, 2.17 mm (3.58 mm), and had the reference dragged half a width to a width from the grab not counted as
        /// motion, 13.19 mm.
        /// </summary>
        [Test]
        public void ABriskSmallLiftRightAfterTheGrabEndsWhereTheWeightPutsItOnQuestLikeInput([Values("paper", "paper-experiment", "gain", "xyz")] string profile)
        {
            double worst = BandEndOverSeeds.Worst(profile, (seed, rng, mass) =>
            {
                double after = QuestLikeInput.Uniform(rng, 0, 0.07), lift = Sign(rng) * QuestLikeInput.Uniform(rng, 0.013, 0.018);
                var path = HandPath.StartAt(1);
                if (after > 0) path.Hold(after);
                path.MoveTo(1 + lift, 1 / 30.0).Hold(3);
                var headset = QuestLikeInput.Headset(new Random(seed * 7919), seed);
                headset.Latency = 0;
                var frames = headset.Render(path);
                var clean = BandEndOverSeeds.WithoutJitter(headset, path);
                return new BandEndOverSeeds.Scene
                {
                    Frames = frames, End = path.Duration, Replay = pr => Run.Replay(Run.Solver(mass, pr), frames),
                    Reference = pr => Run.Replay(Run.Solver(mass, pr), clean), BeyondPosesOwnError = true,
                    Description = $"{mass * 1000} g, lift {lift * 1000:F1} mm {after * 1000:F0} ms after the grab",
                };
            }, out string worstCase);
            TestContext.Progress.WriteLine($"{profile}: a brisk small lift right after the grab ends at most {Math.Abs(worst) * 1000:F2} mm from where the weight puts it over 200 seeds ({worstCase})");
            Assert.That(worst, Is.EqualTo(0).Within(0.01), worstCase);
        }

        /// <summary>
        /// The object does not jump while the band closes early in a brisk lift from the grab: the hand rises or lowers 2–4 cm
        /// within one pose or in up to 0.15 s, 0–70 ms after the grab's pose, on Quest-like input (as in
        /// <see cref="ABriskSmallLiftRightAfterTheGrabEndsWhereTheWeightPutsItOnQuestLikeInput"/>), 200 seeds for each
        /// profile, 1–20 g; over the lift and the first second after it, the object's largest step from one frame to the next
        /// is no more than 1 cm beyond the largest step the weight without a band makes from the same poses (P12's "plus
        /// 1 cm"): the band catching up with the hand adds a few millimetres to a step, never a jump (measured 4.00 mm in
        /// every profile; had the band at the grab closed by the whole push in one pose, whatever the hand's own step,
        /// 24.00 mm).
        /// </summary>
        [Test]
        public void WhileTheBandClosesInABriskLiftFromTheGrabTheObjectDoesNotJump([Values("paper", "paper-experiment", "gain", "xyz")] string profile)
        {
            double worst = double.NegativeInfinity;
            string worstCase = "";
            var noBand = NamedProfiles.Get(profile).Without<MotionDeadband>(profile + "-without-band");
            for (int seed = 1; seed <= 200; seed++)
            {
                var rng = new Random(seed);
                double mass = Masses[seed % 4];
                double after = QuestLikeInput.Uniform(rng, 0, 0.07), lift = Sign(rng) * QuestLikeInput.Uniform(rng, 0.02, 0.04);
                double seconds = rng.NextDouble() < 0.5 ? 1 / 30.0 : QuestLikeInput.Uniform(rng, 1 / 30.0, 0.15);
                var path = HandPath.StartAt(1);
                if (after > 0) path.Hold(after);
                path.MoveTo(1 + lift, seconds).Hold(1.5);
                var headset = QuestLikeInput.Headset(new Random(seed * 7919), seed);
                headset.Latency = 0;
                var frames = headset.Render(path);
                var withBand = Run.Replay(Run.Solver(mass, NamedProfiles.Get(profile)), frames);
                var withoutBand = Run.Replay(Run.Solver(mass, noBand), frames);
                double LargestStep(double[] y)
                {
                    double largest = 0;
                    for (int i = 1; i < frames.Length; i++)
                        if (frames[i].Time <= after + seconds + 1) largest = Math.Max(largest, Math.Abs(y[i] - y[i - 1]));
                    return largest;
                }
                double beyond = LargestStep(withBand) - LargestStep(withoutBand);
                if (beyond > worst) { worst = beyond; worstCase = $"seed {seed}: {mass * 1000} g, lift {lift * 1000:F1} mm in {seconds:F3} s {after * 1000:F0} ms after the grab"; }
            }
            TestContext.Progress.WriteLine($"{profile}: while the band closes in a brisk lift from the grab the object steps at most {worst * 1000:F2} mm beyond the weight without a band's largest step over 200 seeds ({worstCase})");
            Assert.That(worst, Is.LessThanOrEqualTo(0.01), worstCase);
        }

        /// <summary>The grab's rule is continuous: where a light object ends moves with the hand's pose, with no step where a
        /// rule switches. Scanned finely (1000 poses each): a lift from the grab within one 30 Hz pose pushing the band by a
        /// quarter of its width to a width and a quarter (across half a width, where a push stopped being jitter), then 2 s of
        /// rest; and a lift in 1 s of a quarter of a width to two and a half widths (across two widths, where the reference
        /// had been dragged a width from the grab), then 6 s of rest. Neighbouring scans end within 0.1 mm of each other
        /// (the scan's step times G is 0.02–0.07 mm; the half-width switch made steps of 20.9–23.9 mm).</summary>
        [Test]
        public void WhereALightObjectEndsHasNoStepAcrossTheGrabsRule([Values("paper", "gain")] string p, [Values(0.001, 0.01)] double m)
        {
            double w = Run.Solver(m, NamedProfiles.Get(p)).Constants.DeadbandWidth;
            double LargestStep(Func<double, HandPath> path, double from, double to, out double at)
            {
                double previous = double.NaN, largest = 0;
                at = 0;
                for (int i = 0; i <= 1000; i++)
                {
                    double x = from + (to - from) * i / 1000;
                    double y = Settle(Run.Solver(m, NamedProfiles.Get(p)), Run.Headset().Render(path(x)));
                    if (Math.Abs(y - previous) > largest) { largest = Math.Abs(y - previous); at = x; }
                    previous = y;
                }
                return largest;
            }
            double gain = Run.Solver(m, NamedProfiles.Get(p)).Gain;
            double brisk = LargestStep(d => HandPath.StartAt(1).Hold(0.3).MoveTo(1 + d, 1 / 30.0).Hold(2), 1.25 * w, 2.25 * w, out double briskAt);
            double slow = LargestStep(d => HandPath.StartAt(1).Hold(0.3).MoveTo(1 + d, 1.0).Hold(6), 0.25 * w, 2.5 * w, out double slowAt);
            double briskStep = w / 1000, slowStep = 2.25 * w / 1000;
            TestContext.Progress.WriteLine($"{m * 1000} g, {p}: largest step between neighbouring scans, {brisk * 1000:F3} mm = {brisk / (gain * briskStep):F2} G × the scan's step " +
                $"(one-pose lift of {briskAt * 1000:F2} mm), {slow * 1000:F3} mm = {slow / (gain * slowStep):F2} G × the scan's step (lift in 1 s of {slowAt * 1000:F2} mm)");
            // No step: neighbours differ by at most a few times what the weight itself makes of the scan's step (G × it).
            Assert.That(brisk, Is.LessThanOrEqualTo(4 * gain * briskStep), "one-pose lift");
            Assert.That(slow, Is.LessThanOrEqualTo(4 * gain * slowStep), "lift in 1 s");
        }

        /// <summary>A slow small lift from the grab is a lift, not jitter: the hand rises 5–20 mm in 0.5–2 s (less than the two
        /// band widths, 16 mm at 1–10 g, that the grab's rule needed to count it), right at the grab or after 0.3 s of rest, and
        /// rests 3 s; the object ends where the weight without a band puts it, within 2 mm (the grab's rule left it G × the lift
        /// or G × the band width short: up to 24 mm). Not within P1's millimetre: a lift that starts right at the grab lends
        /// its first steady poses to where the hand rests (the lift is measured from the mean of the hold's first poses until
        /// the hand shows it moved), (G − 1) × their mean: measured 1.56 mm at 1 g (20 mm in 0.5 s), 0.59 mm before that
        /// mean set the base. After 0.3 s of rest, 0.84 mm (0.56 mm before: the band's first push is now motion, and the rule
        /// after motion catches the hand up over more poses than the grab's).</summary>
        [Test]
        public void ASlowSmallLiftFromTheGrabEndsWhereTheWeightPutsIt([Values("paper", "gain")] string p, [Values(0.001, 0.01, 0.02)] double m)
        {
            double worst = 0;
            string worstCase = "";
            foreach (double rest in new[] { 0, 0.3 })
                foreach (double seconds in new[] { 0.5, 1, 2 })
                    foreach (double lift in new[] { 0.005, 0.008, 0.012, 0.016, 0.02 })
                    {
                        var path = HandPath.StartAt(1);
                        if (rest > 0) path.Hold(rest);
                        var frames = Run.Headset().Render(path.MoveTo(1 + lift, seconds).Hold(3));
                        double d = BandMinusWithout(m, p, frames, frames.Length - 1);
                        if (Math.Abs(d) > Math.Abs(worst)) { worst = d; worstCase = $"{lift * 1000} mm in {seconds} s after {rest} s"; }
                    }
            TestContext.Progress.WriteLine($"{m * 1000} g, {p}: a slow small lift from the grab ends at most {Math.Abs(worst) * 1000:F2} mm from where the weight puts it ({worstCase})");
            Assert.That(worst, Is.EqualTo(0).Within(0.002), worstCase);
        }

        /// <summary>
        /// The same on Quest-like input (<see cref="QuestLikeInput"/>: 1–2 mm jitter, one-pose glitches), over 200 seeds for each
        /// profile: a lift of 5–20 mm in 0.5–2 s after 0–0.5 s at the grab, 1–20 g, then 3 s at rest; the object's median
        /// height over the last second is within 1 cm (the light-object properties' bound) of the median the weight without a
        /// band gives the hand's real poses (the same headset without its jitter: the weight measured from where the hand
        /// rested, not from the grab's jittered pose, whose error it would carry G times). Measured at most 6.16 mm; 10.17 mm
        /// while the lift was measured from the grab's own pose (against the weight without a band on the same jittered poses,
        /// 2.93 mm); the grab's rule before that left it up to G × the band width short.
        /// </summary>
        [Test]
        public void ASlowSmallLiftFromTheGrabEndsWhereTheWeightPutsItOnQuestLikeInput([Values("paper", "paper-experiment", "gain", "xyz")] string profile)
        {
            double worst = BandEndOverSeeds.Worst(profile, (seed, rng, mass) =>
            {
                double lift = QuestLikeInput.Uniform(rng, 0.005, 0.02), seconds = QuestLikeInput.Uniform(rng, 0.5, 2), rest = QuestLikeInput.Uniform(rng, 0, 0.5);
                var path = HandPath.StartAt(1).Hold(rest).MoveTo(1 + lift, seconds).Hold(3);
                var headset = QuestLikeInput.Headset(new Random(seed * 7919), seed);
                var frames = headset.Render(path);
                var clean = BandEndOverSeeds.WithoutJitter(headset, path);
                return new BandEndOverSeeds.Scene
                {
                    Frames = frames, End = path.Duration, Replay = pr => Run.Replay(Run.Solver(mass, pr), frames),
                    Reference = pr => Run.Replay(Run.Solver(mass, pr), clean),
                    Description = $"{mass * 1000} g, lift {lift * 1000:F1} mm in {seconds:F2} s after {rest:F2} s",
                };
            }, out string worstCase);
            TestContext.Progress.WriteLine($"{profile}: a slow small lift from the grab ends at most {Math.Abs(worst) * 1000:F2} mm from where the weight puts it over 200 seeds ({worstCase})");
            Assert.That(worst, Is.EqualTo(0).Within(0.01), worstCase);
        }

        /// <summary>Near the grab, after a heft that came back and 2 s at rest, the hand drifts 12 mm up in 0.8 s (pushing the
        /// band along) and stops: 1 s later the object is no further from where the weight puts it than after the same drift
        /// made 5 cm above the grab (both measured 1.5–1.6 mm short at 1 g and 10 g; had the push near the grab not restarted
        /// the rest mean, the reference would crawl over a second's fading mean: 7.6–8.4 mm short).</summary>
        [Test]
        public void ASlowDriftNearTheGrabIsCaughtUpAsFastAsOneAfterALift([Values("paper", "gain")] string p, [Values(0.001, 0.01)] double m)
        {
            double ShortOneSecondAfter(HandPath path)
            {
                double stop = path.Duration;
                path.Hold(1.5);
                var frames = Run.Headset().Render(path);
                return Math.Abs(BandMinusWithout(m, p, frames, QuestLikeInput.FrameAt(frames, stop + 1)));
            }
            double nearTheGrab = ShortOneSecondAfter(HandPath.StartAt(1).Hold(0.3).MoveTo(1.03, 0.2).MoveTo(1.0, 0.2).Hold(2).MoveTo(1.012, 0.8));
            double afterALift = ShortOneSecondAfter(HandPath.StartAt(1).Hold(0.3).MoveTo(1.05, 0.4).Hold(1.5).MoveTo(1.062, 0.8));
            TestContext.Progress.WriteLine($"{m * 1000} g, {p}: 1 s after the drift, {nearTheGrab * 1000:F3} mm short near the grab, {afterALift * 1000:F3} mm after a lift");
            Assert.That(nearTheGrab, Is.LessThanOrEqualTo(afterALift + 0.001));
        }

        /// <summary>After 10 s at rest following a lift, the hand settles 4 mm higher (within the band, pushing nothing): the
        /// rest reference follows where the hand now rests, so 4 s later the object is within 1 mm of where the weight puts it
        /// (measured 0.14–0.19 mm; a plain mean over the whole rest, unfaded, moved it a quarter of the way: 6.4–8.6 mm).</summary>
        [Test]
        public void AfterALongRestTheObjectFollowsAHandThatSettlesALittleHigher([Values("paper", "gain")] string p, [Values(0.001, 0.01, 0.02)] double m)
        {
            var path = HandPath.StartAt(1).Hold(0.3).MoveTo(1.05, 0.4).Hold(10).MoveTo(1.054, 0.3);
            double settled = path.Duration;
            path.Hold(4.5);
            var frames = Run.Headset().Render(path);
            Assert.That(BandMinusWithout(m, p, frames, QuestLikeInput.FrameAt(frames, settled + 4)), Is.EqualTo(0).Within(0.001));
        }

        /// <summary>P4 from the grab for light objects: a hand at rest from the grab with 1.5 mm of jitter for 10 s, over 200
        /// seeds; the object's median over the last second is within 1 cm of where it was grabbed, of where the hand rests, and
        /// of its median a second after the grab (it does not creep). Measured at most 4.96 mm from the grab (the hold's first
        /// poses move the object once to their mean, 1 × the grab pose's error), 1.44–1.64 mm from where the hand rests and
        /// 0.31–1.17 mm from where it was at 1–2 s, at 1–10 g. While the lift was measured from the grab's own pose: 4.82–7.22,
        /// 4.72–7.28 and 4.82–5.40 mm (the grab's pose, however unlucky, was where the object stayed until the hand showed it
        /// moved, and G times that pose's error after); had the rest rule's drift toward the steady hand's mean run from the
        /// grab's pose, up to 12.2–17.3 mm.</summary>
        [Test]
        public void JitterAtRestFromTheGrabDoesNotCreep([Values("paper", "gain")] string p, [Values(0.001, 0.01)] double m)
        {
            double fromGrab = 0, fromRest = 0, late = 0;
            for (int seed = 1; seed <= 200; seed++)
            {
                var frames = Run.Headset(jitterSd: 0.0015, seed: seed).Render(HandPath.StartAt(1).Hold(10));
                var y = Run.Replay(Run.Solver(m, NamedProfiles.Get(p)), frames);
                double end = QuestLikeInput.MedianOver(frames, i => y[i], 9, 10);
                double[] d = { end - y[TraceReplay.FirstUsable(frames)], end - 1, end - QuestLikeInput.MedianOver(frames, i => y[i], 1, 2) };
                string what = $"seed {seed}";
                Assert.That(d[0], Is.EqualTo(0).Within(0.01), what + ": from where it was grabbed");
                Assert.That(d[1], Is.EqualTo(0).Within(0.01), what + ": from where the hand rests");
                Assert.That(d[2], Is.EqualTo(0).Within(0.01), what + ": from where it was 1–2 s after the grab");
                fromGrab = Math.Max(fromGrab, Math.Abs(d[0]));
                fromRest = Math.Max(fromRest, Math.Abs(d[1]));
                late = Math.Max(late, Math.Abs(d[2]));
            }
            TestContext.Progress.WriteLine($"{m * 1000} g, {p}: at rest from the grab the object ends at most {fromGrab * 1000:F2} mm from where it was grabbed, {fromRest * 1000:F2} mm from where the hand rests, {late * 1000:F2} mm from where it was at 1–2 s (200 seeds)");
        }

        /// <summary>After a lift, jitter at rest moves a light object by its mean only, a mean fading over about a second
        /// (the band's RestPoses): a 5 cm lift, then 10 s at rest with 1.5 mm of jitter, over 50 seeds; from
        /// 1 s after the hand stops, the object's standard deviation about its own mean is at most 0.8 mm (measured 0.53–0.58 mm
        /// at 1–10 g; a mean over the last 6 poses, as at the grab, let it wander 1.15–1.25 mm).</summary>
        [Test]
        public void AfterALiftJitterMovesALightObjectByItsMeanOnly([Values("paper", "gain")] string p, [Values(0.001, 0.01)] double m)
        {
            double sum = 0;
            int n = 0;
            for (int seed = 1; seed <= 50; seed++)
            {
                var path = HandPath.StartAt(1).Hold(0.3).MoveTo(1.05, 0.4);
                double stop = path.Duration;
                path.Hold(10.5);
                var frames = Run.Headset(jitterSd: 0.0015, seed: seed).Render(path);
                var y = Run.Replay(Run.Solver(m, NamedProfiles.Get(p)), frames);
                int from = QuestLikeInput.FrameAt(frames, stop + 1);
                double mean = 0;
                for (int i = from; i < y.Length; i++) mean += y[i];
                mean /= y.Length - from;
                for (int i = from; i < y.Length; i++) { sum += (y[i] - mean) * (y[i] - mean); n++; }
            }
            double sd = Math.Sqrt(sum / n);
            TestContext.Progress.WriteLine($"{m * 1000} g, {p}: at rest after a lift the object's standard deviation is {sd * 1000:F3} mm");
            Assert.That(sd, Is.LessThanOrEqualTo(0.0008));
        }

        /// <summary>The object's height at frame <paramref name="i"/> under profile <paramref name="p"/> less its height under the
        /// same profile without the band: how far the band leaves it from where the weight puts it.</summary>
        static double BandMinusWithout(double m, string p, TraceFrame[] frames, int i)
            => Run.Replay(Run.Solver(m, NamedProfiles.Get(p)), frames)[i]
               - Run.Replay(Run.Solver(m, NamedProfiles.Get(p).Without<MotionDeadband>(p + "-without-band")), frames)[i];

        /// <summary>A scene's own hand-motion effect, ahead of the band, that reports every step as unknown (+∞): the package
        /// itself never does (a usable pose is a height within ±100 km, its step finite), but a scene's effect may.</summary>
        sealed class UnknownStep : WeightEffect
        {
            public override string Name => "unknown-step";
            public override EffectStage Stage => EffectStage.HandMotion;
            protected override void Apply(ref MotionFrame frame, ref HoldState state, in SolverConstants constants) => frame.HandDelta = double.PositiveInfinity;
        }

        /// <summary>With every hand step reported as unknown (+∞) by a scene's effect ahead of the band, a light object still
        /// never steps more than G × the hand's own step plus the band's catching up (4 mm, as in
        /// <see cref="AfterASlowDriftPushesTheBandTheObjectCatchesUpWithoutAJump"/>): an unknown step closes the band no
        /// faster than no step at all (measured at most 2.0–4.0 mm beyond G × the hand's step on a 5 cm lift; had an infinite
        /// step closed the band by the whole push, the reference would move twice the push: 6.4–20.5 mm beyond).</summary>
        [Test]
        public void AnUnknownHandStepMovesALightObjectNoFurtherThanAKnownOne([Values(0.001, 0.01, 0.02)] double m, [Values(0.4, 1.0)] double seconds)
        {
            var frames = Run.Headset().Render(HandPath.StartAt(1).Hold(0.3).MoveTo(1.05, seconds).Hold(1));
            var solver = new WeightSolver(WeightModel.FromMass(m), new WeightProfile("unknown-step", new WeightEffect[] { new UnknownStep(), new MotionDeadband(), new WeightGain() }), 0.5);
            var y = Run.Replay(solver, frames);
            double beyond = 0;
            for (int i = 1; i < frames.Length; i++)
                beyond = Math.Max(beyond, Math.Abs(y[i] - y[i - 1]) - solver.Gain * Math.Abs(frames[i].HandY - frames[i - 1].HandY));
            TestContext.Progress.WriteLine($"{m * 1000} g, lift in {seconds} s: at most {beyond * 1000:F3} mm beyond G × the hand's step");
            Assert.That(beyond, Is.LessThanOrEqualTo(0.005));
        }

        enum Artifact { GlitchAtRest, GlitchInMotion, LossWhileMoving, LowConfidence, Snap }

        /// <summary>
        /// P12 for light objects: a lift (sometimes a lowering after it) on Quest-like input (<see cref="QuestLikeInput"/>:
        /// 1–2 mm jitter, one-pose glitches, low confidence at speed), replayed clean and with one artifact more (a one-pose
        /// glitch of 2–20 cm at rest or in motion, a loss of 0.05–1 s while the hand moves on, a low-confidence burst, a loss
        /// and a re-acquisition snap of 2–8 cm): 3 s after the artifact the object is within 1 cm of the clean run (and already
        /// 1 s after a glitch or a low-confidence burst, which hide no motion: across a gap a light object's lead on the hand's
        /// step glides at <see cref="SolverLimits.GlideSpeed"/>, which may take seconds), and while it recovers no frame steps
        /// beyond max(G, 1) × the hand's own largest step in the surrounding 100 ms plus 1 cm.
        /// </summary>
        [Test]
        public void ArtifactsLeaveALightObjectWhereTheCleanRunDoes([Range(1, 300)] int seed)
        {
            var rng = new Random(seed);
            var kind = (Artifact)(seed % 5);
            double mass = Masses[seed / 5 % Masses.Length];
            string profile = Profiles[seed / 25 % Profiles.Length];
            double standardSpeed = QuestLikeInput.Uniform(rng, 0.3, 1.2);
            double rise = QuestLikeInput.Uniform(rng, 0.03, 0.4), seconds = QuestLikeInput.Uniform(rng, 0.3, 1.5);
            double start = 0.8, liftAt = 0.5;
            var path = HandPath.StartAt(start).Hold(liftAt).MoveTo(start + rise, seconds);
            bool lowerToo = rng.NextDouble() < 0.3;
            if (lowerToo) path.MoveTo(start + rise * QuestLikeInput.Uniform(rng, 0.2, 0.8), QuestLikeInput.Uniform(rng, 0.3, 1.2));
            double end = path.Duration, at, length = 0, size = 0;
            switch (kind)
            {
                case Artifact.GlitchAtRest: at = end + QuestLikeInput.Uniform(rng, 0.2, 0.8); size = Sign(rng) * QuestLikeInput.Uniform(rng, 0.02, 0.2); break;
                case Artifact.GlitchInMotion: at = QuestLikeInput.Uniform(rng, liftAt, end); size = Sign(rng) * QuestLikeInput.Uniform(rng, 0.02, 0.2); break;
                case Artifact.LossWhileMoving: at = QuestLikeInput.Uniform(rng, liftAt - 0.1, end - 0.05); length = QuestLikeInput.Uniform(rng, 0.05, 1.0); break;
                case Artifact.LowConfidence: at = QuestLikeInput.Uniform(rng, liftAt - 0.2, end); length = QuestLikeInput.Uniform(rng, 0.05, 0.6); break;
                default: at = QuestLikeInput.Uniform(rng, liftAt, end + 0.5); length = QuestLikeInput.Uniform(rng, 0.1, 0.6); size = Sign(rng) * QuestLikeInput.Uniform(rng, 0.02, 0.08); break;
            }
            double artifactEnd = kind == Artifact.Snap ? at + length + 0.1 : at + Math.Max(length, 1.0 / 30);
            path.Hold(Math.Max(0.1, artifactEnd + 3 - path.Duration));
            HeadsetSimulator Headset() => QuestLikeInput.Headset(new Random(seed * 7919), seed);
            var degradedHeadset = Headset();
            switch (kind)
            {
                case Artifact.GlitchAtRest:
                case Artifact.GlitchInMotion: degradedHeadset.Glitch(at, size); break;
                case Artifact.LossWhileMoving: degradedHeadset.Drop(at, length); break;
                case Artifact.LowConfidence: degradedHeadset.LowConfidence(at, length); break;
                default: degradedHeadset.Drop(at, length).Offset(at + length, 0.1, size); break;
            }
            string what = $"seed {seed}: {kind} at {at:F2} s ({length:F2} s, {size * 100:F1} cm), {mass * 1000} g, {profile}, v_std {standardSpeed:F2}, " +
                $"lift {rise:F2} m in {seconds:F2} s{(lowerToo ? " and a lowering" : "")}";
            var clean = Headset().Render(path);
            var degraded = degradedHeadset.Render(path);
            var solver = Run.Solver(mass, NamedProfiles.Get(profile), standardSpeed);
            var a = Run.Replay(Run.Solver(mass, NamedProfiles.Get(profile), standardSpeed), clean);
            var b = Run.Replay(solver, degraded);
            int i = QuestLikeInput.FrameAt(clean, artifactEnd + 1);
            if (kind != Artifact.LossWhileMoving && kind != Artifact.Snap)
                Assert.That(Math.Abs(b[i] - a[i]), Is.LessThanOrEqualTo(0.01), what + ": 1 s after the artifact");
            Assert.That(Math.Abs(Run.Last(b) - Run.Last(a)), Is.LessThanOrEqualTo(0.01), what + ": at the end");
            double beyond = QuestLikeInput.StepBeyondHand(degraded, b, solver.Gain, at, artifactEnd + 1);
            Assert.That(beyond, Is.LessThanOrEqualTo(0.01), what + ": a step beyond the hand's own while it recovers");
        }

        static double Sign(Random rng) => rng.NextDouble() < 0.5 ? -1 : 1;

        /// <summary>
        /// P13 for light objects: a lift, a pause, a heft (up or down by 1–5 cm and back, 0.15–0.5 s each way), a rest, on
        /// Quest-like input; against the same lift resting as long: within 1 cm at the end.
        /// </summary>
        [Test]
        public void AHeftLeavesALightObjectWhereItWas([Range(1, 200)] int seed)
        {
            var rng = new Random(seed);
            double mass = Masses[seed % Masses.Length];
            string profile = Profiles[seed / 5 % Profiles.Length];
            double standardSpeed = QuestLikeInput.Uniform(rng, 0.3, 1.2);
            double rise = QuestLikeInput.Uniform(rng, 0.03, 0.4), seconds = QuestLikeInput.Uniform(rng, 0.3, 1.5), pause = QuestLikeInput.Uniform(rng, 0.3, 1.0);
            double heft = Sign(rng) * QuestLikeInput.Uniform(rng, 0.01, 0.05), up = QuestLikeInput.Uniform(rng, 0.15, 0.5), back = QuestLikeInput.Uniform(rng, 0.15, 0.5);
            double top = 0.8 + rise;
            var hefted = HandPath.StartAt(0.8).Hold(0.5).MoveTo(top, seconds).Hold(pause).MoveTo(top + heft, up).MoveTo(top, back).Hold(2);
            var still = HandPath.StartAt(0.8).Hold(0.5).MoveTo(top, seconds).Hold(pause + up + back + 2);
            string what = $"seed {seed}: {mass * 1000} g, {profile}, v_std {standardSpeed:F2}, lift {rise:F2} m in {seconds:F2} s, heft {heft * 100:F1} cm in {up:F2} + {back:F2} s";
            double a = Settle(Run.Solver(mass, NamedProfiles.Get(profile), standardSpeed), QuestLikeInput.Headset(new Random(seed * 7919), seed).Render(hefted));
            double b = Settle(Run.Solver(mass, NamedProfiles.Get(profile), standardSpeed), QuestLikeInput.Headset(new Random(seed * 7919), seed).Render(still));
            Assert.That(a - b, Is.EqualTo(0).Within(0.01), what);
        }

        /// <summary>
        /// P13 right at the grab: a heft of 1–5 cm up and back (0.15–0.5 s each way) 0–0.3 s after the grab, on Quest-like input,
        /// 1–40 g, 200 seeds for each profile, against the same grab resting as long: the medians of the object's height over
        /// the last second within 1 cm. Measured at most 5.54 mm (6.01 mm under <c>gain</c>); while the lift was measured from
        /// the grab's own pose, the heft took the object G times that pose's jitter from where it rested: 10.82 mm at 5 g.
        /// </summary>
        [Test]
        public void AHeftRightAfterTheGrabLeavesALightObjectWhereItWas([Values("paper", "paper-experiment", "gain", "xyz")] string profile)
        {
            double worst = WorstOverSeeds((seed, rng) =>
            {
                double mass = Masses[seed % Masses.Length];
                double standardSpeed = QuestLikeInput.Uniform(rng, 0.3, 1.2);
                double after = QuestLikeInput.Uniform(rng, 0, 0.3);
                double heft = QuestLikeInput.Uniform(rng, 0.01, 0.05), up = QuestLikeInput.Uniform(rng, 0.15, 0.5), back = QuestLikeInput.Uniform(rng, 0.15, 0.5);
                var hefted = HandPath.StartAt(0.8);
                if (after > 0) hefted.Hold(after);
                hefted.MoveTo(0.8 + heft, up).MoveTo(0.8, back).Hold(2);
                var still = HandPath.StartAt(0.8).Hold(hefted.Duration);
                return (LastSecondMedian(Run.Solver(mass, NamedProfiles.Get(profile), standardSpeed), QuestLikeInput.Headset(new Random(seed * 7919), seed).Render(hefted)),
                        LastSecondMedian(Run.Solver(mass, NamedProfiles.Get(profile), standardSpeed), QuestLikeInput.Headset(new Random(seed * 7919), seed).Render(still)),
                        $"seed {seed}: {mass * 1000} g, v_std {standardSpeed:F2}, heft {heft * 100:F1} cm {after:F2} s after the grab in {up:F2} + {back:F2} s");
            }, out string worstCase);
            TestContext.Progress.WriteLine($"{profile}: a heft right after the grab leaves a light object at most {Math.Abs(worst) * 1000:F2} mm from the grab resting, over 200 seeds ({worstCase})");
            Assert.That(worst, Is.EqualTo(0).Within(0.01), worstCase);
        }

        /// <summary>
        /// P12 right at the grab: a light object grabbed at rest, on Quest-like input, and a one-pose glitch of 2–4 cm up or
        /// down 0.1–1.5 s after the grab (its push on the band counts as motion, after which the band's reference goes to where
        /// the hand rests); against the same grab without that glitch, the medians of the object's height over the last second
        /// are within 1 cm, 200 seeds for each profile, 1–40 g. Measured at most 4.11 mm (<c>gain</c>); while the lift was measured
        /// from the grab's own pose, the glitch left the object G times that pose's distance from where the hand rests: 10.65 mm
        /// at 5 g (7.28 mm under <c>paper</c>).
        /// </summary>
        [Test]
        public void AGlitchRightAfterTheGrabLeavesALightObjectWhereTheCleanGrabDoes([Values("paper", "paper-experiment", "gain", "xyz")] string profile)
        {
            double worst = WorstOverSeeds((seed, rng) =>
            {
                double mass = Masses[seed % Masses.Length];
                double at = QuestLikeInput.Uniform(rng, 0.1, 1.5), size = Sign(rng) * QuestLikeInput.Uniform(rng, 0.02, 0.04);
                var path = HandPath.StartAt(0.8).Hold(3);
                return (LastSecondMedian(Run.Solver(mass, NamedProfiles.Get(profile)), QuestLikeInput.Headset(new Random(seed * 7919), seed).Glitch(at, size).Render(path)),
                        LastSecondMedian(Run.Solver(mass, NamedProfiles.Get(profile)), QuestLikeInput.Headset(new Random(seed * 7919), seed).Render(path)),
                        $"seed {seed}: {mass * 1000} g, a glitch of {size * 100:F1} cm {at:F2} s after the grab");
            }, out string worstCase);
            TestContext.Progress.WriteLine($"{profile}: a glitch right after the grab leaves a light object at most {Math.Abs(worst) * 1000:F2} mm from the clean grab, over 200 seeds ({worstCase})");
            Assert.That(worst, Is.EqualTo(0).Within(0.01), worstCase);
        }

        /// <summary>The signed difference of largest size, over seeds 1–200, between the object's end with and without what a
        /// seed's scene adds (a heft, a glitch), and the scene it came from.</summary>
        static double WorstOverSeeds(Func<int, Random, (double With, double Without, string Case)> scene, out string worstCase)
        {
            double worst = 0;
            worstCase = "";
            for (int seed = 1; seed <= 200; seed++)
            {
                var r = scene(seed, new Random(seed));
                if (Math.Abs(r.With - r.Without) > Math.Abs(worst)) { worst = r.With - r.Without; worstCase = r.Case; }
            }
            return worst;
        }

        static double LastSecondMedian(WeightSolver solver, TraceFrame[] frames)
        {
            var y = Run.Replay(solver, frames);
            int from = QuestLikeInput.FrameAt(frames, frames[frames.Length - 1].Time - 1);
            var last = new double[y.Length - from];
            Array.Copy(y, from, last, 0, last.Length);
            Array.Sort(last);
            return last[last.Length / 2];
        }

        /// <summary>
        /// P4 after a lift, not only from the grab (as <see cref="SolverPropertyTests.P4_NoCreepAtRest"/> judges it from the
        /// grab): a lift or lowering of 3–40 cm, then 10 s at rest with 1.5 mm of jitter; from 0.5 s after the hand stopped
        /// (the band regrows and the reference settles on the mean of the first poses at rest) the object ends within 1 cm of
        /// where it was and never strays from it by more than 1 cm or than the hand's own poses strayed from theirs (at 40 g,
        /// G ≈ 1.06, the band is 0.7 mm wide and the object follows the hand's jitter as the golf ball does), over 200 seeds
        /// for each light mass and profile. (A plain backlash strayed up to 13.5 mm at 1 g.)
        /// </summary>
        [Test]
        public void JitterAfterALiftDoesNotCreep([Values("paper", "paper-experiment", "gain", "xyz")] string profile, [ValueSource(nameof(Masses))] double mass)
        {
            double worst = 0;
            string worstCase = "";
            for (int seed = 1; seed <= 200; seed++)
            {
                var rng = new Random(seed);
                double rise = Sign(rng) * QuestLikeInput.Uniform(rng, 0.03, 0.4), seconds = QuestLikeInput.Uniform(rng, 0.3, 1.5);
                var path = HandPath.StartAt(1).Hold(0.3).MoveTo(1 + rise, seconds);
                double stop = path.Duration;
                path.Hold(10.5);
                var frames = Run.Headset(jitterSd: 0.0015, seed: seed).Render(path);
                var y = Run.Replay(Run.Solver(mass, NamedProfiles.Get(profile)), frames);
                int from = QuestLikeInput.FrameAt(frames, stop + 0.5);
                double creep = Math.Abs(Run.Last(y) - y[from]), stray = 0, handStray = 0;
                for (int i = from; i < y.Length; i++)
                {
                    stray = Math.Max(stray, Math.Abs(y[i] - y[from]));
                    handStray = Math.Max(handStray, Math.Abs(frames[i].HandY - frames[from].HandY));
                }
                string what = $"{mass * 1000} g, {profile}, seed {seed}: lift {rise:F3} m in {seconds:F2} s";
                Assert.That(stray, Is.LessThanOrEqualTo(Math.Max(0.01, handStray) + 1e-12), what + ": strays from where it was 0.5 s after the stop");
                if (creep > worst) { worst = creep; worstCase = what; }
            }
            TestContext.Progress.WriteLine($"creep after a lift, worst of 200 seeds: {worst * 1000:F2} mm ({worstCase})");
            Assert.That(worst, Is.LessThan(0.01), "worst creep in 10 s over 200 seeds (" + worstCase + ")");
        }

        /// <summary>At rest after a lift, the hand drifts 12 mm in 0.8 s (up or down), pushing the band along, and stops: the band's
        /// reference then catches up with where the hand rests a little each pose, so the object makes no jump: no frame from the
        /// drift on steps more than 5 mm (designed: 4 mm a pose, the object's extra step; measured 4.0 mm; with the catching up
        /// unbounded the object jumped 11.7 mm in one frame).</summary>
        [Test]
        public void AfterASlowDriftPushesTheBandTheObjectCatchesUpWithoutAJump([Values("paper", "gain")] string p, [Values(0.001, 0.01)] double m, [Values(1, -1)] int direction)
        {
            var frames = Run.Headset().Render(HandPath.StartAt(1).Hold(0.3).MoveTo(1.05, 0.4).Hold(1.5).MoveTo(1.05 + direction * 0.012, 0.8).Hold(1.5));
            var y = Run.Replay(Run.Solver(m, NamedProfiles.Get(p)), frames);
            double largest = 0;
            for (int i = 1; i < frames.Length; i++)
                if (frames[i].Time >= 2.2) largest = Math.Max(largest, Math.Abs(y[i] - y[i - 1]));
            Assert.That(largest, Is.LessThanOrEqualTo(0.005));
        }

        /// <summary>A loss of 0.2–0.3 s while the hand lifts 3 cm: across the gap the band's reference moves no further than the
        /// hand's step, so the band never makes the object's step across the gap larger than it is without the band (measured:
        /// equal, or smaller where the band still held some of the hand's motion; with the per-pose spare across the gap too, up
        /// to 1.5 mm larger).</summary>
        [Test]
        public void AcrossALossTheBandAddsNothingToTheObjectsStep([Values("paper", "gain")] string p, [Values(0.001, 0.01, 0.04)] double m,
            [Values(0.2, 0.3)] double loss, [Values(0.6, 1.0)] double seconds)
        {
            var frames = Run.Headset().Drop(1.0, loss).Render(HandPath.StartAt(1).Hold(0.8).MoveTo(1.03, seconds).Hold(2));
            double StepAcrossTheGap(WeightProfile profile)
            {
                var y = Run.Replay(Run.Solver(m, profile), frames);
                for (int i = 0, last = -1; i < frames.Length; i++)
                {
                    if (!frames[i].IsUsable) continue;
                    if (last >= 0 && frames[i].Time - frames[last].Time > 0.1) return y[i] - y[last];
                    last = i;
                }
                throw new InvalidOperationException("no gap");
            }
            double withBand = StepAcrossTheGap(NamedProfiles.Get(p));
            double without = StepAcrossTheGap(NamedProfiles.Get(p).Without<MotionDeadband>(p + "-without-band"));
            Assert.That(withBand, Is.LessThanOrEqualTo(without + 1e-6));
        }
    }
}
