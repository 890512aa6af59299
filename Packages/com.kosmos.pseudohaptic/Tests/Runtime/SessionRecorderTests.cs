using System;
using System.Collections.Generic;
using System.IO;
using Kosmos.PseudoHaptic.Simulation;
using NUnit.Framework;
using UnityEngine;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>Holds recorded through <see cref="SessionRecorder"/>: one replay-format CSV per hold, an index, partial writes.</summary>
    public sealed class SessionRecorderTests : PlayModeFixture
    {
        string _folder;

        [SetUp]
        public void UseTemporaryFolder()
        {
            _folder = Path.Combine(Path.GetTempPath(), "kosmos-pseudohaptic-sessions-" + Guid.NewGuid().ToString("N"));
        }

        [TearDown]
        public void RemoveTemporaryFolder()
        {
            if (Directory.Exists(_folder)) Directory.Delete(_folder, true);
        }

        SessionRecorder _recorder;

        SessionRecorder Recorder(string session = "P1")
        {
            var recorder = Track(new GameObject("Session Recorder")).AddComponent<SessionRecorder>();
            recorder.Folder = _folder;
            recorder.SessionId = session;
            return _recorder = recorder;
        }

        /// <summary>Waits for the recorder's background writer, as a pause or a later frame's Update would deliver it.</summary>
        void Saved() => Assert.That(_recorder.WaitForSaves(), Is.True, _recorder.LastError);

        static HoldRecording Read(string path)
        {
            using (var reader = new StreamReader(path)) return HoldRecording.ReadCsv(reader, path);
        }

        /// <summary>The steps <see cref="PlayModeFixture.Lift"/> takes, computed as it computes them.</summary>
        static int Frames(float duration, float hold) => Mathf.CeilToInt((duration + hold) / FrameTime);

        [Test]
        public void EachHoldIsWrittenWhenItEndsAsAReplayTraceWithOneRowPerFrame()
        {
            SessionRecorder recorder = Recorder();
            var written = new List<string>();
            recorder.HoldWritten += written.Add;
            PseudoHapticWeight box = Box("Box B", 1.5f);

            float y = Lift(box, 0.3f, 0.8f, 0.3f);
            Assert.That(written, Is.Empty, "nothing is written during the hold");
            box.EndHold(); Saved();

            string path = Path.Combine(_folder, "P1", "hold-001-Box_B.csv");
            Assert.That(written, Is.EqualTo(new[] { path }));
            Assert.That(File.ReadAllText(path), Does.StartWith("t,hand_y,tracked,pose_t,object_y,mass_kg,profile"));
            HoldRecording r = Read(path);
            Assert.That(r.Count, Is.EqualTo(1 + Frames(0.8f, 0.3f)), "the begin frame and one row per step");
            Assert.That(r[0].Time, Is.EqualTo(0));
            Assert.That(r[r.Count - 1].ObjectY, Is.EqualTo(y).Within(1e-6), "the object's height as it was written");
            Assert.That(r[r.Count - 1].HandY, Is.EqualTo(0.3).Within(1e-5));
            Assert.That(r[1].MassKg, Is.EqualTo(1.5).Within(1e-6));
            Assert.That(r[1].Profile, Is.EqualTo(NamedProfiles.PaperName));
            Assert.That(r.Duration, Is.EqualTo(Frames(0.8f, 0.3f) * FrameTime).Within(1e-4));

            string[] index = File.ReadAllLines(Path.Combine(_folder, "P1", "holds.csv"));
            Assert.That(index[0], Is.EqualTo(SessionRecorder.IndexHeader));
            Assert.That(index[1], Does.StartWith("1,Box_B,hold-001-Box_B.csv," + r.Count + ","));
            Assert.That(recorder.ActiveCount, Is.EqualTo(0));
        }

        [Test]
        public void TheRecordedHandReplaysToTheRecordedObject()
        {
            Recorder();
            PseudoHapticWeight box = Box("box", 2f);
            box.ExplicitStandardSpeed = 0.5f;
            Lift(box, 0.3f, 0.8f);
            box.EndHold(); Saved();
            HoldRecording r = Read(Path.Combine(_folder, "P1", "hold-001-box.csv"));
            double[] replayed = TraceReplay.Run(new WeightSolver(WeightModel.FromMass(2.0), NamedProfiles.Paper, 0.5), r.ToTrace());
            for (int i = 0; i < r.Count; i++) Assert.That(replayed[i], Is.EqualTo(r[i].ObjectY).Within(1e-6), "frame " + i);
        }

        [Test]
        public void HoldsAreNumberedAndOnlyTheListedObjectsRecorded()
        {
            SessionRecorder recorder = Recorder("S 1");
            PseudoHapticWeight a = Box("a", 0.5f, new Vector3(-0.3f, 0, 0));
            PseudoHapticWeight b = Box("b", 0.5f, new Vector3(0.3f, 0, 0));
            Lift(a, 0.1f, 0.3f); a.EndHold(); Saved();
            Lift(b, 0.1f, 0.3f); b.EndHold(); Saved();
            Lift(a, 0.1f, 0.3f); a.EndHold(); Saved();
            string folder = Path.Combine(_folder, "S_1");
            Assert.That(File.Exists(Path.Combine(folder, "hold-001-a.csv")), Is.True);
            Assert.That(File.Exists(Path.Combine(folder, "hold-002-b.csv")), Is.True);
            Assert.That(File.Exists(Path.Combine(folder, "hold-003-a.csv")), Is.True);
            Assert.That(File.ReadAllLines(Path.Combine(folder, "holds.csv")), Has.Length.EqualTo(4));

            recorder.Objects = new[] { b };
            Lift(a, 0.1f, 0.3f); a.EndHold(); Saved();
            Assert.That(recorder.HoldCount, Is.EqualTo(3), "a is not listed");
        }

        [Test]
        public void AHoldRunningAtAPauseIsWrittenAsFarAsItGotThenWhole()
        {
            SessionRecorder recorder = Recorder();
            PseudoHapticWeight box = Box("box", 1f);
            Lift(box, 0.2f, 0.5f, 0f);
            int sofar = 1 + Frames(0.5f, 0f);
            recorder.FlushActive(); // what OnApplicationPause(true) and OnApplicationQuit do
            string path = Path.Combine(_folder, "P1", "hold-001-box.csv");
            Assert.That(Read(path).Count, Is.EqualTo(sofar));
            Assert.That(File.Exists(Path.Combine(_folder, "P1", "holds.csv")), Is.False, "the hold is not over");

            box.Step(box.transform.position, true, true, double.NaN, FrameTime);
            box.EndHold(); Saved();
            Assert.That(Read(path).Count, Is.EqualTo(sofar + 1));
            Assert.That(Directory.GetFiles(Path.Combine(_folder, "P1")), Has.Length.EqualTo(3), "the hold, the index and the session's id; no temporary file");
        }

        [Test]
        public void DisablingTheRecorderWritesTheRunningHoldAndStopsRecording()
        {
            SessionRecorder recorder = Recorder();
            PseudoHapticWeight box = Box("box", 1f);
            Lift(box, 0.2f, 0.5f, 0f);
            recorder.enabled = false;
            string path = Path.Combine(_folder, "P1", "hold-001-box.csv");
            int count = Read(path).Count;
            box.Step(box.transform.position, true, true, double.NaN, FrameTime);
            box.EndHold(); Saved();
            Assert.That(Read(path).Count, Is.EqualTo(count));
        }

        [Test]
        public void AnUntrackedFrameIsRecordedWithoutAHandHeight()
        {
            Recorder();
            PseudoHapticWeight box = Box("box", 1f);
            Assert.That(box.BeginHold(box.transform.position), Is.True);
            box.Step(box.transform.position + Vector3.up * 0.01f, false, false, double.NaN, FrameTime);
            box.EndHold(); Saved();
            HoldRecording r = Read(Path.Combine(_folder, "P1", "hold-001-box.csv"));
            Assert.That(r.Count, Is.EqualTo(2));
            Assert.That(r[1].Tracked, Is.False);
            Assert.That(double.IsNaN(r[1].HandY), Is.True);
            Assert.That(r[1].Time, Is.EqualTo(FrameTime).Within(1e-7));
        }
    }
}
