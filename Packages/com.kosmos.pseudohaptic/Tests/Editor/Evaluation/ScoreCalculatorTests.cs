using System;
using Kosmos.PseudoHaptic.Evaluation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests.Evaluation
{
    public class ScoreCalculatorTests
    {
        const string Part1 = QuestionnaireCatalog.WeightDetectionId;
        const string Part2 = QuestionnaireCatalog.ImmersionId;
        const string Part3 = QuestionnaireCatalog.SelfAssessmentId;

        [Test]
        public void ReverseCodingMirrorsTheScale()
        {
            var five = SampleQuestionnaires.Part("five", 2, 1, 5, 2);
            for (int x = 1; x <= 5; x++)
            {
                Assert.That(five.Recode(2, x), Is.EqualTo(6 - x), "6 − x on the paper's 5-point scale");
                Assert.That(five.Recode(1, x), Is.EqualTo(x), "items not reversed count as given");
            }
            var zeroToSix = SampleQuestionnaires.Part("seven", 1, 0, 6, 1);
            Assert.That(zeroToSix.Recode(1, 0), Is.EqualTo(6));
            Assert.That(zeroToSix.Recode(1, 2), Is.EqualTo(4), "min + max − x in general");
        }

        [Test]
        public void Part1ScoreMatchesAHandComputation()
        {
            var set = new ResponseSet(SampleQuestionnaires.Paper());
            // Items 1..10; 4 and 7 reversed: 2 → 4 and 1 → 5. Recoded: 5 4 5 4 4 5 5 4 3 5 = 44 → 4.4.
            SampleQuestionnaires.Answer(set, "P1", Part1, 5, 4, 5, 2, 4, 5, 1, 4, 3, 5);
            var score = ScoreCalculator.Score(set.Find("P1", Part1));
            Assert.That(score.IsComplete, Is.True);
            Assert.That(score.Score, Is.EqualTo(4.4));
            Assert.That(ScoresCsv.FormatNumber(score.Score.Value), Is.EqualTo("4.4"));
        }

        [Test]
        public void Part2ReversesItems3589()
        {
            var set = new ResponseSet(SampleQuestionnaires.Paper());
            // Everything answered 1: items 3, 5, 8, 9 count 5, the other six count 1 → (4·5 + 6·1)/10 = 2.6.
            SampleQuestionnaires.Answer(set, "P1", Part2, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1);
            Assert.That(ScoreCalculator.Score(set.Find("P1", Part2)).Score, Is.EqualTo(2.6));
        }

        [Test]
        public void SelfAssessmentIsTheAnswerItself()
        {
            var set = new ResponseSet(SampleQuestionnaires.Paper());
            SampleQuestionnaires.Answer(set, "P9", Part3, 8);
            Assert.That(ScoreCalculator.Score(set.Find("P9", Part3)).Score, Is.EqualTo(8.0));
        }

        [Test]
        public void AnIncompletePartHasNoScoreAndNamesWhatIsMissing()
        {
            var set = new ResponseSet(SampleQuestionnaires.Paper());
            SampleQuestionnaires.Answer(set, "P1", Part1, 5, 5, 5, 1, 5, 5, 1, 5, 5); // item 10 unanswered
            set.Add(new Response("P1", Part2, 2, 3));
            var scores = ScoreCalculator.ScoreAll(set);
            Assert.That(scores.Count, Is.EqualTo(2), "one row per participant × questionnaire present");
            Assert.That(scores[0].QuestionnaireId, Is.EqualTo(Part1));
            Assert.That(scores[0].IsComplete, Is.False);
            Assert.That(scores[0].Score, Is.Null, "never the mean of the nine answered items");
            Assert.That(scores[0].MissingItems, Is.EqualTo(new[] { 10 }));
            Assert.That(scores[1].MissingItems, Is.EqualTo(new[] { 1, 3, 4, 5, 6, 7, 8, 9, 10 }));
        }

        [Test]
        public void ScoresComeInParticipantThenCatalogOrder()
        {
            var set = new ResponseSet(SampleQuestionnaires.Paper());
            SampleQuestionnaires.Answer(set, "P10", Part3, 7);
            SampleQuestionnaires.Answer(set, "P2", Part3, 9);
            SampleQuestionnaires.Answer(set, "P10", Part1, 3, 3, 3, 3, 3, 3, 3, 3, 3, 3);
            var scores = ScoreCalculator.ScoreAll(set);
            Assert.That(scores.Count, Is.EqualTo(3));
            Assert.That(scores[0].Participant + " " + scores[0].QuestionnaireId, Is.EqualTo("P2 " + Part3));
            Assert.That(scores[1].Participant + " " + scores[1].QuestionnaireId, Is.EqualTo("P10 " + Part1));
            Assert.That(scores[2].Participant + " " + scores[2].QuestionnaireId, Is.EqualTo("P10 " + Part3));
            Assert.That(scores[1].Score, Is.EqualTo(3.0));
        }

        [Test]
        public void ParticipantsSortNaturally()
        {
            var ids = new System.Collections.Generic.List<string> { "P10", "p1", "P2", "P1", "B", "P02", "A7", "A10", "P1a", "" };
            ids.Sort(ParticipantOrder.Instance);
            Assert.That(ids, Is.EqualTo(new[] { "", "A7", "A10", "B", "P1", "P1a", "P02", "P2", "P10", "p1" }));
        }

        [Test]
        public void TheSetRefusesWhatDoesNotFit()
        {
            var set = new ResponseSet(SampleQuestionnaires.Paper());
            set.Add(new Response("P1", Part1, 1, 3));
            Assert.That(set.TryAdd(new Response("P1", Part1, 1, 4)), Does.Contain("duplicate"));
            Assert.That(set.TryAdd(new Response("P1", Part1, 11, 4)), Does.Contain("no item 11"));
            Assert.That(set.TryAdd(new Response("P1", Part1, 2, 6)), Does.Contain("outside the scale 1 to 5"));
            Assert.That(set.TryAdd(new Response("P1", Part1, 2, 0)), Does.Contain("outside"));
            Assert.That(set.TryAdd(new Response("P1", Part3, 1, 10)), Is.Null, "10 is on the self-assessment's scale");
            Assert.That(set.TryAdd(new Response("P1", "presence", 1, 3)), Does.Contain("unknown questionnaire 'presence'"));
            Assert.That(set.TryAdd("P1", Part1, 2, 3.5), Does.Contain("not a whole number"));
            Assert.That(set.TryAdd("P1", Part1, 2, 1e20), Does.Contain("outside"));
            Assert.That(set.TryAdd(new Response("", Part1, 2, 3)), Does.Contain("participant"));
            Assert.That(set.Count, Is.EqualTo(2), "refused answers leave the set unchanged");
            Assert.Throws<ArgumentException>(() => set.Add(new Response("P1", Part1, 1, 2)));
        }

        [Test]
        public void ScoreAllOfPlainResponsesThrowsOnABadOne()
        {
            var catalog = SampleQuestionnaires.Paper();
            Assert.Throws<ArgumentException>(() => ScoreCalculator.ScoreAll(catalog, new[] { new Response("P1", Part3, 1, 11) }));
            var scores = ScoreCalculator.ScoreAll(catalog, new[] { new Response("P1", Part3, 1, 6) });
            Assert.That(scores[0].Score, Is.EqualTo(6.0));
        }
    }
}
