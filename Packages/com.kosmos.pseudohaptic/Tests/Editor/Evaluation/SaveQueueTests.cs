using System;
using System.Collections.Generic;
using System.IO;
using System.Threading;
using Kosmos.PseudoHaptic.Evaluation;
using NUnit.Framework;
#if UNITY_5_3_OR_NEWER
using UnityEngine.TestTools.Constraints; // AllocatingGCMemory() is an extension method there
// That namespace has its own Is (deriving from NUnit's): without this alias every plain Is is ambiguous (CS0104).
using Is = NUnit.Framework.Is;
#endif

namespace Kosmos.PseudoHaptic.Tests.Evaluation
{
    /// <summary>
    /// The study files' one writer (issue 35): writes in the order given, an acknowledgement only after the write
    /// returned and only on the thread that pumps, a failed write kept and retried before anything after it,
    /// never done again once it succeeded, and a pump that never waits for a write.
    /// </summary>
    public class SaveQueueTests
    {
        [Test]
        public void WritesRunInOrderAndEachIsAcknowledgedOnceAfterItReturned()
        {
            foreach (bool background in new[] { false, true })
            {
                var queue = new SaveQueue(background);
                var written = new List<int>();
                var acknowledged = new List<int>();
                for (int i = 0; i < 50; i++)
                {
                    int n = i;
                    queue.Enqueue(() => { lock (written) written.Add(n); }, () =>
                    {
                        lock (written) Assert.That(written, Does.Contain(n), "acknowledged before it was written");
                        acknowledged.Add(n);
                    }, e => Assert.Fail(e));
                }
                Assert.That(queue.Drain(10000), Is.True);
                var expected = new List<int>();
                for (int i = 0; i < 50; i++) expected.Add(i);
                Assert.That(written, Is.EqualTo(expected), "background " + background);
                Assert.That(acknowledged, Is.EqualTo(expected), "background " + background);
                Assert.That(queue.Pump(), Is.Zero, "nothing is acknowledged twice");
                Assert.That(queue.Writes, Is.EqualTo(50));
                queue.Dispose();
            }
        }

        [Test]
        public void InTheBackgroundTheWriteRunsOffThePumpingThreadAndThePumpDoesNotWaitForIt()
        {
            var queue = new SaveQueue(background: true);
            using (var gate = new ManualResetEventSlim(false))
            using (var started = new ManualResetEventSlim(false))
            {
                int writer = -1, acknowledger = -1;
                queue.Enqueue(() => { writer = Thread.CurrentThread.ManagedThreadId; started.Set(); gate.Wait(10000); },
                    () => acknowledger = Thread.CurrentThread.ManagedThreadId, e => Assert.Fail(e));
                var watch = System.Diagnostics.Stopwatch.StartNew();
                for (int frame = 0; frame < 20; frame++) Assert.That(queue.Pump(), Is.Zero, "not acknowledged while the write is under way");
                Assert.That(watch.ElapsedMilliseconds, Is.LessThan(1000), "a pump waited for the write");
                Assert.That(acknowledger, Is.EqualTo(-1));
                Assert.That(started.Wait(10000), Is.True, "the write began");
                Assert.That(queue.Pending, Is.EqualTo(1), "the write under way, taken off the queue");
                gate.Set();
                Assert.That(queue.Drain(10000), Is.True);
                Assert.That(writer, Is.Not.EqualTo(Thread.CurrentThread.ManagedThreadId), "written on the main thread");
                Assert.That(acknowledger, Is.EqualTo(Thread.CurrentThread.ManagedThreadId), "acknowledged off the main thread");
                Assert.That(queue.Pending, Is.Zero);
            }
            queue.Dispose();
        }

        [Test]
        public void AFailedWriteIsRetriedAfterItsDelayBeforeAnythingQueuedAfterItAndNeverAgainOnceItSucceeded()
        {
            double now = 0;
            var queue = new SaveQueue(background: false, retrySeconds: 3, clock: () => now);
            var log = new List<string>();
            int attemptsOfA = 0;
            queue.Enqueue(() =>
            {
                attemptsOfA++;
                log.Add("write a");
                if (attemptsOfA <= 2) throw new IOException("No space left on device");
            }, () => log.Add("saved a"), e => log.Add("failed a: " + e));
            queue.Enqueue(() => log.Add("write b"), () => log.Add("saved b"), e => log.Add("failed b"));

            Assert.That(queue.Pump(), Is.Zero);
            Assert.That(log, Is.EqualTo(new[] { "write a", "failed a: No space left on device" }), "b waits behind the failed a");
            Assert.That(queue.LastError, Is.EqualTo("No space left on device"));
            Assert.That(queue.Pending, Is.EqualTo(2));
            now = 2.9;
            Assert.That(queue.Pump(), Is.Zero, "not before the delay");
            now = 3.0;
            Assert.That(queue.Pump(), Is.Zero, "second attempt fails too");
            now = 6.0;
            Assert.That(queue.Pump(), Is.EqualTo(2));
            Assert.That(log, Is.EqualTo(new[]
            {
                "write a", "failed a: No space left on device",
                "write a", "failed a: No space left on device",
                "write a", "write b", "saved a", "saved b", // written in order, then delivered in order
            }));
            Assert.That(queue.LastError, Is.Null);
            now = 100;
            Assert.That(queue.Pump(), Is.Zero);
            Assert.That(attemptsOfA, Is.EqualTo(3), "a write that succeeded is not done again");
            Assert.That(queue.Writes, Is.EqualTo(2));
            Assert.That(queue.Failures, Is.EqualTo(2));
        }

