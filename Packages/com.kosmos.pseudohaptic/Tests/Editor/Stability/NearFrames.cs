using System;
using System.Collections.Generic;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>
    /// The frames within 100 ms of each frame, as the step rules (<see cref="GapRule"/>, <see cref="QuestLikeInput.StepBeyondHand"/>)
    /// read them: frame j is near frame i when |t_j − t_i| ≤ <see cref="Window"/>. On time-ordered frames those are one run
    /// of frames around i, found here in one pass, so a rule costs a window per frame instead of the whole trace per frame
    /// (which made the real-recording suite half of the edit-mode suite's time). A rule still tests each frame of the run
    /// with the same predicate, so it reads the same frames as a scan of the whole trace would; frames not in time order
    /// (or a NaN time) give every frame the whole trace.
    /// </summary>
    internal static class NearFrames
    {
        public const double Window = 0.1 + 1e-9;

        public static bool Near(double a, double b) => Math.Abs(a - b) <= Window;

        /// <summary>For each frame, the first and last frame of the run that may hold frames near it.</summary>
        public static void Ranges(IReadOnlyList<double> time, out int[] first, out int[] last)
        {
            int n = time.Count;
            first = new int[n];
            last = new int[n];
            bool ordered = true;
            for (int k = 1; k < n && ordered; k++) ordered = time[k] >= time[k - 1];
            for (int k = 0; k < n && ordered; k++) ordered = !double.IsNaN(time[k]);
            if (!ordered)
            {
                for (int i = 0; i < n; i++) last[i] = n - 1;
                return;
            }
            // Subtraction is monotonic, so on ordered times a frame before the run (or after it) is farther than the run's
            // first (or last) frame that fails the predicate: the run is exactly the frames near i.
            int lo = 0, hi = 0;
            for (int i = 0; i < n; i++)
            {
                while (lo < i && !Near(time[lo], time[i])) lo++;
                if (hi < i) hi = i;
                while (hi + 1 < n && Near(time[hi + 1], time[i])) hi++;
                first[i] = lo;
                last[i] = hi;
            }
        }
    }
}
