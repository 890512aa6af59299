using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using Kosmos.PseudoHaptic.Evaluation;
using Kosmos.PseudoHaptic.Simulation;
using NUnit.Framework;
#if UNITY_5_3_OR_NEWER
using UnityEngine.TestTools.Constraints; // AllocatingGCMemory() is an extension method there
// That namespace has its own Is (deriving from NUnit's): without this alias every plain Is is ambiguous (CS0104).
using Is = NUnit.Framework.Is;
#endif

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>The session recorder's buffering and files, fed by holds of scripted Quest hands (what the play-mode tests assert, run here).</summary>
    public sealed class SessionLogTests
    {
        string _folder;

        [SetUp]
        public void UseTemporaryFolder() => _folder = Path.Combine(Path.GetTempPath(), "kosmos-pseudohaptic-log-" + Guid.NewGuid().ToString("N"));

        [TearDown]
        public void RemoveTemporaryFolder()
        {
            if (Directory.Exists(_folder)) Directory.Delete(_folder, true);
        }

        SessionLog Log(string session = "P1") => new SessionLog { Folder = _folder, SessionId = session };

        /// <summary>A box held by one scripted hand whose hold events feed <paramref name="log"/>, as SessionRecorder wires them.</summary>
        static BoxScene.Box Wired(SessionLog log, string name, double massKg)
        {
            var box = new BoxScene.Box(new Vector3d(0, 0.8, 0), massKg);
            box.Hold.Began += () => { HandSample h = box.Hold.LastHand; log.Began(box, name, box.Hold.Solver, in h, 12.5); };
            box.Hold.Stepped += () => { HandSample h = box.Hold.LastHand; log.Stepped(box, box.Hold.Solver, in h, box.Hold.LastDeltaTime); };
            box.Hold.Ended += () => log.Ended(box);
            return box;
        }

        /// <summary>Begins a hold and steps it through a 30 Hz, 45 ms late lift; returns the frames stepped and the last height.</summary>
        static (int frames, double y) Lift(BoxScene.Box box, double rise, double seconds, double lostFrom = -1)
        {
            var hand = new QuestHand { Path = QuestHand.Lift(box.Position, rise, 0.1, seconds - 0.2) };
            if (lostFrom >= 0) hand.Lose(lostFrom, 0.1);
            HandFrame[] frames = hand.Render(seconds);
            box.Hold.Begin(1, box.Position, double.NaN, box.Position, box.Position.Y);
            double y = double.NaN;
            foreach (HandFrame f in frames) y = box.Hold.Step(1, f.Position, f.Tracked, f.HighConfidence, double.NaN, f.Dt);
            return (frames.Length, y);
        }

        /// <summary>A 1 kg solver holding at 0.8 m and the resting hand it holds with: for driving the log directly.</summary>
        static (WeightSolver solver, HandSample hand) HeldAtRest()
        {
            var solver = Run.Solver(1);
            solver.BeginHold(0.8, 0.8);
            return (solver, new HandSample(0.8));
        }

        static HoldRecording Read(string path)
        {
            using (var reader = new StreamReader(path)) return HoldRecording.ReadCsv(reader, path);
        }

        /// <summary>
        /// What the recorder reports written is on the device: the hold file's temporary copy is synced once, by its writer,
        /// before the rename that makes it the hold file, and the folder after (strace attached to this process,
        /// <see cref="SelfTrace"/>; Linux with strace, ignored elsewhere). The tool's DurabilityTests check the same in a child
        /// process; this one sees the recorder's own code, in the process that runs it.
        /// </summary>
        [Test]
        public void AHoldFileIsSyncedOnceBeforeItsRenameAndItsFolderAfter()
        {
            SessionLog log = Log();
            BoxScene.Box box = Wired(log, "Box B", 1.5);
            Lift(box, 0.3, 1.1);
            string folder = Path.Combine(_folder, "P1"), path = Path.Combine(folder, "hold-001-Box_B.csv");
            Directory.CreateDirectory(_folder);
            List<string> calls = SelfTrace.CallsUnder(() => box.Hold.End(1), _folder, "fsync,fdatasync,rename,renameat,renameat2", folder);
            Assert.That(File.Exists(path), Is.True);

            string all = string.Join("\n", calls);
            int renamed = calls.FindIndex(c => c.StartsWith("rename ", StringComparison.Ordinal) && c.EndsWith(" -> " + path, StringComparison.Ordinal));
            Assert.That(renamed, Is.GreaterThanOrEqualTo(0), "the hold file's rename: " + all);
            string temp = calls[renamed].Substring(7, calls[renamed].IndexOf(" -> ", StringComparison.Ordinal) - 7);
            var syncs = new List<int>();
            for (int i = 0; i < calls.Count; i++)
                if (calls[i] == "fsync " + temp || calls[i] == "fdatasync " + temp) syncs.Add(i);
            Assert.That(syncs.Count, Is.EqualTo(1), "syncs of " + temp + ": " + all);
            Assert.That(syncs[0], Is.LessThan(renamed), "synced before its rename");
            Assert.That(calls.FindIndex(renamed + 1, c => c == "fsync " + folder || c == "fdatasync " + folder),
                Is.GreaterThan(renamed), "the folder synced after the rename: " + all);
        }

        [Test]
        public void EachHoldIsWrittenWhenItEndsAsAReplayTraceWithOneRowPerFrame()
        {
            SessionLog log = Log();
            var written = new List<string>();
            log.HoldWritten += written.Add;
            BoxScene.Box box = Wired(log, "Box B", 1.5);
            var (frames, y) = Lift(box, 0.3, 1.1);
            Assert.That(written, Is.Empty, "nothing is written during the hold");
            Assert.That(log.ActiveCount, Is.EqualTo(1));
            box.Hold.End(1);

            string path = Path.Combine(_folder, "P1", "hold-001-Box_B.csv");
            Assert.That(written, Is.EqualTo(new[] { path }));
            Assert.That(File.ReadAllText(path), Does.StartWith("t,hand_y,tracked,pose_t,object_y,mass_kg,profile"));
            HoldRecording r = Read(path);
            Assert.That(r.Count, Is.EqualTo(1 + frames), "the begin frame and one row per step");
            Assert.That(r[r.Count - 1].ObjectY, Is.EqualTo(y).Within(1e-12));
            Assert.That(r[1].MassKg, Is.EqualTo(1.5));
            Assert.That(r[1].Profile, Is.EqualTo(NamedProfiles.PaperName));
            string[] index = File.ReadAllLines(Path.Combine(_folder, "P1", "holds.csv"));
            Assert.That(index[0], Is.EqualTo(SessionLog.IndexHeader));
            Assert.That(index[1], Does.StartWith("1,Box_B,hold-001-Box_B.csv," + r.Count + ",").And.EndWith(",12.5"));
            Assert.That(log.ActiveCount, Is.EqualTo(0));
        }

        [Test]
        public void ASessionResumedInItsFolderRemovesTheTemporaryFilesAKillLeftThereAndNothingElse()
        {
            // A recorder killed in a hold's write left its temporary file; the session is resumed under the same id.
            string folder = Path.Combine(_folder, "P1");
            Directory.CreateDirectory(folder);
            File.WriteAllText(Path.Combine(folder, ".ph5eed5eed.tmp"), "t,hand_y,tr");
            File.WriteAllText(Path.Combine(folder, "notes.tmp"), "the experimenter's");
            File.WriteAllText(Path.Combine(folder, ".ph12345678.csv"), "not the recorder's");
            SessionLog log = Log();
            BoxScene.Box box = Wired(log, "box", 1);
            Lift(box, 0.2, 0.6);
            Assert.That(File.Exists(Path.Combine(folder, ".ph5eed5eed.tmp")), Is.True, "nothing is removed before the session writes into its folder");
            box.Hold.End(1);
            Assert.That(log.RemovedTemporaries, Is.EqualTo(1));
            var names = new List<string>();
            foreach (string f in Directory.GetFiles(folder)) names.Add(Path.GetFileName(f));
            names.Sort(StringComparer.Ordinal);
            Assert.That(names, Is.EqualTo(new[] { ".ph12345678.csv", "hold-001-box.csv", "holds.csv", "notes.tmp", SessionLog.OwnerFile }));

            // Only the first write into the folder looks: a leftover appearing later waits for the next session.
            File.WriteAllText(Path.Combine(folder, ".ph0000beef.tmp"), "");
            Lift(box, 0.2, 0.6);
            box.Hold.End(1);
            Assert.That(log.RemovedTemporaries, Is.EqualTo(1));
            Assert.That(File.Exists(Path.Combine(folder, ".ph0000beef.tmp")), Is.True);
        }

        [Test]
        public void TheRecordedHandReplaysToTheRecordedObject()
        {
            SessionLog log = Log();
            BoxScene.Box box = Wired(log, "box", 2);
            Lift(box, 0.3, 1.2, lostFrom: 0.5);
            box.Hold.End(1);
            HoldRecording r = Read(Path.Combine(_folder, "P1", "hold-001-box.csv"));
            double[] replayed = TraceReplay.Run(new WeightSolver(WeightModel.FromMass(2.0), NamedProfiles.Paper, 0.5), r.ToTrace());
            for (int i = 0; i < r.Count; i++) Assert.That(replayed[i], Is.EqualTo(r[i].ObjectY).Within(1e-9), "frame " + i);
            Assert.That(r[(int)(0.55 * 90)].Tracked, Is.False, "the loss is in the file");
        }

        [Test]
        public void HoldsAreNumberedPerSessionAndOnlyListedObjectsAreRecorded()
        {
            SessionLog log = Log("S 1");
            BoxScene.Box a = Wired(log, "a", 0.5), b = Wired(log, "b", 0.5);
            Lift(a, 0.1, 0.4); a.Hold.End(1);
            Lift(b, 0.1, 0.4); b.Hold.End(1);
            Lift(a, 0.1, 0.4); a.Hold.End(1);
            string folder = Path.Combine(_folder, "S_1");
            Assert.That(File.Exists(Path.Combine(folder, "hold-001-a.csv")) && File.Exists(Path.Combine(folder, "hold-002-b.csv")) && File.Exists(Path.Combine(folder, "hold-003-a.csv")), Is.True);
            Assert.That(File.ReadAllLines(Path.Combine(folder, "holds.csv")), Has.Length.EqualTo(4));
            Assert.That(SessionLog.IsListed(a, new object[] { b }), Is.False);
            Assert.That(SessionLog.IsListed(a, new object[0]), Is.True);
            Assert.That(SessionLog.IsListed(a, null), Is.True);
            log.SessionId = "S2";
            Lift(b, 0.1, 0.4); b.Hold.End(1);
            Assert.That(File.Exists(Path.Combine(_folder, "S2", "hold-001-b.csv")), Is.True, "a new session numbers from 1");
        }

        /// <summary>
        /// The app restarted (a crash, a power cut) and the session resumed under the same id: what was recorded stays, byte
        /// for byte; the index goes on from its last row and the numbering from the highest hold there, a hold flushed at a
        /// pause and never indexed included.
        /// </summary>
        [Test]
        public void ASessionResumedUnderItsIdKeepsItsHoldsAndNumbersOn()
        {
            SessionLog first = Log();
            BoxScene.Box box = Wired(first, "box", 1);
            Lift(box, 0.2, 0.6); box.Hold.End(1);
            Lift(box, 0.2, 0.6); box.Hold.End(1);
            string folder = Path.Combine(_folder, "P1");
            byte[] hold1 = File.ReadAllBytes(Path.Combine(folder, "hold-001-box.csv")), hold2 = File.ReadAllBytes(Path.Combine(folder, "hold-002-box.csv"));
            string[] index = File.ReadAllLines(Path.Combine(folder, "holds.csv"));
            Assert.That(index, Has.Length.EqualTo(3));

            SessionLog resumed = Log(); // the same id, after a restart
            BoxScene.Box again = Wired(resumed, "box", 2);
            Lift(again, 0.2, 0.6); again.Hold.End(1);
            Assert.That(File.ReadAllBytes(Path.Combine(folder, "hold-001-box.csv")), Is.EqualTo(hold1));
            Assert.That(File.ReadAllBytes(Path.Combine(folder, "hold-002-box.csv")), Is.EqualTo(hold2));
            Assert.That(Read(Path.Combine(folder, "hold-003-box.csv"))[1].MassKg, Is.EqualTo(2), "the resumed session's hold");
            string[] after = File.ReadAllLines(Path.Combine(folder, "holds.csv"));
            Assert.That(after.Take(3), Is.EqualTo(index), "the index's rows kept as they were");
            Assert.That(after, Has.Length.EqualTo(4));
            Assert.That(after[3], Does.StartWith("3,box,hold-003-box.csv,"));
            Assert.That(resumed.HoldCount, Is.EqualTo(3));

            // A hold flushed at a pause, then the power went: its file is there, its index row never was.
            SessionLog paused = Log();
            BoxScene.Box held = Wired(paused, "box", 1);
            Lift(held, 0.2, 0.6);
            paused.FlushActive();
            Assert.That(File.Exists(Path.Combine(folder, "hold-004-box.csv")), Is.True);
            SessionLog afterPowerCut = Log();
            BoxScene.Box last = Wired(afterPowerCut, "box", 1);
            Lift(last, 0.2, 0.6); last.Hold.End(1);
            Assert.That(File.Exists(Path.Combine(folder, "hold-005-box.csv")), Is.True, "numbered after the flushed hold, not over it");
            Assert.That(File.ReadAllLines(Path.Combine(folder, "holds.csv")).Skip(1).Select(l => l.Split(',')[0]), Is.EqualTo(new[] { "1", "2", "3", "5" }));
        }

        /// <summary>
        /// Two participants whose ids make one safe name ("P 1" and "P_1"; "P1" and "p1" on a Quest's storage, which ignores
        /// case) had one folder: their holds were numbered on in it, one index listing both, and nothing told whose a hold
        /// was. Each session folder records its id now, and the second id takes the name with "-2"; both resume in their own.
        /// </summary>
        [Test]
        public void TwoIdsWithOneSafeNameKeepTheirOwnFoldersAndEachResumesInItsOwn()
        {
            SessionLog log = Log("P_1");
            BoxScene.Box box = Wired(log, "box", 1);
            Lift(box, 0.2, 0.6); box.Hold.End(1);
            log.SessionId = "P 1"; // the next participant, on the same log
            Lift(box, 0.2, 0.6); box.Hold.End(1);
            string first = Path.Combine(_folder, "P_1"), second = Path.Combine(_folder, "P_1-2");
            Assert.That(log.SessionFolder, Is.EqualTo(second));
            Assert.That(File.ReadAllText(Path.Combine(first, SessionLog.OwnerFile)), Is.EqualTo("P_1"));
            Assert.That(File.ReadAllText(Path.Combine(second, SessionLog.OwnerFile)), Is.EqualTo("P 1"));
            Assert.That(File.ReadAllLines(Path.Combine(first, "holds.csv")), Has.Length.EqualTo(2), "P_1's one hold");
            Assert.That(File.Exists(Path.Combine(second, "hold-001-box.csv")), Is.True, "P 1 numbered from 1 in its own folder");

            // After a restart, in the other order: each finds its own folder and numbers on there.
            SessionLog again = Log("P 1");
            BoxScene.Box b = Wired(again, "box", 1);
            Lift(b, 0.2, 0.6); b.Hold.End(1);
            Assert.That(File.Exists(Path.Combine(second, "hold-002-box.csv")), Is.True);
            again.SessionId = "P_1";
            Lift(b, 0.2, 0.6); b.Hold.End(1);
            Assert.That(File.Exists(Path.Combine(first, "hold-002-box.csv")), Is.True);
            Assert.That(Directory.GetDirectories(_folder), Has.Length.EqualTo(2));

            // A folder written before folders recorded their ids (no owner file) is the first id's that finds it.
            string legacy = Path.Combine(_folder, "Q_7");
            Directory.CreateDirectory(legacy);
            File.WriteAllText(Path.Combine(legacy, "hold-001-box.csv"), "t,hand_y\n");
            SessionLog old = Log("Q 7");
            BoxScene.Box c = Wired(old, "box", 1);
            Lift(c, 0.2, 0.6); c.Hold.End(1);
            Assert.That(old.SessionFolder, Is.EqualTo(legacy));
            Assert.That(File.Exists(Path.Combine(legacy, "hold-002-box.csv")), Is.True, "numbered on");
            Assert.That(File.ReadAllText(Path.Combine(legacy, SessionLog.OwnerFile)), Is.EqualTo("Q 7"), "and claimed");

            // "p1" begun while "P1"'s first hold runs (its folder not yet written): on a Quest's storage, which ignores case,
            // the two would be one folder, each numbering from 1 over the other's files.
            SessionLog cased = Log("P1");
            BoxScene.Box held = Wired(cased, "box", 1);
            Lift(held, 0.2, 0.6); // still held: nothing written yet
            cased.SessionId = "p1";
            BoxScene.Box other = Wired(cased, "box", 1);
            Lift(other, 0.2, 0.6);
            Assert.That(Path.GetFileName(cased.SessionFolder), Is.EqualTo("p1-2"));
            held.Hold.End(1);
            other.Hold.End(1);
        }

        /// <summary>
        /// The index the session resumes on as it is: one edited without a final line end gets the next row on a line of its
        /// own; an empty one is started again; rows whose hold files were removed still count (no number is used twice in it).
        /// </summary>
        [Test]
        public void AResumedIndexKeepsItsRowsApartAndItsNumbersUnique()
        {
            string folder = Path.Combine(_folder, "P1");
            Directory.CreateDirectory(folder);
            string index = Path.Combine(folder, "holds.csv");
            File.WriteAllText(index, SessionLog.IndexHeader + "\n1,box,hold-001-box.csv,10,0.1,1,paper,0.5,1\n7,box,hold-007-box.csv,10,0.1,1,paper,0.5,2");
            SessionLog log = Log();
            BoxScene.Box box = Wired(log, "box", 1);
            Lift(box, 0.2, 0.6); box.Hold.End(1);
            string[] rows = File.ReadAllLines(index);
            Assert.That(rows, Has.Length.EqualTo(4), "the new row on a line of its own");
            Assert.That(rows[2], Does.EndWith(",0.5,2"));
            Assert.That(rows[3], Does.StartWith("8,box,hold-008-box.csv,"), "after the index's highest number, its file gone or not");

            File.WriteAllText(index, "");
            SessionLog again = Log();
            BoxScene.Box other = Wired(again, "box", 1);
            Lift(other, 0.2, 0.6); other.Hold.End(1);
            rows = File.ReadAllLines(index);
            Assert.That(rows[0], Is.EqualTo(SessionLog.IndexHeader), "an empty index starts again with its header");
            Assert.That(rows[1], Does.StartWith("9,box,hold-009-box.csv,"), "after the files there (hold-008)");
        }

        [Test]
        public void AHoldRunningAtAPauseIsWrittenAsFarAsItGotThenWhole()
        {
            SessionLog log = Log();
            BoxScene.Box box = Wired(log, "box", 1);
            var (frames, _) = Lift(box, 0.2, 0.6);
            log.FlushActive();
            string path = Path.Combine(_folder, "P1", "hold-001-box.csv");
            Assert.That(Read(path).Count, Is.EqualTo(1 + frames));
            Assert.That(File.Exists(Path.Combine(_folder, "P1", "holds.csv")), Is.False, "the hold is not over");
            box.Hold.Step(1, box.Position, true, true, double.NaN, 1 / 90.0);
            box.Hold.End(1);
            Assert.That(Read(path).Count, Is.EqualTo(2 + frames));
            Assert.That(Directory.GetFiles(Path.Combine(_folder, "P1")), Has.Length.EqualTo(3), "the hold, the index and the session's id; no temporary file");
        }

        [Test]
        public void FinishingAllWritesTheRunningHoldsAndStopsRecordingThem()
        {
            SessionLog log = Log();
            BoxScene.Box a = Wired(log, "a", 1), b = Wired(log, "b", 1);
            Lift(a, 0.2, 0.4);
            Lift(b, 0.2, 0.4);
            Assert.That(log.ActiveCount, Is.EqualTo(2), "two hands, two holds");
            log.FinishAll();
            int count = Read(Path.Combine(_folder, "P1", "hold-001-a.csv")).Count;
            a.Hold.Step(1, a.Position, true, true, double.NaN, 1 / 90.0);
            a.Hold.End(1);
            Assert.That(Read(Path.Combine(_folder, "P1", "hold-001-a.csv")).Count, Is.EqualTo(count));
            Assert.That(File.ReadAllLines(Path.Combine(_folder, "P1", "holds.csv")), Has.Length.EqualTo(3));
        }

        [Test]
        public void AFolderThatCannotBeWrittenIsReportedNotThrown()
        {
            string blocker = Path.Combine(Path.GetTempPath(), "kosmos-pseudohaptic-file-" + Guid.NewGuid().ToString("N"));
            File.WriteAllText(blocker, "a file where the folder should be");
            try
            {
                var log = new SessionLog { Folder = blocker, SessionId = "P1" };
                string failed = null;
                log.WriteFailed += m => failed = m;
                BoxScene.Box box = Wired(log, "box", 1);
                Lift(box, 0.1, 0.3);
                Assert.That(() => box.Hold.End(1), Throws.Nothing);
                Assert.That(log.LastError, Does.Contain("hold 1 of 'box' was not written"));
                Assert.That(failed, Is.EqualTo(log.LastError));
            }
            finally
            {
                File.Delete(blocker);
            }
        }

        [Test]
        public void AHoldThatCannotBeWrittenIsKeptAndWrittenOnceByTheRetry()
        {
            double now = 0;
            string blocker = Path.Combine(Path.GetTempPath(), "kosmos-pseudohaptic-file-" + Guid.NewGuid().ToString("N"));
            File.WriteAllText(blocker, "a file where the folder should be");
            try
            {
                var log = new SessionLog(saver: new SaveQueue(background: false, retrySeconds: 1, clock: () => now)) { Folder = blocker, SessionId = "P1" };
                var written = new List<string>();
                log.HoldWritten += written.Add;
                BoxScene.Box box = Wired(log, "box", 1);
                int frames = Lift(box, 0.1, 0.3).frames;
                box.Hold.End(1);
                Assert.That(log.LastError, Does.Contain("hold 1 of 'box' was not written"));
                Assert.That(log.PendingWrites, Is.EqualTo(1), "kept");
                Lift(box, 0.2, 0.5); // a second hold meanwhile: its buffer is another one
                box.Hold.End(1);
                File.Delete(blocker);
                now = 1;
                log.Pump();
                Assert.That(log.LastError, Is.Null);
                Assert.That(log.PendingWrites, Is.Zero);
                Assert.That(written, Has.Count.EqualTo(2));
                Assert.That(Read(written[0]).Count, Is.EqualTo(1 + frames), "the first hold as it was recorded (its begin frame and each step)");
                string[] index = File.ReadAllLines(Path.Combine(blocker, "P1", "holds.csv"));
                Assert.That(index, Has.Length.EqualTo(3), "the header and each hold once");
                Assert.That(index[1], Does.StartWith("1,box,"));
                Assert.That(index[2], Does.StartWith("2,box,"));
            }
            finally
            {
                if (File.Exists(blocker)) File.Delete(blocker);
                else if (Directory.Exists(blocker)) Directory.Delete(blocker, true);
            }
        }

        [Test]
        public void RecordingAFrameAllocatesNothing()
        {
            // Within its buffer (a hold of 200 000 frames here; 5400, one minute at 90 Hz, by default).
            var log = new SessionLog(framesPerHold: 210000) { Folder = _folder, SessionId = "P1" };
            var (solver, hand) = HeldAtRest();
            object key = new object();
            log.Began(key, "box", solver, in hand, 0);
            Frames(log, key, solver, 1000);
#if UNITY_5_3_OR_NEWER
            Assert.That(() => Frames(log, key, solver, 10000), UnityEngine.TestTools.Constraints.Is.Not.AllocatingGCMemory());
#else
            // Fewer bytes than frames: any allocation per frame (24 bytes at least) fails; the runtime's one-off
            // re-compilation of the hot loop, which lands on this thread now and then, does not.
            long before = GC.GetAllocatedBytesForCurrentThread();
            Frames(log, key, solver, 100000);
            Assert.That(GC.GetAllocatedBytesForCurrentThread() - before, Is.LessThan(100000), "bytes allocated over 100 000 frames");
#endif
        }

        static void Frames(SessionLog log, object key, WeightSolver solver, int n)
        {
            var hand = new HandSample(0.8);
            for (int i = 0; i < n; i++) log.Stepped(key, solver, in hand, 1 / 90.0);
        }

        [Test]
        public void SafeNamesKeepFilesAndCsvFieldsIntact()
        {
            Assert.That(SessionLog.SafeName("Box B, heavy/1"), Is.EqualTo("Box_B__heavy_1"));
            Assert.That(SessionLog.SafeName("..hidden"), Is.EqualTo("_.hidden"));
            Assert.That(SessionLog.SafeName(""), Is.EqualTo("object"));
        }

        // Issue 35 (logic-session survivors): the defaults, the guards and the files a study relies on.

        [Test]
        public void ALogWithoutASessionIdNamesItsSessionByTheLocalDateAndTimeOfItsFirstHold()
        {
            var unset = new SessionLog();
            Assert.That(unset.Folder, Is.Empty, "no folder until one is set");
            unset.Folder = null;
            Assert.That(unset.Folder, Is.Empty, "null is no folder");
            foreach (bool setToNull in new[] { false, true })
            {
                var log = new SessionLog { Folder = Path.Combine(_folder, setToNull ? "null" : "unset") };
                if (setToNull) log.SessionId = null;
                Assert.That(log.SessionId, Is.Empty);
                BoxScene.Box box = Wired(log, "box", 1);
                DateTime before = DateTime.Now.AddSeconds(-1);
                Lift(box, 0.1, 0.3);
                box.Hold.End(1);
                DateTime after = DateTime.Now.AddSeconds(1);
                string name = Path.GetFileName(log.SessionFolder);
                Assert.That(name, Does.Match(@"^\d{8}-\d{6}$"), "yyyyMMdd-HHmmss");
                DateTime at = DateTime.ParseExact(name, "yyyyMMdd-HHmmss", System.Globalization.CultureInfo.InvariantCulture);
                Assert.That(at, Is.InRange(before, after));
                Assert.That(log.SessionId, Is.EqualTo(name));
                Assert.That(File.Exists(Path.Combine(log.SessionFolder, "hold-001-box.csv")), Is.True);
            }
        }

        [Test]
        public void AnObjectAnywhereOnTheListIsRecorded()
        {
            object a = new object(), b = new object(), c = new object();
            Assert.That(SessionLog.IsListed(a, new[] { a, b }), Is.True);
            Assert.That(SessionLog.IsListed(b, new[] { a, b }), Is.True);
            Assert.That(SessionLog.IsListed(c, new[] { a, b }), Is.False);
        }

        [Test]
        public void AHoldWithoutAnObjectOrASolverIsNotRecordedAndABeginWithoutAnEndKeepsTheFirstHold()
        {
            SessionLog log = Log();
            var (solver, hand) = HeldAtRest();
            log.Began(null, "box", solver, in hand, 0);
            log.Began(new object(), "box", null, in hand, 0);
            Assert.That(log.ActiveCount, Is.Zero);
            Assert.That(log.HoldCount, Is.Zero);

            object key = new object();
            log.Began(key, "box", solver, in hand, 0);
            Frames(log, key, solver, 10);
            log.Began(key, "box", solver, in hand, 1); // its end was missed
            Assert.That(log.ActiveCount, Is.EqualTo(1));
            Assert.That(Read(Path.Combine(_folder, "P1", "hold-001-box.csv")).Count, Is.EqualTo(11), "the first hold as far as it got");
            log.Ended(key);
            Assert.That(Read(Path.Combine(_folder, "P1", "hold-002-box.csv")).Count, Is.EqualTo(1));
            Assert.That(log.ActiveCount, Is.Zero);
        }

        [Test]
        public void ThreeObjectsHeldAtOnceAreAllRecorded()
        {
            SessionLog log = Log();
            var (solver, hand) = HeldAtRest();
            var keys = new[] { new object(), new object(), new object() };
            for (int i = 0; i < keys.Length; i++) log.Began(keys[i], "o" + i, solver, in hand, 0);
            for (int i = 0; i < keys.Length; i++) Frames(log, keys[i], solver, 5 + i);
            Assert.That(log.ActiveCount, Is.EqualTo(3));
            foreach (object key in keys) log.Ended(key);
            for (int i = 0; i < keys.Length; i++)
                Assert.That(Read(Path.Combine(_folder, "P1", "hold-00" + (i + 1) + "-o" + i + ".csv")).Count, Is.EqualTo(6 + i));
        }

        [Test]
        public void HoldsOfTwoHandsTakeTheReadyBuffersAndLaterHoldsReuseThem()
        {
            // A frame buffer is about a megabyte here (20 000 frames): beginning a hold must not allocate one, neither for the
            // first two holds (two hands) nor for later ones once the earlier ones are written.
            var log = new SessionLog(framesPerHold: 20000) { Folder = _folder, SessionId = "P1" };
            var (solver, hand) = HeldAtRest();
            object a = new object(), b = new object();
            var warm = new SessionLog { Folder = _folder, SessionId = "warm-up" }; // the runtime compiles Began once, outside the count
            warm.Began(a, "a", solver, in hand, 0);
            for (int round = 0; round < 2; round++)
            {
                long before = Allocated();
                log.Began(a, "a", solver, in hand, 0);
                log.Began(b, "b", solver, in hand, 0);
                Assert.That(Allocated() - before, Is.LessThan(100000), "bytes allocated by two begins, round " + round);
                log.Ended(a);
                log.Ended(b);
            }
            Assert.That(log.HoldCount, Is.EqualTo(4));
        }

        // The GC's per-thread counter under the .NET SDK; in the editor (Mono) the heap's size, which a buffer of a megabyte moves too.
#if UNITY_5_3_OR_NEWER
        static long Allocated() => GC.GetTotalMemory(false);
#else
        static long Allocated() => GC.GetAllocatedBytesForCurrentThread();
#endif

        [Test]
        public void AHoldFlushedAtAPauseEndsInItsOwnSessionsFileWhenTheSessionChangesMeanwhile()
        {
            SessionLog log = Log();
            BoxScene.Box box = Wired(log, "box", 1);
            var (frames, _) = Lift(box, 0.2, 0.6);
            log.FlushActive();
            log.SessionId = "P2"; // the experimenter starts the next participant before the hold ends
            box.Hold.Step(1, box.Position, true, true, double.NaN, 1 / 90.0);
            box.Hold.End(1);
            Assert.That(Read(Path.Combine(_folder, "P1", "hold-001-box.csv")).Count, Is.EqualTo(2 + frames), "the whole hold, where its first part is");
            Assert.That(File.ReadAllLines(Path.Combine(_folder, "P1", "holds.csv")), Has.Length.EqualTo(2));
            Assert.That(Directory.Exists(Path.Combine(_folder, "P2")), Is.False);
        }

        [Test]
        public void AHoldRunningWhenTheSessionChangesIsWrittenInTheSessionItBeganIn()
        {
            // P1 is still holding the box when the experimenter starts P2, whose first hold is of another box: each hold
            // lands in its own participant's folder as that session's hold 1, and neither overwrites the other.
            SessionLog log = Log();
            BoxScene.Box first = Wired(log, "box", 1);
            var (frames, _) = Lift(first, 0.2, 0.6);
            log.SessionId = "P2";
            BoxScene.Box second = Wired(log, "box", 2);
            var (secondFrames, _) = Lift(second, 0.1, 0.3);
            first.Hold.End(1);
            second.Hold.End(1);
            Assert.That(Read(Path.Combine(_folder, "P1", "hold-001-box.csv")).Count, Is.EqualTo(1 + frames), "P1's hold, in P1");
            Assert.That(Read(Path.Combine(_folder, "P2", "hold-001-box.csv")).Count, Is.EqualTo(1 + secondFrames), "P2's hold, in P2");
            Assert.That(File.ReadAllLines(Path.Combine(_folder, "P1", "holds.csv")), Has.Length.EqualTo(2));
            Assert.That(File.ReadAllLines(Path.Combine(_folder, "P2", "holds.csv")), Has.Length.EqualTo(2), "hold 1 listed once");
        }

        [Test]
        public void TheIndexRowHoldsTheLastFramesMassProfileAndSpeedExactlyAndFilesHaveNoByteOrderMark()
        {
            SessionLog log = Log();
            BoxScene.Box box = Wired(log, "Box B", 1.5);
            Lift(box, 0.3, 1.1);
            box.Hold.End(1);
            string path = Path.Combine(_folder, "P1", "hold-001-Box_B.csv");
            HoldRecording r = Read(path);
            RecordedFrame last = r[r.Count - 1];
            string[] row = File.ReadAllLines(Path.Combine(_folder, "P1", "holds.csv"))[1].Split(',');
            var inv = System.Globalization.CultureInfo.InvariantCulture;
            Assert.That(double.Parse(row[4], inv), Is.EqualTo(r.Duration), "duration_s");
            Assert.That(double.Parse(row[5], inv), Is.EqualTo(1.5), "mass_kg");
            Assert.That(row[6], Is.EqualTo(SessionLog.SafeName(last.Profile)).And.Not.Empty, "profile");
            Assert.That(double.Parse(row[7], inv), Is.EqualTo(last.StandardSpeed).And.GreaterThan(0), "standard_speed");
            Assert.That(double.Parse(row[8], inv), Is.EqualTo(12.5), "started_at_s");
            // The header's first bytes are the file's: a reader that does not strip a byte-order mark sees "t,".
            Assert.That(File.ReadAllBytes(path)[0], Is.EqualTo((byte)'t'));
            Assert.That(File.ReadAllBytes(Path.Combine(_folder, "P1", "holds.csv"))[0], Is.EqualTo((byte)'h'));
        }

        [Test]
        public void AnIndexThatCannotBeWrittenIsReportedAndTheHoldIsStillWritten()
        {
            Directory.CreateDirectory(Path.Combine(_folder, "P1", "holds.csv")); // a folder where the index should be
            SessionLog log = Log();
            var written = new List<string>();
            log.HoldWritten += written.Add;
            BoxScene.Box box = Wired(log, "box", 1);
            Lift(box, 0.1, 0.3);
            Assert.That(() => box.Hold.End(1), Throws.Nothing);
            Assert.That(written, Is.EqualTo(new[] { Path.Combine(_folder, "P1", "hold-001-box.csv") }));
            Assert.That(log.LastError, Does.Contain("holds.csv was not written"));
        }
    }
}
