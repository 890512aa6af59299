using Kosmos.PseudoHaptic.Evaluation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests.Evaluation
{
    /// <summary>
    /// Answers checked as they arrive (evaluation.md §2), refused in the words evaluation.md §4 prints, and found
    /// again by questionnaire; one answer a row in the responses file's column order.
    /// </summary>
    public class ResponseSetTests
    {
        [Test]
        public void AnUnknownQuestionnaireAndASecondAnswerToAnItemAreRefusedAsDocumented()
        {
            var set = new ResponseSet(SampleQuestionnaires.Paper());
            Assert.That(set.TryAdd(new Response("P1", "presence", 1, 3)),
                Is.EqualTo("unknown questionnaire 'presence' (expected one of 'weight-detection', 'immersion', 'self-assessment')"));
            Assert.That(set.TryAdd(new Response("P1", "immersion", 4, 3)), Is.Null);
            Assert.That(set.TryAdd(new Response("P1", "immersion", 4, 5)),
                Is.EqualTo("duplicate answer: participant 'P1' already answered 'immersion' item 4"));
            Assert.That(set.Count, Is.EqualTo(1), "answers are recorded once per item");
            Assert.That(set.Find("P1", "immersion").AnswerAt(3), Is.EqualTo(3), "the first answer stands");
        }

        [Test]
        public void TheSheetsOfEachQuestionnaireAreFoundIncludingTheFirstOne()
        {
            var set = new ResponseSet(SampleQuestionnaires.Paper());
            SampleQuestionnaires.Answer(set, "P1", QuestionnaireCatalog.WeightDetectionId, 4, 4);
            SampleQuestionnaires.Answer(set, "P2", QuestionnaireCatalog.ImmersionId, 2);
            SampleQuestionnaires.Answer(set, "P2", QuestionnaireCatalog.WeightDetectionId, 1);
            var first = set.SheetsOf(QuestionnaireCatalog.WeightDetectionId);
            Assert.That(first, Has.Count.EqualTo(2));
            Assert.That(first[0].Participant, Is.EqualTo("P1"));
            Assert.That(first[0].AnsweredCount, Is.EqualTo(2));
            Assert.That(first[1].Participant, Is.EqualTo("P2"));
            Assert.That(set.SheetsOf(QuestionnaireCatalog.ImmersionId), Has.Count.EqualTo(1));
            Assert.That(set.SheetsOf(QuestionnaireCatalog.SelfAssessmentId), Is.Empty);
            Assert.That(set.SheetsOf("presence"), Is.Empty);
        }

        [Test]
        public void NoParticipantNoQuestionnaireAndNoAnswerFindNoSheet()
        {
            var set = new ResponseSet(SampleQuestionnaires.Paper());
            SampleQuestionnaires.Answer(set, "P1", QuestionnaireCatalog.ImmersionId, 3);
            Assert.That(set.Find("P1", QuestionnaireCatalog.ImmersionId).AnswerAt(0), Is.EqualTo(3));
            Assert.That(set.Find(null, QuestionnaireCatalog.ImmersionId), Is.Null, "no participant");
            Assert.That(set.Find("P2", QuestionnaireCatalog.ImmersionId), Is.Null, "a participant who answered nothing");
            Assert.That(set.Find("P1", "presence"), Is.Null, "a questionnaire the catalog does not have");
            Assert.That(set.Find("P1", QuestionnaireCatalog.WeightDetectionId), Is.Null, "a questionnaire P1 did not answer");
        }

        [Test]
        public void AResponseReadsAsItsRowInTheFile()
        {
            Assert.That(new Response("P1", "immersion", 4, 3).ToString(), Is.EqualTo("P1,immersion,4,3"));
        }
    }
}
