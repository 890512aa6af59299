using System;
using System.Collections.Generic;
using Kosmos.PseudoHaptic.Simulation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests.Stability
{
    /// <summary>
    /// ALGORITHM.md §2: the offset is a function of where the hand is (for a given base and pace), so nothing moves while the
    /// hand rests. <see cref="FasterMovesFurther"/>'s pause used to change the pace of a rise under
    /// <see cref="FasterMovesFurther.MinPacedRise"/> while the hand was still (to 0, or to a very slow lift's mean since the
    /// band), and the solver glided the object to the new gain at 0.3 m/s: a 0.5 kg object lifted in eight stages of 25 mm
    /// moved 16.05 mm in all while the hand rested, up to 3.33 mm in one frame.
    /// </summary>
    [TestFixture]
    public class HandAtRestObjectAtRestTests
    {
        /// <summary>
        /// A hand lifted in eight stages with a 0.4 s rest after each, clean 30 Hz poses over 90 Hz frames: summed over every
        /// frame on which the hand rests (it shows the pose the frame before did, and that pose the place the pose before it did), the object moves at most 0.1 mm (on the old code 6–16 mm at stages of
        /// 25 mm, 8–12 mm at 15 mm in 0.5 s; each a glide of the pace's change at up to 3.3 mm a frame). 0.1 mm in all is 1/30 of
        /// one frame of that glide, and far below what a user sees; what may remain is a glide begun while the hand moved.
        /// </summary>
        [Test]
        public void OnCleanPosesAnObjectLiftedInStagesIsStillWhileTheHandRests([Values(0.5, 2, 5)] double mass,
            [Values(0.015, 0.025)] double stage, [Values(0.5, 1.5)] double seconds)
        {
            var path = HandPath.StartAt(0.8).Hold(0.4);
            double h = 0.8;
            for (int k = 0; k < 8; k++) { h += stage; path.MoveTo(h, seconds).Hold(0.4); }
            path.Hold(1);
            AssertStill(path, Run.Solver(mass, NamedProfiles.Paper, 0.6), $"{mass} kg, stages of {stage * 1000} mm in {seconds} s");
        }

        /// <summary>
        /// A composed profile's faster-moves-further (rest band 5 cm, sensitivity 1.05): a single fast lift of 73 mm leaves the
        /// band by 23 mm, under <see cref="FasterMovesFurther.MinPacedRise"/>; its pause set the pace to 0 and a 2 kg object sank
        /// 16 mm while the hand rested.
        /// </summary>
        [Test]
        public void AFastLiftUnderMinPacedRiseAboveAWideBandIsStillAtRest([Values(0.5, 2, 5)] double mass)
        {
            var profile = NamedProfiles.Paper.With(new FasterMovesFurther(restBand: 0.05, sensitivity: 1.05));
            var path = HandPath.StartAt(0.8).Hold(0.4).MoveTo(0.873, 0.3).Hold(2);
            AssertStill(path, Run.Solver(mass, profile, 0.6), $"{mass} kg, 73 mm in 0.3 s, rest band 5 cm, sensitivity 1.05");
        }

        /// <summary>The headset's pose period, s (30 Hz). A frame counts as the hand at rest once the hand stands still over two poses:
        /// on the frames that still show the last step, the glide of a pace changed by the rise's last new top, while the hand
        /// moved, may be under way (0.64 mm on the frame after the last step of the 73 mm lift below).</summary>
        const double PosePeriod = 1.0 / 30;

        static void AssertStill(HandPath path, WeightSolver solver, string what)
        {
            var frames = Run.Headset(jitterSd: 0).Render(path);
            var y = Run.Replay(solver, frames);
            double worst = 0, total = 0;
            for (int i = 1; i < frames.Length; i++)
            {
                // The hand rests: the frame shows the pose the last one did, and that pose the place the pose before it did.
                double pose = frames[i].PoseTime;
                if (frames[i].HandY != frames[i - 1].HandY || path.HeightAt(pose) != path.HeightAt(pose - PosePeriod)) continue;
                double d = Math.Abs(y[i] - y[i - 1]);
                total += d;
                worst = Math.Max(worst, d);
            }
            TestContext.WriteLine($"{what}: the object moved {total * 1000:F3} mm in all on frames the hand rested, {worst * 1000:F3} mm at most in one");
            Assert.That(total, Is.LessThanOrEqualTo(1e-4), what);
        }

        /// <summary>
        /// Quest-like input (30 Hz poses over 72–120 Hz frames, 45 ms late, 1–2 mm jitter, low-confidence fast poses; no
        /// glitches: a two-pose glitch is a separate, documented exception, ALGORITHM.md §2), 200 seeds of a lift in 3–8 stages
        /// of 1–6 cm, 0.3–1.5 s each, with a rest of 0.3–0.8 s after each; 0.5–5 kg, v_std 0.3–1.2 m/s. Jitter moves the object
        /// at rest with or without faster-moves-further, so what faster-moves-further adds is measured on the difference of the
        /// object's height under <c>paper</c> and under <c>paper</c> without it, on the same frames: over each rest (from when the
        /// second pose of the rest is shown to when the hand moves again), the change of that difference from its median over
        /// the rest's first 0.1 s to its median over its last 0.1 s, summed over a seed's rests. At most 2.5 mm a seed and
        /// 0.5 mm a seed on average (now 1.93 mm at most, 0.36 mm on average, 4 seeds over 1 mm; on the old code 6.60 mm at most,
        /// 0.78 mm on average, 57 seeds over 1 mm and 10 over 2.5 mm). What remains is not the pause: jitter at rest lifts the steady hand 2 mm above the rise's top, a new top
        /// by the effect's own measure, whose pace then differs from the one in use (seed 97: 0.137 → 0.053 m/s, 0.6 mm).
        /// </summary>
        [Test]
        public void OnQuestLikeInputFasterMovesFurtherAddsNoMotionWhileTheHandRests()
        {
            const int seeds = 200;
            double worst = 0, sum = 0;
            int worstSeed = 0, overOne = 0;
            var failures = new List<string>();
            for (int seed = 1; seed <= seeds; seed++)
            {
                var rng = new Random(seed);
                double mass = QuestLikeInput.Masses[1 + rng.Next(QuestLikeInput.Masses.Length - 1)], vStd = QuestLikeInput.Uniform(rng, 0.3, 1.2);
                var path = HandPath.StartAt(0.8).Hold(0.4);
                double h = 0.8;
                int stages = 3 + rng.Next(6);
                var rests = new List<(double from, double to)>();
                for (int k = 0; k < stages; k++)
                {
                    h += QuestLikeInput.Uniform(rng, 0.01, 0.06);
                    path.MoveTo(h, QuestLikeInput.Uniform(rng, 0.3, 1.5));
                    double from = path.Duration;
                    path.Hold(k == stages - 1 ? 1.0 : QuestLikeInput.Uniform(rng, 0.3, 0.8));
                    rests.Add((from, path.Duration));
                }
                var headset = QuestLikeInput.Headset(rng, seed);
                headset.GlitchChance = 0;
                var frames = headset.Render(path);
                var with = Run.Replay(Run.Solver(mass, NamedProfiles.Paper, vStd), frames);
                var without = Run.Replay(Run.Solver(mass, NamedProfiles.Paper.Without<FasterMovesFurther>(), vStd), frames);
                Func<int, double> added = k => with[k] - without[k];
                double moved = 0;
                foreach (var (from, to) in rests)
                {
                    double a = from + headset.Latency + 1.0 / headset.PoseRate, b = to + headset.Latency;
                    moved += Math.Abs(QuestLikeInput.MedianOver(frames, added, b - 0.1, b) - QuestLikeInput.MedianOver(frames, added, a, a + 0.1));
                }
                sum += moved;
                if (moved > 0.001) overOne++;
                if (moved > worst) { worst = moved; worstSeed = seed; }
                if (moved > 0.0025) failures.Add($"seed {seed}: {mass} kg, v_std {vStd:F2}, {stages} stages: {moved * 1000:F2} mm");
            }
            TestContext.WriteLine($"over {seeds} seeds, faster-moves-further moved the object while the hand rested by {sum / seeds * 1000:F2} mm a seed on average, {worst * 1000:F2} mm at most (seed {worstSeed}); {overOne} seeds over 1 mm");
            Assert.That(failures, Is.Empty);
            Assert.That(sum / seeds, Is.LessThanOrEqualTo(0.0005), "on average");
        }
    }
}
