using System;
using System.Collections.Generic;

namespace Kosmos.PseudoHaptic.Simulation
{
    /// <summary>
    /// Degrades a true hand path the way a Quest 2 delivers it: poses sampled at 30 Hz (60 in fast-motion
    /// mode), about 45 ms late, with millimetre jitter, held over 72–120 Hz frames whose times may wobble,
    /// and stretches of lost tracking. Seeded: the same settings give the same frames, and a pose's jitter
    /// depends only on the seed and the pose, not on the frame clock.
    /// </summary>
    public sealed class HeadsetSimulator
    {
        public double FrameRate = 90;

        /// <summary>Each frame's duration varies uniformly by ± this fraction.</summary>
        public double FrameTimeWobble;

        public double PoseRate = 30;

        /// <summary>Pose latency, s: a pose shows the hand where it was at its stamp and reaches the frames this much later.</summary>
        public double Latency = 0.045;

        /// <summary>Gaussian jitter of each pose, standard deviation, m.</summary>
        public double JitterSd;

        /// <summary>Whether frames carry the pose's timestamp (else NaN, as in traces without pose_t).</summary>
        public bool WritePoseTime = true;

        public int Seed = 1;

        readonly List<double> _dropStart = new List<double>();
        readonly List<double> _dropEnd = new List<double>();

        /// <summary>Tracking is lost from <paramref name="start"/> for <paramref name="seconds"/> (frames there are untracked, NaN).</summary>
        public HeadsetSimulator Drop(double start, double seconds)
        {
            _dropStart.Add(start);
            _dropEnd.Add(start + seconds);
            return this;
        }

        /// <summary>Renders frames from 0 to the path's end (plus <paramref name="extra"/> seconds).</summary>
        public TraceFrame[] Render(HandPath path, double extra = 0)
        {
            var rng = new Random(Seed);
            var frames = new List<TraceFrame>();
            double end = path.Duration + extra;
            double posePeriod = 1.0 / PoseRate, framePeriod = 1.0 / FrameRate;
            double t = 0;
            long lastPose = long.MinValue;
            double poseY = 0, poseT = 0;
            while (t <= end + 1e-12)
            {
                // The newest pose that has arrived by frame time t was sampled at or before t − latency.
                long k = (long)Math.Floor((t - Latency) / posePeriod + 1e-9);
                if (k != lastPose)
                {
                    lastPose = k;
                    poseT = k * posePeriod;
                    poseY = path.HeightAt(poseT) + (JitterSd > 0 ? JitterSd * Gaussian(Seed, k) : 0);
                }
                bool lost = false;
                for (int i = 0; i < _dropStart.Count; i++)
                    if (t >= _dropStart[i] && t < _dropEnd[i]) lost = true;
                frames.Add(lost
                    ? new TraceFrame(t, double.NaN, false, double.NaN)
                    : new TraceFrame(t, poseY, true, WritePoseTime ? poseT : double.NaN));
                double wobble = FrameTimeWobble > 0 ? 1 + FrameTimeWobble * (2 * rng.NextDouble() - 1) : 1;
                t += framePeriod * wobble;
            }
            return frames.ToArray();
        }

        /// <summary>Standard normal noise of pose k: a function of (seed, k) only, so the same pose carries the
        /// same jitter whatever the frame clock that shows it.</summary>
        static double Gaussian(int seed, long k)
        {
            double u1 = 1.0 - Uniform((ulong)seed * 0x9E3779B97F4A7C15UL + (ulong)k * 2);
            double u2 = Uniform((ulong)seed * 0x9E3779B97F4A7C15UL + (ulong)k * 2 + 1);
            return Math.Sqrt(-2.0 * Math.Log(u1)) * Math.Cos(2 * Math.PI * u2);
        }

        /// <summary>SplitMix64 of <paramref name="x"/> as a double in [0, 1).</summary>
        static double Uniform(ulong x)
        {
            x += 0x9E3779B97F4A7C15UL;
            x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9UL;
            x = (x ^ (x >> 27)) * 0x94D049BB133111EBUL;
            x ^= x >> 31;
            return (x >> 11) * (1.0 / (1UL << 53));
        }
    }
}
