using System;
using System.Collections.Generic;

namespace Kosmos.PseudoHaptic.Simulation
{
    /// <summary>
    /// Degrades a true hand path the way a Quest 2 delivers it: poses sampled at 30 Hz (60 in fast-motion
    /// mode), about 45 ms late, with millimetre jitter, held over 72–120 Hz frames whose times may wobble;
    /// low-confidence poses in fast motion; one-pose glitches (a joint jumping a few centimetres for one pose);
    /// and stretches of lost or low-confidence tracking. Seeded: the same settings give the same frames, and a
    /// pose's jitter, confidence and glitch depend only on the seed and the pose, not on the frame clock.
    /// </summary>
    public sealed class HeadsetSimulator
    {
        // Every setting is checked when it is set (the exception names it): a simulator with a zero frame rate or a
        // negative jitter would loop for ever or render a different headset than the one asked for.
        double _frameRate = 90, _frameTimeWobble, _poseRate = 30, _latency = 0.045, _jitterSd;
        double _lowConfidenceAboveSpeed = double.PositiveInfinity, _lowConfidenceChance = 0.5, _glitchChance, _glitchSize = 0.03;

        /// <summary>Frames per second (finite, &gt; 0; default 90).</summary>
        public double FrameRate { get => _frameRate; set => _frameRate = ConfigurationGuard.Positive(value, nameof(FrameRate)); }

        /// <summary>Each frame's duration varies uniformly by ± this fraction, within [0, <see cref="MaxFrameTimeWobble"/>]
        /// (default 0).</summary>
        public double FrameTimeWobble
        {
            get => _frameTimeWobble;
            set => _frameTimeWobble = ConfigurationGuard.InRange(value, 0, MaxFrameTimeWobble, nameof(FrameTimeWobble));
        }

        /// <summary>The largest <see cref="FrameTimeWobble"/>: at ±100 % a frame could last no time and the clock not advance.</summary>
        public const double MaxFrameTimeWobble = 0.9;

        /// <summary>Poses per second (finite, &gt; 0; default 30).</summary>
        public double PoseRate { get => _poseRate; set => _poseRate = ConfigurationGuard.Positive(value, nameof(PoseRate)); }

        /// <summary>Pose latency, s (finite, ≥ 0; default 0.045): a pose shows the hand where it was at its stamp and reaches
        /// the frames this much later.</summary>
        public double Latency { get => _latency; set => _latency = ConfigurationGuard.NonNegative(value, nameof(Latency)); }

        /// <summary>Gaussian jitter of each pose, standard deviation, m (finite, ≥ 0; default 0).</summary>
        public double JitterSd { get => _jitterSd; set => _jitterSd = ConfigurationGuard.NonNegative(value, nameof(JitterSd)); }

        /// <summary>Whether frames carry the pose's timestamp (else NaN, as in traces without pose_t).</summary>
        public bool WritePoseTime = true;

        public int Seed = 1;

        /// <summary>A pose whose true hand speed exceeds this, m/s, may be delivered with low confidence (≥ 0; default ∞:
        /// never).</summary>
        public double LowConfidenceAboveSpeed
        {
            get => _lowConfidenceAboveSpeed;
            set => _lowConfidenceAboveSpeed = ConfigurationGuard.InRange(value, 0, double.PositiveInfinity, nameof(LowConfidenceAboveSpeed));
        }

        /// <summary>The chance that such a fast pose is low-confidence, 0–1 (default 0.5).</summary>
        public double LowConfidenceChance
        {
            get => _lowConfidenceChance;
            set => _lowConfidenceChance = ConfigurationGuard.InRange(value, 0, 1, nameof(LowConfidenceChance));
        }

        /// <summary>The chance that a pose is a glitch: displaced by ±<see cref="GlitchSize"/> for that one pose, 0–1
        /// (default 0).</summary>
        public double GlitchChance
        {
            get => _glitchChance;
            set => _glitchChance = ConfigurationGuard.InRange(value, 0, 1, nameof(GlitchChance));
        }

        /// <summary>How far a glitched pose is off, m (finite, ≥ 0; default 0.03: a joint jumping a few centimetres).</summary>
        public double GlitchSize { get => _glitchSize; set => _glitchSize = ConfigurationGuard.NonNegative(value, nameof(GlitchSize)); }

        readonly List<(double start, double end, double size)> _offsets = new List<(double, double, double)>();
        readonly List<double> _dropStart = new List<double>();
        readonly List<double> _dropEnd = new List<double>();
        readonly List<double> _lowStart = new List<double>();
        readonly List<double> _lowEnd = new List<double>();

