using System;
using System.Collections.Generic;
using System.IO;
using Kosmos.PseudoHaptic.Evaluation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests.Evaluation
{
    /// <summary>The in-headset session's logic: order, progress, answers written at once, resume, changes, the file score reads.</summary>
    public class QuestionnaireSessionTests
    {
        string dir;
        string path;

        [SetUp]
        public void SetUp()
        {
            dir = Path.Combine(Path.GetTempPath(), "ph-session-" + Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(dir);
            path = Path.Combine(dir, "responses.csv");
        }

        [TearDown]
        public void TearDown()
        {
            if (Directory.Exists(dir)) Directory.Delete(dir, true);
        }

        static QuestionnaireCatalog Paper() => SampleQuestionnaires.Paper();

        QuestionnaireSession Session(string participant = "P1", IEnumerable<string> ids = null)
            => new QuestionnaireSession(Paper(), participant, path, ids);

        ResponseSet FileAsScoreReadsIt() => ResponsesCsv.Load(path, Paper());

        string[] DataLines()
        {
            var lines = new List<string>(File.ReadAllText(path).Split('\n'));
            lines.RemoveAt(0);
            lines.RemoveAll(l => l.Length == 0);
            return lines.ToArray();
        }

        void AssertNoTemporaryFiles()
        {
            foreach (string file in Directory.GetFiles(dir))
                Assert.That(Path.GetFileName(file), Does.Not.EndWith(".tmp"), "temporary file left behind");
        }

        [Test]
        public void AsksEveryItemOfEveryPartInOrderWithProgress()
        {
            var s = Session();
            Assert.That(s.StepCount, Is.EqualTo(21));
            Assert.That(s.StepIndex, Is.EqualTo(0));
            Assert.That(s.ResumedCount, Is.EqualTo(0));
            Assert.That(File.Exists(path), Is.False, "nothing is written before the first answer");
            var seen = new List<string>();
            while (!s.IsFinished)
            {
                seen.Add(s.CurrentQuestionnaire.Id + "#" + s.CurrentItem.Number + " " + s.ProgressText);
                Assert.That(s.CurrentAnswer, Is.Null);
                s.Answer(s.CurrentQuestionnaire.ScaleMin + 1);
            }
            Assert.That(seen[0], Is.EqualTo("weight-detection#1 1 / 10"));
            Assert.That(seen[2], Is.EqualTo("weight-detection#3 3 / 10"));
            Assert.That(seen[9], Is.EqualTo("weight-detection#10 10 / 10"));
            Assert.That(seen[10], Is.EqualTo("immersion#1 1 / 10"));
            Assert.That(seen[20], Is.EqualTo("self-assessment#1 1 / 1"));
            Assert.That(seen, Has.Count.EqualTo(21));
            Assert.That(s.IsComplete, Is.True);
            Assert.That(s.CurrentQuestionnaire, Is.Null);
            Assert.That(s.ProgressText, Is.EqualTo(""));
            Assert.Throws<InvalidOperationException>(() => s.Answer(2));
        }

        [Test]
        public void EveryAnswerIsInTheFileAtOnceAndNoTemporaryFileStays()
        {
            var s = Session();
            for (int n = 1; n <= 12; n++)
            {
                s.Answer(3);
                var set = FileAsScoreReadsIt();
                Assert.That(set.Count, Is.EqualTo(n), "after answer " + n);
                AssertNoTemporaryFiles();
            }
            Assert.That(File.ReadAllText(path), Does.StartWith(ResponsesCsv.Header + "\n"));
            Assert.That(DataLines()[11], Is.EqualTo("P1,immersion,2,3"));
        }

        [Test]
        public void ANewSessionFromTheFileResumesAtTheFirstUnansweredItem()
        {
            var first = Session();
            int[] given = { 5, 4, 2, 1 };
            foreach (int a in given) first.Answer(a);

            var resumed = Session(); // as after a crash: a new session from the file alone
            Assert.That(resumed.ResumedCount, Is.EqualTo(4));
            Assert.That(resumed.AnsweredCount, Is.EqualTo(4));
            Assert.That(resumed.StepIndex, Is.EqualTo(4));
            Assert.That(resumed.CurrentItem.Number, Is.EqualTo(5));
            Assert.That(resumed.ProgressText, Is.EqualTo("5 / 10"));
            Assert.That(resumed.CurrentAnswer, Is.Null);
            for (int i = 0; i < 4; i++) Assert.That(resumed.AnswerAt(i), Is.EqualTo(given[i]));
            Assert.That(resumed.CanGoBack, Is.True);

            resumed.Answer(3);
            Assert.That(FileAsScoreReadsIt().Find("P1", "weight-detection").AnsweredCount, Is.EqualTo(5));
        }

        [Test]
        public void AChangedAnswerReplacesItsRowAndNeverDuplicatesIt()
        {
            var s = Session();
            foreach (int a in new[] { 5, 4, 2, 1 }) s.Answer(a);
            Assert.That(s.Back(), Is.True);
            Assert.That(s.Back(), Is.True);
            Assert.That(s.CurrentItem.Number, Is.EqualTo(3));
            Assert.That(s.CurrentAnswer, Is.EqualTo(2));
            s.Answer(4);
            Assert.That(s.CurrentItem.Number, Is.EqualTo(5), "on to the first item not yet answered");
            Assert.That(s.AnsweredCount, Is.EqualTo(4));
            Assert.That(DataLines(), Is.EqualTo(new[]
            {
                "P1,weight-detection,1,5", "P1,weight-detection,2,4", "P1,weight-detection,3,4", "P1,weight-detection,4,1",
            }), "the row is replaced where it was");

            // The same after a resume: go back from item 5 to item 4 and change it.
            var resumed = Session();
            Assert.That(resumed.Back(), Is.True);
            Assert.That(resumed.CurrentItem.Number, Is.EqualTo(4));
            resumed.Answer(5);
            var set = FileAsScoreReadsIt(); // score refuses duplicates: this would throw
            Assert.That(set.Count, Is.EqualTo(4));
            Assert.That(set.Find("P1", "weight-detection").AnswerAt(3), Is.EqualTo(5));
            Assert.That(set.Find("P1", "weight-detection").AnswerAt(2), Is.EqualTo(4));
        }

        [Test]
        public void BackAndForwardMoveWithoutChangingAnswers()
        {
            var s = Session();
            Assert.That(s.CanGoBack, Is.False);
            Assert.That(s.Back(), Is.False);
            Assert.That(s.CanGoForward, Is.False, "an unanswered item cannot be skipped");
            Assert.That(s.Forward(), Is.False);
            s.Answer(2);
            s.Answer(3);
            Assert.That(s.Back() && s.Back(), Is.True);
            Assert.That(s.StepIndex, Is.EqualTo(0));
            Assert.That(s.CanGoForward, Is.True);
            Assert.That(s.Forward(), Is.True);
            Assert.That(s.CurrentAnswer, Is.EqualTo(3));
            Assert.That(s.Forward(), Is.True);
            Assert.That(s.StepIndex, Is.EqualTo(2));
            Assert.That(s.Forward(), Is.False);
            Assert.That(DataLines(), Has.Length.EqualTo(2));
        }

        [Test]
        public void AfterTheLastItemTheSessionIsFinishedAndCanStillGoBack()
        {
            var s = Session("P1", new[] { QuestionnaireCatalog.SelfAssessmentId });
            Assert.That(s.StepCount, Is.EqualTo(1));
            Assert.That(s.ProgressText, Is.EqualTo("1 / 1"));
            s.Answer(10);
            Assert.That(s.IsFinished && s.IsComplete, Is.True);
            Assert.That(s.Back(), Is.True);
            Assert.That(s.CurrentAnswer, Is.EqualTo(10));
            s.Answer(7);
            Assert.That(s.IsFinished, Is.True);
            Assert.That(DataLines(), Is.EqualTo(new[] { "P1,self-assessment,1,7" }));
            Assert.That(Session("P1", new[] { QuestionnaireCatalog.SelfAssessmentId }).IsFinished, Is.True, "a finished participant resumes at the end");
        }

        [Test]
        public void TheQuestionnairesAskedAndTheirOrderCanBeChosen()
        {
            var s = Session("P1", new[] { QuestionnaireCatalog.SelfAssessmentId, QuestionnaireCatalog.ImmersionId });
            Assert.That(s.Questionnaires, Has.Count.EqualTo(2));
            Assert.That(s.StepCount, Is.EqualTo(11));
            Assert.That(s.CurrentQuestionnaire.Id, Is.EqualTo("self-assessment"));
            s.Answer(8);
            Assert.That(s.CurrentQuestionnaire.Id, Is.EqualTo("immersion"));
            Assert.That(s.CurrentPart, Is.EqualTo(2));
            Assert.Throws<ArgumentException>(() => Session("P1", new[] { "presence" }));
            Assert.Throws<ArgumentException>(() => Session("P1", new[] { "immersion", "immersion" }));
            Assert.Throws<ArgumentException>(() => Session("P1", new string[0]));
        }

        [Test]
        public void ASessionResumesOnlyItsOwnQuestionnairesAndKeepsTheRest()
        {
            var a = Session("P1", new[] { QuestionnaireCatalog.SelfAssessmentId });
            a.Answer(9);
            var b = Session("P1", new[] { QuestionnaireCatalog.ImmersionId });
            Assert.That(b.ResumedCount, Is.EqualTo(0));
            b.Answer(4);
            Assert.That(DataLines(), Is.EqualTo(new[] { "P1,self-assessment,1,9", "P1,immersion,1,4" }));
        }

        [Test]
        public void OtherParticipantsRowsAreKeptVerbatimAndInOrder()
        {
            File.WriteAllText(path, "\uFEFFParticipant,Questionnaire,Item,Response\r\n" +
                                    "P2,immersion,1,4\r\n" +
                                    "\r\n" +
                                    "\"P 3, left\",self-assessment,1,6.0\r\n" +
                                    "P1,weight-detection,1,2\r\n");
            var s = Session();
            Assert.That(s.ResumedCount, Is.EqualTo(1));
            Assert.That(s.CurrentItem.Number, Is.EqualTo(2));
            s.Answer(5);
            Assert.That(File.ReadAllText(path), Is.EqualTo(
                "Participant,Questionnaire,Item,Response\n" +
                "P2,immersion,1,4\n" +
                "\"P 3, left\",self-assessment,1,6.0\n" +
                "P1,weight-detection,1,2\n" +
                "P1,weight-detection,2,5\n"));
            Assert.That(FileAsScoreReadsIt().Count, Is.EqualTo(4));
        }

        /// <summary>Lone "\r" line ends and no final line end: the file resumes as score reads it (it threw IndexOutOfRangeException).</summary>
        [Test]
        public void AFileWithLoneCarriageReturnsResumes()
        {
            File.WriteAllText(path, "participant,questionnaire,item,response\rP2,immersion,1,4\rP1,weight-detection,1,2");
            var s = Session();
            Assert.That(s.ResumedCount, Is.EqualTo(1));
            s.Answer(5);
            Assert.That(DataLines(), Is.EqualTo(new[] { "P2,immersion,1,4", "P1,weight-detection,1,2", "P1,weight-detection,2,5" }));
        }

        [Test]
        public void AParticipantIdWithACommaIsQuotedAndResumes()
        {
            var s = Session("P 4, right");
            s.Answer(3);
            Assert.That(DataLines(), Is.EqualTo(new[] { "\"P 4, right\",weight-detection,1,3" }));
            Assert.That(Session("P 4, right").ResumedCount, Is.EqualTo(1));
            Assert.That(Session("P 4").ResumedCount, Is.EqualTo(0));
        }

        [TestCase("")]
        [TestCase("   ")]
        [TestCase(" P1")]
        [TestCase("P1 ")]
        [TestCase("P\n1")]
        [TestCase(null)]
        public void AnUnusableParticipantIdIsRefused(string participant)
        {
            Assert.Throws<ArgumentException>(() => Session(participant));
        }

        [Test]
        public void AGapInTheFileIsFilledFirst()
        {
            File.WriteAllText(path, ResponsesCsv.Header + "\nP1,weight-detection,1,3\nP1,weight-detection,2,3\nP1,weight-detection,4,3\n");
            var s = Session();
            Assert.That(s.CurrentItem.Number, Is.EqualTo(3));
            s.Answer(1);
            Assert.That(s.CurrentItem.Number, Is.EqualTo(5), "item 4 is answered already");
        }

        [Test]
        public void AnAnswerOffTheScaleIsRefusedAndNothingIsWritten()
        {
            var s = Session();
            Assert.Throws<ArgumentOutOfRangeException>(() => s.Answer(6));
            Assert.Throws<ArgumentOutOfRangeException>(() => s.Answer(0));
            Assert.That(s.StepIndex, Is.EqualTo(0));
            Assert.That(File.Exists(path), Is.False);
        }

        [Test]
        public void AFailedWriteLeavesTheSessionAndTheFileAsTheyWere()
        {
            var s = Session();
            s.Answer(4);
            string before = File.ReadAllText(path);
            File.Delete(path);
            Directory.CreateDirectory(path); // the file's name is now taken by a folder: the rename must fail
            var e = Assert.Catch<Exception>(() => s.Answer(2));
            Assert.That(e is IOException || e is UnauthorizedAccessException, Is.True, e.ToString());
            Assert.That(s.StepIndex, Is.EqualTo(1));
            Assert.That(s.AnsweredCount, Is.EqualTo(1));
            Assert.That(s.CurrentAnswer, Is.Null);
            Assert.That(s.FileText(), Is.EqualTo(before), "the rows are as they were");
            AssertNoTemporaryFiles();

            Directory.Delete(path);
            s.Answer(2); // the next attempt writes both answers
            Assert.That(DataLines(), Is.EqualTo(new[] { "P1,weight-detection,1,4", "P1,weight-detection,2,2" }));
        }

        [TestCase("participant,questionnaire,item,response\nP1,immersion,1,3\nP1,immersion,1,4\n", "duplicate")]
        [TestCase("participant,questionnaire,item,response\nP1,immersion,1,9\n", "outside the scale")]
        [TestCase("questionnaire,participant,item,response\nimmersion,P1,1,3\n", "header must name exactly")]
        [TestCase("participant,questionnaire,item,response,note\nP1,immersion,1,3,x\n", "header must name exactly")]
        [TestCase("who,questionnaire,item,response\n", "missing column 'participant'")]
        public void AFileScoreWouldRefuseIsRefusedAndLeftUntouched(string text, string reason)
        {
            File.WriteAllText(path, text);
            var e = Assert.Throws<EvaluationFormatException>(() => Session());
            Assert.That(e.Message, Does.Contain(reason));
            Assert.That(File.ReadAllText(path), Is.EqualTo(text));
        }

        [Test]
        public void AnEmptyFileIsANewOne()
        {
            File.WriteAllText(path, "\n");
            var s = Session();
            s.Answer(1);
            Assert.That(File.ReadAllText(path), Is.EqualTo(ResponsesCsv.Header + "\nP1,weight-detection,1,1\n"));
        }

        [Test]
        public void TheFolderIsCreatedWhenMissing()
        {
            path = Path.Combine(dir, "study", "day 1", "responses.csv");
            Session().Answer(2);
            Assert.That(File.Exists(path), Is.True);
        }

        [Test]
        public void ACompletedSessionScoresLikeAHandComputation()
        {
            var s = Session();
            while (!s.IsFinished) s.Answer(s.CurrentQuestionnaire.Id == QuestionnaireCatalog.SelfAssessmentId ? 8 : 4);
            var scores = ScoreCalculator.ScoreAll(FileAsScoreReadsIt());
            Assert.That(scores, Has.Count.EqualTo(3));
            // Part 1: eight 4s and items 4, 7 reversed (6 − 4 = 2): (32 + 4) / 10; Part 2: six 4s and four 2s.
            Assert.That(scores[0].Score, Is.EqualTo(3.6).Within(1e-12));
            Assert.That(scores[1].Score, Is.EqualTo(3.2).Within(1e-12));
            Assert.That(scores[2].Score, Is.EqualTo(8));
        }

        [Test]
        public void AtTheEndNoItemIsShownAndStepsOutsideTheSessionAreRefused()
        {
            var s = Session("P1", new[] { QuestionnaireCatalog.SelfAssessmentId });
            Assert.That(() => s.AnswerAt(1), Throws.TypeOf<ArgumentOutOfRangeException>());
            Assert.That(() => s.AnswerAt(-1), Throws.TypeOf<ArgumentOutOfRangeException>());
            Assert.That(() => s.ItemAt(1, out _), Throws.TypeOf<ArgumentOutOfRangeException>());
            Assert.That(() => s.ItemAt(-1, out _), Throws.TypeOf<ArgumentOutOfRangeException>());
            s.Answer(6);
            Assert.That(s.IsFinished, Is.True);
            Assert.That(s.CurrentItem, Is.Null);
            Assert.That(s.CurrentPosition, Is.EqualTo(0));
            Assert.That(s.CurrentPart, Is.EqualTo(0));
            Assert.That(s.CurrentAnswer, Is.Null);
            Assert.That(s.AnswerAt(0), Is.EqualTo(6));
            var e = Assert.Throws<InvalidOperationException>(() => s.Answer(7));
            Assert.That(e.Message, Does.Contain("the session is finished"));
        }

        [Test]
        public void MisuseIsRefusedSayingWhatIsWrong()
        {
            var e = Assert.Throws<ArgumentException>(() => Session(" "));
            Assert.That((e.ParamName, e.Message.Contains("the participant id is empty")), Is.EqualTo(("participant", true)), e.Message);
            e = Assert.Throws<ArgumentException>(() => Session("P1 "));
            Assert.That(e.Message, Does.Contain("the participant id 'P1 ' has surrounding spaces or a line break"));
            foreach (string empty in new[] { "", null })
            {
                e = Assert.Throws<ArgumentException>(() => new QuestionnaireSession(Paper(), "P1", empty));
                Assert.That((e.ParamName, e.Message.Contains("the responses file path is empty")), Is.EqualTo(("responsesPath", true)), e.Message);
            }
            e = Assert.Throws<ArgumentException>(() => Session("P1", new[] { "presence" }));
            Assert.That(e.Message, Does.Contain("unknown questionnaire 'presence' (expected one of 'weight-detection', 'immersion', 'self-assessment')"));
            e = Assert.Throws<ArgumentException>(() => Session("P1", new[] { "immersion", "self-assessment", "immersion" }));
            Assert.That(e.Message, Does.Contain("questionnaire 'immersion' is listed twice"));
            e = Assert.Throws<ArgumentException>(() => Session("P1", new string[0]));
            Assert.That(e.Message, Does.Contain("no questionnaires to ask"));
        }

        [Test]
        public void AnAnswerIsTakenOnlyOnceItsWriteIsAcknowledgedAndOneAtATime()
        {
            var s = Session();
            var e = Assert.Throws<InvalidOperationException>(() => s.Acknowledge());
            Assert.That(e.Message, Does.Contain("no answer is waiting for its write"));
            Assert.That(s.AnsweredCount, Is.EqualTo(0));
            s.Submit(4);
            Assert.That(s.IsSaving, Is.True);
            e = Assert.Throws<InvalidOperationException>(() => s.Submit(2));
            Assert.That(e.Message, Does.Contain("the last answer is still being saved"));
            Assert.That(s.FileText(), Is.EqualTo(ResponsesCsv.Header + "\nP1,weight-detection,1,4\n"), "the first answer, once");
            s.Acknowledge();
            Assert.That(() => s.Acknowledge(), Throws.InvalidOperationException, "one write, one acknowledgement");
            Assert.That((s.AnsweredCount, s.StepIndex), Is.EqualTo((1, 1)));
        }

        [Test]
        public void AChangeToTheFirstAnswerIsCountedOnceAndAFailedWriteOfItKeepsTheAnswerGiven()
        {
            var s = Session();
            s.Answer(4);
            s.Answer(2);
            Assert.That(s.Back() && s.Back(), Is.True);
            s.Answer(5);
            Assert.That(s.AnsweredCount, Is.EqualTo(2), "a changed answer is not a new one");
            Assert.That(s.StepIndex, Is.EqualTo(2));

            Assert.That(s.Back() && s.Back(), Is.True);
            string before = File.ReadAllText(path);
            File.Delete(path);
            Directory.CreateDirectory(path); // the rename must fail
            Assert.Catch<Exception>(() => s.Answer(1));
            Assert.That(s.FileText(), Is.EqualTo(before), "the acknowledged answer 5 stays where it was");
            Assert.That((s.CurrentAnswer, s.AnsweredCount, s.StepIndex), Is.EqualTo(((int?)5, 2, 0)));

            Directory.Delete(path);
            File.WriteAllText(path, before); // as the last write left it
            Assert.That(Session().AnswerAt(0), Is.EqualTo(5), "after a crash here the file holds the acknowledged answer");
            s.Answer(1);
            Assert.That(DataLines(), Is.EqualTo(new[] { "P1,weight-detection,1,1", "P1,weight-detection,2,2" }));
        }

        [Test]
        public void BlankLinesBeforeTheHeaderAndAByteOrderMarkWrittenTwiceAreReadAsScoreReadsThem()
        {
            // An editor that adds a byte-order mark to a file that had one leaves U+FEFF as the first character read.
            File.WriteAllText(path, "\uFEFF\n\r\nparticipant,questionnaire,item,response\nP1,weight-detection,1,3\n", new System.Text.UTF8Encoding(true));
            Assert.That(FileAsScoreReadsIt().Count, Is.EqualTo(1));
            var s = Session();
            Assert.That(s.ResumedCount, Is.EqualTo(1));
            s.Answer(4);
            Assert.That(File.ReadAllText(path), Is.EqualTo(ResponsesCsv.Header + "\nP1,weight-detection,1,3\nP1,weight-detection,2,4\n"));
        }

        [Test]
        public void AHeaderInAnotherOrderIsRefusedNamingItsLineAndTheOrderNeeded()
        {
            File.WriteAllText(path, "\n\nquestionnaire,participant,item,response\nimmersion,P1,1,3\n");
            var e = Assert.Throws<EvaluationFormatException>(() => Session());
            Assert.That(e.Line, Is.EqualTo(3), "the header's line, blank lines counted");
            Assert.That(e.Reason, Does.Contain("answers are appended as participant,questionnaire,item,response, so the header must name exactly these columns in this order"));
        }

        [Test]
        public void AnotherParticipantsRowWithALineBreakInAQuotedFieldIsKeptWhole()
        {
            string text = ResponsesCsv.Header + "\n\"P5\n(left hand)\",immersion,1,3\nP1,weight-detection,1,2\n";
            File.WriteAllText(path, text);
            var s = Session();
            Assert.That(s.ResumedCount, Is.EqualTo(1));
            s.Answer(4);
            Assert.That(File.ReadAllText(path), Is.EqualTo(text + "P1,weight-detection,2,4\n"));
            var set = FileAsScoreReadsIt();
            Assert.That(set.Find("P5\n(left hand)", QuestionnaireCatalog.ImmersionId).AnswerAt(0), Is.EqualTo(3));
        }

        [Test]
        public void ThePackagesQuestionnairesGiveEachItemItsWordsAndScaleLabels()
        {
            var catalog = EvaluationFiles.PackageCatalog();
            var s = new QuestionnaireSession(catalog, "P1", path);
            Assert.That(s.StepCount, Is.EqualTo(21));
            Assert.That(s.CurrentQuestionnaire.Title, Is.EqualTo("Part 1: Weight detection"));
            Assert.That(s.CurrentQuestionnaire.ScaleMinLabel, Is.EqualTo("Strongly disagree"));
            Assert.That(s.CurrentQuestionnaire.ScaleMaxLabel, Is.EqualTo("Strongly agree"));
            for (int step = 0; step < s.StepCount; step++)
                Assert.That(s.ItemAt(step, out _).Text, Is.Not.Empty);
            s.ItemAt(20, out Questionnaire last);
            Assert.That(last.ScaleMax, Is.EqualTo(10));
        }
    }
}
