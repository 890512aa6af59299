using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.Threading;

namespace Kosmos.PseudoHaptic.Evaluation
{
    /// <summary>
    /// One writer for a study's files, so that "acknowledged" means "on disk" without stalling a frame: writes are
    /// queued on the main thread (<see cref="Enqueue"/>), done one at a time in the order given (on a background
    /// thread, or on the caller's thread when <see cref="Background"/> is false), and each one's outcome comes back
    /// on the main thread when it calls <see cref="Pump"/> (every frame, from a component's Update): its
    /// <c>saved</c> callback after the write returned, or its <c>failed</c> callback with the error. A failed write
    /// stays at the head of the queue (nothing after it is written, so order holds) and is tried again
    /// <see cref="RetrySeconds"/> later, for as long as it fails; a write that succeeded is never done again.
    /// </summary>
    /// <remarks>
    /// A write is given as an action that writes a whole file (a snapshot of its text, through
    /// <see cref="AtomicFile"/>): doing it again after a failure writes the same file again, never an answer twice.
    /// <see cref="Pump"/> allocates nothing when there is nothing to deliver. Callbacks run inside <see cref="Pump"/>
    /// or <see cref="Drain"/>, on the thread that called them.
    /// </remarks>
    public sealed class SaveQueue : IDisposable
    {
        public const double DefaultRetrySeconds = 2;

        sealed class Job
        {
            public Action Write;
            public Action Saved;
            public Action<string> Failed;
            public string Error;
        }

        readonly object _lock = new object();
        readonly List<Job> _todo = new List<Job>();     // to write, in order (the head is retried first)
        readonly Queue<Job> _done = new Queue<Job>();   // written or failed, to deliver on the main thread
        readonly Func<double> _clock;
        readonly Stopwatch _watch;
        Thread _thread;
        bool _busy, _blocked, _stopped;
        Job _failed;        // main thread: the failed write waiting for its retry
        double _retryAt;

        /// <summary>Whether writes run on a background thread (false: on the thread that calls <see cref="Pump"/>).</summary>
        public bool Background { get; }
        /// <summary>Seconds between a failed write and its next attempt.</summary>
        public double RetrySeconds { get; }
        /// <summary>The last write's error while it has not yet succeeded; null when all is written or being written.</summary>
        public string LastError { get; private set; }
        /// <summary>Writes that succeeded / failed (attempts), over the queue's life.</summary>
        public long Writes { get; private set; }
        public long Failures { get; private set; }

        /// <summary>Writes not yet acknowledged: queued, being written, failed and waiting, or done but not yet delivered.</summary>
        public int Pending
        {
            get { lock (_lock) return _todo.Count + (_busy ? 1 : 0) + _done.Count + (_failed != null ? 1 : 0); }
        }

        /// <param name="background">Write on one background thread (the headset); false: write inside <see cref="Pump"/>.</param>
        /// <param name="retrySeconds">Seconds before a failed write is tried again (≥ 0).</param>
        /// <param name="clock">Seconds, for the retry delay; default a monotonic stopwatch.</param>
        public SaveQueue(bool background, double retrySeconds = DefaultRetrySeconds, Func<double> clock = null)
        {
            if (!(retrySeconds >= 0) || double.IsInfinity(retrySeconds)) throw new ArgumentOutOfRangeException(nameof(retrySeconds), "retrySeconds must be finite and ≥ 0");
            Background = background;
            RetrySeconds = retrySeconds;
            if (clock == null)
            {
                _watch = Stopwatch.StartNew();
                clock = () => _watch.Elapsed.TotalSeconds;
            }
            _clock = clock;
        }

        /// <summary>Queues <paramref name="write"/>; <paramref name="saved"/> runs after it returned, <paramref name="failed"/> after each failure (then it is retried).</summary>
        public void Enqueue(Action write, Action saved, Action<string> failed)
        {
            if (write == null) throw new ArgumentNullException(nameof(write));
            var job = new Job { Write = write, Saved = saved, Failed = failed };
            lock (_lock)
            {
                if (_stopped) throw new ObjectDisposedException(nameof(SaveQueue));
                _todo.Add(job);
                if (Background && _thread == null)
                {
                    _thread = new Thread(Run) { IsBackground = true, Name = "Kosmos.PseudoHaptic.SaveQueue" };
                    _thread.Start();
                }
                Monitor.PulseAll(_lock);
            }
        }

