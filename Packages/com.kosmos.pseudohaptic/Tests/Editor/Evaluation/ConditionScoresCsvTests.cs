using System.IO;
using Kosmos.PseudoHaptic.Evaluation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests.Evaluation
{
    /// <summary>
    /// The scores file with conditions (<see cref="ConditionScoresCsv"/>, what compare reads): columns by name,
    /// an empty score an incomplete part, and every refusal with its line and words.
    /// </summary>
    public class ConditionScoresCsvTests
    {
        const string Header = "participant,condition,questionnaire,score\n";

        static System.Collections.Generic.List<ConditionScore> Read(string text, int maxRows = int.MaxValue)
            => ConditionScoresCsv.Read(new StringReader(text), "scores.csv", maxRows);

        static EvaluationFormatException Refused(string rows)
            => Assert.Throws<EvaluationFormatException>(() => Read(Header + rows));

        [Test]
        public void TheColumnsAreTheFourNames()
        {
            Assert.That(ConditionScoresCsv.Columns, Is.EqualTo(new[] { "participant", "condition", "questionnaire", "score" }));
        }

        [Test]
        public void ScoresAreReadTrimmedWithTheirLines()
        {
            var scores = Read(Header + " P1 , on , SUS , 72.5 \nP1,off,SUS,-1e1\nP2,,IPQ,0\nP2,on,IPQ,\n");
            Assert.That(scores.Count, Is.EqualTo(4));
            Assert.That(scores[0].Participant, Is.EqualTo("P1"));
            Assert.That(scores[0].Condition, Is.EqualTo("on"));
            Assert.That(scores[0].Questionnaire, Is.EqualTo("SUS"));
            Assert.That(scores[0].Score, Is.EqualTo(72.5));
            Assert.That(scores[0].Line, Is.EqualTo(2));
            Assert.That(scores[1].Score, Is.EqualTo(-10.0));
            Assert.That(scores[1].Line, Is.EqualTo(3));
            Assert.That(scores[2].Condition, Is.EqualTo(""), "an empty condition is a condition");
            Assert.That(scores[2].Score.HasValue, Is.True, "zero is a score");
            Assert.That(scores[2].Score.Value, Is.EqualTo(0.0));
            Assert.That(scores[3].Score.HasValue, Is.False, "an empty score is an incomplete part");
            Assert.That(scores[3].Line, Is.EqualTo(5));
        }

        [Test]
        public void ColumnsAreFoundByNameInAnyOrderAndCase()
        {
            var scores = Read("Score,Questionnaire,note,Condition,PARTICIPANT\n3,NASA-TLX,x,on,P9\n");
            Assert.That(scores.Count, Is.EqualTo(1));
            Assert.That(scores[0].Participant, Is.EqualTo("P9"));
            Assert.That(scores[0].Condition, Is.EqualTo("on"));
            Assert.That(scores[0].Questionnaire, Is.EqualTo("NASA-TLX"));
            Assert.That(scores[0].Score, Is.EqualTo(3.0));
        }

        [Test]
        public void OnlyTheHeaderIsNoScores()
        {
            Assert.That(Read(Header), Is.Empty);
        }

        [Test]
        public void TheSameTripleInAnotherQuestionnaireOrConditionIsNoDuplicate()
        {
            var scores = Read(Header + "P1,on,SUS,1\nP1,on,IPQ,2\nP1,off,SUS,3\nP2,on,SUS,4\nP1o,n,SUS,5\nP1,o,nSUS,6\n");
            Assert.That(scores.Count, Is.EqualTo(6), "the three fields are kept apart, not run together");
        }

        [Test]
        public void AMissingColumnIsRefused()
        {
            var e = Assert.Throws<EvaluationFormatException>(() => Read("participant,condition,score\nP1,on,1\n"));
            Assert.That(e.Line, Is.EqualTo(1));
            Assert.That(e.Reason, Does.StartWith("missing column 'questionnaire'"));
        }

        [TestCase(",on,SUS,1\n", 2, "participant is empty")]
        [TestCase("P1,on,SUS,1\n  ,on,SUS,1\n", 3, "participant is empty")]
        [TestCase("P1,on,,1\n", 2, "questionnaire is empty")]
        [TestCase("P1,on, ,1\n", 2, "questionnaire is empty")]
        [TestCase("P1,on,SUS,1\nP2,on,SUS,2\nP1,on,SUS,3\n", 4, "duplicate score: participant 'P1', condition 'on' and 'SUS' already on line 2")]
        [TestCase("P1,on,SUS,\n P1 ,on, SUS ,3\n", 3, "duplicate score: participant 'P1', condition 'on' and 'SUS' already on line 2")]
        [TestCase("P1,on,SUS,abc\n", 2, "score 'abc' is not a finite number (leave it empty for an incomplete part)")]
        [TestCase("P1,on,SUS,NaN\n", 2, "score 'NaN' is not a finite number (leave it empty for an incomplete part)")]
        [TestCase("P1,on,SUS,Infinity\n", 2, "score 'Infinity' is not a finite number (leave it empty for an incomplete part)")]
        [TestCase("P1,on,SUS,-Infinity\n", 2, "score '-Infinity' is not a finite number (leave it empty for an incomplete part)")]
        [TestCase("P1,on,SUS,1e400\n", 2, "score '1e400' is not a finite number (leave it empty for an incomplete part)")]
        public void ABadRowIsRefusedNamingItsLine(string rows, int line, string reason)
        {
            var e = Refused(rows);
            Assert.That(e.Line, Is.EqualTo(line));
            Assert.That(e.Reason, Is.EqualTo(reason));
            Assert.That(e.Message, Is.EqualTo("scores.csv:" + line + ": " + reason));
        }

        [Test]
        public void TheRowLimitIsPassedOn()
        {
            Assert.That(Read(Header + "P1,on,SUS,1\nP2,on,SUS,2\n", 2).Count, Is.EqualTo(2));
            var e = Assert.Throws<EvaluationFormatException>(() => Read(Header + "P1,on,SUS,1\nP2,on,SUS,2\n", 1));
            Assert.That(e.Line, Is.EqualTo(3));
        }

        [Test]
        public void TheCharacterLimitIsPassedOn()
        {
            Assert.Throws<EvaluationFormatException>(() => ConditionScoresCsv.Read(new StringReader(Header + "P1,on,SUS,1\n"), "scores.csv", int.MaxValue, 5));
            Assert.That(ConditionScoresCsv.Read(new StringReader(Header + "P1,on,SUS,1\n"), "scores.csv", int.MaxValue, 8).Count, Is.EqualTo(1));
        }

        [Test]
        public void AScoreKeepsWhatItWasGiven()
        {
            var s = new ConditionScore("P1", "on", "SUS", null, 9);
            Assert.That(s.Participant, Is.EqualTo("P1"));
            Assert.That(s.Condition, Is.EqualTo("on"));
            Assert.That(s.Questionnaire, Is.EqualTo("SUS"));
            Assert.That(s.Score.HasValue, Is.False);
            Assert.That(s.Line, Is.EqualTo(9));
        }
    }
}
