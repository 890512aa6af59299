using System;
using System.Collections.Generic;
using Kosmos.PseudoHaptic.Evaluation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests.Evaluation
{
    /// <summary>
    /// What a questionnaire definition accepts and refuses, in the words a study team reads: the checks that the
    /// JSON reader, the CSV reader and the headset panel share (<see cref="Questionnaire.Reject"/>), reverse coding
    /// at both ends of other scales, and the text forms of items and scores.
    /// </summary>
    public class QuestionnaireContractTests
    {
        static QuestionnaireItem[] Items(params int[] numbers)
        {
            var items = new QuestionnaireItem[numbers.Length];
            for (int i = 0; i < numbers.Length; i++) items[i] = new QuestionnaireItem(numbers[i], "item " + numbers[i], numbers[i] % 2 == 0);
            return items;
        }

        static string Refusal(TestDelegate build)
        {
            var e = Assert.Throws(Is.InstanceOf<ArgumentException>(), build);
            return e.Message;
        }

        [Test]
        public void ADefinitionIsRefusedNamingWhatIsWrong()
        {
            Assert.That(Refusal(() => new Questionnaire(" ", "t", 1, 5, Items(1))), Does.Contain("questionnaire id is empty"));
            Assert.That(Refusal(() => new Questionnaire(null, "t", 1, 5, Items(1))), Does.Contain("questionnaire id is empty"));
            Assert.That(Refusal(() => new Questionnaire(" a", "t", 1, 5, Items(1))), Does.Contain("questionnaire id ' a' has surrounding spaces, a comma or a quote"));
            Assert.That(Refusal(() => new Questionnaire("a,b", "t", 1, 5, Items(1))), Does.Contain("a comma or a quote"));
            Assert.That(Refusal(() => new Questionnaire("a\"b", "t", 1, 5, Items(1))), Does.Contain("a comma or a quote"));
            Assert.That(Refusal(() => new Questionnaire("q", "t", 5, 5, Items(1))), Does.Contain("questionnaire 'q': scale min 5 is not below max 5"));
            Assert.That(Refusal(() => new Questionnaire("q", "t", 6, 5, Items(1))), Does.Contain("scale min 6 is not below max 5"));
            Assert.That(Refusal(() => new Questionnaire(",a", "t", 1, 5, Items(1))), Does.Contain("a comma or a quote"), "a comma first");
            Assert.That(Refusal(() => new Questionnaire("\"a\"", "t", 1, 5, Items(1))), Does.Contain("a comma or a quote"), "a quote first");
            Assert.That(() => new Questionnaire("q", "t", 1, 5, null), Throws.InstanceOf<ArgumentNullException>().With.Property("ParamName").EqualTo("items"));
            Assert.That(Refusal(() => new Questionnaire("q", "t", 1, 5, Items())), Does.Contain("questionnaire 'q' has no items"));
            Assert.That(Refusal(() => new Questionnaire("q", "t", 1, 5, new QuestionnaireItem[] { null })), Does.Contain("questionnaire 'q' has a null item"));
            Assert.That(Refusal(() => new Questionnaire("q", "t", 1, 5, Items(0))), Does.Contain("questionnaire 'q': item number 0 is below 1"));
            Assert.That(Refusal(() => new Questionnaire("q", "t", 1, 5, Items(-3))), Does.Contain("item number -3 is below 1"));
            Assert.That(Refusal(() => new Questionnaire("q", "t", 1, 5, Items(1, 2, 1))), Does.Contain("questionnaire 'q': item number 1 appears twice"));
        }

        [Test]
        public void TheSmallestDefinitionIsAccepted()
        {
            // One item numbered 1 and a two-point scale are the least a part can have.
            var q = new Questionnaire("q", null, 0, 1, Items(1));
            Assert.That(q.Title, Is.EqualTo("q"), "no title: the id stands in");
            Assert.That(q.Instructions, Is.EqualTo(""));
            Assert.That(q.ScaleMinLabel, Is.EqualTo(""));
            Assert.That(q.ScaleMaxLabel, Is.EqualTo(""));
            Assert.That(q.ItemCount, Is.EqualTo(1));
            Assert.That(q.ToString(), Is.EqualTo("q"));

            var labelled = new Questionnaire("r", "", 1, 7, Items(1), null, null, null);
            Assert.That(labelled.Title, Is.EqualTo("r"));
            Assert.That((labelled.Instructions, labelled.ScaleMinLabel, labelled.ScaleMaxLabel), Is.EqualTo(("", "", "")));
        }

        [Test]
        public void ItemsKeepTheirDefinitionOrderAndAreFoundByNumber()
        {
            var q = new Questionnaire("q", "Title", 1, 5, Items(3, 1, 2), "Read first.", "no", "yes");
            Assert.That(q.Items[0].Number, Is.EqualTo(3));
            Assert.That(q.Items[2].Number, Is.EqualTo(2));
            Assert.That(q.FindItem(2).Text, Is.EqualTo("item 2"));
            Assert.That(q.FindItem(4), Is.Null);
            Assert.That(q.FindItem(0), Is.Null);
            Assert.That((q.Title, q.Instructions, q.ScaleMinLabel, q.ScaleMaxLabel), Is.EqualTo(("Title", "Read first.", "no", "yes")));
        }

        [TestCase(0, false)]
        [TestCase(1, true)]
        [TestCase(5, true)]
        [TestCase(6, false)]
        [TestCase(-1, false)]
        public void IsOnScaleIncludesBothEnds(int response, bool onScale)
        {
            Assert.That(new Questionnaire("q", "t", 1, 5, Items(1)).IsOnScale(response), Is.EqualTo(onScale));
        }

        [Test]
        public void RejectNamesTheFirstProblemOrAcceptsWithNull()
        {
            var q = new Questionnaire("immersion", "t", 1, 5, Items(1, 2, 3));
            Assert.That(q.Reject(1, 1), Is.Null, "bottom of the scale");
            Assert.That(q.Reject(3, 5), Is.Null, "top of the scale");
            Assert.That(q.Reject(2, 3.0), Is.Null);
            Assert.That(q.Reject(4, 3), Is.EqualTo("questionnaire 'immersion' has no item 4 (items are 1 to 3)"));
            Assert.That(q.Reject(0, double.NaN), Is.EqualTo("questionnaire 'immersion' has no item 0 (items are 1 to 3)"), "the item is checked first");
            Assert.That(q.Reject(2, double.NaN), Is.EqualTo("response to 'immersion' item 2 is not a number"));
            Assert.That(q.Reject(2, double.PositiveInfinity), Is.EqualTo("response to 'immersion' item 2 is not a number"));
            Assert.That(q.Reject(2, double.NegativeInfinity), Is.EqualTo("response to 'immersion' item 2 is not a number"));
            Assert.That(q.Reject(2, 0), Is.EqualTo("response 0 to 'immersion' item 2 is outside the scale 1 to 5"));
            Assert.That(q.Reject(2, 6), Is.EqualTo("response 6 to 'immersion' item 2 is outside the scale 1 to 5"));
            Assert.That(q.Reject(2, 0.5), Is.EqualTo("response 0.5 to 'immersion' item 2 is outside the scale 1 to 5"), "off the scale before not whole");
            Assert.That(q.Reject(2, 5.5), Is.EqualTo("response 5.5 to 'immersion' item 2 is outside the scale 1 to 5"));
            Assert.That(q.Reject(2, 3.5), Is.EqualTo("response 3.5 to 'immersion' item 2 is not a whole number on the scale 1 to 5"));
            Assert.That(q.Reject(2, 1e20), Is.EqualTo("response 1E+20 to 'immersion' item 2 is outside the scale 1 to 5"));
            // Every digit it takes to tell the value from the whole number next to it (a 15-digit form would read "3").
            Assert.That(q.Reject(2, 3.0000000000000004), Is.EqualTo("response 3.0000000000000004 to 'immersion' item 2 is not a whole number on the scale 1 to 5"));
        }

        [Test]
        public void ItemNumbersWithGapsAreListedOneByOne()
        {
            Assert.That(new Questionnaire("q", "t", 1, 5, Items(5, 1, 2)).Reject(3, 1), Is.EqualTo("questionnaire 'q' has no item 3 (items are 1, 2, 5)"));
            Assert.That(new Questionnaire("q", "t", 1, 5, Items(2, 3)).Reject(1, 1), Is.EqualTo("questionnaire 'q' has no item 1 (items are 2, 3)"), "not from 1");
            Assert.That(new Questionnaire("q", "t", 1, 5, Items(1)).Reject(2, 1), Is.EqualTo("questionnaire 'q' has no item 2 (items are 1)"));
            Assert.That(new Questionnaire("q", "t", 1, 5, Items(7)).Reject(1, 1), Is.EqualTo("questionnaire 'q' has no item 1 (items are 7)"));
        }

        [TestCase(1, 5, 1, 5)]
        [TestCase(1, 5, 2, 4)]
        [TestCase(1, 5, 3, 3)]
        [TestCase(1, 10, 1, 10)]
        [TestCase(1, 10, 7, 4)]
        [TestCase(0, 6, 0, 6)]
        [TestCase(0, 6, 4, 2)]
        [TestCase(-3, 3, -3, 3)]
        public void AReversedItemIsMirroredOnItsOwnScale(int min, int max, int response, int counted)
        {
            // Items(1, 2): item 2 is reverse-coded, item 1 counts as given.
            var q = new Questionnaire("q", "t", min, max, Items(1, 2));
            Assert.That(q.Recode(2, response), Is.EqualTo(counted));
            Assert.That(q.Recode(1, response), Is.EqualTo(response));
        }

        [Test]
        public void RecodeRefusesWhatRejectRefuses()
        {
            var q = new Questionnaire("q", "t", 1, 5, Items(1, 2));
            var e = Assert.Throws<ArgumentOutOfRangeException>(() => q.Recode(2, 6));
            Assert.That(e.ParamName, Is.EqualTo("response"));
            Assert.That(e.Message, Does.Contain("response 6 to 'q' item 2 is outside the scale 1 to 5"));
            Assert.That(() => q.Recode(3, 1), Throws.InstanceOf<ArgumentOutOfRangeException>().With.Message.Contains("has no item 3"));
            Assert.That(() => q.Recode(1, 0), Throws.InstanceOf<ArgumentOutOfRangeException>());
        }

        [Test]
        public void ScaleTextAndItemText()
        {
            Assert.That(new Questionnaire("q", "t", 1, 10, Items(1)).ScaleText(), Is.EqualTo("1 to 10"));
            Assert.That(new Questionnaire("q", "t", -2, 2, Items(1)).ScaleText(), Is.EqualTo("-2 to 2"));
            Assert.That(new QuestionnaireItem(4, "I felt it was light.", true).ToString(), Is.EqualTo("Q4 (reversed)"));
            Assert.That(new QuestionnaireItem(2, null, false).ToString(), Is.EqualTo("Q2"));
            Assert.That(new QuestionnaireItem(2, null, false).Text, Is.EqualTo(""));
        }

        [Test]
        public void AScoreIsFiniteOrAbsentAndReadsAsItsCsvRow()
        {
            Assert.That(new ParticipantScore("P1", "immersion", 4.25).ToString(), Is.EqualTo("P1,immersion,4.25"));
            Assert.That(new ParticipantScore("P1", "immersion", null).ToString(), Is.EqualTo("P1,immersion,incomplete"));
            Assert.That(new ParticipantScore("P1", "immersion", null).IsComplete, Is.False);
            Assert.That(new ParticipantScore("P1", "immersion", 1).IsComplete, Is.True);
            Assert.That(new ParticipantScore("P1", "immersion", 3, null).MissingItems, Is.Empty);
            Assert.That(new ParticipantScore("P1", "immersion", null, new List<int> { 4, 7 }).MissingItems, Is.EqualTo(new[] { 4, 7 }));
            foreach (double bad in new[] { double.NaN, double.PositiveInfinity, double.NegativeInfinity })
            {
                var e = Assert.Throws<ArgumentException>(() => new ParticipantScore("P1", "immersion", bad));
                Assert.That(e.ParamName, Is.EqualTo("score"));
            }
        }
    }
}
