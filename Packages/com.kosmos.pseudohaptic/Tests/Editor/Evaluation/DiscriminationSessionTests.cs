using System;
using System.IO;
using System.Linq;
using Kosmos.PseudoHaptic.Evaluation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests.Evaluation
{
    /// <summary>The headset task's logic: sides from the plan, answers to responses, the file after every answer, resume.</summary>
    public class DiscriminationSessionTests
    {
        string _dir;
        string Path1 => Path.Combine(_dir, "trials.csv");

        [SetUp]
        public void SetUp()
        {
            _dir = Path.Combine(Path.GetTempPath(), "ph-2afc-" + Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(_dir);
        }

        [TearDown]
        public void TearDown() => Directory.Delete(_dir, true);

        static ConstantStimuliPlan Plan() => new ConstantStimuliPlan { Standard = 0.5, Levels = new[] { 0.4, 0.5, 0.6 }, Repetitions = 2, CatchLevels = new[] { 1.0 }, CatchRepetitions = 1, Seed = 3 };

        [Test]
        public void AnswersFollowTheSidesAndAreWrittenAtOnce()
        {
            var s = new DiscriminationSession("P1", "on", Path1, Plan());
            Assert.That(s.TrialCount, Is.EqualTo(7));
            Assert.That(s.CanAnswer, Is.False, "nothing lifted yet");
            Assert.That(s.Answer(PairSide.Left), Is.False);
            s.NoteLift(PairSide.Left);
            Assert.That(s.CanAnswer, Is.False, "one lifted");
            s.NoteLift(PairSide.Right);
            var t = s.Current;
            double left = s.MassAt(PairSide.Left), right = s.MassAt(PairSide.Right);
            Assert.That(new[] { left, right }, Is.EquivalentTo(new[] { t.Standard, t.Comparison }));
            Assert.That(left, Is.EqualTo(t.ComparisonFirst ? t.Comparison : t.Standard));
            // Say the heavier is the comparison's side: response 1.
            Assert.That(s.Answer(t.ComparisonFirst ? PairSide.Left : PairSide.Right), Is.True);
            Assert.That(t.Response, Is.EqualTo(1));
            var lines = File.ReadAllLines(Path1);
            Assert.That(lines[0], Is.EqualTo(TrialsCsv.Header));
            Assert.That(lines[1], Is.EqualTo(TrialsCsv.FormatRow(t)));
            Assert.That(lines[1], Does.EndWith(",1"));
            Assert.That(s.CanAnswer, Is.False, "the next trial needs its own lifts");
            Assert.That(Directory.GetFiles(_dir).Length, Is.EqualTo(1), "no temporary file left");
        }

        [Test]
        public void ASessionResumesWhereItStoppedAndPsychometricReadsTheFile()
        {
            var observer = new SimulatedObserver(0.52, 0.05, 1);
            var first = new DiscriminationSession("P1", "on", Path1, Plan());
            for (int i = 0; i < 3; i++) AnswerLikeTheObserver(first, observer);
            // Another participant meanwhile, same file.
            var other = new DiscriminationSession("P2", "on", Path1, Plan());
            AnswerLikeTheObserver(other, observer);

            var resumed = new DiscriminationSession("P1", "on", Path1, Plan());
            Assert.That(resumed.ResumedCount, Is.EqualTo(3));
            Assert.That(resumed.CurrentIndex, Is.EqualTo(3));
            while (!resumed.IsFinished) AnswerLikeTheObserver(resumed, observer);
            Assert.That(resumed.AnsweredCount, Is.EqualTo(7));
            var answers = TrialsCsv.Read(new StringReader(File.ReadAllText(Path1)), "trials.csv");
            Assert.That(answers.Count(a => a.Participant == "P1"), Is.EqualTo(7));
            Assert.That(answers.Count(a => a.Participant == "P2"), Is.EqualTo(1));
            Assert.That(answers.Where(a => a.Participant == "P1").Select(a => a.Comparison).OrderBy(x => x),
                Is.EqualTo(Plan().Build("P1", "on").Select(t => t.Comparison).OrderBy(x => x)));
            var finished = new DiscriminationSession("P1", "on", Path1, Plan());
            Assert.That(finished.IsFinished, Is.True);
        }

        /// <summary>A file saved with lone "\r" line ends (an editor's old Mac setting, no final line end) resumes as the reader numbers its lines; it threw IndexOutOfRangeException.</summary>
        [Test]
        public void AFileWithLoneCarriageReturnsResumes()
        {
            var observer = new SimulatedObserver(0.52, 0.05, 1);
            var first = new DiscriminationSession("P1", "on", Path1, Plan());
            for (int i = 0; i < 3; i++) AnswerLikeTheObserver(first, observer);
            File.WriteAllText(Path1, File.ReadAllText(Path1).TrimEnd('\n').Replace('\n', '\r'));
            var resumed = new DiscriminationSession("P1", "on", Path1, Plan());
            Assert.That(resumed.ResumedCount, Is.EqualTo(3));
            while (!resumed.IsFinished) AnswerLikeTheObserver(resumed, observer);
            Assert.That(TrialsCsv.Read(new StringReader(File.ReadAllText(Path1)), "trials.csv").Count, Is.EqualTo(7));
        }

        [Test]
        public void AFileOfAnotherPlanIsRefusedAndLeftAlone()
        {
            var s = new DiscriminationSession("P1", "", Path1, Plan());
            s.NoteLift(PairSide.Left); s.NoteLift(PairSide.Right);
            s.Answer(PairSide.Left);
            string before = File.ReadAllText(Path1);
            var otherSeed = Plan();
            otherSeed.Seed = 4;
            // With another seed trial 1 may still match; find a seed whose first trial differs.
            for (long seed = 4; otherSeed.Build("P1")[0].Comparison == Plan().Build("P1")[0].Comparison; seed++) otherSeed.Seed = seed;
            Assert.Throws<EvaluationFormatException>(() => new DiscriminationSession("P1", "", Path1, otherSeed));
            Assert.That(File.ReadAllText(Path1), Is.EqualTo(before));
            File.WriteAllText(Path1, "participant,standard,comparison,response\nP1,1,1,1\n");
            Assert.Throws<EvaluationFormatException>(() => new DiscriminationSession("P1", "", Path1, Plan()), "header not in append order");
            File.WriteAllText(Path1, TrialsCsv.Header + "\nP1,,1,0.5,0.4,standard,0,7\n");
            Assert.Throws<EvaluationFormatException>(() => new DiscriminationSession("P1", "", Path1, Plan()), "psychometric would refuse it");
        }

        static Staircase MakeStaircase(string participant, string condition)
            => new Staircase(participant, condition, 0.5, 0.7, 0.08, 2, 8, 6, 5, halvingReversals: 2);

        [Test]
        public void AStaircaseSessionResumesByReplayingItsAnswers()
        {
            var observer = new SimulatedObserver(0.55, 0.05, 2);
            var first = new DiscriminationSession("P1", "on", Path1, MakeStaircase);
            for (int i = 0; i < 10; i++) AnswerLikeTheObserver(first, observer);
            double levelAfterTen = first.Current.Comparison;
            var resumed = new DiscriminationSession("P1", "on", Path1, MakeStaircase);
            Assert.That(resumed.ResumedCount, Is.EqualTo(10));
            Assert.That(resumed.Current.Comparison, Is.EqualTo(levelAfterTen), "the replayed staircase stands where the first one stopped");
            Assert.That(resumed.Staircase.ReversalLevels, Is.EqualTo(first.Staircase.ReversalLevels));
            while (!resumed.IsFinished) AnswerLikeTheObserver(resumed, observer);
            Assert.That(resumed.Staircase.ReversalLevels.Count, Is.EqualTo(8));
            var answers = TrialsCsv.Read(new StringReader(File.ReadAllText(Path1)), "trials.csv");
            Assert.That(answers.Count, Is.EqualTo(resumed.Staircase.Trials.Count));
            // Another seed (another side order) still replays: sides are not part of the check; another start is refused.
            Assert.Throws<EvaluationFormatException>(() => new DiscriminationSession("P1", "on", Path1,
                (p, c) => new Staircase(p, c, 0.5, 0.65, 0.08, 2, 8, 6, 5, halvingReversals: 2)));
        }

        [Test]
        public void AFinishedSessionShowsNoTrialAndSaysSoWhenAskedForAMass()
        {
            var s = new DiscriminationSession("P1", "on", Path1, Plan());
            var observer = new SimulatedObserver(0.52, 0.05, 1);
            while (!s.IsFinished) AnswerLikeTheObserver(s, observer);
            Assert.That(s.Current, Is.Null);
            Assert.That(s.ProgressText, Is.EqualTo("7 / 7"));
            Assert.That(() => s.MassAt(PairSide.Left), Throws.InvalidOperationException.With.Message.EqualTo("the session is finished"));
            Assert.That(() => s.Acknowledge(), Throws.InvalidOperationException.With.Message.EqualTo("no answer is waiting for its write"));
            Assert.That(s.AnsweredCount, Is.EqualTo(7), "a stray acknowledgement counts nothing");
        }

        [Test]
        public void AStaircaseSessionCountsTheTrialShownUntilItFinishes()
        {
            // 1-up-2-down from 0.7 kg, at most three trials: the count is the trials answered and the one shown.
            var s = new DiscriminationSession("P1", "on", Path1, (p, c) => new Staircase(p, c, 0.5, 0.7, 0.08, 2, 8, 6, 5, maxTrials: 3));
            Assert.That(s.TrialCount, Is.EqualTo(1));
            Assert.That(s.ProgressText, Is.EqualTo("1 (reversals 0 / 8)"));
            foreach (int heavier in new[] { 1, 1, 0 }) LiftBothAndAnswer(s, heavier);
            // Two "heavier" lower the level, the "lighter" after them raises it: one reversal; then the trial limit.
            Assert.That(s.IsFinished, Is.True);
            Assert.That(s.TrialCount, Is.EqualTo(3), "no trial shown after the last");
            Assert.That(s.ProgressText, Is.EqualTo("3 (reversals 1 / 8)"));
            Assert.That(s.Current, Is.Null);
        }

        [TestCase("")]
        [TestCase(" \r\n\n")]
        [TestCase("\uFEFF\n")]
        public void AnEmptyOrBlankFileIsANewOne(string text)
        {
            File.WriteAllText(Path1, text, new System.Text.UTF8Encoding(true));
            var s = new DiscriminationSession("P1", "on", Path1, Plan());
            Assert.That(s.ResumedCount, Is.Zero);
            Assert.That(s.CurrentIndex, Is.Zero);
            AnswerLikeTheObserver(s, new SimulatedObserver(0.52, 0.05, 1));
            Assert.That(File.ReadAllText(Path1), Is.EqualTo(TrialsCsv.Header + "\n" + TrialsCsv.FormatRow(s.Plan[0]) + "\n"), "the blank file replaced");
        }

        [Test]
        public void AByteOrderMarkWrittenTwiceAndAnotherParticipantsRowWithALineBreakAreKept()
        {
            // An editor that adds a byte-order mark to a file that had one leaves U+FEFF as the first character read;
            // another program's participant id may hold a quoted line break. Both are read as psychometric reads them.
            var plan = Plan().Build("P1", "on");
            string other = "\"P2\n(left hand)\",on,1,0.5,0.4,standard,0,1";
            string mine = DiscriminationSessionRefusalTests.Row(plan[0], 0);
            File.WriteAllText(Path1, "\uFEFF" + TrialsCsv.Header + "\r\n" + other + "\r\n" + mine + "\r\n", new System.Text.UTF8Encoding(true));
            Assert.That(TrialsCsv.Read(new StringReader(File.ReadAllText(Path1)), "trials.csv"), Has.Count.EqualTo(2));

            var s = new DiscriminationSession("P1", "on", Path1, Plan());
            Assert.That(s.ResumedCount, Is.EqualTo(1));
            Assert.That(s.Plan[0].Response, Is.EqualTo(0), "the answer read as recorded");
            Assert.That(s.CurrentIndex, Is.EqualTo(1));
            Assert.That(s.FileText(), Is.EqualTo(TrialsCsv.Header + "\n" + other + "\n" + mine + "\n"));
            AnswerLikeTheObserver(s, new SimulatedObserver(0.52, 0.05, 1));
            var answers = TrialsCsv.Read(new StringReader(File.ReadAllText(Path1)), "trials.csv");
            Assert.That(answers.Select(a => a.Participant), Is.EqualTo(new[] { "P2\n(left hand)", "P1", "P1" }));
        }

        static void AnswerLikeTheObserver(DiscriminationSession s, SimulatedObserver observer)
            => LiftBothAndAnswer(s, observer.Answer(s.Current.Comparison));

        /// <summary>Lifts both objects and answers 1 ("the comparison was heavier") or 0, on whichever side it stands.</summary>
        static void LiftBothAndAnswer(DiscriminationSession s, int heavier)
        {
            s.NoteLift(PairSide.Left);
            s.NoteLift(PairSide.Right);
            Assert.That(s.Answer((heavier == 1) == s.Current.ComparisonFirst ? PairSide.Left : PairSide.Right), Is.True);
        }
    }
}
