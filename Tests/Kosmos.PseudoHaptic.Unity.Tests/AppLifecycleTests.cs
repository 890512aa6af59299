using System;
using System.IO;
using Kosmos.PseudoHaptic.Evaluation;
using Kosmos.PseudoHaptic.Samples;
using NUnit.Framework;
using UnityDouble;
using UnityEngine;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>
    /// The application's messages reach <see cref="SaveLifecycle"/> in each study component (the double's frames never
    /// send them; <see cref="AppEvents"/> does): a pause or quitting delivers the answer being written without a frame,
    /// a resume leaves it pending, the recorder writes a running hold, and a destroyed component has written its answer
    /// and stopped its writer. Under the double only: the files go under persistentDataPath, a temporary folder here.
    /// </summary>
    public sealed class AppLifecycleTests : PlayModeFixture
    {
        /// <summary>A name no other test uses: persistentDataPath is one folder for the whole run.</summary>
        static string Unique(string name) => "lifecycle-" + Guid.NewGuid().ToString("N") + "-" + name;

        static QuestionnairePanel Panel(string file)
        {
            var go = new GameObject("Questionnaire");
            var panel = go.AddComponent<QuestionnairePanel>();
            panel.ResponsesFile = Path.Combine(Application.persistentDataPath, file);
            var items = new[] { new QuestionnaireItem(1, "Heavy?", false), new QuestionnaireItem(2, "Real?", false) };
            Assert.That(panel.Begin(new QuestionnaireCatalog(new[] { new Questionnaire("q", "Q", 1, 5, items) }), "P1"), Is.True, panel.Error);
            return panel;
        }

        [Test]
        public void APauseDeliversThePanelsAnswerWithoutAFrameAndAResumeDoesNot()
        {
            QuestionnairePanel panel = Panel(Unique("responses.csv"));
            Assert.That(panel.Answer(4), Is.True, panel.Error);
            AppEvents.Pause(false);
            Assert.That(panel.Model.Saver.Pending, Is.GreaterThanOrEqualTo(1), "a resume waited for the write");
            Assert.That(panel.Session.IsSaving, Is.True);

            AppEvents.Pause(true);
            Assert.That(panel.Model.Saver.Pending, Is.Zero, panel.Error);
            Assert.That(panel.Session.IsSaving, Is.False, "acknowledged by the pause, no Update ran");
            Assert.That(panel.ItemText, Does.Contain("Real?"), "and the page turned on the panel");
            Assert.That(File.ReadAllText(panel.ResponsesPath), Does.Contain("P1,q,1,4"));
        }

        [Test]
        public void QuittingDeliversTheTasksAnswerWithoutAFrame()
        {
            var root = new GameObject("Sample").transform;
            PseudoHapticProfile profile = PseudoHapticProfile.CreatePreset(NamedProfiles.PaperName);
            DiscriminationTask task = DiscriminationStation.Build(root, profile, "P1", new IHandPoseSource[0]);
            task.TrialsFile = Unique("trials.csv"); // not the sample's trials file, which other tests resume
            UnityDouble.Frames.Run(2); // Start begins the session
            Assert.That(task.Session, Is.Not.Null, task.Error);
            foreach (PseudoHapticWeight ball in PseudoHapticWeight.Enabled)
            {
                Assert.That(ball.BeginHold(ball.transform.position), Is.True, ball.ConfigurationError);
                ball.EndHold();
            }
            Assert.That(task.Answer(PairSide.Right), Is.True, task.Error);
            Assert.That(task.Session.IsSaving, Is.True);

            AppEvents.Quit();
            Assert.That(task.Model.Saver.Pending, Is.Zero, task.Error);
            Assert.That(task.Session.IsSaving, Is.False, "acknowledged by quitting, no Update ran");
            Assert.That(File.ReadAllLines(task.TrialsPath), Has.Length.EqualTo(2), "the header and the answer");
        }

        [Test]
        public void APauseWritesTheRecordersRunningHold()
        {
            var recorder = Track(new GameObject("Session Recorder")).AddComponent<SessionRecorder>();
            recorder.Folder = Path.Combine(Application.persistentDataPath, Unique("sessions"));
            recorder.SessionId = "P1";
            PseudoHapticWeight box = Box("box", 1f);
            Lift(box, 0.2f, 0.3f, 0f);
            string path = Path.Combine(recorder.Folder, "P1", "hold-001-box.csv");

            AppEvents.Pause(false);
            Assert.That(File.Exists(path), Is.False, "a resume wrote the hold");
            AppEvents.Pause(true);
            Assert.That(box.IsHeld, Is.True);
            Assert.That(File.Exists(path), Is.True, "the running hold, as far as it got");
            Assert.That(recorder.PendingWrites, Is.Zero, recorder.LastError);
        }

        [Test]
        public void ADestroyedPanelHasWrittenItsAnswerAndStoppedItsWriter()
        {
            QuestionnairePanel panel = Panel(Unique("responses.csv"));
            SaveQueue saver = panel.Model.Saver;
            string path = panel.ResponsesPath;
            Assert.That(panel.Answer(2), Is.True, panel.Error);
            UnityEngine.Object.DestroyImmediate(panel.gameObject);
            Assert.That(saver.Pending, Is.Zero);
            Assert.That(File.ReadAllText(path), Does.Contain("P1,q,1,2"));
            Assert.That(() => saver.Enqueue(() => { }, null, null), Throws.TypeOf<ObjectDisposedException>(), "the writer is stopped");
        }
    }
}
