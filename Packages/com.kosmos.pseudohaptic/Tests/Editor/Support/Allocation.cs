using System;
using NUnit.Framework;
#if UNITY_5_3_OR_NEWER
using UnityEngine.TestTools.Constraints; // AllocatingGCMemory() is an extension method there
#endif

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>
    /// P10's one measurement: run the work once to warm up (JIT, static initialisers), then assert that running it
    /// again allocates nothing; with the Unity Test Framework's constraint in the editor, with the GC's
    /// per-thread counter under the .NET SDK.
    /// </summary>
    internal static class Allocation
    {
        /// <param name="work">Does <c>count</c> units of the work (steps, calls, frames).</param>
        /// <param name="units">What a unit is, for the message ("steps").</param>
        public static void AssertNone(Action<int> work, string units)
        {
            work(1000);
#if UNITY_5_3_OR_NEWER
            Assert.That(() => work(10000), UnityEngine.TestTools.Constraints.Is.Not.AllocatingGCMemory(), units);
#else
            // Up to three runs, one of which must allocate nothing: an allocation per unit shows in every run
            // (2.4 MB at least), while the runtime's one-off work that lands on this thread now and then (tiered
            // re-compilation of the hot loop, seen as ~8 KB once on a loaded two-core machine) does not repeat.
            long allocated = 0;
            for (int attempt = 0; attempt < 3; attempt++)
            {
                long before = GC.GetAllocatedBytesForCurrentThread();
                work(100000);
                allocated = GC.GetAllocatedBytesForCurrentThread() - before;
                if (allocated == 0) break;
            }
            Assert.That(allocated, Is.EqualTo(0), "bytes allocated over 100 000 " + units + ", in each of three runs");
#endif
        }
    }
}