        /// <summary>Tracking is lost from <paramref name="start"/> for <paramref name="seconds"/> (frames there are untracked, NaN).</summary>
        public HeadsetSimulator Drop(double start, double seconds)
        {
            CheckSpan(start, seconds);
            _dropStart.Add(start);
            _dropEnd.Add(start + seconds);
            return this;
        }

        /// <summary>One pose is off by <paramref name="size"/> m: the first pose sampled at or after <paramref name="at"/>
        /// (a tracked joint jumping for one pose).</summary>
        public HeadsetSimulator Glitch(double at, double size) => Offset(at, 1.0 / PoseRate, size);

        /// <summary>Every pose sampled from <paramref name="start"/> for <paramref name="seconds"/> is off by
        /// <paramref name="size"/> m: after a <see cref="Drop"/>, the re-acquisition snap (the first poses of a hand found
        /// again are centimetres off, then snap back).</summary>
        public HeadsetSimulator Offset(double start, double seconds, double size)
        {
            CheckSpan(start, seconds);
            ConfigurationGuard.Finite(size, nameof(size));
            _offsets.Add((start, start + seconds, size));
            return this;
        }

        /// <summary>Tracking is low-confidence from <paramref name="start"/> for <paramref name="seconds"/> (frames there are
        /// tracked, with their poses, but flagged <see cref="TraceFrame.LowConfidence"/>).</summary>
        public HeadsetSimulator LowConfidence(double start, double seconds)
        {
            CheckSpan(start, seconds);
            _lowStart.Add(start);
            _lowEnd.Add(start + seconds);
            return this;
        }

        static void CheckSpan(double start, double seconds)
        {
            ConfigurationGuard.Finite(start, nameof(start));
            ConfigurationGuard.NonNegative(seconds, nameof(seconds));
        }

        /// <summary>Renders frames from 0 to the path's end (plus <paramref name="extra"/> seconds, finite, ≥ 0).</summary>
        public TraceFrame[] Render(HandPath path, double extra = 0)
        {
            if (path == null) throw new ArgumentNullException(nameof(path));
            ConfigurationGuard.NonNegative(extra, nameof(extra));
            var rng = new Random(Seed);
            var frames = new List<TraceFrame>();
            double end = path.Duration + extra;
            double posePeriod = 1.0 / PoseRate, framePeriod = 1.0 / FrameRate;
            double t = 0;
            long lastPose = long.MinValue;
            double poseY = 0, poseT = 0;
            bool poseLow = false;
            while (t <= end + 1e-12)
            {
                // The newest pose that has arrived by frame time t was sampled at or before t − latency.
                long k = (long)Math.Floor((t - Latency) / posePeriod + 1e-9);
                if (k != lastPose)
                {
                    lastPose = k;
                    poseT = k * posePeriod;
                    poseY = path.HeightAt(poseT) + (JitterSd > 0 ? JitterSd * Gaussian(Seed, k) : 0);
                    if (GlitchChance > 0 && Uniform(Mix(Seed, k, 3)) < GlitchChance)
                        poseY += Uniform(Mix(Seed, k, 4)) < 0.5 ? -GlitchSize : GlitchSize;
                    foreach (var o in _offsets)
                        if (poseT >= o.start - 1e-9 && poseT < o.end - 1e-9) poseY += o.size;
                    double speed = Math.Abs(path.HeightAt(poseT + 0.005) - path.HeightAt(poseT - 0.005)) / 0.01;
                    poseLow = speed > LowConfidenceAboveSpeed && Uniform(Mix(Seed, k, 5)) < LowConfidenceChance;
                }
                bool lost = false, low = poseLow;
                for (int i = 0; i < _dropStart.Count; i++)
                    if (t >= _dropStart[i] && t < _dropEnd[i]) lost = true;
                for (int i = 0; i < _lowStart.Count; i++)
                    if (t >= _lowStart[i] && t < _lowEnd[i]) low = true;
                var frame = lost
                    ? new TraceFrame(t, double.NaN, false, double.NaN)
                    : new TraceFrame(t, poseY, true, WritePoseTime ? poseT : double.NaN);
                frame.LowConfidence = !lost && low;
                frames.Add(frame);
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

        static ulong Mix(int seed, long k, int stream) => (ulong)seed * 0x9E3779B97F4A7C15UL + (ulong)k * 8 + (ulong)stream + 0x5851F42D4C957F2DUL;

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
