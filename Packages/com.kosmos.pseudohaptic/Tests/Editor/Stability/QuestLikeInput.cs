using System;
using Kosmos.PseudoHaptic.Simulation;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>
    /// The degradation a Quest 2 gives every hold, for the property suites: 30 Hz poses held over 72, 90 or 120 Hz
    /// frames, 45 ms late, 1–2 mm jitter, low confidence on some fast poses, and a few one-pose glitches of 2–4 cm.
    /// Seeded: the same seed gives the same headset, and a pose's jitter, confidence and glitch depend only on the seed
    /// and the pose (so a clean run and the same run with one more artifact see the same poses elsewhere).
    /// </summary>
    internal static class QuestLikeInput
    {
        public static readonly double[] FrameRates = { 72, 90, 120 };

        public static HeadsetSimulator Headset(Random rng, int seed) => new HeadsetSimulator
        {
            FrameRate = FrameRates[rng.Next(FrameRates.Length)],
            PoseRate = 30,
            Latency = 0.045,
            JitterSd = 0.001 + 0.001 * rng.NextDouble(),
            LowConfidenceAboveSpeed = 0.6,
            LowConfidenceChance = 0.3,
            GlitchChance = 0.02,
            GlitchSize = 0.02 + 0.02 * rng.NextDouble(),
            Seed = seed,
        };

        /// <summary>The masses the suites weigh: the standard weight and four heavier ones, kg.</summary>
        public static readonly double[] Masses = { PhysicalConstants.StandardMassKg, 0.5, 1, 2, 5 };

        public static double Uniform(Random rng, double min, double max) => min + (max - min) * rng.NextDouble();

        /// <summary>Issue 22's heft, appended to <paramref name="path"/> resting at <paramref name="top"/>: 1–3 bounces of 5–15 cm
        /// up and back, 0.1–1 s each way, then 0.6 s of rest. Returns the number of bounces.</summary>
        public static int AddHeft(Random rng, HandPath path, double top)
        {
            int bounces = 1 + rng.Next(3);
            for (int b = 0; b < bounces; b++)
            {
                double amplitude = Uniform(rng, 0.05, 0.15);
                path.MoveTo(top + amplitude, Uniform(rng, 0.1, 1.0)).MoveTo(top, Uniform(rng, 0.1, 1.0));
            }
            path.Hold(0.6);
            return bounces;
        }

        /// <summary>Index of the first frame at or after <paramref name="time"/> (the last frame if none).</summary>
        public static int FrameAt(TraceFrame[] frames, double time)
        {
            for (int i = 0; i < frames.Length; i++)
                if (frames[i].Time >= time - 1e-9) return i;
            return frames.Length - 1;
        }

        /// <summary>The median of <paramref name="values"/> over the usable frames from <paramref name="from"/> to
        /// <paramref name="to"/> (frame times, s): a level at rest that one glitched pose does not move.</summary>
        public static double MedianOver(TraceFrame[] frames, Func<int, double> values, double from, double to)
        {
            var picked = new System.Collections.Generic.List<double>();
            for (int i = 0; i < frames.Length; i++)
                if (frames[i].IsUsable && frames[i].Time >= from && frames[i].Time <= to) picked.Add(values(i));
            if (picked.Count == 0) return double.NaN;
            picked.Sort();
            int n = picked.Count;
            return n % 2 == 1 ? picked[n / 2] : 0.5 * (picked[n / 2 - 1] + picked[n / 2]);
        }

        /// <summary>
        /// The largest step the object makes between <paramref name="from"/> and <paramref name="to"/> (frame times, s)
        /// beyond what the hand did: its step less max(G, 1) × the hand's largest step within 100 ms of that frame (the
        /// hand's step between consecutive tracked frames, as the user sees it). A value ≤ 1 cm keeps the rule "no frame's
        /// step exceeds the hand's own largest step in the surrounding 100 ms plus 1 cm".
        /// </summary>
        public static double StepBeyondHand(TraceFrame[] frames, double[] objectY, double gain, double from, double to)
        {
            var handStep = new double[frames.Length];
            int last = -1;
            for (int i = 0; i < frames.Length; i++)
            {
                if (!frames[i].IsUsable) continue;
                if (last >= 0) handStep[i] = Math.Abs(frames[i].HandY - frames[last].HandY);
                last = i;
            }
            double worst = double.NegativeInfinity, scale = Math.Max(1, gain);
            var times = new double[frames.Length];
            for (int i = 0; i < frames.Length; i++) times[i] = frames[i].Time;
            NearFrames.Ranges(times, out var nearFirst, out var nearLast);
            for (int i = 1; i < frames.Length; i++)
            {
                double t = frames[i].Time;
                if (t < from || t > to) continue;
                double near = 0;
                for (int j = nearFirst[i]; j <= nearLast[i]; j++)
                    if (NearFrames.Near(frames[j].Time, t)) near = Math.Max(near, handStep[j]);
                worst = Math.Max(worst, Math.Abs(objectY[i] - objectY[i - 1]) - scale * near);
            }
            return worst;
        }
    }
}
