using System;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>
    /// The per-frame allocation measure of the tests under the double, as Tests/Editor/Support/Allocation.cs measures the
    /// solver: up to three runs, one of which must allocate nothing (an allocation per frame shows in every run; the
    /// runtime's one-off work on this thread, such as a tiered re-compilation, does not repeat).
    /// </summary>
    internal static class Allocations
    {
        /// <summary>Bytes <paramref name="run"/> allocated on this thread: 0 as soon as one of three runs allocates nothing, else the last run's.</summary>
        public static long OfOneInThree(Action run) => OfOneInThree(() =>
        {
            long before = GC.GetAllocatedBytesForCurrentThread();
            run();
            return GC.GetAllocatedBytesForCurrentThread() - before;
        });

        /// <summary>The same, where <paramref name="measuredRun"/> counts its own bytes (leaving out the double's frame loop).</summary>
        public static long OfOneInThree(Func<long> measuredRun)
        {
            long allocated = 0;
            for (int attempt = 0; attempt < 3; attempt++)
                if ((allocated = measuredRun()) == 0) break;
            return allocated;
        }
    }
}
