using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Text;
using Kosmos.PseudoHaptic.Evaluation;
using Kosmos.PseudoHaptic.Simulation;
using UnityEngine;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// Records every hold of a study session: each frame of each held object (the hand as the solver saw it,
    /// the object's height, mass, profile) into a preallocated <see cref="HoldRecording"/>, written when the
    /// hold ends as one CSV per hold in the replay trace format, so that <c>pseudohaptic replay</c> can run it
    /// again and <c>demo</c>-style tools can plot it. Files go to
    /// <c>&lt;folder&gt;/&lt;session&gt;/hold-001-&lt;object&gt;.csv</c>, with an index <c>holds.csv</c> naming each hold's
    /// object, mass and profile (the options replay needs). Files are written to a temporary name and renamed
    /// (<see cref="AtomicFile"/>); a hold still running when the app is paused, quits or this component is
    /// disabled is written as far as it got. Recording a frame allocates nothing.
    /// </summary>
    [DisallowMultipleComponent]
    [AddComponentMenu("Kosmos/Pseudo-Haptic/Session Recorder")]
    public sealed class SessionRecorder : MonoBehaviour
    {
        /// <summary>The index's columns.</summary>
        public const string IndexHeader = "hold,object,file,frames,duration_s,mass_kg,profile,standard_speed,started_at_s";

        [Tooltip("Where sessions are written; empty: Kosmos.PseudoHaptic/sessions under Application.persistentDataPath. A relative path is taken under persistentDataPath.")]
        [SerializeField] string _folder = "";
        [Tooltip("The session's folder name, e.g. the participant id; empty: the local date and time when recording starts.")]
        [SerializeField] string _sessionId = "";
        [Tooltip("Only these objects are recorded; empty: every object with a Pseudo-Haptic Weight.")]
        [SerializeField] PseudoHapticWeight[] _objects = new PseudoHapticWeight[0];
        [Tooltip("Frames each hold's buffer holds before it grows (90 per second at 90 Hz).")]
        [SerializeField] int _framesPerHold = HoldRecording.DefaultCapacity;

        sealed class Hold
        {
            public PseudoHapticWeight Weight;
            public readonly HoldRecording Recording;
            public int Number;
            public string File;
            public string ObjectName;
            public double StartedAt;
            public Hold(int capacity) => Recording = new HoldRecording(capacity);
        }

        readonly List<Hold> _active = new List<Hold>(2);
        readonly Stack<Hold> _spare = new Stack<Hold>(2);
        readonly StringBuilder _index = new StringBuilder();
        string _sessionFolder;
        int _holds;
        string _lastError;

        /// <summary>The folder this session writes into; null until the first hold (or <see cref="SessionId"/> set).</summary>
        public string SessionFolder => _sessionFolder;

        /// <summary>Holds begun in this session.</summary>
        public int HoldCount => _holds;

        /// <summary>The last write error, or null.</summary>
        public string LastError => _lastError;

        /// <summary>Objects being held and recorded now.</summary>
        public int ActiveCount => _active.Count;

        /// <summary>Invoked with the file's path after a hold's file is written (at its end, or partly at a pause).</summary>
        public event Action<string> HoldWritten;

        /// <summary>
        /// The session's name (its folder under <see cref="Folder"/>). Setting it starts a new session: later holds
        /// are numbered from 1 in the new folder.
        /// </summary>
        public string SessionId
        {
            get => _sessionId;
            set
            {
                _sessionId = value ?? "";
                _sessionFolder = null;
                _holds = 0;
                _index.Length = 0;
            }
        }

        /// <summary>Only these objects are recorded; null or empty: every object with a Pseudo-Haptic Weight.</summary>
        public PseudoHapticWeight[] Objects
        {
            get => _objects;
            set => _objects = value ?? new PseudoHapticWeight[0];
        }

        /// <summary>The folder sessions are written under.</summary>
        public string Folder
        {
            get
            {
                string root = Path.Combine(Application.persistentDataPath, "Kosmos.PseudoHaptic");
                if (string.IsNullOrEmpty(_folder)) return Path.Combine(root, "sessions");
                return Path.IsPathRooted(_folder) ? _folder : Path.Combine(Application.persistentDataPath, _folder);
            }
            set
            {
                _folder = value ?? "";
                _sessionFolder = null;
            }
        }

        void Awake()
        {
            int capacity = Math.Max(64, _framesPerHold);
            for (int i = 0; i < 2; i++) _spare.Push(new Hold(capacity)); // two hands
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
            // What is running is written as far as it got; its remaining frames are not recorded.
            for (int i = _active.Count - 1; i >= 0; i--) Finish(i);
        }

        void OnApplicationPause(bool paused)
        {
            if (paused) FlushActive();
        }

        void OnApplicationQuit() => FlushActive();

        /// <summary>Writes every hold still running as far as it got (it goes on recording, and is written again at its end).</summary>
        public void FlushActive()
        {
            for (int i = 0; i < _active.Count; i++) Write(_active[i]);
        }

        bool Records(PseudoHapticWeight weight)
        {
            if (_objects == null || _objects.Length == 0) return true;
            for (int i = 0; i < _objects.Length; i++)
                if (_objects[i] == weight) return true;
            return false;
        }

        int IndexOf(PseudoHapticWeight weight)
        {
            for (int i = 0; i < _active.Count; i++)
                if (ReferenceEquals(_active[i].Weight, weight)) return i;
            return -1;
        }

        void OnHoldBegan(PseudoHapticWeight weight)
        {
            if (!Records(weight) || weight.Solver == null) return;
            int at = IndexOf(weight);
            if (at >= 0) Finish(at); // a begin without an end: keep what was recorded

            Hold hold = _spare.Count > 0 ? _spare.Pop() : new Hold(Math.Max(64, _framesPerHold));
            hold.Weight = weight;
            hold.Number = ++_holds;
            hold.ObjectName = weight.name;
            hold.StartedAt = Time.timeAsDouble;
            hold.File = null;
            HandSample hand = weight.LastHand;
            hold.Recording.Begin(weight.Solver, in hand);
            _active.Add(hold);
        }

        void OnHoldStepped(PseudoHapticWeight weight)
        {
            int at = IndexOf(weight);
            if (at < 0) return;
            HandSample hand = weight.LastHand;
            _active[at].Recording.Step(weight.Solver, in hand, weight.LastDeltaTime);
        }

        void OnHoldEnded(PseudoHapticWeight weight)
        {
            int at = IndexOf(weight);
            if (at >= 0) Finish(at);
        }

        void Finish(int at)
        {
            Hold hold = _active[at];
            _active.RemoveAt(at);
            Write(hold);
            AppendIndex(hold);
            hold.Weight = null;
            hold.Recording.Clear();
            _spare.Push(hold);
        }

        /// <summary>Writes one hold's file (write, then rename); a failure is logged and kept in <see cref="LastError"/>.</summary>
        void Write(Hold hold)
        {
            try
            {
                if (hold.File == null)
                {
                    string folder = EnsureSessionFolder();
                    hold.File = Path.Combine(folder, "hold-" + hold.Number.ToString("000", CultureInfo.InvariantCulture) + "-" + SafeName(hold.ObjectName) + ".csv");
                }
                HoldRecording recording = hold.Recording;
                AtomicFile.WriteWith(hold.File, temp =>
                {
                    using (var writer = new StreamWriter(temp, false, new UTF8Encoding(false)))
                        recording.WriteCsv(writer);
                });
                _lastError = null;
                HoldWritten?.Invoke(hold.File);
            }
            catch (Exception e) when (e is IOException || e is UnauthorizedAccessException || e is ArgumentException || e is NotSupportedException)
            {
                _lastError = "Session recorder: hold " + hold.Number + " of '" + hold.ObjectName + "' was not written: " + e.Message;
                Debug.LogError(_lastError, this);
            }
        }

        /// <summary>Adds the finished hold to holds.csv (rewritten whole, write then rename).</summary>
        void AppendIndex(Hold hold)
        {
            if (hold.File == null) return; // its file could not be written either
            HoldRecording r = hold.Recording;
            RecordedFrame last = r.Count > 0 ? r[r.Count - 1] : default;
            if (_index.Length == 0) _index.Append(IndexHeader).Append('\n');
            _index.Append(hold.Number.ToString(CultureInfo.InvariantCulture)).Append(',')
                .Append(SafeName(hold.ObjectName)).Append(',')
                .Append(Path.GetFileName(hold.File)).Append(',')
                .Append(r.Count.ToString(CultureInfo.InvariantCulture)).Append(',')
                .Append(r.Duration.ToString("R", CultureInfo.InvariantCulture)).Append(',')
                .Append(last.MassKg.ToString("R", CultureInfo.InvariantCulture)).Append(',')
                .Append(SafeName(last.Profile)).Append(',')
                .Append(last.StandardSpeed.ToString("R", CultureInfo.InvariantCulture)).Append(',')
                .Append(hold.StartedAt.ToString("R", CultureInfo.InvariantCulture)).Append('\n');
            try
            {
                AtomicFile.WriteAllText(Path.Combine(EnsureSessionFolder(), "holds.csv"), _index.ToString());
            }
            catch (Exception e) when (e is IOException || e is UnauthorizedAccessException || e is ArgumentException || e is NotSupportedException)
            {
                _lastError = "Session recorder: holds.csv was not written: " + e.Message;
                Debug.LogError(_lastError, this);
            }
        }

        string EnsureSessionFolder()
        {
            if (_sessionFolder != null) return _sessionFolder;
            if (string.IsNullOrWhiteSpace(_sessionId)) _sessionId = DateTime.Now.ToString("yyyyMMdd-HHmmss", CultureInfo.InvariantCulture);
            _sessionFolder = Path.Combine(Folder, SafeName(_sessionId));
            Directory.CreateDirectory(_sessionFolder);
            return _sessionFolder;
        }

        /// <summary>
        /// A name fit for a file name and a CSV field: letters, digits, '-', '_' and '.' are kept, anything else
        /// (spaces, commas, slashes) becomes '_', and a leading '.' too (no hidden files, no "..").
        /// </summary>
        public static string SafeName(string name)
        {
            if (string.IsNullOrEmpty(name)) return "object";
            var sb = new StringBuilder(name.Length);
            foreach (char ch in name)
                sb.Append((ch < 128 && char.IsLetterOrDigit(ch)) || ch == '-' || ch == '_' || (ch == '.' && sb.Length > 0) ? ch : '_');
            return sb.ToString();
        }
    }
}
