using System;
using Kosmos.PseudoHaptic.Simulation;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>Small helpers shared by the tests: build a solver, replay a path through a simulated headset.</summary>
    internal static class Run
    {
        public static WeightSolver Solver(double massKg, WeightProfile profile = null, double standardSpeed = WeightSolver.DefaultStandardSpeed)
            => new WeightSolver(WeightModel.FromMass(massKg), profile ?? NamedProfiles.Paper, standardSpeed);

        /// <summary>A lift of <paramref name="rise"/> m from 0.8 m taking <paramref name="seconds"/>, with holds before and after.</summary>
        public static HandPath Lift(double rise = 0.3, double seconds = 1.0, double start = 0.8)
            => HandPath.StartAt(start).Hold(0.3).MoveTo(start + rise, seconds).Hold(0.5);

        public static HeadsetSimulator Headset(double frameRate = 90, double poseRate = 30, double jitterSd = 0, int seed = 1, double wobble = 0)
            => new HeadsetSimulator { FrameRate = frameRate, PoseRate = poseRate, JitterSd = jitterSd, Seed = seed, FrameTimeWobble = wobble };

        public static double[] Replay(WeightSolver solver, TraceFrame[] frames) => TraceReplay.Run(solver, frames);

        public static double Last(double[] values) => values[values.Length - 1];

        public static double MaxAbs(double[] values)
        {
            double m = 0;
            foreach (var v in values) m = Math.Max(m, Math.Abs(v));
            return m;
        }

        /// <summary>Largest |hand − object| over the frames with a usable pose.</summary>
        public static double MaxOffset(TraceFrame[] frames, double[] objectY)
        {
            double m = 0;
            for (int i = 0; i < frames.Length; i++)
                if (frames[i].Tracked && !double.IsNaN(frames[i].HandY))
                    m = Math.Max(m, Math.Abs(frames[i].HandY - objectY[i]));
            return m;
        }

        public static double MaxStep(double[] objectY)
        {
            double m = 0;
            for (int i = 1; i < objectY.Length; i++) m = Math.Max(m, Math.Abs(objectY[i] - objectY[i - 1]));
            return m;
        }

        public static bool AllFinite(double[] values)
        {
            foreach (var v in values) if (double.IsNaN(v) || double.IsInfinity(v)) return false;
            return true;
        }
    }
}
