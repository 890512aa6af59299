using System;
using System.Collections.Generic;

namespace Kosmos.PseudoHaptic.Simulation
{
    /// <summary>
    /// Runs a trace through a solver the way the replay contract says: the hold begins at the first frame
    /// with a usable pose (tracked, finite), the object starting at that frame's hand height; before it the
    /// object height is the hold's starting height too. One object height per frame, always finite.
    /// </summary>
    public static class TraceReplay
    {
        /// <summary>Replays <paramref name="frames"/>; writes one height per frame into <paramref name="objectY"/>.</summary>
        public static void Run(WeightSolver solver, IReadOnlyList<TraceFrame> frames, double[] objectY)
        {
            if (solver == null) throw new ArgumentNullException(nameof(solver));
            if (frames == null) throw new ArgumentNullException(nameof(frames));
            if (objectY == null || objectY.Length < frames.Count) throw new ArgumentException("objectY must hold one value per frame.", nameof(objectY));

            int first = FirstUsable(frames);
            if (first < 0)
            {
                for (int i = 0; i < frames.Count; i++) objectY[i] = 0;
                return;
            }
            double start = frames[first].HandY;
            solver.BeginHold(start, start, frames[first].PoseTime);
            for (int i = 0; i <= first; i++) objectY[i] = solver.ObjectY; // the floor may lift the start
            for (int i = first + 1; i < frames.Count; i++)
                objectY[i] = solver.Step(frames[i].ToSample(), frames[i].Time - frames[i - 1].Time);
            solver.EndHold();
        }

        public static double[] Run(WeightSolver solver, IReadOnlyList<TraceFrame> frames)
        {
            var y = new double[frames.Count];
            Run(solver, frames, y);
            return y;
        }

        /// <summary>Index of the first frame with a usable pose, or −1.</summary>
        public static int FirstUsable(IReadOnlyList<TraceFrame> frames)
        {
            for (int i = 0; i < frames.Count; i++)
            {
                if (frames[i].IsUsable) return i;
            }
            return -1;
        }
    }
}
