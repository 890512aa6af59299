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
        /// <summary>A background queue whose one write waits for <paramref name="gate"/>; the events in order go to <paramref name="log"/>.</summary>
        static SaveQueue GatedWrite(ManualResetEventSlim gate, List<string> log)
        {
            var queue = new SaveQueue(background: true);
            queue.Enqueue(() => gate.Wait(10000), () => log.Add("saved"), e => log.Add("failed: " + e));
            return queue;
        }

        /// <summary>Opens <paramref name="gate"/> from another thread after <paramref name="ms"/>: the write ends while the main thread waits.</summary>
        static Thread OpenLater(ManualResetEventSlim gate, int ms)
        {
            var opener = new Thread(() => { Thread.Sleep(ms); gate.Set(); });
            opener.Start();
            return opener;
        }

        [Test]
        public void APauseWaitsForTheWriteUnderWayThenShowsItAndAResumeDoesNothing()
        {
            var log = new List<string>();
            using (var gate = new ManualResetEventSlim(false))
            {
                SaveQueue queue = GatedWrite(gate, log);
                var life = new SaveLifecycle(() => queue, () => log.Add("shown"), () => log.Add("running queued"));

                Assert.That(life.OnPause(false), Is.True);
                Assert.That(log, Is.Empty, "a resume neither queues, waits nor shows");
                Assert.That(queue.Pending, Is.EqualTo(1));

                Thread opener = OpenLater(gate, 100);
                Assert.That(life.OnPause(true), Is.True, "the write ended within the wait");
                Assert.That(log, Is.EqualTo(new[] { "running queued", "saved", "shown" }), "queued what runs, waited for the acknowledgement, then showed it");
                Assert.That(queue.Pending, Is.Zero);
                opener.Join();
                queue.Dispose();
            }
        }

        [Test]
        public void QuittingDoesWhatAPauseDoes()
        {
            var pause = new List<string>();
            var quit = new List<string>();
            foreach (bool quitting in new[] { false, true })
            {
                List<string> log = quitting ? quit : pause;
                using (var gate = new ManualResetEventSlim(false))
                {
                    SaveQueue queue = GatedWrite(gate, log);
                    var life = new SaveLifecycle(() => queue, () => log.Add("shown"), () => log.Add("running queued"));
                    Thread opener = OpenLater(gate, 50);
                    Assert.That(quitting ? life.OnQuit() : life.OnPause(true), Is.True);
                    opener.Join();
                    queue.Dispose();
                }
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
            var log = new List<string>();
            using (var gate = new ManualResetEventSlim(false))
            {
                SaveQueue queue = GatedWrite(gate, log);
                var life = new SaveLifecycle(() => queue, () => log.Add("shown"));
                var watch = System.Diagnostics.Stopwatch.StartNew();
                Assert.That(life.Wait(100), Is.False, "the write is still under way");
                Assert.That(watch.ElapsedMilliseconds, Is.GreaterThanOrEqualTo(90).And.LessThan(5000), "waited about the time asked");
                Assert.That(log, Is.EqualTo(new[] { "shown" }));
                gate.Set();
                Assert.That(life.Wait(), Is.True);
                Assert.That(log, Is.EqualTo(new[] { "shown", "saved", "shown" }));
                queue.Dispose();
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
            var log = new List<string>();
            using (var gate = new ManualResetEventSlim(false))
            {
                SaveQueue queue = GatedWrite(gate, log);
                var life = new SaveLifecycle(() => queue, () => log.Add("shown"), () => log.Add("running queued"));
                Thread opener = OpenLater(gate, 100);
                life.OnDestroy();
                Assert.That(log, Is.EqualTo(new[] { "saved" }), "waited for the write, queued nothing more, showed nothing");
                Assert.That(() => queue.Enqueue(() => { }, null, null), Throws.TypeOf<ObjectDisposedException>(), "the writer is stopped");
                opener.Join();
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
