using System;
using System.IO;
using Kosmos.PseudoHaptic.Evaluation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests.Evaluation
{
    /// <summary>
    /// <see cref="DiscriminationSession"/>'s refusals (ids, files of another plan, trials out of the plan or
    /// answered twice, a header in another order), each with its line and words, the file left untouched; and
    /// an answer whose write fails is withdrawn whole.
    /// </summary>
    public class DiscriminationSessionRefusalTests
    {
        string _dir;
        string TrialsPath => Path.Combine(_dir, "trials.csv");

        [SetUp]
        public void SetUp()
        {
            _dir = Path.Combine(Path.GetTempPath(), "ph-2afc-refusal-" + Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(_dir);
        }

        [TearDown]
        public void TearDown() => Directory.Delete(_dir, true);

        static ConstantStimuliPlan Plan() => new ConstantStimuliPlan { Standard = 0.5, Levels = new[] { 0.4, 0.5, 0.6 }, Repetitions = 2, CatchLevels = new[] { 1.0 }, CatchRepetitions = 1, Seed = 3 };

        /// <summary>The trials file's row of <paramref name="t"/> answered <paramref name="response"/>, the trial itself left unanswered.</summary>
        internal static string Row(Trial t, int response)
        {
            var copy = new Trial(t.Index, t.Participant, t.Condition, t.Standard, t.Comparison, t.ComparisonFirst, t.Catch) { Response = response };
            return TrialsCsv.FormatRow(copy);
        }

        EvaluationFormatException RefusedWith(string text)
        {
            File.WriteAllText(TrialsPath, text);
            var e = Assert.Throws<EvaluationFormatException>(() => new DiscriminationSession("P1", "on", TrialsPath, Plan()));
            Assert.That(File.ReadAllText(TrialsPath), Is.EqualTo(text), "a refused file is left untouched");
            Assert.That(e.SourceName, Is.EqualTo(TrialsPath));
            return e;
        }

        [TestCase(" on")]
        [TestCase("on ")]
        [TestCase("o\nn")]
        [TestCase("o\rn")]
        public void AConditionWithEdgeSpacesOrALineBreakIsRefused(string condition)
        {
            var e = Assert.Throws<ArgumentException>(() => new DiscriminationSession("P1", condition, TrialsPath, Plan()));
            Assert.That(e.ParamName, Is.EqualTo("condition"));
            Assert.That(e.Message, Does.StartWith("the condition '" + condition + "' has surrounding spaces or a line break"));
            var s = Assert.Throws<ArgumentException>(() => new DiscriminationSession("P1", condition, TrialsPath, (p, c) => new Staircase(p, c, 0.5, 0.7, 0.08, 2, 8, 6, 5)));
            Assert.That(s.ParamName, Is.EqualTo("condition"));
            Assert.That(File.Exists(TrialsPath), Is.False);
        }

        [TestCase(" P1")]
        [TestCase("P1 ")]
        [TestCase("P\n1")]
        [TestCase("P\r1")]
        public void AParticipantWithEdgeSpacesOrALineBreakIsRefused(string participant)
        {
            var e = Assert.Throws<ArgumentException>(() => new DiscriminationSession(participant, "on", TrialsPath, Plan()));
            Assert.That(e.ParamName, Is.EqualTo("participant"));
            Assert.That(e.Message, Does.StartWith("the participant id '" + participant + "' has surrounding spaces or a line break"));
        }

        [TestCase(null)]
        [TestCase("")]
        [TestCase("  ")]
        public void AnEmptyParticipantIsRefused(string participant)
        {
            var e = Assert.Throws<ArgumentException>(() => new DiscriminationSession(participant, "on", TrialsPath, Plan()));
            Assert.That(e.ParamName, Is.EqualTo("participant"));
            Assert.That(e.Message, Does.StartWith("the participant id is empty"));
        }

        [TestCase(null)]
        [TestCase("")]
        public void AnEmptyPathIsRefused(string path)
        {
            var e = Assert.Throws<ArgumentException>(() => new DiscriminationSession("P1", "on", path, Plan()));
            Assert.That(e.ParamName, Is.EqualTo("trialsPath"));
            Assert.That(e.Message, Does.StartWith("the trials file path is empty"));
        }

        [Test]
        public void ANullConditionIsTheEmptyCondition()
        {
            var s = new DiscriminationSession("P1", null, TrialsPath, Plan());
            Assert.That(s.Condition, Is.EqualTo(""));
            Assert.That(s.Plan[0].Condition, Is.EqualTo(""));
        }

        [Test]
        public void NoPlanNoStaircaseMakerAndAMakerThatMakesNoneAreRefused()
        {
            Assert.That(() => new DiscriminationSession("P1", "on", TrialsPath, (ConstantStimuliPlan)null),
                Throws.ArgumentNullException.With.Property("ParamName").EqualTo("planSettings"));
            Assert.That(() => new DiscriminationSession("P1", "on", TrialsPath, (Func<string, string, Staircase>)null),
                Throws.ArgumentNullException.With.Property("ParamName").EqualTo("makeStaircase"));
            var e = Assert.Throws<ArgumentException>(() => new DiscriminationSession("P1", "on", TrialsPath, (p, c) => null));
            Assert.That(e.ParamName, Is.EqualTo("makeStaircase"));
            Assert.That(e.Message, Does.StartWith("no staircase made"));
            Assert.That(File.Exists(TrialsPath), Is.False);
        }

        [TestCase("0")]
        [TestCase("8")]
        [TestCase("x")]
        [TestCase("-1")]
        public void ATrialOutsideThePlanIsRefused(string index)
        {
            var t = Plan().Build("P1", "on")[0];
            var e = RefusedWith(TrialsCsv.Header + "\nP1,on," + index + ",0.5," + t.Comparison.ToString("R", System.Globalization.CultureInfo.InvariantCulture) + ",standard,0,1\n");
            Assert.That(e.Line, Is.EqualTo(2));
            Assert.That(e.Reason, Is.EqualTo("trial '" + index + "' is not one of this plan's 1 … 7"));
        }

        [Test]
        public void TheLastTrialOfThePlanIsInThePlan()
        {
            var plan = Plan().Build("P1", "on");
            File.WriteAllText(TrialsPath, TrialsCsv.Header + "\n" + Row(plan[6], 1) + "\n");
            var s = new DiscriminationSession("P1", "on", TrialsPath, Plan());
            Assert.That(s.ResumedCount, Is.EqualTo(1));
            Assert.That(s.CurrentIndex, Is.EqualTo(0), "the first unanswered trial");
            Assert.That(s.Plan[6].Response, Is.EqualTo(1));
        }

        [Test]
        public void ATrialAnsweredTwiceIsRefused()
        {
            var plan = Plan().Build("P1", "on");
            var e = RefusedWith(TrialsCsv.Header + "\n" + Row(plan[1], 1) + "\n" + Row(plan[0], 0) + "\n" + Row(plan[1], 0) + "\n");
            Assert.That(e.Line, Is.EqualTo(4));
            Assert.That(e.Reason, Is.EqualTo("trial 2 of participant 'P1' is answered twice"));
        }

        [Test]
        public void ATrialOfAnotherPlanIsRefusedNamingThePlansValues()
        {
            var t = Plan().Build("P1", "on")[2];
            string c = t.Comparison.ToString("R", System.Globalization.CultureInfo.InvariantCulture);
            var e = RefusedWith(TrialsCsv.Header + "\nP1,on,3,0.75," + c + ",standard,0,1\n");
            Assert.That(e.Line, Is.EqualTo(2));
            Assert.That(e.Reason, Is.EqualTo("trial 3 does not match the plan (standard 0.5, comparison " + c + "): was the file written with another plan or seed?"));
            RefusedWith(TrialsCsv.Header + "\nP1,on,3,0.5," + (t.Comparison + 0.125).ToString("R", System.Globalization.CultureInfo.InvariantCulture) + ",standard,0,1\n");
        }

        [Test]
        public void AHeaderInAnotherOrderIsRefusedAtItsLine()
        {
            var t = Plan().Build("P1", "on")[0];
            string row = Row(t, 1);
            var e = RefusedWith(TrialsCsv.Header + ",note\n" + row + ",x\n");
            Assert.That(e.Line, Is.EqualTo(1));
            Assert.That(e.Reason, Is.EqualTo("answers are appended as participant,condition,trial,standard,comparison,first,catch,response, so the header must be exactly that"));
            var afterBlank = RefusedWith("\n" + TrialsCsv.Header + ",note\n" + row + ",x\n");
            Assert.That(afterBlank.Line, Is.EqualTo(2), "the header's own line, after a blank one");
        }

        [Test]
        public void TheHeaderIsComparedWithoutCaseOrEdgeSpaces()
        {
            var t = Plan().Build("P1", "on")[0];
            File.WriteAllText(TrialsPath, TrialsCsv.Header.ToUpperInvariant() + " \r\n" + Row(t, 1) + "\r\n");
            var s = new DiscriminationSession("P1", "on", TrialsPath, Plan());
            Assert.That(s.ResumedCount, Is.EqualTo(1));
            Assert.That(s.FileText(), Is.EqualTo(TrialsCsv.Header + "\n" + Row(t, 1) + "\n"), "rows kept verbatim under the session's own header");
        }

        static Staircase StaircaseOf(string participant, string condition, double start, int maxTrials)
            => new Staircase(participant, condition, 0.5, start, 0.0625, 2, 8, 6, 5, maxTrials: maxTrials);

        [Test]
        public void AFileThatDoesNotFollowTheStaircaseIsRefusedNamingWhereItStands()
        {
            var first = new DiscriminationSession("P1", "on", TrialsPath, (p, c) => StaircaseOf(p, c, 0.75, 200));
            for (int i = 0; i < 3; i++)
            {
                first.NoteLift(PairSide.Left);
                first.NoteLift(PairSide.Right);
                Assert.That(first.Answer(PairSide.Left), Is.True);
            }
            string before = File.ReadAllText(TrialsPath);

            var other = Assert.Throws<EvaluationFormatException>(() => new DiscriminationSession("P1", "on", TrialsPath, (p, c) => StaircaseOf(p, c, 0.625, 200)));
            Assert.That(other.Line, Is.EqualTo(2));
            Assert.That(other.Reason, Is.EqualTo("this row does not follow the staircase (trial 1 at 0.625): was the file written with other settings or seed?"));

            var shorter = Assert.Throws<EvaluationFormatException>(() => new DiscriminationSession("P1", "on", TrialsPath, (p, c) => StaircaseOf(p, c, 0.75, 2)));
            Assert.That(shorter.Line, Is.EqualTo(4));
            Assert.That(shorter.Reason, Is.EqualTo("this row does not follow the staircase (trial none: it had finished): was the file written with other settings or seed?"));
            Assert.That(File.ReadAllText(TrialsPath), Is.EqualTo(before));

            var same = new DiscriminationSession("P1", "on", TrialsPath, (p, c) => StaircaseOf(p, c, 0.75, 200));
            Assert.That(same.ResumedCount, Is.EqualTo(3));
            Assert.That(same.Staircase.Trials.Count, Is.EqualTo(3));
        }

        [Test]
        public void AnAnswerWhoseWriteFailsIsWithdrawn()
        {
            var s = new DiscriminationSession("P1", "on", TrialsPath, Plan());
            s.NoteLift(PairSide.Left);
            s.NoteLift(PairSide.Right);
            var shown = s.Current;
            Directory.CreateDirectory(TrialsPath); // the file cannot be written: a folder stands in its place
            Assert.Throws<IOException>(() => s.Answer(PairSide.Left));
            Assert.That(s.IsSaving, Is.False);
            Assert.That(shown.Response, Is.EqualTo(-1), "the trial has no answer again");
            Assert.That(s.AnsweredCount, Is.EqualTo(0));
            Assert.That(s.CurrentIndex, Is.EqualTo(0));
            Assert.That(s.Current, Is.SameAs(shown));
            Assert.That(s.FileText(), Is.EqualTo(TrialsCsv.Header + "\n"), "the row is taken back");
            Assert.That(s.CanAnswer, Is.True, "the lifts still count: the participant answers again");

            Directory.Delete(TrialsPath);
            Assert.That(s.Answer(PairSide.Left), Is.True);
            int response = shown.ComparisonFirst ? 1 : 0;
            Assert.That(shown.Response, Is.EqualTo(response));
            Assert.That(File.ReadAllText(TrialsPath), Is.EqualTo(TrialsCsv.Header + "\n" + Row(shown, response) + "\n"), "one row, not two");
            Assert.That(s.AnsweredCount, Is.EqualTo(1));
        }

        [Test]
        public void AStaircaseAnswerWhoseWriteFailsIsWithdrawn()
        {
            var s = new DiscriminationSession("P1", "on", TrialsPath, (p, c) => new Staircase(p, c, 0.5, 0.7, 0.08, 2, 8, 6, 5));
            s.NoteLift(PairSide.Left);
            s.NoteLift(PairSide.Right);
            var shown = s.Current;
            Directory.CreateDirectory(TrialsPath);
            Assert.Throws<IOException>(() => s.Answer(PairSide.Right));
            Assert.That(shown.Response, Is.EqualTo(-1));
            Assert.That(s.Staircase.Trials, Is.Empty, "the staircase was not fed the answer");
            Assert.That(s.FileText(), Is.EqualTo(TrialsCsv.Header + "\n"));
            Assert.That(s.IsSaving, Is.False);
        }
    }
}
