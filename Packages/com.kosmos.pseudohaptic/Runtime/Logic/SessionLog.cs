using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Text;
using Kosmos.PseudoHaptic.Evaluation;
using Kosmos.PseudoHaptic.Simulation;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// The session recorder's buffering and files, engine-free: each hold of a held object (the hand as the solver saw
    /// it, the object's height, mass, profile) goes frame by frame into a preallocated <see cref="HoldRecording"/>
    /// (two ready, for two hands; reused), and is written when the hold ends as one CSV in the replay trace format,
    /// <c>&lt;folder&gt;/&lt;session&gt;/hold-001-&lt;object&gt;.csv</c>, with an index <c>holds.csv</c> naming each
    /// hold's object, mass and profile. Files are written durably to a temporary name and renamed (<see cref="AtomicFile"/>)
    /// by one writer (<see cref="Saver"/>, in order; on a background thread in the headset; the first write into a session
    /// folder removes the temporary files a kill or a power cut left there), and a hold counts as saved
    /// (<see cref="HoldWritten"/>, its index row) only when its write returned, delivered on the main thread by
    /// <see cref="Pump"/>; a failed write is kept and tried again (<see cref="LastError"/> says so meanwhile), its buffer
    /// not reused until it is saved. <see cref="FlushActive"/> writes running holds as far as they got. Recording a frame
    /// allocates nothing (until a hold outgrows its buffer, which then doubles, or a hold ends while two others wait to be written).
    /// </summary>
    public sealed class SessionLog
    {
        /// <summary>The index's columns.</summary>
        public const string IndexHeader = "hold,object,file,frames,duration_s,mass_kg,profile,standard_speed,started_at_s";

        /// <summary>The file in a session folder that holds its session id, exactly (<see cref="OwnedName"/>).</summary>
        public const string OwnerFile = "session-id.txt";

        sealed class Hold
        {
            public object Key;
            public readonly HoldRecording Recording;
            public int Number;
            public string File, ObjectName, Folder, SessionId;
            public double StartedAt;
            public StringBuilder Index; // its session's index
            public Hold(int capacity) => Recording = new HoldRecording(capacity);
        }

        readonly List<Hold> _active = new List<Hold>(2);
        readonly Stack<Hold> _spare = new Stack<Hold>(2);
        StringBuilder _index = new StringBuilder();
        readonly int _capacity;
        string _folder = "", _sessionId = "", _sessionFolder;
        readonly object _openedLock = new object();
        string _openedFolder; // the session folder the writer last opened (and cleaned)
        // Session folders this log gave out, by path, with their ids: their owner files are written with the first hold, at its
        // end. Case ignored, as a Quest's shared storage ignores it: "p1" begun while "P1"'s first hold runs is another folder.
        readonly Dictionary<string, string> _given = new Dictionary<string, string>(StringComparer.OrdinalIgnoreCase);
        readonly Func<string, bool> _folderTaken;
        readonly Func<string, string> _folderOwner;

        /// <param name="saver">Writes the files; default one writing on the caller's thread (inside <see cref="Ended"/> and <see cref="Pump"/>). The headset passes a background one.</param>
        public SessionLog(int framesPerHold = HoldRecording.DefaultCapacity, SaveQueue saver = null)
        {
            _capacity = Math.Max(64, framesPerHold);
            for (int i = 0; i < 2; i++) _spare.Push(new Hold(_capacity)); // two hands
            Saver = saver ?? new SaveQueue(background: false);
            _folderTaken = FolderTaken;
            _folderOwner = FolderOwner;
        }

        /// <summary>The one writer of this log's files.</summary>
        public SaveQueue Saver { get; }

        /// <summary>Files written but not yet acknowledged (being written, or failed and waiting to be tried again).</summary>
        public int PendingWrites => Saver.Pending;

        /// <summary>Every frame (main thread): delivers finished writes (<see cref="HoldWritten"/>, index rows) and retries a failed one.</summary>
        public void Pump() => Saver.Pump();

        /// <summary>Waits up to <paramref name="timeoutMs"/> for the queued writes (a pause, quitting). True when nothing is left unwritten.</summary>
        public bool Drain(int timeoutMs = 5000) => Saver.Drain(timeoutMs);

        /// <summary>The folder sessions are written under (absolute).</summary>
        public string Folder { get => _folder; set { _folder = value ?? ""; _sessionFolder = null; } }

        /// <summary>
        /// The session's name (its folder); setting it starts a new session, numbered from 1, or, when its folder already
        /// holds recordings (the same id after a restart or a power cut), from the last of them: the holds and the index
        /// there are kept, the index goes on from its last row. Empty: the local date and time at the first hold.
        /// Two ids never share a folder: one whose safe name another id's folder has ("P 1" after "P_1", "p1" after "P1"
        /// where case is ignored) gets the name with "-2" (<see cref="OwnedName"/>, <see cref="OwnerFile"/>).
        /// </summary>
        public string SessionId
        {
            get => _sessionId;
            set
            {
                _sessionId = value ?? "";
                _sessionFolder = null;
                HoldCount = 0;
                _index = new StringBuilder(); // holds of the last session still being written keep theirs
            }
        }

        /// <summary>The folder this session writes into; null until its first hold begins.</summary>
        public string SessionFolder => _sessionFolder;
        /// <summary>The number of the last hold begun in this session's folder (holds found there when it resumed included).</summary>
        public int HoldCount { get; private set; }
        /// <summary>Objects being held and recorded now.</summary>
        public int ActiveCount => _active.Count;
        /// <summary>Leftover temporary files removed from session folders when this log first wrote into each (read from the writer; exact once <see cref="Drain"/> returned).</summary>
        public int RemovedTemporaries { get; private set; }
        /// <summary>The last write error, or null.</summary>
        public string LastError { get; private set; }

        /// <summary>Invoked with the file's path after a hold's file is written.</summary>
        public event Action<string> HoldWritten;
        /// <summary>Invoked with the message when a file could not be written.</summary>
        public event Action<string> WriteFailed;

        /// <summary>Whether <paramref name="item"/> is to be recorded: every item when <paramref name="only"/> is null or empty.</summary>
        public static bool IsListed<T>(T item, T[] only) where T : class
        {
            if (only == null || only.Length == 0) return true;
            for (int i = 0; i < only.Length; i++)
                if (ReferenceEquals(only[i], item)) return true;
            return false;
        }

        /// <summary>A hold of <paramref name="key"/> began (a begin without an end first finishes the old one).</summary>
        public void Began(object key, string objectName, WeightSolver solver, in HandSample hand, double startedAt)
        {
            if (key == null || solver == null) return;
            int at = IndexOf(key);
            if (at >= 0) Finish(at); // a begin without an end: keep what was recorded
            Hold hold = _spare.Count > 0 ? _spare.Pop() : new Hold(_capacity);
            hold.Key = key;
            hold.Folder = SessionFolderPath(); // first: a resumed session numbers on from the holds already there
            hold.SessionId = _sessionId;
            hold.Number = ++HoldCount;
            hold.ObjectName = objectName;
            hold.StartedAt = startedAt;
            // Its folder, file and index are the session's it begins in: a new SessionId while it runs (the next participant
            // started early) neither moves it nor lets it overwrite the new session's hold of the same number.
            Name(hold);
            hold.Recording.Begin(solver, in hand);
            _active.Add(hold);
        }

        /// <summary>One frame of <paramref name="key"/>'s hold; ignored when it is not being recorded.</summary>
        public void Stepped(object key, WeightSolver solver, in HandSample hand, double dt)
        {
            int at = IndexOf(key);
            if (at >= 0) _active[at].Recording.Step(solver, in hand, dt);
        }

        /// <summary><paramref name="key"/>'s hold ended: its file is written and indexed.</summary>
        public void Ended(object key)
        {
            int at = IndexOf(key);
            if (at >= 0) Finish(at);
        }

        /// <summary>
        /// Writes every running hold as far as it got (it goes on recording, and is written again at its end): its
        /// text is taken now, on this thread (a pause or quitting), and queued. Then <see cref="Drain"/> waits for it.
        /// </summary>
        public void FlushActive()
        {
            for (int i = 0; i < _active.Count; i++)
            {
                Hold hold = _active[i];
                string file = hold.File, folder = hold.Folder, owner = hold.SessionId, text = hold.Recording.ToCsv();
                int number = hold.Number;
                string objectName = hold.ObjectName;
                Saver.Enqueue(() => { OpenFolder(folder, owner); AtomicFile.WriteAllText(file, text); },
                    () => Written(file), e => NotWritten(number, objectName, e));
            }
            Saver.Pump();
        }

        /// <summary>Writes and ends every running hold (the recorder was disabled): later frames are not recorded.</summary>
        public void FinishAll()
        {
            for (int i = _active.Count - 1; i >= 0; i--) Finish(i);
        }

        int IndexOf(object key)
        {
            for (int i = 0; i < _active.Count; i++)
                if (ReferenceEquals(_active[i].Key, key)) return i;
            return -1;
        }

        void Finish(int at)
        {
            Hold hold = _active[at];
            _active.RemoveAt(at);
            hold.Key = null;
            // The recording is no longer touched here until its write is acknowledged: the writer reads it.
            Saver.Enqueue(() => WriteHold(hold), () => HoldSaved(hold), e => NotWritten(hold.Number, hold.ObjectName, e));
            Saver.Pump();
        }

        void Name(Hold hold)
        {
            hold.Index = _index;
            hold.File = Path.Combine(hold.Folder, "hold-" + hold.Number.ToString("000", CultureInfo.InvariantCulture) + "-" + SafeName(hold.ObjectName) + ".csv");
        }

        /// <summary>
        /// On the writer (the queue runs one write at a time): creates the session's folder, and the first time this log
        /// writes into a folder, removes the temporary files that a kill or a power cut left there
        /// (<see cref="AtomicFile.RemoveStaleTemporaries"/>: a session resumed under the same id) and records its owner
        /// when it records none (<see cref="OwnerFile"/>).
        /// </summary>
        void OpenFolder(string folder, string owner)
        {
            AtomicFile.CreateDirectory(folder);
            lock (_openedLock)
            {
                if (folder == _openedFolder) return;
                RemovedTemporaries += AtomicFile.RemoveStaleTemporaries(folder);
                string ownerFile = Path.Combine(folder, OwnerFile);
                if (!File.Exists(ownerFile)) AtomicFile.WriteAllText(ownerFile, owner);
                _openedFolder = folder;
            }
        }

        void WriteHold(Hold hold)
        {
            OpenFolder(hold.Folder, hold.SessionId);
            HoldRecording recording = hold.Recording;
            AtomicFile.Write(hold.File, synced: true, write: temp =>
            {
                using (var stream = new FileStream(temp, FileMode.CreateNew, FileAccess.Write, FileShare.None, 65536))
                {
                    using (var writer = new StreamWriter(stream, new UTF8Encoding(false), 65536, leaveOpen: true))
                        recording.WriteCsv(writer);
                    if (AtomicFile.Durable) AtomicFile.SyncStream(stream);
                }
            });
        }

        void HoldSaved(Hold hold)
        {
            Written(hold.File);
            AppendIndex(hold);
            hold.Recording.Clear();
            hold.File = null;
            hold.Index = null;
            _spare.Push(hold);
        }

        void Written(string file)
        {
            LastError = null;
            HoldWritten?.Invoke(file);
        }

        void NotWritten(int number, string objectName, string error) =>
            Fail("Session recorder: hold " + number + " of '" + objectName + "' was not written (kept; tried again): " + error);

        void AppendIndex(Hold hold)
        {
            HoldRecording r = hold.Recording;
            RecordedFrame last = r.Count > 0 ? r[r.Count - 1] : default;
            StringBuilder index = hold.Index;
            if (index.Length == 0) index.Append(IndexHeader).Append('\n');
            index.Append(hold.Number.ToString(CultureInfo.InvariantCulture)).Append(',')
                .Append(SafeName(hold.ObjectName)).Append(',')
                .Append(Path.GetFileName(hold.File)).Append(',')
                .Append(r.Count.ToString(CultureInfo.InvariantCulture)).Append(',')
                .Append(r.Duration.ToString("R", CultureInfo.InvariantCulture)).Append(',')
                .Append(last.MassKg.ToString("R", CultureInfo.InvariantCulture)).Append(',')
                .Append(SafeName(last.Profile)).Append(',')
                .Append(last.StandardSpeed.ToString("R", CultureInfo.InvariantCulture)).Append(',')
                .Append(hold.StartedAt.ToString("R", CultureInfo.InvariantCulture)).Append('\n');
            string path = Path.Combine(hold.Folder, "holds.csv"), text = index.ToString();
            Saver.Enqueue(() => AtomicFile.WriteAllText(path, text), () => LastError = null,
                e => Fail("Session recorder: holds.csv was not written (kept; tried again): " + e));
        }

        void Fail(string message)
        {
            LastError = message;
            WriteFailed?.Invoke(message);
        }

        string SessionFolderPath()
        {
            if (_sessionFolder != null) return _sessionFolder;
            if (string.IsNullOrWhiteSpace(_sessionId)) _sessionId = DateTime.Now.ToString("yyyyMMdd-HHmmss", CultureInfo.InvariantCulture);
            _sessionFolder = OwnedName.Find(Path.Combine(_folder, SafeName(_sessionId)), "", _sessionId, _folderTaken, _folderOwner);
            _given[_sessionFolder] = _sessionId;
            Resume(_sessionFolder);
            return _sessionFolder;
        }

        bool FolderTaken(string folder) => _given.ContainsKey(folder) || Directory.Exists(folder);

        /// <summary>The id a session folder records: the one this log gave it, else its <see cref="OwnerFile"/>'s (null when it has none or it cannot be read).</summary>
        string FolderOwner(string folder)
        {
            if (_given.TryGetValue(folder, out string id)) return id;
            try
            {
                string file = Path.Combine(folder, OwnerFile);
                return File.Exists(file) ? File.ReadAllText(file) : null;
            }
            catch (Exception e) when (e is IOException || e is UnauthorizedAccessException)
            {
                return null;
            }
        }

        /// <summary>
        /// Once per session folder, on the main thread (a listing and one small read when its first hold begins): the index
        /// already there is kept and goes on, and numbering goes on after the highest hold number in it or among the
        /// hold files (one flushed at a pause and never indexed included), so that nothing recorded before is overwritten.
        /// </summary>
        void Resume(string folder)
        {
            _index = new StringBuilder();
            HoldCount = 0;
            try
            {
                if (!Directory.Exists(folder)) return;
                string indexPath = Path.Combine(folder, "holds.csv");
                if (File.Exists(indexPath))
                {
                    string text = File.ReadAllText(indexPath);
                    _index.Append(text);
                    if (text.Length > 0 && text[text.Length - 1] != '\n') _index.Append('\n');
                    foreach (string line in text.Split('\n'))
                    {
                        int comma = line.IndexOf(',');
                        if (comma > 0 && int.TryParse(line.Substring(0, comma), NumberStyles.None, CultureInfo.InvariantCulture, out int n))
                            HoldCount = Math.Max(HoldCount, n);
                    }
                }
                foreach (string file in Directory.GetFiles(folder, "hold-*.csv"))
                {
                    string name = Path.GetFileName(file);
                    int end = name.IndexOf('-', 5);
                    if (end > 5 && int.TryParse(name.Substring(5, end - 5), NumberStyles.None, CultureInfo.InvariantCulture, out int n))
                        HoldCount = Math.Max(HoldCount, n);
                }
            }
            catch (Exception e) when (e is IOException || e is UnauthorizedAccessException)
            {
                Fail("Session recorder: the recordings already in " + folder + " could not be read (" + e.Message + "): later holds may replace them");
            }
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
