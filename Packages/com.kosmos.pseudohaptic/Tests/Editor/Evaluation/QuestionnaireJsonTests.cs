using System.Collections.Generic;
using Kosmos.PseudoHaptic.Evaluation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests.Evaluation
{
    public class QuestionnaireJsonTests
    {
        static int[] ReversedItems(Questionnaire q)
        {
            var reversed = new List<int>();
            foreach (var item in q.Items) if (item.Reverse) reversed.Add(item.Number);
            return reversed.ToArray();
        }

        [Test]
        public void PackageDefinitionsAreThePapersThreeParts()
        {
            var catalog = EvaluationFiles.PackageCatalog();
            Assert.That(catalog.Questionnaires.Count, Is.EqualTo(3));

            var part1 = catalog.Questionnaires[0];
            Assert.That(part1.Id, Is.EqualTo(QuestionnaireCatalog.WeightDetectionId));
            Assert.That(part1.ItemCount, Is.EqualTo(10));
            Assert.That(new[] { part1.ScaleMin, part1.ScaleMax }, Is.EqualTo(new[] { 1, 5 }));
            Assert.That(ReversedItems(part1), Is.EqualTo(new[] { 4, 7 }));

            var part2 = catalog.Questionnaires[1];
            Assert.That(part2.Id, Is.EqualTo(QuestionnaireCatalog.ImmersionId));
            Assert.That(part2.ItemCount, Is.EqualTo(10));
            Assert.That(new[] { part2.ScaleMin, part2.ScaleMax }, Is.EqualTo(new[] { 1, 5 }));
            Assert.That(ReversedItems(part2), Is.EqualTo(new[] { 3, 5, 8, 9 }));

            var part3 = catalog.Questionnaires[2];
            Assert.That(part3.Id, Is.EqualTo(QuestionnaireCatalog.SelfAssessmentId));
            Assert.That(part3.ItemCount, Is.EqualTo(1));
            Assert.That(new[] { part3.ScaleMin, part3.ScaleMax }, Is.EqualTo(new[] { 1, 10 }));
            Assert.That(ReversedItems(part3), Is.Empty);
        }

        [Test]
        public void PackageItemsAreNumberedOneToNWithText()
        {
            foreach (var q in EvaluationFiles.PackageCatalog().Questionnaires)
                for (int i = 0; i < q.ItemCount; i++)
                {
                    Assert.That(q.Items[i].Number, Is.EqualTo(i + 1), q.Id);
                    Assert.That(q.Items[i].Text, Is.Not.Empty, q.Id);
                    Assert.That(q.Items[i].Text.Trim(), Does.EndWith(".").Or.EndWith("?"), q.Id + " item " + (i + 1));
                }
        }

        [Test]
        public void ParsesAMinimalDefinitionWithDefaults()
        {
            var q = QuestionnaireJson.Parse(
                "{ \"id\": \"demo\", \"scale\": { \"min\": 0, \"max\": 6 }, \"items\": [ { \"number\": 2, \"text\": \"B\" }, { \"number\": 1, \"text\": \"A\", \"reverse\": true } ], \"language\": \"en\" }",
                "demo.json");
            Assert.That(q.Id, Is.EqualTo("demo"));
            Assert.That(q.Title, Is.EqualTo("demo"));
            Assert.That(q.ScaleMin, Is.EqualTo(0));
            Assert.That(q.ScaleMax, Is.EqualTo(6));
            Assert.That(q.Items[0].Number, Is.EqualTo(2));
            Assert.That(q.Items[0].Reverse, Is.False);
            Assert.That(q.FindItem(1).Reverse, Is.True);
            Assert.That(q.Recode(1, 2), Is.EqualTo(4));
        }

        [TestCase("{ \"id\": \"x\",\n  \"scale\": { \"min\": 5, \"max\": 1 },\n  \"items\": [ { \"number\": 1, \"text\": \"A\" } ] }", 2, "below max")]
        [TestCase("{ \"id\": \"x\",\n  \"scale\": { \"min\": 1, \"max\": 5 },\n  \"items\": [\n { \"number\": 1, \"text\": \"A\" },\n { \"number\": 1, \"text\": \"B\" } ] }", 5, "appears twice")]
        [TestCase("{ \"id\": \"x\",\n  \"scale\": { \"min\": 1, \"max\": 5 },\n  \"items\": [\n { \"number\": \"one\", \"text\": \"A\" } ] }", 4, "whole number")]
        [TestCase("{ \"id\": \"x\",\n  \"scale\": { \"min\": 1, \"max\": 5 },\n  \"items\": [\n { \"number\": 1 } ] }", 4, "missing \"text\"")]
        [TestCase("{ \"id\": \"x\",\n  \"items\": [ { \"number\": 1, \"text\": \"A\" } ] }", 1, "missing \"scale\"")]
        [TestCase("{ \"id\": \"x\",\n  \"scale\": { \"min\": 1, \"max\": 5 },\n  \"items\": [ { \"number\": 1, \"text\": \"A\", \"reverse\": \"yes\" } ] }", 3, "true or false")]
        [TestCase("{ \"id\": \"x\",\n  \"scale\": { \"min\": 1, \"max\": 5 },\n  \"items\": [ ] }", 3, "empty")]
        [TestCase("{ \"id\": \"x\",\n  \"scale\": { \"min\": 1, \"max\": 5 }\n  \"items\": [] }", 3, "not valid JSON")]
        [TestCase("[1, 2]", 1, "JSON object")]
        public void RejectsABrokenDefinitionNamingTheLine(string json, int line, string reason)
        {
            var e = Assert.Throws<EvaluationFormatException>(() => QuestionnaireJson.Parse(json, "x.json"));
            Assert.That(e.Line, Is.EqualTo(line), e.Message);
            Assert.That(e.Reason, Does.Contain(reason));
            Assert.That(e.Message, Does.StartWith("x.json:" + line + ": "));
        }

        [Test]
        public void ParseAllOfNoDefinitionIsAFormatErrorNamingTheQuestionnairesAndNullIsTheCallers()
        {
            // A study whose embedded definitions are all missing gets the one-line FILE: reason message, not a crash.
            var e = Assert.Throws<EvaluationFormatException>(() => QuestionnaireJson.ParseAll(new KeyValuePair<string, string>[0]));
            Assert.That(e.Message, Does.StartWith("questionnaires: "));
            Assert.That(e.Reason, Does.Contain("no questionnaires"));
            Assert.That(Assert.Throws<System.ArgumentNullException>(() => QuestionnaireJson.ParseAll(null)).ParamName, Is.EqualTo("namedJson"));
        }

        [Test]
        public void ParseAllKeepsTheGivenOrderAndRejectsRepeatedIds()
        {
            string a = "{ \"id\": \"a\", \"scale\": { \"min\": 1, \"max\": 5 }, \"items\": [ { \"number\": 1, \"text\": \"A\" } ] }";
            string b = "{ \"id\": \"b\", \"scale\": { \"min\": 1, \"max\": 5 }, \"items\": [ { \"number\": 1, \"text\": \"B\" } ] }";
            var catalog = QuestionnaireJson.ParseAll(new[] { new KeyValuePair<string, string>("b.json", b), new KeyValuePair<string, string>("a.json", a) });
            Assert.That(catalog.Questionnaires[0].Id, Is.EqualTo("b"));
            Assert.That(catalog.IndexOf("a"), Is.EqualTo(1));
            Assert.That(catalog.Find("A"), Is.Null, "ids are case-sensitive");
            // Two copies of one definition: the error names the copy and where the id was first given.
            var e = Assert.Throws<EvaluationFormatException>(() => QuestionnaireJson.ParseAll(new[] { new KeyValuePair<string, string>("b.json", b),
                new KeyValuePair<string, string>("a.json", a), new KeyValuePair<string, string>("a2.json", a) }));
            Assert.That(e.SourceName, Is.EqualTo("a2.json"));
            Assert.That(e.Message, Does.Contain("'a'").And.Contain("already defined in a.json"));
        }
    }
}
