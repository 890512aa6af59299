using System;
using Kosmos.PseudoHaptic.Evaluation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests.Evaluation
{
    public class CsvTests
    {
        static ResponseSet Responses(string text) => ResponsesCsv.Parse(text, "R.csv", SampleQuestionnaires.Paper());

        static EvaluationFormatException ResponsesFail(string text)
            => Assert.Throws<EvaluationFormatException>(() => Responses(text));

        [Test]
        public void ReadsColumnsByNameInAnyOrder()
        {
            var set = Responses("\uFEFFresponse, item ,Participant,questionnaire,note\r\n8,1,P1,self-assessment,\"tired, but fine\"\r\n\r\n9,1,\"P 2\",self-assessment,\r\n");
            Assert.That(set.Count, Is.EqualTo(2));
            Assert.That(set.Participants, Is.EqualTo(new[] { "P1", "P 2" }));
            Assert.That(set.Find("P1", "self-assessment").AnswerAt(0), Is.EqualTo(8));
        }

        [Test]
        public void AcceptsAWholeNumberWrittenWithADecimalPoint()
        {
            Assert.That(Responses("participant,questionnaire,item,response\nP1,immersion,3,4.0\n").Find("P1", "immersion").AnswerAt(2), Is.EqualTo(4));
        }

        [Test]
        public void AHeaderOnlyFileHasNoAnswers()
        {
            Assert.That(Responses("participant,questionnaire,item,response\n").Count, Is.EqualTo(0));
        }

        [TestCase("participant,questionnaire,item,response\nP1,immersion,1,3\nP1,immersion,2,6\n", 3, "outside the scale")]
        [TestCase("participant,questionnaire,item,response\nP1,immersion,1,0\n", 2, "outside the scale")]
        [TestCase("participant,questionnaire,item,response\nP1,self-assessment,1,11\n", 2, "outside the scale 1 to 10")]
        [TestCase("participant,questionnaire,item,response\nP1,immersion,1,3\n\nP1,immersion,1,4\n", 4, "duplicate")]
        [TestCase("participant,questionnaire,item,response\nP1,presence,1,3\n", 2, "unknown questionnaire 'presence'")]
        [TestCase("participant,questionnaire,item,response\nP1,Immersion,1,3\n", 2, "unknown questionnaire")]
        [TestCase("participant,questionnaire,item,response\nP1,immersion,11,3\n", 2, "no item 11")]
        [TestCase("participant,questionnaire,item,response\nP1,immersion,0,3\n", 2, "no item 0")]
        [TestCase("participant,questionnaire,item,response\nP1,immersion,one,3\n", 2, "item 'one' is not a whole number")]
        [TestCase("participant,questionnaire,item,response\nP1,immersion,1,three\n", 2, "response 'three' is not a number")]
        [TestCase("participant,questionnaire,item,response\nP1,immersion,1,NaN\n", 2, "not a number")]
        [TestCase("participant,questionnaire,item,response\nP1,immersion,1,\n", 2, "response is empty")]
        [TestCase("participant,questionnaire,item,response\nP1,immersion,1,3.5\n", 2, "not a whole number")]
        [TestCase("participant,questionnaire,item,response\nP1,immersion,1\n", 2, "expected 4 fields")]
        [TestCase("participant,questionnaire,item,response\nP1,immersion,1,3,x\n", 2, "expected 4 fields")]
        [TestCase("participant,questionnaire,item,response\n,immersion,1,3\n", 2, "participant is empty")]
        [TestCase("participant,questionnaire,item,response\n\"P1,immersion,1,3\n", 2, "unterminated")]
        [TestCase("participant,questionnaire,response\nP1,immersion,3\n", 1, "missing column 'item'")]
        [TestCase("participant,questionnaire,item,item,response\n", 1, "appears twice")]
        [TestCase("", 1, "empty file")]
        [TestCase("\n\n", 1, "empty file")]
        public void RejectsAMalformedRowNamingItsLine(string text, int line, string reason)
        {
            var e = ResponsesFail(text);
            Assert.That(e.Line, Is.EqualTo(line), e.Message);
            Assert.That(e.Reason, Does.Contain(reason));
            Assert.That(e.Message, Does.StartWith("R.csv:" + line + ": "));
            Assert.That(e.Message, Does.Not.Contain("\n"));
        }

        [Test]
        public void ScoresRoundTrip()
        {
            var scores = new[]
            {
                new ParticipantScore("P1", "weight-detection", 4.6),
                new ParticipantScore("P1", "immersion", null, new[] { 4 }),
                new ParticipantScore("P, 2", "self-assessment", 8.0),
                new ParticipantScore("P3", "immersion", 10.0 / 3),
            };
            string text = ScoresCsv.Format(scores);
            Assert.That(text, Is.EqualTo("participant,questionnaire,score\nP1,weight-detection,4.6\nP1,immersion,\n\"P, 2\",self-assessment,8\nP3,immersion,3.3333333333333335\n"));
            var back = ScoresCsv.Parse(text, "S.csv", SampleQuestionnaires.Paper());
            Assert.That(back.Count, Is.EqualTo(4));
            Assert.That(back[1].IsComplete, Is.False);
            Assert.That(back[2].Participant, Is.EqualTo("P, 2"));
            Assert.That(back[3].Score, Is.EqualTo(10.0 / 3));
        }

        [TestCase("participant,questionnaire,score\nP1,immersion,4\nP1,immersion,3\n", 3, "duplicate score")]
        [TestCase("participant,questionnaire,score\nP1,immersion,5.5\n", 2, "outside its scale")]
        [TestCase("participant,questionnaire,score\nP1,self-assessment,0\n", 2, "outside its scale")]
        [TestCase("participant,questionnaire,score\nP1,immersion,high\n", 2, "not a number")]
        [TestCase("participant,questionnaire,score\nP1,fatigue,3\n", 2, "unknown questionnaire")]
        [TestCase("participant,score\nP1,3\n", 1, "missing column 'questionnaire'")]
        public void RejectsAMalformedScoresFile(string text, int line, string reason)
        {
            var e = Assert.Throws<EvaluationFormatException>(() => ScoresCsv.Parse(text, "S.csv", SampleQuestionnaires.Paper()));
            Assert.That(e.Line, Is.EqualTo(line), e.Message);
            Assert.That(e.Reason, Does.Contain(reason));
        }

        [Test]
        public void EscapeQuotesOnlyWhenNeeded()
        {
            Assert.That(CsvTable.Escape("P1"), Is.EqualTo("P1"));
            Assert.That(CsvTable.Escape("a,b"), Is.EqualTo("\"a,b\""));
            Assert.That(CsvTable.Escape("say \"hi\""), Is.EqualTo("\"say \"\"hi\"\"\""));
            Assert.That(CsvTable.Escape(" pad"), Is.EqualTo("\" pad\""));
        }

        [Test]
        public void ARowFormattedForAppendingReadsBack()
        {
            var r = new Response("P \"7\"", "immersion", 3, 2);
            var set = Responses(ResponsesCsv.Header + "\n" + ResponsesCsv.FormatRow(r) + "\n");
            Assert.That(set.Find("P \"7\"", "immersion").AnswerAt(2), Is.EqualTo(2));
        }

        [Test]
        public void AtomicWriteReplacesAndLeavesNoTemporaryFile()
        {
            string dir = System.IO.Path.Combine(System.IO.Path.GetTempPath(), "ph-atomic-" + Guid.NewGuid().ToString("N"));
            System.IO.Directory.CreateDirectory(dir);
            try
            {
                string path = System.IO.Path.Combine(dir, "S.csv");
                AtomicFile.WriteAllText(path, "one");
                AtomicFile.WriteAllText(path, "two");
                Assert.That(System.IO.File.ReadAllText(path), Is.EqualTo("two"));
                Assert.Throws<InvalidOperationException>(() => AtomicFile.WriteWith(path, temp =>
                {
                    System.IO.File.WriteAllText(temp, "half");
                    throw new InvalidOperationException("crash");
                }));
                Assert.That(System.IO.File.ReadAllText(path), Is.EqualTo("two"), "a failed write leaves the old file");
                Assert.That(System.IO.Directory.GetFiles(dir), Is.EqualTo(new[] { path }), "and no temporary file");
            }
            finally { System.IO.Directory.Delete(dir, true); }
        }
    }
}
