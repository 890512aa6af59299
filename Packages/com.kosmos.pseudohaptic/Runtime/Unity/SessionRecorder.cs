using System.IO;
using Kosmos.PseudoHaptic.Evaluation;
using Kosmos.PseudoHaptic.Simulation;
using UnityEngine;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// Records every hold of a study session, one replay-format CSV per hold and an index <c>holds.csv</c>, so that
    /// <c>pseudohaptic replay</c> can run it again. Glue over the engine-free <see cref="SessionLog"/> (buffers, file
    /// names, index, atomic writes): this listens to <see cref="PseudoHapticWeight"/>'s hold events, resolves the
    /// folder under <see cref="Application.persistentDataPath"/>, pumps the log's writer every frame (files are written on
    /// a background thread; <see cref="HoldWritten"/> comes once a file is on disk), and writes running holds at a pause, at
    /// quit and when disabled, waiting for them. Recording a frame allocates nothing.
    /// </summary>
    [DisallowMultipleComponent]
    [AddComponentMenu("Kosmos/Pseudo-Haptic/Session Recorder")]
    public sealed class SessionRecorder : MonoBehaviour
    {
        /// <summary>The index's columns.</summary>
        public const string IndexHeader = SessionLog.IndexHeader;

        [Tooltip("Where sessions are written; empty: Kosmos.PseudoHaptic/sessions under Application.persistentDataPath. A relative path is taken under persistentDataPath.")]
        [SerializeField] string _folder = "";
        [Tooltip("The session's folder name, e.g. the participant id; empty: the local date and time when recording starts.")]
        [SerializeField] string _sessionId = "";
        [Tooltip("Only these objects are recorded; empty: every object with a Pseudo-Haptic Weight.")]
        [SerializeField] PseudoHapticWeight[] _objects = new PseudoHapticWeight[0];
        [Tooltip("Frames each hold's buffer holds before it grows (90 per second at 90 Hz).")]
        [SerializeField] int _framesPerHold = HoldRecording.DefaultCapacity;

        SessionLog _log;
        SaveLifecycle _saves; // a pause, quitting, the end: writing running holds and waiting for the writer

        public SessionLog Log => _log ?? (_log = CreateLog());
        public string SessionFolder => Log.SessionFolder;
        public int HoldCount => Log.HoldCount;
        public string LastError => Log.LastError;
        public int ActiveCount => Log.ActiveCount;

        /// <summary>Invoked with the file's path after a hold's file is written (at its end, or partly at a pause).</summary>
        public event System.Action<string> HoldWritten;

        /// <summary>The session's name (its folder under <see cref="Folder"/>); setting it starts a new session.</summary>
        public string SessionId { get => Log.SessionId; set => Log.SessionId = _sessionId = value ?? ""; }

        /// <summary>Only these objects are recorded; null or empty: every object with a Pseudo-Haptic Weight.</summary>
        public PseudoHapticWeight[] Objects { get => _objects; set => _objects = value ?? new PseudoHapticWeight[0]; }

        /// <summary>The folder sessions are written under.</summary>
        public string Folder
        {
            get => Log.Folder;
            set => Log.Folder = Resolve(_folder = value ?? "");
        }

        static string Resolve(string folder) =>
            string.IsNullOrEmpty(folder) ? Path.Combine(Application.persistentDataPath, "Kosmos.PseudoHaptic", "sessions")
            : Path.Combine(Application.persistentDataPath, folder); // Path.Combine keeps a rooted folder as it is

        SessionLog CreateLog()
        {
            // Holds are written on a background thread, in order; Update delivers each one's acknowledgement.
            var log = new SessionLog(_framesPerHold, new SaveQueue(background: true)) { Folder = Resolve(_folder), SessionId = _sessionId };
            log.HoldWritten += path => HoldWritten?.Invoke(path);
            log.WriteFailed += message => Debug.LogError(message, this);
            return log;
        }

        void OnEnable()
        {
            PseudoHapticWeight.HoldBegan += OnHoldBegan;
            PseudoHapticWeight.HoldStepped += OnHoldStepped;
            PseudoHapticWeight.HoldEnded += OnHoldEnded;
        }

        void OnDisable()
        {
            PseudoHapticWeight.HoldBegan -= OnHoldBegan;
            PseudoHapticWeight.HoldStepped -= OnHoldStepped;
            PseudoHapticWeight.HoldEnded -= OnHoldEnded;
            Log.FinishAll(); // what is running is written as far as it got; its remaining frames are not recorded
            Log.Drain();
        }

        void Update()
        {
            if (_log != null) _log.Pump(); // acknowledgements of written holds, retries of failed ones
        }

        SaveLifecycle Saves => _saves ?? (_saves = new SaveLifecycle(() => _log?.Saver, null, () => Log.FlushActive()));
        void OnApplicationPause(bool paused) => Saves.OnPause(paused);
        void OnApplicationQuit() => Saves.OnQuit();
        void OnDestroy() => Saves.OnDestroy(); // OnDisable has written and waited for everything: this stops the writer

        /// <summary>Writes every hold still running as far as it got, and waits (up to 5 s) for every queued write (what a pause and quitting do).</summary>
        public void FlushActive() => Saves.OnQuit();

        /// <summary>Waits up to <paramref name="timeoutMs"/> for every queued write and delivers <see cref="HoldWritten"/>. True when nothing is left unwritten.</summary>
        public bool WaitForSaves(int timeoutMs = SaveLifecycle.TimeoutMs) => Saves.Wait(timeoutMs);

        /// <summary>Files written but not yet acknowledged (being written, or failed and waiting to be tried again).</summary>
        public int PendingWrites => Log.PendingWrites;

        void OnHoldBegan(PseudoHapticWeight w)
        {
            HandSample hand = w.LastHand;
            if (SessionLog.IsListed(w, _objects)) Log.Began(w, w.name, w.Solver, in hand, Time.unscaledTimeAsDouble);
        }

        void OnHoldStepped(PseudoHapticWeight w)
        {
            HandSample hand = w.LastHand;
            Log.Stepped(w, w.Solver, in hand, w.LastDeltaTime);
        }

        void OnHoldEnded(PseudoHapticWeight w) => Log.Ended(w);

        /// <summary>A name fit for a file name and a CSV field (see <see cref="SessionLog.SafeName"/>).</summary>
        public static string SafeName(string name) => SessionLog.SafeName(name);
    }
}
