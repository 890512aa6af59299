using System;
using System.IO;
using System.Linq;
using Kosmos.PseudoHaptic.Evaluation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests.Evaluation
{
    /// <summary>
    /// The trials file's contract (<see cref="TrialsCsv"/>): rows written byte for byte, the whole file, the
    /// reader's round trip and every refusal with the line and the words a user reads.
    /// </summary>
    public class TrialsCsvContractTests
    {
        static Trial Answered(int index, string participant, string condition, double standard, double comparison, bool comparisonFirst, bool isCatch, int response)
            => new Trial(index, participant, condition, standard, comparison, comparisonFirst, isCatch) { Response = response };

        static EvaluationFormatException Refused(string text)
            => Assert.Throws<EvaluationFormatException>(() => TrialsCsv.Read(new StringReader(text), "trials.csv"));

        [Test]
        public void TheHeaderIsTheEightColumnsInOrder()
        {
            Assert.That(TrialsCsv.Header, Is.EqualTo("participant,condition,trial,standard,comparison,first,catch,response"));
            Assert.That(TrialsCsv.RequiredColumns, Is.EqualTo(new[] { "participant", "standard", "comparison", "response" }));
        }

        [Test]
        public void ARowIsWrittenExactly()
        {
            Assert.That(TrialsCsv.FormatRow(Answered(3, "P1", "on", 0.5, 0.45, true, false, 1)),
                Is.EqualTo("P1,on,3,0.5,0.45,comparison,0,1"));
            Assert.That(TrialsCsv.FormatRow(Answered(12, "P2", "off", 0.5, 1, false, true, 0)),
                Is.EqualTo("P2,off,12,0.5,1,standard,1,0"));
        }

        [Test]
        public void NumbersAreWrittenRoundTripAndFieldsEscaped()
        {
            Assert.That(TrialsCsv.FormatRow(Answered(1, "a,b", "say \"x\"", 0.1 + 0.2, 1e-7, false, false, 1)),
                Is.EqualTo("\"a,b\",\"say \"\"x\"\"\",1,0.30000000000000004,1E-07,standard,0,1"));
            Assert.That(TrialsCsv.FormatRow(Answered(1, "P1", "", 2, 3, true, true, 1)),
                Is.EqualTo("P1,,1,2,3,comparison,1,1"), "an empty condition is an empty field");
        }

        [Test]
        public void ANullTrialIsRefused()
        {
            var e = Assert.Throws<ArgumentNullException>(() => TrialsCsv.FormatRow(null));
            Assert.That(e.ParamName, Is.EqualTo("t"));
        }

        [TestCase(-1)]
        [TestCase(2)]
        public void AnUnansweredTrialIsRefused(int response)
        {
            var t = Answered(7, "P1", "on", 0.5, 0.6, true, false, response);
            var e = Assert.Throws<InvalidOperationException>(() => TrialsCsv.FormatRow(t));
            Assert.That(e.Message, Is.EqualTo("trial 7 has no answer yet"));
        }

        [Test]
        public void AFreshTrialHasNoAnswer()
        {
            var t = new Trial(1, "P1", "on", 0.5, 0.6, true, false);
            Assert.Throws<InvalidOperationException>(() => TrialsCsv.FormatRow(t));
        }

        [Test]
        public void AFileIsTheHeaderAndOneLinePerTrial()
        {
            Assert.That(TrialsCsv.Format(new Trial[0]), Is.EqualTo(TrialsCsv.Header + "\n"));
            Assert.That(TrialsCsv.Format(new[] { Answered(1, "P1", "on", 0.5, 0.45, true, false, 1), Answered(2, "P1", "on", 0.5, 0.55, false, false, 0) }),
                Is.EqualTo("participant,condition,trial,standard,comparison,first,catch,response\n"
                           + "P1,on,1,0.5,0.45,comparison,0,1\n"
                           + "P1,on,2,0.5,0.55,standard,0,0\n"));
        }

        [Test]
        public void WhatIsWrittenIsReadBack()
        {
            var trials = new[]
            {
                Answered(1, "P1", "on", 0.5, 0.1 + 0.2, true, false, 1),
                Answered(2, "P 2", "a,b", 0.75, 1e-7, false, true, 0),
                Answered(3, "P3", "", 1.25, 2.5, false, false, 1),
            };
            var answers = TrialsCsv.Read(new StringReader(TrialsCsv.Format(trials)), "trials.csv");
            Assert.That(answers.Count, Is.EqualTo(3));
            for (int i = 0; i < 3; i++)
            {
                Assert.That(answers[i].Participant, Is.EqualTo(trials[i].Participant));
                Assert.That(answers[i].Condition, Is.EqualTo(trials[i].Condition));
                Assert.That(answers[i].Standard, Is.EqualTo(trials[i].Standard));
                Assert.That(answers[i].Comparison, Is.EqualTo(trials[i].Comparison));
                Assert.That(answers[i].Response, Is.EqualTo(trials[i].Response));
                Assert.That(answers[i].Line, Is.EqualTo(i + 2), "the header is line 1");
            }
        }

        [Test]
        public void CatchTrialsAreLeftOutOnlyWhenAskedAndTheirMarkIsChecked()
        {
            const string text = "participant,condition,standard,comparison,catch,response\nP1,on,0.5,0.6,0,1\nP1,on,0.5,1,1,0\nP1,on,0.5,0.4, 0 ,0\n";
            Assert.That(TrialsCsv.Read(new StringReader(text), "t.csv"), Has.Count.EqualTo(3), "by default catch is a column like any other");
            var kept = TrialsCsv.Read(new StringReader(text), "t.csv", int.MaxValue, long.MaxValue, leaveOutCatch: true, out int leftOut);
            Assert.That(leftOut, Is.EqualTo(1));
            Assert.That(kept.Select(a => a.Line), Is.EqualTo(new[] { 2, 4 }), "the others keep their lines");
            Assert.That(kept.Select(a => a.Condition), Is.All.EqualTo("on"), "and their condition");
            var none = TrialsCsv.Read(new StringReader("participant,standard,comparison,response\nP1,0.5,0.6,1\n"), "t.csv", int.MaxValue, long.MaxValue, true, out leftOut);
            Assert.That(none, Has.Count.EqualTo(1));
            Assert.That(leftOut, Is.Zero, "a file without the column has no catch trials");
            const string bad = "participant,standard,comparison,catch,response\nP1,0.5,0.6,yes,1\n";
            Assert.That(TrialsCsv.Read(new StringReader(bad), "t.csv"), Has.Count.EqualTo(1), "not read, not checked");
            var e = Assert.Throws<EvaluationFormatException>(() => TrialsCsv.Read(new StringReader(bad), "t.csv", int.MaxValue, long.MaxValue, true, out _));
            Assert.That(e.Message, Is.EqualTo("t.csv:2: catch 'yes' must be 1 (a catch trial) or 0"));
        }

        [Test]
        public void ColumnsAreFoundByNameInAnyCaseAndConditionIsOptional()
        {
            var answers = TrialsCsv.Read(new StringReader("Response,EXTRA,Comparison,Standard,Participant\n1,x,0.6,0.5, P7 \n0,y,0.4,0.5,P8\n"), "t.csv");
            Assert.That(answers.Count, Is.EqualTo(2));
            Assert.That(answers[0].Participant, Is.EqualTo("P7"), "trimmed");
            Assert.That(answers[0].Condition, Is.EqualTo(""));
            Assert.That(answers[0].Standard, Is.EqualTo(0.5));
            Assert.That(answers[0].Comparison, Is.EqualTo(0.6));
            Assert.That(answers[0].Response, Is.EqualTo(1));
            Assert.That(answers[1].Response, Is.EqualTo(0));
            var withCondition = TrialsCsv.Read(new StringReader("participant,condition,standard,comparison,response\nP1, on ,0.5, 0.7 , 1 \n"), "t.csv");
            Assert.That(withCondition[0].Condition, Is.EqualTo("on"), "trimmed");
            Assert.That(withCondition[0].Comparison, Is.EqualTo(0.7));
            Assert.That(withCondition[0].Response, Is.EqualTo(1));
        }

        [Test]
        public void TheSmallestPositiveWeightIsAWeight()
        {
            var answers = TrialsCsv.Read(new StringReader("participant,standard,comparison,response\nP1,5e-324,1e3,0\n"), "t.csv");
            Assert.That(answers[0].Standard, Is.EqualTo(double.Epsilon));
            Assert.That(answers[0].Comparison, Is.EqualTo(1000.0));
        }

        [Test]
        public void AMissingColumnIsRefused()
        {
            var e = Refused("participant,standard,comparison\nP1,0.5,0.6\n");
            Assert.That(e.Line, Is.EqualTo(1));
            Assert.That(e.Reason, Does.StartWith("missing column 'response'"));
        }

        [TestCase("P1,0.5,0.6,1\n,0.5,0.6,1\n", 3, "participant is empty")]
        [TestCase("  ,0.5,0.6,1\n", 2, "participant is empty")]
        [TestCase("P1,abc,0.6,1\n", 2, "standard 'abc' is not a number")]
        [TestCase("P1,0.5,,1\n", 2, "comparison '' is not a number")]
        [TestCase("P1,NaN,0.6,1\n", 2, "standard 'NaN' is not a finite number")]
        [TestCase("P1,0.5,Infinity,1\n", 2, "comparison 'Infinity' is not a finite number")]
        [TestCase("P1,0.5,-Infinity,1\n", 2, "comparison '-Infinity' is not a finite number")]
        [TestCase("P1,0.5,1e400,1\n", 2, "comparison '1e400' is not a finite number")]
        [TestCase("P1,0,0.6,1\n", 2, "standard 0 is not a positive weight (kg)")]
        [TestCase("P1,0.5,-0.25,1\n", 2, "comparison -0.25 is not a positive weight (kg)")]
        [TestCase("P1,0.5,-0,1\n", 2, "comparison -0 is not a positive weight (kg)")]
        [TestCase("P1,0.5,0.6,2\n", 2, "response '2' must be 1 (comparison judged heavier) or 0")]
        [TestCase("P1,0.5,0.6,\n", 2, "response '' must be 1 (comparison judged heavier) or 0")]
        [TestCase("P1,0.5,0.6,1.0\n", 2, "response '1.0' must be 1 (comparison judged heavier) or 0")]
        public void ABadRowIsRefusedNamingItsLine(string rows, int line, string reason)
        {
            var e = Refused("participant,standard,comparison,response\n" + rows);
            Assert.That(e.Line, Is.EqualTo(line));
            Assert.That(e.Reason, Is.EqualTo(reason));
            Assert.That(e.SourceName, Is.EqualTo("trials.csv"));
            Assert.That(e.Message, Is.EqualTo("trials.csv:" + line + ": " + reason));
        }
    }
}
