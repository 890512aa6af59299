using System;
using System.Collections.Generic;
using System.IO;
using Kosmos.PseudoHaptic.Evaluation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests.Evaluation
{
    /// <summary>
    /// The scores file (evaluation.md, section 4): per participant and questionnaire, and per condition when the
    /// study has conditions (columns <c>participant,condition,questionnaire,score</c>), the score empty when the
    /// part is incomplete; read back as strictly as the responses, each fault named with its line and with the
    /// reason saying what the row holds and what was expected.
    /// </summary>
    public class ScoresFileTests
    {
        static readonly ParticipantScore[] StudyScores =
        {
            new ParticipantScore("P1", "visual", "immersion", 4.6),
            new ParticipantScore("P1", "pseudo-haptic", "immersion", null, new[] { 7 }),
            new ParticipantScore("P, 2", "pseudo-haptic", "self-assessment", 8.0),
        };

        [Test]
        public void WithConditionsTheConditionFollowsTheParticipantAndAnIncompletePartIsEmpty()
        {
            Assert.That(ScoresCsv.Format(StudyScores, true), Is.EqualTo(
                "participant,condition,questionnaire,score\n"
                + "P1,visual,immersion,4.6\n"
                + "P1,pseudo-haptic,immersion,\n"
                + "\"P, 2\",pseudo-haptic,self-assessment,8\n"));
        }

        [Test]
        public void WithoutConditionsTheFileIsExactlyTheOneWithoutTheColumn()
        {
            Assert.That(ScoresCsv.Format(StudyScores, false), Is.EqualTo(ScoresCsv.Format(StudyScores)));
            Assert.That(ScoresCsv.Format(StudyScores, false), Does.StartWith("participant,questionnaire,score\nP1,immersion,4.6\n"));
        }

        static EvaluationFormatException Refused(string text)
            => Assert.Throws<EvaluationFormatException>(() => ScoresCsv.Parse(text, "S.csv", SampleQuestionnaires.Paper()));

        [Test]
        public void ScoresAtBothEndsOfTheScaleAreAccepted()
        {
            var back = ScoresCsv.Parse("participant,questionnaire,score\nP1,immersion,1\nP2,immersion,5\nP1,self-assessment,1\nP2,self-assessment,10\n",
                "S.csv", SampleQuestionnaires.Paper());
            Assert.That(back.Count, Is.EqualTo(4));
            Assert.That(back[0].Score, Is.EqualTo(1));
            Assert.That(back[3].Score, Is.EqualTo(10));
        }

        [Test]
        public void AnUnknownQuestionnaireIsRefusedListingTheKnownOnes()
        {
            var e = Refused("participant,questionnaire,score\nP1,fatigue,3\n");
            Assert.That(e.Line, Is.EqualTo(2));
            // The wording of evaluation.md's table ("refused like R.csv").
            Assert.That(e.Reason, Is.EqualTo("unknown questionnaire 'fatigue' (expected one of 'weight-detection', 'immersion', 'self-assessment')"));
        }

        [Test]
        public void ADuplicateScoreNamesTheParticipantThePartAndTheFirstRow()
        {
            var e = Refused("participant,questionnaire,score\nP1,immersion,4\nP2,immersion,3\nP1,immersion,3\n");
            Assert.That(e.Line, Is.EqualTo(4));
            Assert.That(e.Reason, Does.Contain("'P1'").And.Contain("'immersion'").And.Contain("line 2"), e.Message);
        }

        [Test]
        public void ParticipantAndQuestionnaireAreNotConfusedWhenOneIdEndsAnother()
        {
            // A study's own parts "presence" and "copresence": participant "Pco" on presence and participant "P" on
            // copresence are two different rows, whatever characters the participant ids hold.
            var catalog = new QuestionnaireCatalog(new[]
            {
                SampleQuestionnaires.Part("presence", 1, 1, 7),
                SampleQuestionnaires.Part("copresence", 1, 1, 7),
            });
            var back = ScoresCsv.Parse("participant,questionnaire,score\nPco,presence,3\nP,copresence,5\n", "S.csv", catalog);
            Assert.That(back.Count, Is.EqualTo(2));
            Assert.That(back[1].Participant, Is.EqualTo("P"));
            Assert.That(back[1].Score, Is.EqualTo(5));
        }

        [Test]
        public void AnEmptyParticipantIsRefusedNamingTheField()
        {
            var e = Refused("participant,questionnaire,score\nP1,immersion,4\n,immersion,3\n");
            Assert.That(e.Line, Is.EqualTo(3));
            Assert.That(e.Reason, Does.Contain("participant"));
        }

        [Test]
        public void AScoreThatIsNotANumberIsQuoted()
        {
            var e = Refused("participant,questionnaire,score\nP1,immersion,high\n");
            Assert.That(e.Line, Is.EqualTo(2));
            Assert.That(e.Reason, Does.Contain("score").And.Contain("'high'"), e.Message);
        }

        [Test]
        public void AScoreOffTheScaleNamesTheScoreThePartAndItsScale()
        {
            var e = Refused("participant,questionnaire,score\nP1,immersion,5.5\n");
            Assert.That(e.Line, Is.EqualTo(2));
            Assert.That(e.Reason, Does.Contain("score 5.5").And.Contain("'immersion'").And.Contain("1 to 5"), e.Message);
        }

        [Test]
        public void MissingArgumentsAreTheCallersError()
        {
            Assert.That(Assert.Throws<ArgumentNullException>(() => ScoresCsv.Format(null)).ParamName, Is.EqualTo("scores"));
            Assert.That(Assert.Throws<ArgumentNullException>(() => ScoresCsv.Format(null, true)).ParamName, Is.EqualTo("scores"));
            Assert.That(Assert.Throws<ArgumentNullException>(() => ScoresCsv.Parse((string)null, "S.csv", SampleQuestionnaires.Paper())).ParamName, Is.EqualTo("text"));
            Assert.That(Assert.Throws<ArgumentNullException>(() => ScoresCsv.Parse(
                new StringReader("participant,questionnaire,score\nP1,immersion,4\n"), "S.csv", null)).ParamName, Is.EqualTo("catalog"));
        }
    }
}
