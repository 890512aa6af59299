using System;
using System.Collections;
using System.Collections.Generic;
using System.IO;
using Kosmos.PseudoHaptic.Evaluation;
using NUnit.Framework;
using UnityEngine;
using UnityEngine.TestTools;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>The in-headset questionnaire panel: pages, progress, scale labels, pokes, the responses file.</summary>
    public sealed class QuestionnairePanelTests : PlayModeFixture
    {
        string _folder;
        string _responses;

        [SetUp]
        public void UseTemporaryFolder()
        {
            _folder = Path.Combine(Path.GetTempPath(), "kosmos-pseudohaptic-panel-" + Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(_folder);
            _responses = Path.Combine(_folder, "responses.csv");
        }

        [TearDown]
        public void RemoveTemporaryFolder()
        {
            if (Directory.Exists(_folder)) Directory.Delete(_folder, true);
        }

        /// <summary>Two parts: three items on 1–5 with end labels, one item on 1–10.</summary>
        static QuestionnaireCatalog Catalog()
        {
            var a = new Questionnaire("part-a", "Part A", 1, 5,
                new[] { new QuestionnaireItem(1, "The box felt heavy.", false), new QuestionnaireItem(2, "The ball felt light.", false), new QuestionnaireItem(3, "Nothing felt real.", true) },
                "How much do you agree?", "Strongly disagree", "Strongly agree");
            var b = new Questionnaire("part-b", "Part B", 1, 10, new[] { new QuestionnaireItem(1, "How immersed were you?", false) });
            return new QuestionnaireCatalog(new[] { a, b });
        }

        QuestionnairePanel Panel(string participant = "P1")
        {
            var go = Track(new GameObject("Questionnaire"));
            go.transform.position = new Vector3(0, 1.3f, 0.6f);
            var panel = go.AddComponent<QuestionnairePanel>();
            panel.ResponsesFile = _responses;
            Assert.That(panel.Begin(Catalog(), participant), Is.True, panel.Error);
            return panel;
        }

        /// <summary>Waits for the panel's background writer, as a later frame's Update would deliver it.</summary>
        static void Saved(QuestionnairePanel panel) => Assert.That(panel.WaitForSaves(), Is.True, panel.Error);

        static int ActiveScaleButtons(QuestionnairePanel panel)
        {
            int n = 0;
            foreach (PokeButton b in panel.ScaleButtons) if (b.gameObject.activeSelf) n++;
            return n;
        }

        string[] Rows()
        {
            var rows = new List<string>(File.ReadAllText(_responses).Split('\n'));
            rows.RemoveAt(0);
            rows.RemoveAll(r => r.Length == 0);
            return rows.ToArray();
        }

        [Test]
        public void APageShowsTheItemItsProgressAndTheScaleWithItsLabels()
        {
            QuestionnairePanel panel = Panel();
            Assert.That(panel.TitleText, Is.EqualTo("Part A"));
            Assert.That(panel.ProgressText, Is.EqualTo("1 / 3"));
            Assert.That(panel.ItemText, Is.EqualTo("The box felt heavy."));
            Assert.That(ActiveScaleButtons(panel), Is.EqualTo(5));
            for (int i = 0; i < 5; i++)
            {
                Assert.That(panel.ScaleButtons[i].Value, Is.EqualTo(i + 1));
                Assert.That(panel.ScaleButtons[i].Label.text, Is.EqualTo((i + 1).ToString()));
            }
            Assert.That(panel.MinLabelText, Is.EqualTo("Strongly disagree"));
            Assert.That(panel.MaxLabelText, Is.EqualTo("Strongly agree"));
            Assert.That(panel.BackButton.gameObject.activeSelf, Is.False, "nothing to go back to");
            Assert.That(panel.NextButton.gameObject.activeSelf, Is.False, "an unanswered item cannot be skipped");
            Assert.That(panel.ScaleButtons[0].transform.position.x, Is.LessThan(panel.ScaleButtons[4].transform.position.x), "1 on the left");
        }

        [Test]
        public void PressingAnAnswerSavesItAndTurnsThePage()
        {
            QuestionnairePanel panel = Panel();
            Assert.That(panel.Press(panel.ScaleButtons[3]), Is.True);
            Saved(panel);
            Assert.That(Rows(), Is.EqualTo(new[] { "P1,part-a,1,4" }));
            Assert.That(panel.ProgressText, Is.EqualTo("2 / 3"));
            Assert.That(panel.BackButton.gameObject.activeSelf, Is.True);

            Assert.That(panel.Press(panel.BackButton), Is.True);
            Assert.That(panel.ProgressText, Is.EqualTo("1 / 3"));
            Assert.That(panel.Session.CurrentAnswer, Is.EqualTo(4));
            Assert.That(panel.NextButton.gameObject.activeSelf, Is.True);
            Assert.That(panel.Press(panel.ScaleButtons[1]), Is.True, "a changed answer");
            Saved(panel);
            Assert.That(Rows(), Is.EqualTo(new[] { "P1,part-a,1,2" }), "replaces its row");
        }

        [Test]
        public void ATenPointScaleGetsTenButtonsAndTheEndSaysThankYou()
        {
            QuestionnairePanel panel = Panel();
            int completed = 0;
            panel.Completed += s => completed++;
            for (int i = 0; i < 3; i++)
            {
                panel.Answer(3);
                Saved(panel);
            }
            Assert.That(panel.TitleText, Is.EqualTo("Part B"));
            Assert.That(panel.ProgressText, Is.EqualTo("1 / 1"));
            Assert.That(ActiveScaleButtons(panel), Is.EqualTo(10));
            Assert.That(panel.ScaleButtons[9].Value, Is.EqualTo(10));
            Assert.That(panel.MinLabelText, Is.Empty, "this scale has no labels");

            panel.Press(panel.ScaleButtons[7]);
            Saved(panel);
            Assert.That(panel.Session.IsComplete, Is.True);
            Assert.That(completed, Is.EqualTo(1));
            Assert.That(ActiveScaleButtons(panel), Is.EqualTo(0));
            Assert.That(panel.ProgressText, Is.Empty);
            Assert.That(panel.ItemText, Does.Contain("Thank you"));
            Assert.That(Rows(), Has.Length.EqualTo(4));
            Assert.That(Rows()[3], Is.EqualTo("P1,part-b,1,8"));
        }

        [Test]
        public void APanelStartedAgainResumesWhereItStopped()
        {
            QuestionnairePanel first = Panel();
            first.Answer(5);
            Saved(first);
            first.Answer(4);
            Saved(first);
            QuestionnairePanel second = Panel(); // as after a crash
            Assert.That(second.ProgressText, Is.EqualTo("3 / 3"));
            Assert.That(second.ItemText, Is.EqualTo("Nothing felt real."));
        }

        [Test]
        public void OnePokeIsOneAnswer()
        {
            QuestionnairePanel panel = Panel();
            panel.Touch(panel.ScaleButtons[2], 10.0);
            Saved(panel);
            for (double t = 10.02; t < 10.3; t += 0.02) panel.Stay(t);
            panel.Touch(panel.ScaleButtons[3], 10.3); // slid onto the neighbour on the next page
            Assert.That(panel.Session.AnsweredCount, Is.EqualTo(1));
            panel.Touch(panel.ScaleButtons[0], 11.0); // withdrawn, then poked again
            Saved(panel);
            Assert.That(panel.Session.AnsweredCount, Is.EqualTo(2));
            Assert.That(Rows(), Is.EqualTo(new[] { "P1,part-a,1,3", "P1,part-a,2,1" }));
        }

        [Test]
        public void APokeOnTheSurfacePressesTheButtonUnderIt()
        {
            QuestionnairePanel panel = Panel();
            PokeButton two = panel.ScaleButtons[1];
            Assert.That(panel.ButtonAt(two.transform.position), Is.SameAs(two));
            Assert.That(panel.PokeAt(panel.transform.position + new Vector3(0, 0.5f, 0), 5.0), Is.False, "above the panel");
            Assert.That(panel.PokeAt(two.transform.position + new Vector3(0.01f, 0.01f, -0.01f), 5.1), Is.True);
            Saved(panel);
            Assert.That(Rows(), Is.EqualTo(new[] { "P1,part-a,1,2" }));
            Assert.That(panel.PokeAt(panel.ScaleButtons[0].transform.position, 5.2), Is.False, "within the cooldown");
        }

        [Test]
        public void DefinitionsComeFromJsonTextAssets()
        {
            var go = Track(new GameObject("Questionnaire"));
            var panel = go.AddComponent<QuestionnairePanel>();
            panel.ResponsesFile = _responses;
            var json = new TextAsset("{ \"id\": \"only\", \"title\": \"Only part\", \"scale\": { \"min\": 1, \"max\": 7, \"minLabel\": \"Never\", \"maxLabel\": \"Always\" }, " +
                                     "\"items\": [ { \"number\": 1, \"text\": \"I forgot where I was.\" } ] }");
            json.name = "only";
            panel.InjectQuestionnaires(json);
            Assert.That(panel.Begin("P9"), Is.True, panel.Error);
            Assert.That(ActiveScaleButtons(panel), Is.EqualTo(7));
            Assert.That(panel.MaxLabelText, Is.EqualTo("Always"));

            panel.InjectQuestionnaires(new TextAsset("{ \"id\": \"broken\" }"));
            LogAssert.Expect(LogType.Error, new System.Text.RegularExpressions.Regex("missing|required"));
            Assert.That(panel.Begin("P9"), Is.False);
            Assert.That(panel.Error, Is.Not.Null);
        }

        [Test]
        public void AResponsesFileScoreWouldRefuseStopsThePanelWithTheReason()
        {
            File.WriteAllText(_responses, "participant,questionnaire,item,response\nP1,part-a,1,3\nP1,part-a,1,4\n");
            var go = Track(new GameObject("Questionnaire"));
            var panel = go.AddComponent<QuestionnairePanel>();
            panel.ResponsesFile = _responses;
            LogAssert.Expect(LogType.Error, new System.Text.RegularExpressions.Regex("duplicate"));
            Assert.That(panel.Begin(Catalog(), "P1"), Is.False);
            Assert.That(panel.Error, Does.Contain("duplicate"));
            Assert.That(panel.ItemText, Does.Contain("duplicate"));
            Assert.That(ActiveScaleButtons(panel), Is.EqualTo(0));
        }

        [Test]
        public void FindsTheIndexTipBoneAndSkipsBindPoses()
        {
            var hand = Track(new GameObject("OVRHandPrefab")).transform;
            var bindPoses = new GameObject("BindPoses").transform;
            bindPoses.SetParent(hand, false);
            new GameObject("Hand_IndexTip").transform.SetParent(bindPoses, false);
            var bones = new GameObject("Bones").transform;
            bones.SetParent(hand, false);
            var wrist = new GameObject("Hand_WristRoot").transform;
            wrist.SetParent(bones, false);
            new GameObject("Hand_IndexTip_CapsuleCollider").transform.SetParent(wrist, false);
            var tip = new GameObject("Hand_IndexTip").transform;
            tip.SetParent(wrist, false);
            Assert.That(FingertipPoker.FindBone(hand, "IndexTip"), Is.SameAs(tip));
            Assert.That(FingertipPoker.FindBone(hand, "ThumbTip"), Is.Null);
        }

        [UnityTest]
        public IEnumerator AFingertipPushedIntoAButtonAnswersOnce()
        {
            QuestionnairePanel panel = Panel();
            var tip = Track(new GameObject("Index tip"));
            tip.transform.position = panel.transform.position + new Vector3(0, 0, -0.3f);
            tip.AddComponent<FingertipPoker>();
            yield return null;

            tip.transform.position = panel.ScaleButtons[4].transform.position; // into the "5"
            for (int i = 0; i < 120 && panel.Session.AnsweredCount == 0; i++) yield return null;
            Saved(panel);
            Assert.That(Rows(), Is.EqualTo(new[] { "P1,part-a,1,5" }));

            for (int i = 0; i < 60; i++) yield return null; // resting in the button: still one answer
            Assert.That(panel.Session.AnsweredCount, Is.EqualTo(1));
        }
    }
}
