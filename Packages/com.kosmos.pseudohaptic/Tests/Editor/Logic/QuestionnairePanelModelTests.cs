using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using Kosmos.PseudoHaptic.Evaluation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>The questionnaire panel's paging, resume, pokes and view, engine-free (what the play-mode panel tests assert, run here).</summary>
    public sealed class QuestionnairePanelModelTests
    {
        string _folder, _responses;

        [SetUp]
        public void UseTemporaryFolder()
        {
            _folder = Path.Combine(Path.GetTempPath(), "kosmos-pseudohaptic-panelmodel-" + Guid.NewGuid().ToString("N"));
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

        QuestionnairePanelModel Panel(string participant = "P1")
        {
            var model = new QuestionnairePanelModel();
            Assert.That(model.Begin(Catalog(), participant, _responses, null), Is.True, model.Error);
            return model;
        }

        string[] Rows()
        {
            string[] lines = File.ReadAllLines(_responses);
            return lines.Length > 0 ? new List<string>(lines).GetRange(1, lines.Length - 1).ToArray() : lines;
        }

        static PanelView View(QuestionnairePanelModel m) => m.View(0.6f, 0.004f);

        [Test]
        public void APageShowsTheItemItsProgressAndTheScaleWithItsLabels()
        {
            PanelView v = View(Panel());
            Assert.That(v.Title, Is.EqualTo("Part A"));
            Assert.That(v.Progress, Is.EqualTo("1 / 3"));
            Assert.That(v.Main, Is.EqualTo("The box felt heavy."));
            Assert.That(v.Points, Is.EqualTo(5));
            Assert.That(v.ScaleMin, Is.EqualTo(1));
            Assert.That(v.MinLabel, Is.EqualTo("Strongly disagree"));
            Assert.That(v.MaxLabel, Is.EqualTo("Strongly agree"));
            Assert.That(v.Instructions, Is.EqualTo("How much do you agree?"));
            Assert.That(v.CanBack, Is.False, "nothing to go back to");
            Assert.That(v.CanNext, Is.False, "an unanswered item cannot be skipped");
            Assert.That(v.Chosen, Is.Null);
            float x0 = QuestionnairePanelModel.ScaleLayout(0, 5, 0.6f, out float w, out float edge);
            float x4 = QuestionnairePanelModel.ScaleLayout(4, 5, 0.6f, out _, out _);
            Assert.That(x0, Is.LessThan(x4), "1 on the left");
            Assert.That(x4 + w / 2, Is.EqualTo(edge).Within(1e-6), "the row is centred and the labels sit at its ends");
            Assert.That(2 * edge, Is.LessThanOrEqualTo(0.6f - 2 * QuestionnairePanelModel.Margin + 1e-6), "inside the panel");
        }

        [Test]
        public void PressingAnAnswerSavesItTurnsThePageAndBackShowsTheAnswer()
        {
            QuestionnairePanelModel m = Panel();
            Assert.That(m.Press(PanelAction.Answer, 4), Is.True);
            Assert.That(Rows(), Is.EqualTo(new[] { "P1,part-a,1,4" }));
            Assert.That(View(m).Progress, Is.EqualTo("2 / 3"));
            Assert.That(View(m).CanBack, Is.True);
            Assert.That(m.Press(PanelAction.Back, 0), Is.True);
            Assert.That(View(m).Progress, Is.EqualTo("1 / 3"));
            Assert.That(View(m).Chosen, Is.EqualTo(4));
            Assert.That(View(m).CanNext, Is.True);
            Assert.That(m.Press(PanelAction.Answer, 2), Is.True, "a changed answer");
            Assert.That(Rows(), Is.EqualTo(new[] { "P1,part-a,1,2" }), "replaces its row");
            Assert.That(m.Press(PanelAction.Back, 0) && m.Press(PanelAction.Next, 0), Is.True);
        }

        [Test]
        public void ATenPointScaleAndTheEndSaysThankYouOnce()
        {
            QuestionnairePanelModel m = Panel();
            int completed = 0;
            m.Completed += s => completed++;
            m.Answer(3); m.Answer(3); m.Answer(3);
            PanelView v = View(m);
            Assert.That(v.Title, Is.EqualTo("Part B"));
            Assert.That(v.Points, Is.EqualTo(10));
            Assert.That(v.MinLabel, Is.Empty, "this scale has no labels");
            m.Answer(8);
            v = View(m);
            Assert.That(completed, Is.EqualTo(1));
            Assert.That(v.Points, Is.EqualTo(0));
            Assert.That(v.Progress, Is.Empty);
            Assert.That(v.Main, Does.Contain("Thank you"));
            Assert.That(m.Answer(9), Is.False, "nothing left to answer");
            m.Press(PanelAction.Back, 0);
            m.Answer(7);
            Assert.That(completed, Is.EqualTo(1), "raised once");
            Assert.That(Rows()[3], Is.EqualTo("P1,part-b,1,7"));
        }

        [Test]
        public void APanelStartedAgainResumesWhereItStopped()
        {
            QuestionnairePanelModel first = Panel();
            first.Answer(2); first.Answer(5);
            PanelView v = View(Panel());
            Assert.That(v.Progress, Is.EqualTo("3 / 3"));
            Assert.That(v.Main, Is.EqualTo("Nothing felt real."));
            var done = Panel("P2");
            Assert.That(View(done).Progress, Is.EqualTo("1 / 3"), "another participant starts at the beginning");
        }

        [Test]
        public void OnePokeIsOneAnswer()
        {
            QuestionnairePanelModel m = Panel();
            if (m.Touch(10.0)) m.Press(PanelAction.Answer, 3);
            for (double t = 10.02; t < 10.3; t += 0.02) m.Stay(t);
            if (m.Touch(10.3)) m.Press(PanelAction.Answer, 4); // slid onto the neighbour on the next page
            Assert.That(m.Session.AnsweredCount, Is.EqualTo(1));
            if (m.Touch(11.0)) m.Press(PanelAction.Answer, 1); // withdrawn, then poked again
            Assert.That(Rows(), Is.EqualTo(new[] { "P1,part-a,1,3", "P1,part-a,2,1" }));
            Assert.That(m.Poke(11.05), Is.False, "an Interaction SDK poke within the cooldown");
        }

        [Test]
        public void DefinitionsComeFromJsonAndABrokenOneSaysWhy()
        {
            var m = new QuestionnairePanelModel();
            string failed = null;
            m.Failed += e => failed = e;
            var json = "{ \"id\": \"only\", \"title\": \"Only part\", \"scale\": { \"min\": 1, \"max\": 7, \"minLabel\": \"Never\", \"maxLabel\": \"Always\" }, " +
                       "\"items\": [ { \"number\": 1, \"text\": \"I forgot where I was.\" } ] }";
            Assert.That(m.Begin(new[] { new KeyValuePair<string, string>("only.json", json) }, "P9", _responses, null), Is.True, m.Error);
            Assert.That(View(m).Points, Is.EqualTo(7));
            Assert.That(View(m).MaxLabel, Is.EqualTo("Always"));
            Assert.That(m.Begin(new[] { new KeyValuePair<string, string>("broken.json", "{ \"id\": \"broken\" }") }, "P9", _responses, null), Is.False);
            Assert.That(m.Error, Does.Match("missing|required"));
            Assert.That(failed, Is.EqualTo(m.Error));
            Assert.That(m.Begin(new KeyValuePair<string, string>[0], "P9", _responses, null), Is.False);
            Assert.That(m.Error, Does.Contain("no questionnaire definitions"));
            Assert.That(View(m).Main, Does.Contain("no questionnaire definitions"), "shown in place of an item");
        }

        [Test]
        public void AResponsesFileScoreWouldRefuseStopsThePanelWithTheReason()
        {
            File.WriteAllText(_responses, "participant,questionnaire,item,response\nP1,part-a,1,3\nP1,part-a,1,4\n");
            var m = new QuestionnairePanelModel();
            Assert.That(m.Begin(Catalog(), "P1", _responses, null), Is.False);
            Assert.That(m.Error, Does.Contain("duplicate"));
            PanelView v = View(m);
            Assert.That(v.Main, Does.Contain("duplicate"));
            Assert.That(v.Points, Is.EqualTo(0));
            Assert.That(m.Press(PanelAction.Answer, 3), Is.False);
        }

        [Test]
        public void AnAnswerThatCannotBeSavedIsSaidAndTheItemStays()
        {
            QuestionnairePanelModel m = Panel();
            Directory.Delete(_folder, true);
            File.WriteAllText(_folder, "a file where the responses folder was"); // nothing can be written under it
            try
            {
                Assert.That(m.Answer(3), Is.False);
                Assert.That(m.Error, Is.Not.Null);
                PanelView v = View(m);
                Assert.That(v.Message, Does.Contain("could not be saved"));
                Assert.That(v.Progress, Is.EqualTo("1 / 3"), "the item is asked again");
            }
            finally
            {
                File.Delete(_folder);
            }
        }
    
        [Test]
        public void WrittenInTheBackgroundThePageMovesOnlyWhenTheWriteIsAcknowledged()
        {
            var m = new QuestionnairePanelModel(saver: new SaveQueue(background: true));
            Assert.That(m.Begin(Catalog(), "P1", _responses, null), Is.True, m.Error);
            int answered = 0;
            m.Answered += s => answered++;
            Assert.That(m.Answer(4), Is.True, "taken");
            Assert.That(m.IsSaving, Is.True);
            Assert.That(View(m).Progress, Is.EqualTo("1 / 3"), "the item stays until its write is acknowledged");
            Assert.That(View(m).Message, Is.EqualTo(m.SavingText).And.StartWith("Saving"), "the participant is told");
            Assert.That(m.Answer(5), Is.False, "no second answer while the first is being saved");
            Assert.That(m.Press(PanelAction.Back, 0), Is.False);
            Assert.That(m.Flush(10000), Is.True);
            Assert.That(answered, Is.EqualTo(1));
            Assert.That(m.IsSaving, Is.False);
            Assert.That(View(m).Progress, Is.EqualTo("2 / 3"));
            Assert.That(View(m).Message, Is.EqualTo(""));
            Assert.That(Rows(), Is.EqualTo(new[] { "P1,part-a,1,4" }));
            m.Saver.Dispose();
        }

        /// <summary>P1's first answer (2) is saved; then the responses folder is replaced by a file, and the second (3) is not.</summary>
        QuestionnairePanelModel WithAnUnsavedAnswer(Func<double> clock)
        {
            var m = new QuestionnairePanelModel(saver: new SaveQueue(background: false, retrySeconds: 1, clock: clock));
            Assert.That(m.Begin(Catalog(), "P1", _responses, null), Is.True, m.Error);
            m.Answer(2);
            Directory.Delete(_folder, true);
            File.WriteAllText(_folder, "a file where the responses folder was");
            Assert.That(m.Answer(3), Is.False);
            return m;
        }

        [Test]
        public void AFailedAnswerIsKeptShownAsNotSavedAndWrittenOnceWhenTheFolderIsBack()
        {
            double now = 0;
            var m = WithAnUnsavedAnswer(() => now);
            Assert.That(View(m).Message, Does.Contain("could not be saved"));
            Assert.That(View(m).Progress, Is.EqualTo("2 / 3"), "not acknowledged");
            Assert.That(m.Session.AnsweredCount, Is.EqualTo(1));
            now = 5;
            Assert.That(m.Update(), Is.False, "the folder is still blocked: tried again and failed");
            Assert.That(m.Saver.Failures, Is.EqualTo(2));
            File.Delete(_folder);
            now = 6;
            Assert.That(m.Update(), Is.True);
            Assert.That(m.Error, Is.Null);
            Assert.That(View(m).Progress, Is.EqualTo("3 / 3"));
            Assert.That(Rows(), Is.EqualTo(new[] { "P1,part-a,1,2", "P1,part-a,2,3" }), "the earlier answer is kept, the kept one written once");
            now = 60;
            m.Update();
            Assert.That(m.Saver.Writes, Is.EqualTo(2));
        }

        // Issue 35 (logic-session survivors): what the participant sees and what a press or a restart does.

        [Test]
        public void APanelNotYetBegunAsksTheParticipantToWaitAndShowsNothingElse()
        {
            PanelView v = View(new QuestionnairePanelModel());
            Assert.That(v.Main, Does.Contain("wait for the experimenter"));
            Assert.That(new[] { v.Title, v.Progress, v.Instructions, v.MinLabel, v.MaxLabel, v.Message }, Is.All.Empty);
            Assert.That(v.Points, Is.Zero);
        }

        static int Longest(string text) => text.Split('\n').Max(line => line.Length);

        [Test]
        public void TextsAreWrappedInsideThePanelsMarginsAndEachEndLabelInHalfTheRow()
        {
            // One-letter words: greedy wrapping fills each line to within one character of what fits.
            string words = string.Join(" ", Enumerable.Repeat("a", 150));
            var part = new Questionnaire("long", "Long", 1, 5, new[] { new QuestionnaireItem(1, words, false) }, words, words, words);
            var m = new QuestionnairePanelModel();
            Assert.That(m.Begin(new QuestionnaireCatalog(new[] { part }), "P1", _responses, null), Is.True, m.Error);
            const float size = 0.004f;
            foreach (float width in new[] { 0.2f, 0.6f })
            {
                int fits = QuestionnairePanelModel.CharsPerLine(width - 2 * QuestionnairePanelModel.Margin, size);
                Assert.That(Longest(m.View(width, size).Main), Is.LessThanOrEqualTo(fits).And.GreaterThanOrEqualTo(fits - 1), "a panel " + width + " m wide");
            }
            // The two end labels sit side by side under the scale: each gets at most half the width the instructions
            // (the same smaller text) have, so they never meet in the middle.
            PanelView v = m.View(1.0f, size);
            Assert.That(Longest(v.MinLabel), Is.LessThanOrEqualTo(Longest(v.Instructions) / 2));
            Assert.That(Longest(v.MaxLabel), Is.LessThanOrEqualTo(Longest(v.Instructions) / 2));
        }

        [Test]
        public void ALineOfCharsPerLineAverageGlyphsFitsTheWidth()
        {
            // A TextMesh line is characterSize × fontSize / 10 m high, and a legacy font's glyphs average about half that.
            foreach (float width in new[] { 0.6f, 1f, 2f })
                foreach (float size in new[] { 0.004f, 0.008f })
                {
                    float glyph = 0.5f * size * QuestionnairePanelModel.FontSize / 10f;
                    int n = QuestionnairePanelModel.CharsPerLine(width, size);
                    Assert.That(n * glyph, Is.LessThanOrEqualTo(width).And.GreaterThan(0.7f * width), width + " m at " + size);
                }
        }

        [Test]
        public void ScaleButtonsAreEightCentimetresWideWhenThereIsRoomAndShrinkToFillTheRowWhenNot()
        {
            const float width = 0.6f, gap = QuestionnairePanelModel.ButtonGap;
            QuestionnairePanelModel.ScaleLayout(0, 5, width, out float w5, out float edge5);
            Assert.That(w5, Is.EqualTo(0.08f), "five fit at the largest width");
            Assert.That(2 * edge5, Is.EqualTo(5 * w5 + 4 * gap).Within(1e-6));
            float x0 = QuestionnairePanelModel.ScaleLayout(0, 10, width, out float w, out float edge);
            float x1 = QuestionnairePanelModel.ScaleLayout(1, 10, width, out _, out _);
            float x9 = QuestionnairePanelModel.ScaleLayout(9, 10, width, out _, out _);
            Assert.That(w, Is.GreaterThan(0).And.LessThan(0.08f), "ten do not fit at 8 cm");
            Assert.That(2 * edge, Is.EqualTo(width - 2 * QuestionnairePanelModel.Margin).Within(1e-6), "they fill the row inside the margins");
            Assert.That(x0 - w / 2, Is.EqualTo(-edge).Within(1e-6));
            Assert.That(x9 + w / 2, Is.EqualTo(edge).Within(1e-6));
            Assert.That(x1 - x0, Is.EqualTo(w + gap).Within(1e-6), "side by side, 1 cm apart");
        }

        [Test]
        public void AFingerSlidingOntoAnotherButtonIsNoPokeEvenAfterTheCooldownAndANewSessionTakesTheFirstPoke()
        {
            QuestionnairePanelModel m = Panel();
            Assert.That(m.Touch(10.0), Is.True);
            for (double t = 10.02; t < 10.79; t += 0.02) m.Stay(t);
            Assert.That(m.Touch(10.8), Is.False, "never withdrawn: it slid onto another button");
            // The next participant's session: what the last finger did no longer counts.
            Assert.That(m.Begin(Catalog(), "P2", _responses, null), Is.True, m.Error);
            Assert.That(m.Touch(10.85), Is.True);
        }

        [Test]
        public void AValueOffTheScaleIsRefusedAndItsMessageGoesWhenThePageChanges()
        {
            QuestionnairePanelModel m = Panel();
            string failed = null;
            m.Failed += e => failed = e;
            Assert.That(m.Answer(4), Is.True);
            Assert.That(m.Answer(9), Is.False, "the scale is 1–5");
            Assert.That(m.Error, Is.Not.Null);
            Assert.That(failed, Is.EqualTo(m.Error));
            Assert.That(Rows(), Is.EqualTo(new[] { "P1,part-a,1,4" }), "nothing written");
            Assert.That(View(m).Message, Is.Empty, "nothing is kept to be tried again: the headset does not say so");
            Assert.That(m.Press(PanelAction.Next, 0), Is.False, "an unanswered item cannot be skipped");
            Assert.That(m.Error, Is.Not.Null, "a press that changed nothing leaves the message");
            Assert.That(m.Press(PanelAction.Back, 0), Is.True);
            Assert.That(m.Error, Is.Null);
            Assert.That(View(m).Message, Is.Empty);
        }

        /// <summary>Part A of <see cref="Catalog"/> as the JSON a panel's definition asset holds.</summary>
        static readonly KeyValuePair<string, string>[] PartAJson =
        {
            new KeyValuePair<string, string>("part-a.json", "{ \"id\": \"part-a\", \"title\": \"Part A\", \"scale\": { \"min\": 1, \"max\": 5 }, " +
                "\"items\": [ { \"number\": 1, \"text\": \"The box felt heavy.\" }, { \"number\": 2, \"text\": \"The ball felt light.\" }, " +
                "{ \"number\": 3, \"text\": \"Nothing felt real.\", \"reverse\": true } ] }"),
        };

        // Both ways a panel begins (a catalog built in code, or the JSON definitions the panel's assets hold) refuse a new
        // session while the last participant's answer is unsaved, and lose none of it once it is.
        [TestCase(false)]
        [TestCase(true)]
        public void AnotherSessionIsRefusedWhileAnAnswerIsNotSavedAndBegunOnceItIs(bool fromJson)
        {
            double now = 0;
            var m = new QuestionnairePanelModel(saver: new SaveQueue(background: false, retrySeconds: 1, clock: () => now));
            Func<string, bool> begin = p => fromJson ? m.Begin(PartAJson, p, _responses, null) : m.Begin(Catalog(), p, _responses, null);
            Assert.That(m.Begin(Catalog(), "P1", _responses, null), Is.True, m.Error);
            m.Answer(2);
            Directory.Delete(_folder, true);
            File.WriteAllText(_folder, "a file where the responses folder was");
            try
            {
                Assert.That(m.Answer(3), Is.False);
                Assert.That(begin("P2"), Is.False);
                Assert.That(m.Error, Does.Contain("not saved yet"));
                Assert.That(View(m).Progress, Is.EqualTo("2 / 3"), "P1's page stays, the answer kept");
            }
            finally
            {
                File.Delete(_folder);
            }
            now = 5;
            Assert.That(m.Update(), Is.True);
            bool begun = begin("P2");
            Assert.That(begun, Is.True, "once it is saved: " + m.Error);
            Assert.That(Rows(), Is.EqualTo(new[] { "P1,part-a,1,2", "P1,part-a,2,3" }));
            m.Answer(5);
            Assert.That(Rows(), Is.EqualTo(new[] { "P1,part-a,1,2", "P1,part-a,2,3", "P2,part-a,1,5" }), "P2's answer is added, P1's kept");
        }

        [Test]
        public void AnotherSessionBegunWhileAnUnsavedAnswerCanBeSavedAgainSavesItFirstThenBegins()
        {
            // The next participant is started before a frame has run the due retry, and the folder is back: the begin waits for
            // the write (SaveQueue.Drain), which now succeeds, and then begins; it refuses only when the write still fails.
            double now = 0;
            var m = WithAnUnsavedAnswer(() => now);
            File.Delete(_folder);
            now = 5; // the retry is due, but no frame has run it yet
            Assert.That(m.IsSaving, Is.True, "the answer is still unsaved when P2 is started");
            Assert.That(m.Begin(Catalog(), "P2", _responses, null), Is.True, m.Error);
            Assert.That(Rows(), Is.EqualTo(new[] { "P1,part-a,1,2", "P1,part-a,2,3" }), "P1's answer saved before P2's session read the file");
            Assert.That(View(m).Progress, Is.EqualTo("1 / 3"), "P2 begins at the first item");
        }
    }
}