        [Test]
        public void InTheBackgroundAFailureIsDeliveredByThePumpAndRetriedInOrder()
        {
            double now = 0;
            var queue = new SaveQueue(background: true, retrySeconds: 1, clock: () => Volatile.Read(ref now));
            int attempts = 0;
            var order = new List<string>();
            queue.Enqueue(() => { if (Interlocked.Increment(ref attempts) == 1) throw new UnauthorizedAccessException("read-only"); lock (order) order.Add("a"); },
                null, null);
            queue.Enqueue(() => { lock (order) order.Add("b"); }, null, null);
            Assert.That(queue.Drain(10000), Is.False, "a failed");
            Assert.That(queue.LastError, Is.EqualTo("read-only"));
            Thread.Sleep(50);
            lock (order) Assert.That(order, Is.Empty, "b is not written before a");
            now = 1;
            queue.Pump();
            Assert.That(queue.Drain(10000), Is.True);
            Assert.That(order, Is.EqualTo(new[] { "a", "b" }));
            queue.Dispose();
        }

        [Test]
        public void APumpWithNothingToDeliverAllocatesNothing()
        {
            var queue = new SaveQueue(background: true);
            queue.Pump();
#if UNITY_5_3_OR_NEWER
            Assert.That(() => Pumps(queue, 1000), UnityEngine.TestTools.Constraints.Is.Not.AllocatingGCMemory());
#else
            // Fewer bytes than pumps: any allocation per pump (24 bytes at least) fails; a one-off re-compilation does not.
            long before = GC.GetAllocatedBytesForCurrentThread();
            Pumps(queue, 100000);
            Assert.That(GC.GetAllocatedBytesForCurrentThread() - before, Is.LessThan(100000), "bytes allocated over 100 000 pumps");
#endif
            queue.Dispose();
        }

        static void Pumps(SaveQueue queue, int n)
        {
            for (int i = 0; i < n; i++) queue.Pump();
        }

        [Test]
        public void ABadRetryDelayIsRefusedNamingIt()
        {
            foreach (double bad in new[] { double.NaN, -0.001, double.PositiveInfinity, double.NegativeInfinity })
            {
                var e = Assert.Throws<ArgumentOutOfRangeException>(() => new SaveQueue(false, bad), bad.ToString());
                Assert.That(e.ParamName, Is.EqualTo("retrySeconds"));
                Assert.That(e.Message, Does.Contain("retrySeconds must be finite"));
            }
            Assert.That(new SaveQueue(false, 0).RetrySeconds, Is.Zero, "no delay is a valid delay");
        }

        [Test]
        public void ANullWriteIsRefusedNamingIt()
        {
            var queue = new SaveQueue(false);
            var e = Assert.Throws<ArgumentNullException>(() => queue.Enqueue(null, null, null));
            Assert.That(e.ParamName, Is.EqualTo("write"));
            Assert.That(queue.Pending, Is.Zero);
        }

        [Test]
        public void PendingCountsAWriteDoneButNotYetAcknowledged()
        {
            var queue = new SaveQueue(background: false);
            var seen = new List<int>();
            queue.Enqueue(() => { }, () => seen.Add(queue.Pending), null);
            queue.Enqueue(() => { }, () => seen.Add(queue.Pending), null);
            Assert.That(queue.Pending, Is.EqualTo(2));
            Assert.That(queue.Pump(), Is.EqualTo(2));
            // Both are written before the first acknowledgement: during it, the second is done and not yet delivered.
            Assert.That(seen, Is.EqualTo(new[] { 1, 0 }));
        }

