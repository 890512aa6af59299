using System;
using System.Collections.Generic;
using System.Threading;
using Kosmos.PseudoHaptic.Evaluation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests.Evaluation
{
    /// <summary>
    /// What the study components do at a pause, quitting and their end (<see cref="SaveLifecycle"/>): a pause or
    /// quitting queues what is running and then waits for the background writer before showing the outcome, a resume
    /// does nothing, the end waits and then stops the writer, and a component that never wrote has nothing to wait for.
    /// </summary>
    public class SaveLifecycleTests
    {
        /// <summary>
        /// A background queue whose one write waits for a gate, and a lifecycle over it that logs, in order, what it
        /// queues before waiting, the acknowledgement (or failure) of the write and what it shows.
        /// </summary>
        sealed class GatedWrite : IDisposable
        {
            public readonly List<string> Log = new List<string>();
            public readonly SaveQueue Queue = new SaveQueue(background: true);
            public readonly SaveLifecycle Life;
            readonly ManualResetEventSlim _gate = new ManualResetEventSlim(false);
            Thread _opener;

            public GatedWrite()
            {
                Queue.Enqueue(() => _gate.Wait(10000), () => Log.Add("saved"), e => Log.Add("failed: " + e));
                Life = new SaveLifecycle(() => Queue, () => Log.Add("shown"), () => Log.Add("running queued"));
            }

            /// <summary>The write ends now.</summary>
            public void Open() => _gate.Set();

            /// <summary>The write ends <paramref name="ms"/> from now, from another thread, while the main thread waits.</summary>
            public void OpenAfter(int ms)
            {
                _opener = new Thread(() => { Thread.Sleep(ms); _gate.Set(); });
                _opener.Start();
            }

            public void Dispose()
            {
                _gate.Set();
                _opener?.Join();
                Queue.Dispose();
                _gate.Dispose();
            }
        }

        [Test]
        public void APauseWaitsForTheWriteUnderWayThenShowsItAndAResumeDoesNothing()
        {
            using (var w = new GatedWrite())
            {
                Assert.That(w.Life.OnPause(false), Is.True);
                Assert.That(w.Log, Is.Empty, "a resume neither queues, waits nor shows");
                Assert.That(w.Queue.Pending, Is.EqualTo(1));

                w.OpenAfter(100);
                Assert.That(w.Life.OnPause(true), Is.True, "the write ended within the wait");
                Assert.That(w.Log, Is.EqualTo(new[] { "running queued", "saved", "shown" }), "queued what runs, waited for the acknowledgement, then showed it");
                Assert.That(w.Queue.Pending, Is.Zero);
            }
        }

        [Test]
        public void QuittingDoesWhatAPauseDoes()
        {
            List<string> pause, quit;
            using (var w = new GatedWrite())
            {
                w.OpenAfter(50);
                Assert.That(w.Life.OnPause(true), Is.True);
                pause = w.Log;
            }
            using (var w = new GatedWrite())
            {
                w.OpenAfter(50);
                Assert.That(w.Life.OnQuit(), Is.True);
                quit = w.Log;
            }
            Assert.That(quit, Is.EqualTo(pause));
            Assert.That(quit, Has.Count.EqualTo(3));
        }

        [Test]
        public void WhatIsQueuedBeforeTheWaitIsWaitedFor()
        {
            // The recorder's running holds: taken at the pause, on the main thread, and written before the pause returns.
            var log = new List<string>();
            var queue = new SaveQueue(background: true);
            var life = new SaveLifecycle(() => queue, null,
                () => queue.Enqueue(() => Thread.Sleep(50), () => log.Add("running hold saved"), e => log.Add("failed: " + e)));
            Assert.That(life.OnPause(true), Is.True);
            Assert.That(log, Is.EqualTo(new[] { "running hold saved" }));
            queue.Dispose();
        }

        [Test]
        public void AWaitThatRunsOutSaysSoAndStillShowsWhereTheWriteIs()
        {
            using (var w = new GatedWrite())
            {
                var watch = System.Diagnostics.Stopwatch.StartNew();
                Assert.That(w.Life.Wait(100), Is.False, "the write is still under way");
                Assert.That(watch.ElapsedMilliseconds, Is.GreaterThanOrEqualTo(90).And.LessThan(5000), "waited about the time asked");
                Assert.That(w.Log, Is.EqualTo(new[] { "shown" }), "a wait queues nothing, and shows even when it ran out");
                w.Open();
                Assert.That(w.Life.Wait(), Is.True);
                Assert.That(w.Log, Is.EqualTo(new[] { "shown", "saved", "shown" }));
            }
        }

        [Test]
        public void AFailedWriteEndsTheWaitAtOnceUnsavedAndShown()
        {
            var log = new List<string>();
            var queue = new SaveQueue(background: true, retrySeconds: 60);
            queue.Enqueue(() => throw new System.IO.IOException("No space left on device"), () => log.Add("saved"), e => log.Add("failed: " + e));
            var life = new SaveLifecycle(() => queue, () => log.Add("shown"));
            var watch = System.Diagnostics.Stopwatch.StartNew();
            Assert.That(life.OnQuit(), Is.False);
            Assert.That(watch.ElapsedMilliseconds, Is.LessThan(SaveLifecycle.TimeoutMs / 2), "waited for a write that had failed");
            Assert.That(log, Is.EqualTo(new[] { "failed: No space left on device", "shown" }));
            queue.Dispose();
        }

        [Test]
        public void TheEndWaitsForTheQueueThenStopsTheWriterAndShowsNothing()
        {
            using (var w = new GatedWrite())
            {
                w.OpenAfter(100);
                w.Life.OnDestroy();
                Assert.That(w.Log, Is.EqualTo(new[] { "saved" }), "waited for the write, queued nothing more, showed nothing");
                Assert.That(() => w.Queue.Enqueue(() => { }, null, null), Throws.TypeOf<ObjectDisposedException>(), "the writer is stopped");
            }
        }

        [Test]
        public void WithoutAQueueThereIsNothingToWaitForOrShow()
        {
            var log = new List<string>();
            var life = new SaveLifecycle(() => null, () => log.Add("shown"));
            Assert.That(life.Wait(), Is.True);
            Assert.That(life.OnPause(true), Is.True);
            Assert.That(life.OnQuit(), Is.True);
            life.OnDestroy();
            Assert.That(log, Is.Empty);
        }

        [Test]
        public void TheQueueIsAskedForAtEachEventSoOneMadeLaterIsWaitedFor()
        {
            // A component makes its writer when it first begins: the lifecycle, made before, must see it.
            SaveQueue queue = null;
            var log = new List<string>();
            var life = new SaveLifecycle(() => queue, () => log.Add("shown"));
            Assert.That(life.Wait(), Is.True);
            queue = new SaveQueue(background: true);
            queue.Enqueue(() => Thread.Sleep(50), () => log.Add("saved"), e => log.Add("failed: " + e));
            Assert.That(life.Wait(), Is.True);
            Assert.That(log, Is.EqualTo(new[] { "saved", "shown" }));
            queue.Dispose();
        }

        [Test]
        public void NoQueueSourceIsRefusedNamingIt()
        {
            Assert.That(() => new SaveLifecycle(null), Throws.TypeOf<ArgumentNullException>().With.Property("ParamName").EqualTo("queue"));
        }
    }
}
