using System;

namespace Kosmos.PseudoHaptic.Evaluation
{
    /// <summary>
    /// What a component that writes a study's files through a <see cref="SaveQueue"/> does when the app pauses or
    /// quits and when the component goes, decided once for all of them (the discrimination task, the questionnaire
    /// panel and the session recorder call it in one line per Unity message):
    /// <list type="bullet">
    /// <item>a pause (the headset taken off, the menu button) or quitting first queues what is still running (the
    /// recorder's holds, as far as they got), then waits up to <see cref="TimeoutMs"/> for the queue and shows the
    /// outcome; a resume does nothing;</item>
    /// <item>the component's end (OnDestroy) waits the same for the queue, then stops its writer's thread, showing
    /// nothing (the component is going);</item>
    /// <item>a component that has no queue yet (it never began, so never wrote) has nothing to wait for.</item>
    /// </list>
    /// </summary>
    /// <remarks>
    /// Waiting bounds the loss: the app may be killed once it is in the background, and an answer still in the queue
    /// then is lost (it was not acknowledged). The wait returns at once when a write failed: that one stays unsaved
    /// and shown as such (<see cref="SaveQueue.Drain"/>).
    /// </remarks>
    public sealed class SaveLifecycle
    {
        /// <summary>How long a pause, quitting or the component's end waits for the queue, ms.</summary>
        public const int TimeoutMs = 5000;

        readonly Func<SaveQueue> _queue;
        readonly Action _show, _takeRunning;

        /// <param name="queue">The component's writer, or null while it has none (called at each event, never kept).</param>
        /// <param name="show">Shows the outcome after a wait (may be null).</param>
        /// <param name="takeRunning">Queues what is still running before a pause or quitting waits (may be null).</param>
        public SaveLifecycle(Func<SaveQueue> queue, Action show = null, Action takeRunning = null)
        {
            _queue = queue ?? throw new ArgumentNullException(nameof(queue));
            _show = show;
            _takeRunning = takeRunning;
        }

        /// <summary>Waits up to <paramref name="timeoutMs"/> for every queued write and shows the outcome. True when nothing is left unsaved (also when there is no queue).</summary>
        public bool Wait(int timeoutMs = TimeoutMs)
        {
            SaveQueue queue = _queue();
            if (queue == null) return true;
            bool saved = queue.Drain(timeoutMs);
            _show?.Invoke();
            return saved;
        }

        /// <summary>OnApplicationPause: pausing queues what is running and waits (<see cref="OnQuit"/>); resuming does nothing. True when nothing is left unsaved.</summary>
        public bool OnPause(bool paused) => !paused || OnQuit();

        /// <summary>OnApplicationQuit: queues what is running, then waits (<see cref="Wait"/>). True when nothing is left unsaved.</summary>
        public bool OnQuit()
        {
            _takeRunning?.Invoke();
            return Wait();
        }

        /// <summary>OnDestroy: waits up to <see cref="TimeoutMs"/> for the queue, then stops its thread (after the write under way). Shows nothing.</summary>
        public void OnDestroy()
        {
            SaveQueue queue = _queue();
            if (queue == null) return;
            queue.Drain(TimeoutMs);
            queue.Dispose();
        }
    }
}
