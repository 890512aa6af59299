using System;
using System.Collections.Generic;
using Kosmos.PseudoHaptic.Simulation;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>
    /// Issue 32's step rule, for every mass, lighter than the standard included: the hand's motion across a gap (a loss, a
    /// NaN burst, a refused pose, or a hitch: more than 0.1 s of frame time without a usable pose) is never amplified. On
    /// the frame a usable pose comes back after a gap the object steps at most the hand's own step + 1 cm; on every other
    /// frame at most max(G, 1) × the hand's largest ordinary step (not across a gap) within 100 ms, + 1 cm. What a clean
    /// run would have done beyond that must come by gliding. The bounds are the issue's, not the code's.
    /// </summary>
    internal static class GapRule
    {
        /// <summary>More frame time than this between two usable poses is a gap (a hitch), s.</summary>
        public const double Hitch = 0.1;

        public const double Allowance = 0.01;

        /// <summary>The largest excess of an object's step over what the rule allows, m (≤ 0 when it holds), with the frame
        /// where it happened. <paramref name="usable"/>, <paramref name="hand"/>: what the solver was given per frame;
        /// <paramref name="objectY"/>: what it returned.</summary>
        public static double WorstExcess(IReadOnlyList<double> time, IReadOnlyList<bool> usable, IReadOnlyList<double> hand,
            IReadOnlyList<double> objectY, double gain, out int worstFrame, double from = double.NegativeInfinity, double to = double.PositiveInfinity)
        {
            int n = time.Count;
            var step = new double[n];
            var gap = new bool[n];
            int last = -1;
            bool lostSince = false;
            for (int i = 0; i < n; i++)
            {
                if (!usable[i]) { lostSince = true; continue; }
                if (last >= 0)
                {
                    step[i] = Math.Abs(hand[i] - hand[last]);
                    gap[i] = lostSince || time[i] - time[last] > Hitch;
                }
                last = i;
                lostSince = false;
            }
            double worst = double.NegativeInfinity, scale = Math.Max(1, gain);
            worstFrame = -1;
            NearFrames.Ranges(time, out var nearFirst, out var nearLast);
            for (int i = 1; i < n; i++)
            {
                if (time[i] < from || time[i] > to) continue;
                double allowed;
                if (gap[i]) allowed = step[i];
                else
                {
                    double near = 0;
                    for (int j = nearFirst[i]; j <= nearLast[i]; j++)
                        if (!gap[j] && NearFrames.Near(time[j], time[i])) near = Math.Max(near, step[j]);
                    allowed = scale * near;
                }
                double excess = Math.Abs(objectY[i] - objectY[i - 1]) - allowed - Allowance;
                if (excess > worst) { worst = excess; worstFrame = i; }
            }
            return worst;
        }

        /// <summary>The rule over a replayed trace (the frames' times; usable = tracked and a usable height).</summary>
        public static double WorstExcess(TraceFrame[] frames, double[] objectY, double gain, out int worstFrame,
            double from = double.NegativeInfinity, double to = double.PositiveInfinity)
        {
            var t = new double[frames.Length];
            var u = new bool[frames.Length];
            var h = new double[frames.Length];
            for (int i = 0; i < frames.Length; i++) { t[i] = frames[i].Time; u[i] = frames[i].IsUsable; h[i] = frames[i].HandY; }
            return WorstExcess(t, u, h, objectY, gain, out worstFrame, from, to);
        }

        /// <summary><paramref name="frames"/> without those in [<paramref name="at"/>, <paramref name="at"/> +
        /// <paramref name="seconds"/>): one frame of that length, a hitch, during which the hand went on moving.</summary>
        public static TraceFrame[] WithHitch(TraceFrame[] frames, double at, double seconds)
        {
            var kept = new List<TraceFrame>();
            foreach (var f in frames)
                if (f.Time < at || f.Time >= at + seconds) kept.Add(f);
            return kept.ToArray();
        }
    }
}
