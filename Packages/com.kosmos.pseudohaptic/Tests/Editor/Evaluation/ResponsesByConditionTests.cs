using System;
using System.Collections.Generic;
using System.IO;
using Kosmos.PseudoHaptic.Evaluation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests.Evaluation
{
    /// <summary>
    /// A responses file of a study with conditions (evaluation.md, "Conditions", issue 11): one answer set per
    /// condition in the order the conditions first appear, the same item answerable once per condition; without
    /// the column, one set named "" read exactly as <see cref="ResponsesCsv.Parse(string, string, QuestionnaireCatalog)"/>.
    /// And the bound on what a streamed file may make the reader keep (<see cref="ParticipantLimit"/>).
    /// </summary>
    public class ResponsesByConditionTests
    {
        static IReadOnlyList<KeyValuePair<string, ResponseSet>> ByCondition(string text, out bool hasCondition)
            => ResponsesCsv.ParseByCondition(new StringReader(text), "R.csv", SampleQuestionnaires.Paper(), out hasCondition);

        static string[] Keys(IReadOnlyList<KeyValuePair<string, ResponseSet>> sets)
        {
            var keys = new string[sets.Count];
            for (int i = 0; i < sets.Count; i++) keys[i] = sets[i].Key;
            return keys;
        }

        [Test]
        public void EachConditionHasItsOwnAnswersInTheOrderTheConditionsFirstAppear()
        {
            var sets = ByCondition(
                "participant,condition,questionnaire,item,response\n"
                + "P1,visual,immersion,1,3\n"
                + "P1,pseudo-haptic,immersion,1,4\n"   // the same item, another condition: not a duplicate
                + "P2,visual,immersion,1,2\n"
                + "P2,pseudo-haptic,self-assessment,1,9\n", out bool hasCondition);

            Assert.That(hasCondition, Is.True);
            Assert.That(Keys(sets), Is.EqualTo(new[] { "visual", "pseudo-haptic" }));
            var visual = sets[0].Value;
            var haptic = sets[1].Value;
            Assert.That(visual.Count, Is.EqualTo(2));
            Assert.That(visual.Participants, Is.EqualTo(new[] { "P1", "P2" }));
            Assert.That(visual.Find("P1", "immersion").AnswerAt(0), Is.EqualTo(3));
            Assert.That(visual.Find("P2", "immersion").AnswerAt(0), Is.EqualTo(2));
            Assert.That(haptic.Count, Is.EqualTo(2));
            Assert.That(haptic.Find("P1", "immersion").AnswerAt(0), Is.EqualTo(4));
            Assert.That(haptic.Find("P2", "self-assessment").AnswerAt(0), Is.EqualTo(9));
        }

        [Test]
        public void TheSameItemTwiceInOneConditionIsStillADuplicateNamingItsLine()
        {
            var e = Assert.Throws<EvaluationFormatException>(() => ByCondition(
                "participant,condition,questionnaire,item,response\nP1,visual,immersion,1,3\nP1,haptic,immersion,1,3\nP1,visual,immersion,1,4\n", out _));
            Assert.That(e.Line, Is.EqualTo(4), e.Message);
            Assert.That(e.Reason, Does.Contain("duplicate"));
        }

        [Test]
        public void WithoutTheColumnThereIsOneSetNamedNothingReadAsTheOrdinaryReaderReadsIt()
        {
            const string text = "participant,questionnaire,item,response\nP1,immersion,1,3\nP2,immersion,1,5\nP1,self-assessment,1,7\n";
            var sets = ByCondition(text, out bool hasCondition);
            Assert.That(hasCondition, Is.False);
            Assert.That(Keys(sets), Is.EqualTo(new[] { "" }));

            var plain = ResponsesCsv.Parse(text, "R.csv", SampleQuestionnaires.Paper());
            var set = sets[0].Value;
            Assert.That(set.Count, Is.EqualTo(plain.Count));
            Assert.That(set.Participants, Is.EqualTo(plain.Participants));
            Assert.That(set.Find("P1", "self-assessment").AnswerAt(0), Is.EqualTo(plain.Find("P1", "self-assessment").AnswerAt(0)));
            Assert.That(set.Find("P2", "immersion").AnswerAt(0), Is.EqualTo(5));
        }

        [TestCase("participant,questionnaire,item,response\n", false)]
        [TestCase("participant,condition,questionnaire,item,response\n", true)]
        public void AHeaderOnlyFileIsOneEmptySetNamedNothing(string text, bool column)
        {
            // "A header-only R.csv gives a header-only S.csv": one set, no answers, no condition invented.
            var sets = ByCondition(text, out bool hasCondition);
            Assert.That(hasCondition, Is.EqualTo(column));
            Assert.That(Keys(sets), Is.EqualTo(new[] { "" }));
            Assert.That(sets[0].Value.Count, Is.EqualTo(0));
        }

        [Test]
        public void AFileWithMoreParticipantsThanTheLimitIsRefusedAtTheFirstRowBeyondIt()
        {
            const string text = "participant,questionnaire,item,response\nP1,immersion,1,3\nP1,immersion,2,3\n\nP2,immersion,1,3\n";
            var plain = Assert.Throws<EvaluationFormatException>(() => ResponsesCsv.Parse(
                new StringReader(text), "R.csv", SampleQuestionnaires.Paper(), int.MaxValue, long.MaxValue, new ParticipantLimit(1, long.MaxValue)));
            Assert.That(plain.Line, Is.EqualTo(5), plain.Message);
            Assert.That(plain.Reason, Does.Contain("more than 1 participant"));

            var byCondition = Assert.Throws<EvaluationFormatException>(() => ResponsesCsv.ParseByCondition(
                new StringReader(text), "R.csv", SampleQuestionnaires.Paper(), out _, int.MaxValue, long.MaxValue, new ParticipantLimit(1, long.MaxValue)));
            Assert.That(byCondition.Line, Is.EqualTo(5), byCondition.Message);
            Assert.That(byCondition.Reason, Does.Contain("more than 1 participant"));
        }

        [Test]
        public void MissingArgumentsAreTheCallersErrorWhateverTheFileHolds()
        {
            const string rows = "participant,questionnaire,item,response\nP1,immersion,1,3\n";
            var catalog = SampleQuestionnaires.Paper();
            Assert.That(Assert.Throws<ArgumentNullException>(() => ResponsesCsv.Parse((string)null, "R.csv", catalog)).ParamName, Is.EqualTo("text"));
            Assert.That(Assert.Throws<ArgumentNullException>(() => ResponsesCsv.Parse(
                new StringReader(rows), "R.csv", catalog, int.MaxValue, long.MaxValue, null)).ParamName, Is.EqualTo("limit"));
            // An empty file would be refused too, but a missing catalog is a programming error and is reported first.
            Assert.That(Assert.Throws<ArgumentNullException>(() => ResponsesCsv.ParseByCondition(
                new StringReader(""), "R.csv", null, out _)).ParamName, Is.EqualTo("catalog"));
            Assert.That(Assert.Throws<ArgumentNullException>(() => ResponsesCsv.Parse(
                new StringReader(rows), "R.csv", null, -1, long.MaxValue, ParticipantLimit.None)).ParamName, Is.EqualTo("catalog"), "before a bad row limit");
            Assert.That(Assert.Throws<ArgumentNullException>(() => ResponsesCsv.ParseByCondition(
                new StringReader(rows), "R.csv", catalog, out _, int.MaxValue, long.MaxValue, null)).ParamName, Is.EqualTo("limit"));
        }
    }
}
