using System;
using Kosmos.PseudoHaptic.Simulation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests.Stability
{
    /// <summary>
    /// The offset relaxation's time constant on Quest-like input (<see cref="QuestLikeInput"/>: 30 Hz poses over 72–120 Hz
    /// frames, 45 ms late, here 1–3 mm of jitter, low-confidence poses, one-pose glitches): a hand resting after a lift relaxes
    /// its lift as a clean one does, e^(−1) of it left after τ and e^(−3) after 3τ, and ends at the hand; a hand at rest from
    /// the grab does not creep (P4). The still test once read the pose-to-pose speed, which jitter of 1.5 mm at 30 Hz puts
    /// above 0.1 × v_std about half the time: 0.576 of the lift was left after τ and 0.199 after 3τ (3 mm: 0.750 and 0.420),
    /// and 12 s after the lift the object still hung 4.5 mm (3 mm: 31 mm) below the hand.
    /// </summary>
    [TestFixture]
    public class OffsetRelaxationJitterTests
    {
        const double Tau = 1.5, Start = 1.0, Rise = 0.3, MoveEnd = 0.3 + 1.0, RestFrom = MoveEnd + 0.3;

        static WeightProfile Profile(int which) => which == 0
            ? new WeightProfile("gain+relaxation", new WeightEffect[] { new WeightGain(), new OffsetRelaxation(Tau) })
            : which == 1 ? NamedProfiles.Paper.With(new OffsetRelaxation(Tau)) : NamedProfiles.PaperExperiment.With(new OffsetRelaxation(Tau));

        static readonly double[] Masses = { 0.5, 1, 2, 5 };

        static HeadsetSimulator Headset(Random rng, int seed, bool jitter)
        {
            var h = QuestLikeInput.Headset(rng, seed);
            h.JitterSd = QuestLikeInput.Uniform(rng, 0.001, 0.003);
            if (!jitter) { h.JitterSd = 0; h.GlitchChance = 0; h.LowConfidenceChance = 0; }
            return h;
        }

        /// <summary>The lift left after τ and 3τ of rest (of what was left 0.3 s after the hand stopped), the lift being the
        /// hand's true height less the base; and the object's median height over the last second less the hand's.</summary>
        static (double afterTau, double afterThreeTau, double endOffset, string description) Relax(int seed, bool jitter)
        {
            var rng = new Random(seed);
            int which = rng.Next(3);
            double mass = Masses[rng.Next(Masses.Length)], vStd = QuestLikeInput.Uniform(rng, 0.3, 1.2);
            var headset = Headset(rng, seed, jitter);
            var frames = headset.Render(HandPath.StartAt(Start).Hold(0.3).MoveTo(Start + Rise, 1.0).Hold(12));
            var s = Run.Solver(mass, Profile(which), vStd);
            int first = TraceReplay.FirstUsable(frames);
            s.BeginHold(frames[first].HandY, frames[first].HandY, frames[first].PoseTime);
            var y = new double[frames.Length];
            double l0 = double.NaN, l1 = double.NaN, l3 = double.NaN;
            for (int i = first + 1; i < frames.Length; i++)
            {
                y[i] = s.Step(frames[i].ToSample(), frames[i].Time - frames[i - 1].Time);
                double t = frames[i].Time, lift = Start + Rise - s.State.Base;
                if (double.IsNaN(l0) && t >= RestFrom) l0 = lift;
                if (double.IsNaN(l1) && t >= RestFrom + Tau) l1 = lift;
                if (double.IsNaN(l3) && t >= RestFrom + 3 * Tau) l3 = lift;
            }
            double end = frames[frames.Length - 1].Time;
            double endOffset = QuestLikeInput.MedianOver(frames, i => y[i], end - 1, end) - (Start + Rise);
            return (l1 / l0, l3 / l0, endOffset,
                $"seed {seed}: {Profile(which).Name}, {mass} kg, v_std {vStd:F2}, jitter {headset.JitterSd * 1000:F1} mm, {headset.FrameRate} Hz frames");
        }

        [Test]
        public void TheTimeConstantHoldsWithoutJitter([Range(1, 20)] int seed)
        {
            var r = Relax(seed, jitter: false);
            Assert.That(r.afterTau, Is.EqualTo(Math.Exp(-1)).Within(0.01), r.description + ": after τ");
            Assert.That(r.afterThreeTau, Is.EqualTo(Math.Exp(-3)).Within(0.005), r.description + ": after 3τ");
        }

        /// <summary>Each seed on its own: a two-pose glitch (which passes the median of three, as in issue 22's rule 1) may hold
        /// the relaxation for up to twice <see cref="OffsetRelaxation.StillWindow"/>, or, through the lowering guard, leave a
        /// lift of a few centimetres that then relaxes (seed 13: 17 mm below the hand 0.6 s after such a glitch), so where the object
        /// settles is held over the seeds, by the next test; the bounds here are the worst case's.</summary>
        [Test]
        public void TheTimeConstantHoldsWhenTheRestingHandJitters([Range(1, 200)] int seed)
        {
            var r = Relax(seed, jitter: true);
            Assert.That(r.afterTau, Is.EqualTo(Math.Exp(-1)).Within(0.06), r.description + ": after τ");
            Assert.That(r.afterThreeTau, Is.EqualTo(Math.Exp(-3)).Within(0.02), r.description + ": after 3τ");
        }

        /// <summary>Over the same 200 seeds, the typical hold: the median seed leaves e^(−1) of the lift after τ and e^(−3) after
        /// 3τ, and the object rests at the hand, neither sped up, slowed nor biased by the jitter. Measured: medians 0.369 and
        /// 0.050 (clean: 0.369, 0.050), |end offset| median 0.33 mm, 95th percentile 1.19 mm; on the old still test (the pose-to-pose speed) 0.549, 0.165
        /// and 2.57 mm (95th percentile 26.6 mm); 186 of the previous test's 200 seeds failed there.</summary>
        [Test]
        public void OverManySeedsJitterNeitherSpeedsNorSlowsNorBiasesTheRelaxation()
        {
            var tau = new double[200]; var three = new double[200]; var end = new double[200];
            for (int seed = 1; seed <= 200; seed++)
            {
                var r = Relax(seed, jitter: true);
                tau[seed - 1] = r.afterTau; three[seed - 1] = r.afterThreeTau; end[seed - 1] = Math.Abs(r.endOffset);
            }
            Array.Sort(tau); Array.Sort(three); Array.Sort(end);
            TestContext.Out.WriteLine($"after τ: median {tau[100]:F3} (5–95 % {tau[10]:F3}–{tau[190]:F3}); after 3τ: median {three[100]:F3} ({three[10]:F3}–{three[190]:F3}); |end offset|: median {end[100] * 1000:F2} mm, 95 % {end[190] * 1000:F2} mm");
            Assert.That(tau[100], Is.EqualTo(Math.Exp(-1)).Within(0.01), "median after τ");
            Assert.That(three[100], Is.EqualTo(Math.Exp(-3)).Within(0.005), "median after 3τ");
            Assert.That(end[100], Is.LessThanOrEqualTo(0.001), "median |object − hand| 8τ after the lift");
            Assert.That(end[190], Is.LessThanOrEqualTo(0.003), "95th percentile of |object − hand| 8τ after the lift");
        }

        /// <summary>P4 with the relaxation on: a hand at rest from the grab, jittering 1–3 mm, for 10 s; the object's median over
        /// the last half second lies within 1 cm of where it was grabbed (measured: at most 3.4 mm over these seeds; the old still
        /// test passed this too; a relaxation toward 3 cm above the hand fails 67 of the 200).</summary>
        [Test]
        public void JitterAtRestFromTheGrabDoesNotCreep([Range(1, 200)] int seed)
        {
            var rng = new Random(seed);
            int which = rng.Next(3);
            double mass = Masses[rng.Next(Masses.Length)], vStd = QuestLikeInput.Uniform(rng, 0.3, 1.2);
            var frames = Headset(rng, seed, jitter: true).Render(HandPath.StartAt(Start).Hold(10));
            var y = Run.Replay(Run.Solver(mass, Profile(which), vStd), frames);
            double end = frames[frames.Length - 1].Time;
            double creep = QuestLikeInput.MedianOver(frames, i => y[i], end - 0.5, end) - Start;
            TestContext.WriteLine($"creep {creep * 1000:F2} mm"); // the largest over the 200 seeds is the 3.4 mm ALGORITHM.md quotes
            Assert.That(Math.Abs(creep), Is.LessThanOrEqualTo(0.01), $"seed {seed}: {Profile(which).Name}, {mass} kg, v_std {vStd:F2}");
        }

        /// <summary>Steps a gain + relaxation (τ = 1.5 s) hold of 2 kg over the frames, begun at the first usable frame (or, untracked,
        /// at the first frame with no hand, the object at 1 m); the lift left, the hand's height given less the base, at each frame.</summary>
        static double[] LiftLeft(TraceFrame[] frames, double handY, double vStd, bool untracked = false)
        {
            var s = Run.Solver(2, Profile(0), vStd);
            int first = untracked ? 0 : TraceReplay.FirstUsable(frames);
            if (untracked) s.BeginHold(double.NaN, 1.0);
            else s.BeginHold(frames[first].HandY, frames[first].HandY, frames[first].PoseTime);
            var left = new double[frames.Length];
            for (int i = first + 1; i < frames.Length; i++)
            {
                s.Step(frames[i].ToSample(), frames[i].Time - frames[i - 1].Time);
                left[i] = handY - s.State.Base;
            }
            return left;
        }

        static double At(TraceFrame[] frames, double[] values, double t)
        {
            int i = 0;
            while (i < frames.Length - 1 && frames[i + 1].Time <= t) i++;
            return values[i];
        }

        /// <summary>A 3 cm lift in 0.1 s from the grab, then rest, by a fast user (v_std 1.2 m/s: still is below 0.12 m/s): the
        /// hand's mean speed since the grab (3 cm over 0.25 s) is still from about 0.25 s, and the lift relaxes from then, 30 ×
        /// e^(−0.75/1.5) = 18.2 mm left at 1 s (measured 17.8 mm). Measured from height 0 rather than the grab's hand, the
        /// speed read 4 m/s until the window first moved on, and 20.7 mm were left. The same lift 0.5 s after a hold begun
        /// untracked: the window starts at the first pose, not at the hold's start (which read 3 cm over 0.75 s as still at
        /// once).</summary>
        [Test]
        public void ALiftRightAfterTheGrabRelaxesOnceTheMeanSpeedSinceTheGrabIsStill([Values(false, true)] bool untrackedFirst)
        {
            double t0 = untrackedFirst ? 0.5 : 0;
            var headset = Run.Headset();
            if (untrackedFirst) headset.Drop(0, t0);
            var path = HandPath.StartAt(1.0);
            if (untrackedFirst) path.Hold(t0);
            var frames = headset.Render(path.MoveTo(1.03, 0.1).Hold(1.5));
            var left = LiftLeft(frames, 1.03, 1.2, untrackedFirst);
            Assert.That(At(frames, left, t0 + 1.0), Is.EqualTo(0.0182).Within(0.0008), "lift left 1 s after the grab");
        }

        /// <summary>Stillness is judged over the last 0.21–0.42 s: a hand that stops after a 0.3 m lift (60 Hz poses and frames,
        /// the stop at 30 phases over half a second) has its lift relax again 0.21–0.43 s later, never sooner, never later
        /// (measured 0.225–0.417 s; a window of 0.2 s resumed after 0.208 s, one of 0.25 s after up to 0.5 s).</summary>
        [Test]
        public void TheRelaxationResumesBetweenOneAndTwoStillWindowsAfterTheHandStops()
        {
            double soonest = double.PositiveInfinity, latest = 0;
            for (int k = 0; k < 30; k++)
            {
                double move = 0.3 + k / 120.0, stop = 0.5 + move;
                var frames = Run.Headset(frameRate: 60, poseRate: 60).Render(HandPath.StartAt(1.0).Hold(0.5).MoveTo(1.3, move).Hold(1.0));
                var left = LiftLeft(frames, 1.3, 0.5);
                double resumed = double.NaN;
                for (int i = 2; i < frames.Length && double.IsNaN(resumed); i++)
                    if (frames[i].Time > stop && left[i] != left[i - 1]) resumed = frames[i].Time - stop;
                soonest = Math.Min(soonest, resumed);
                latest = Math.Max(latest, resumed);
            }
            TestContext.Out.WriteLine($"resumed {soonest:F3}–{latest:F3} s after the stop");
            Assert.That(soonest, Is.GreaterThanOrEqualTo(0.21), "soonest");
            Assert.That(latest, Is.LessThanOrEqualTo(0.43), "latest");
        }
    }
}
