using Kosmos.PseudoHaptic.Evaluation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests.Evaluation
{
    public class CronbachAlphaTests
    {
        // Four participants × three items, by hand (divisor n − 1 = 3):
        //   items  (1,2,2) (2,3,3) (3,3,4) (4,5,4); totals 5, 8, 10, 13, mean 9
        //   item variances 5/3, 4.75/3, 2.75/3 → Σ = 12.5/3; total variance 34/3
        //   α = 3/2 · (1 − 12.5/34) = 32.25/34 = 0.94852941…
        static readonly double[][] Example =
        {
            new[] { 1.0, 2.0, 2.0 },
            new[] { 2.0, 3.0, 3.0 },
            new[] { 3.0, 3.0, 4.0 },
            new[] { 4.0, 5.0, 4.0 },
        };

        [Test]
        public void MatchesAHandComputation()
        {
            var alpha = CronbachAlpha.Compute(Example);
            Assert.That(alpha.Alpha, Is.EqualTo(32.25 / 34).Within(1e-12));
            Assert.That(alpha.Participants, Is.EqualTo(4));
            Assert.That(alpha.Items, Is.EqualTo(3));
        }

        [Test]
        public void UsesReverseCodedAnswersOfCompleteParticipantsOnly()
        {
            var three = SampleQuestionnaires.Part("three", 3, 1, 5, 2); // item 2 reversed
            var set = new ResponseSet(new QuestionnaireCatalog(new[] { three }));
            // The example with item 2 given as 6 − x, so that recoding restores it.
            SampleQuestionnaires.Answer(set, "A", "three", 1, 4, 2);
            SampleQuestionnaires.Answer(set, "B", "three", 2, 3, 3);
            SampleQuestionnaires.Answer(set, "C", "three", 3, 3, 4);
            SampleQuestionnaires.Answer(set, "D", "three", 4, 1, 4);
            SampleQuestionnaires.Answer(set, "E", "three", 5, 5);       // incomplete: left out
            var alpha = CronbachAlpha.Of(set, "three");
            Assert.That(alpha.Alpha, Is.EqualTo(32.25 / 34).Within(1e-12));
            Assert.That(alpha.Participants, Is.EqualTo(4));
        }

        [Test]
        public void UndefinedWithoutTwoItemsTwoParticipantsOrVaryingTotals()
        {
            Assert.That(CronbachAlpha.Compute(new[] { new[] { 1.0, 2.0 } }).IsDefined, Is.False);
            Assert.That(CronbachAlpha.Compute(new[] { new[] { 1.0 }, new[] { 2.0 } }).IsDefined, Is.False);
            Assert.That(CronbachAlpha.Compute(new[] { new[] { 3.0, 3.0 }, new[] { 3.0, 3.0 } }).IsDefined, Is.False);
            var empty = CronbachAlpha.Of(new ResponseSet(SampleQuestionnaires.Paper()), QuestionnaireCatalog.ImmersionId);
            Assert.That(empty.IsDefined, Is.False);
            Assert.That(empty.Items, Is.EqualTo(10));
        }
    }
}