        /// <summary>
        /// Main thread, every frame: retries a failed write when its delay has passed, writes (when not in the
        /// background), and delivers the outcomes that are ready. Returns how many writes were acknowledged.
        /// </summary>
        public int Pump()
        {
            if (_failed != null && _clock() >= _retryAt)
            {
                lock (_lock)
                {
                    _todo.Insert(0, _failed);
                    _failed = null;
                    _blocked = false;
                    Monitor.PulseAll(_lock);
                }
            }
            int saved = 0;
            while (true)
            {
                if (!Background) WriteHere();
                int delivered = Deliver();
                saved += delivered;
                // Written here: an acknowledgement that queued another write (an index after its file) is written now too.
                if (Background || delivered == 0 || !HasWork) return saved;
            }
        }

        bool HasWork
        {
            get { lock (_lock) return _todo.Count > 0 && !_blocked; }
        }

        /// <summary>
        /// Waits up to <paramref name="timeoutMs"/> for every queued write to be done (or for one to fail), then
        /// delivers the outcomes (a pause, quitting, a disabled component). True when nothing is left unwritten.
        /// </summary>
        public bool Drain(int timeoutMs = 5000)
        {
            if (!Background)
            {
                Pump();
                lock (_lock) return _todo.Count == 0 && _failed == null;
            }
            var deadline = Stopwatch.StartNew();
            while (true)
            {
                lock (_lock)
                {
                    while ((_todo.Count > 0 && !_blocked) || _busy)
                    {
                        int left = timeoutMs - (int)deadline.ElapsedMilliseconds;
                        if (left <= 0) break;
                        Monitor.Wait(_lock, left);
                    }
                }
                Deliver(); // an acknowledgement may queue another write (an index after its file): wait for it too
                lock (_lock)
                {
                    bool idle = _todo.Count == 0 && !_busy;
                    if (idle || _blocked || _failed != null || deadline.ElapsedMilliseconds >= timeoutMs)
                        return idle && _failed == null;
                }
            }
        }

        int Deliver()
        {
            int saved = 0;
            while (true)
            {
                Job job;
                lock (_lock)
                {
                    if (_done.Count == 0) break;
                    job = _done.Dequeue();
                }
                if (job.Error == null)
                {
                    saved++;
                    Writes++;
                    LastError = null;
                    job.Saved?.Invoke();
                }
                else
                {
                    Failures++;
                    LastError = job.Error;
                    string error = job.Error;
                    job.Error = null;
                    _failed = job; // retried later, before anything queued after it
                    _retryAt = _clock() + RetrySeconds;
                    job.Failed?.Invoke(error);
                }
            }
            return saved;
        }

        void WriteHere()
        {
            while (true)
            {
                Job job;
                lock (_lock)
                {
                    if (_blocked || _todo.Count == 0) return;
                    job = _todo[0];
                    _todo.RemoveAt(0);
                }
                Finish(job, Execute(job));
            }
        }

        void Run()
        {
            while (true)
            {
                Job job;
                lock (_lock)
                {
                    while (!_stopped && (_blocked || _todo.Count == 0)) Monitor.Wait(_lock);
                    if (_stopped) return;
                    job = _todo[0];
                    _todo.RemoveAt(0);
                    _busy = true;
                }
                Finish(job, Execute(job));
            }
        }

        static string Execute(Job job)
        {
            try
            {
                job.Write();
                return null;
            }
            catch (Exception e)
            {
                return string.IsNullOrEmpty(e.Message) ? e.GetType().Name : e.Message;
            }
        }

        void Finish(Job job, string error)
        {
            lock (_lock)
            {
                _busy = false;
                job.Error = error;
                if (error != null) _blocked = true; // nothing after it is written until it is
                _done.Enqueue(job);
                Monitor.PulseAll(_lock);
            }
        }

        /// <summary>Stops the background thread after the write under way (call <see cref="Drain"/> first to finish the queue).</summary>
        public void Dispose()
        {
            lock (_lock)
            {
                _stopped = true;
                Monitor.PulseAll(_lock);
            }
        }
    }
}