        [Test]
        public void TheWriterIsABackgroundThreadNamedAsDocumentedAndDisposeStopsIt()
        {
            var queue = new SaveQueue(background: true);
            Thread writer = null;
            queue.Enqueue(() => writer = Thread.CurrentThread, null, null);
            Assert.That(queue.Drain(10000), Is.True);
            Assert.That(writer.IsBackground, Is.True, "a background thread does not keep the application alive");
            Assert.That(writer.Name, Is.EqualTo("Kosmos.PseudoHaptic.SaveQueue"));
            queue.Dispose();
            Assert.That(writer.Join(10000), Is.True, "Dispose wakes the waiting writer and it ends");
        }

        [Test]
        public void AnErrorWithoutAMessageIsNamedByItsType()
        {
            var queue = new SaveQueue(background: false);
            string failed = null;
            queue.Enqueue(() => throw new IOException(""), null, e => failed = e);
            queue.Pump();
            Assert.That(failed, Is.EqualTo("IOException"));
            Assert.That(queue.LastError, Is.EqualTo("IOException"));
        }

        [Test]
        public void DrainReturnsAsSoonAsAllIsWrittenOrAWriteFailedNotAtItsTimeout()
        {
            var queue = new SaveQueue(background: true);
            var watch = System.Diagnostics.Stopwatch.StartNew();
            queue.Enqueue(() => { }, null, null);
            Assert.That(queue.Drain(20000), Is.True);
            Assert.That(watch.ElapsedMilliseconds, Is.LessThan(10000), "Drain waited after the queue was empty");

            queue.Enqueue(() => throw new IOException("full"), null, null);
            queue.Enqueue(() => { }, null, null); // held behind the failure
            watch.Restart();
            Assert.That(queue.Drain(20000), Is.False);
            Assert.That(watch.ElapsedMilliseconds, Is.LessThan(10000), "Drain waited for a write held behind a failure");
            Assert.That(queue.LastError, Is.EqualTo("full"));
            queue.Dispose();
        }

        [Test]
        public void DrainWithNoTimeWhileAWriteIsUnderWayReturnsAtOnce()
        {
            var queue = new SaveQueue(background: true);
            using (var started = new ManualResetEventSlim(false))
            using (var gate = new ManualResetEventSlim(false))
            {
                queue.Enqueue(() => { started.Set(); gate.Wait(20000); }, null, null);
                Assert.That(started.Wait(10000), Is.True);
                bool? drained = null;
                var run = System.Threading.Tasks.Task.Run(() => drained = queue.Drain(0));
                try
                {
                    Assert.That(run.Wait(5000), Is.True, "Drain(0) waited for the write");
                    Assert.That(drained, Is.False, "not written yet");
                }
                finally
                {
                    gate.Set();
                }
                Assert.That(queue.Drain(10000), Is.True);
            }
            queue.Dispose();
        }

        [Test]
        public void DrainAlsoWaitsForAWriteQueuedByAnAcknowledgement()
        {
            var queue = new SaveQueue(background: true);
            bool indexWritten = false;
            queue.Enqueue(() => { }, () => queue.Enqueue(() => { Thread.Sleep(20); Volatile.Write(ref indexWritten, true); }, null, null), null);
            Assert.That(queue.Drain(10000), Is.True, "the index after its file is written too");
            Assert.That(Volatile.Read(ref indexWritten), Is.True);
            Assert.That(queue.Pending, Is.Zero);
            queue.Dispose();
        }

        [Test]
        public void DisposingTheQueueEndsItsThreadWhileItWaitsForWork()
        {
            // The background thread waits for work without a timeout; Dispose must wake it, or every study scene left would
            // leave a thread behind. Linux names threads in /proc (the name cut to 15 characters).
            if (!System.Runtime.InteropServices.RuntimeInformation.IsOSPlatform(System.Runtime.InteropServices.OSPlatform.Linux))
                Assert.Ignore("Linux only (/proc/self/task)");
            int Threads()
            {
                int n = 0;
                foreach (string task in Directory.GetDirectories("/proc/self/task"))
                    try { if (File.ReadAllText(Path.Combine(task, "comm")).Trim() == "Kosmos.PseudoHa") n++; } catch (IOException) { }
                return n;
            }
            int before = Threads();
            var queue = new SaveQueue(background: true);
            bool saved = false;
            queue.Enqueue(() => { }, () => saved = true, _ => { });
            Assert.That(queue.Drain(5000), Is.True);
            Assert.That(saved, Is.True);
            Assert.That(Threads(), Is.EqualTo(before + 1), "its thread, waiting for work");
            queue.Dispose();
            var clock = System.Diagnostics.Stopwatch.StartNew();
            while (Threads() > before && clock.ElapsedMilliseconds < 5000) Thread.Sleep(10);
            Assert.That(Threads(), Is.EqualTo(before), "the thread ended");
        }
    }
}
