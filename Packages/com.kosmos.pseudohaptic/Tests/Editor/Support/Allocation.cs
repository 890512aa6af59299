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
            long before = GC.GetAllocatedBytesForCurrentThread();
            work(100000);
            Assert.That(GC.GetAllocatedBytesForCurrentThread() - before, Is.EqualTo(0), "bytes allocated over 100 000 " + units);
#endif
        }
    }
}
