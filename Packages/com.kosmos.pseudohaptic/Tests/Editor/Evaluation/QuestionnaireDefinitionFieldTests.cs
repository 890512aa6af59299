using System;
using System.Collections.Generic;
using System.IO;
using Kosmos.PseudoHaptic.Evaluation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests.Evaluation
{
    /// <summary>
    /// A translated or home-made questionnaire definition as a study designer edits it (evaluation.md, "The JSON
    /// format"): every required field present and of its type, the optional ones defaulting as documented, and
    /// each broken field refused as <c>FILE:LINE: reason</c> with the reason naming the field as the file spells
    /// it and saying what it must be. One property per line below, so the line tells which field is blamed.
    /// </summary>
    public class QuestionnaireDefinitionFieldTests
    {
        const string Item = "{ \"number\": 1, \"text\": \"The object felt heavy.\" }";

        /// <summary>A definition laid out one property a line: line 2 id, 3 title, 4 scale, 5 items.</summary>
        static string Definition(string id = "\"comfort\"", string title = "\"Comfort\"", string scale = "{ \"min\": 1, \"max\": 5 }", string items = "[ " + Item + " ]")
            => "{\n  \"id\": " + id + ",\n  \"title\": " + title + ",\n  \"scale\": " + scale + ",\n  \"items\": " + items + "\n}";

        static EvaluationFormatException Refused(string json)
            => Assert.Throws<EvaluationFormatException>(() => QuestionnaireJson.Parse(json, "comfort.json"));

        static void AssertRefused(string json, int line, params string[] reasonWords)
        {
            var e = Refused(json);
            Assert.That(e.SourceName, Is.EqualTo("comfort.json"));
            Assert.That(e.Line, Is.EqualTo(line), e.Message);
            Assert.That(e.Message, Does.StartWith("comfort.json:" + line + ": "));
            foreach (var word in reasonWords) Assert.That(e.Reason, Does.Contain(word), e.Message);
        }

        [Test]
        public void TheOptionalTextsAreReadAsWrittenAndAreEmptyWhenLeftOut()
        {
            var full = QuestionnaireJson.Parse(
                "{ \"id\": \"comfort\", \"instructions\": \"Think of the last lift.\",\n"
                + "  \"scale\": { \"min\": 1, \"max\": 7, \"minLabel\": \"Not at all\", \"maxLabel\": \"Very much\" },\n"
                + "  \"items\": [ " + Item + " ] }", "comfort.json");
            Assert.That(full.Instructions, Is.EqualTo("Think of the last lift."));
            Assert.That(full.ScaleMinLabel, Is.EqualTo("Not at all"));
            Assert.That(full.ScaleMaxLabel, Is.EqualTo("Very much"));

            // The panel shows the instructions and the end labels only when the file has them.
            var bare = QuestionnaireJson.Parse(Definition(), "comfort.json");
            Assert.That(bare.Instructions, Is.Empty);
            Assert.That(bare.ScaleMinLabel, Is.Empty);
            Assert.That(bare.ScaleMaxLabel, Is.Empty);
        }

        [Test]
        public void AnyWholeNumberIsAcceptedForTheScaleAndTheItemNumbers()
        {
            // "whole numbers, min < max" and "a number >= 1": the bounds of a 32-bit whole number included.
            var q = QuestionnaireJson.Parse(Definition(
                scale: "{ \"min\": -2147483648, \"max\": 2147483647 }",
                items: "[ { \"number\": 2147483647, \"text\": \"Last.\" } ]"), "comfort.json");
            Assert.That(q.ScaleMin, Is.EqualTo(int.MinValue));
            Assert.That(q.ScaleMax, Is.EqualTo(int.MaxValue));
            Assert.That(q.Items[0].Number, Is.EqualTo(int.MaxValue));
        }

        [Test]
        public void AScaleThatIsNotAnObjectIsNamed() => AssertRefused(Definition(scale: "5"), 4, "\"scale\"", "object");

        [Test]
        public void ItemsThatAreNotAnArrayAreNamed() => AssertRefused(Definition(items: Item), 5, "\"items\"", "array");

        [Test]
        public void AnItemThatIsNotAnObjectIsNamed()
            => AssertRefused(Definition(items: "[\n  " + Item + ",\n  \"The object felt light.\" ]"), 7, "item", "object");

        [Test]
        public void AnItemNumberBelowOneIsNamedWithTheLeastAllowed()
            => AssertRefused(Definition(items: "[\n  { \"number\": 0, \"text\": \"A.\" } ]"), 6, "number 0", "1");

        [Test]
        public void ARepeatedItemNumberIsNamed()
            => AssertRefused(Definition(items: "[\n  { \"number\": 2, \"text\": \"A.\" },\n  { \"number\": 2, \"text\": \"B.\" } ]"), 7, "number 2", "twice");

        [Test]
        public void AScaleWhoseMinIsNotBelowItsMaxIsRefused()
            => AssertRefused(Definition(scale: "{ \"min\": 3, \"max\": 3 }"), 4, "min", "max");

        [TestCase("5", "\"id\"", "string")]
        [TestCase("\"  \"", "\"id\"", "empty")]
        public void AMistypedOrBlankIdIsNamed(string id, string field, string what) => AssertRefused(Definition(id: id), 2, field, what);

        [Test]
        public void AMistypedTitleIsNamed() => AssertRefused(Definition(title: "7"), 3, "\"title\"", "string");

        [TestCase("{ \"min\": 1,\n \"max\": \"five\" }", 5, "whole number")]
        [TestCase("{ \"min\": 1,\n \"max\": 2147483648 }", 5, "large")]
        [TestCase("{ \"min\": 1,\n \"max\": 99999999999999999999 }", 5, "large")]
        public void AScaleEndThatIsNotAWholeNumberOrTooLargeIsNamed(string scale, int line, string what)
            => AssertRefused(Definition(scale: scale), line, "\"max\"", what);

        [Test]
        public void AReverseFlagThatIsNotTrueOrFalseIsNamed()
            => AssertRefused(Definition(items: "[\n  { \"number\": 1, \"text\": \"A.\", \"reverse\": \"yes\" } ]"), 6, "\"reverse\"", "true or false");

        [Test]
        public void AFieldGivenTwiceIsRefusedNotSilentlyTheLastOne()
        {
            // A copy-and-paste slip: which max did the designer mean? Neither is guessed.
            AssertRefused(Definition(scale: "{ \"min\": 1, \"max\": 5,\n \"max\": 7 }"), 5, "'max'");
        }

        [Test]
        public void BrokenJsonIsReportedOnceWithItsLineNotAgainInTheReason()
        {
            var e = Refused("{ \"id\": \"comfort\",\n  \"scale\": { \"min\": 1, \"max\": 5 }\n  \"items\": [] }");
            Assert.That(e.Line, Is.EqualTo(3), e.Message);
            Assert.That(e.Reason, Does.StartWith("not valid JSON: "));
            // FILE:LINE already says where: the reason carries neither the line again nor the parser's path and position.
            Assert.That(e.Reason, Does.Not.Contain("line").And.Not.Contain("position").And.Not.Contain("Path"), e.Message);
        }

        [Test]
        public void AnIdTheCsvFilesCouldNotHoldIsRefusedNamingTheFile()
        {
            // Ids are written into responses.csv and scores.csv unquoted: no comma, quote or edge space.
            var e = Refused(Definition(id: "\"comfort, part 2\""));
            Assert.That(e.SourceName, Is.EqualTo("comfort.json"));
            Assert.That(e.Reason, Does.Contain("comfort, part 2"));
        }

        [Test]
        public void ANullDefinitionIsTheCallersError()
        {
            var e = Assert.Throws<ArgumentNullException>(() => QuestionnaireJson.Parse(null, "comfort.json"));
            Assert.That(e.ParamName, Is.EqualTo("json"));
        }

        // --- a folder of definitions (LoadDirectory) ---

        static string NewFolder()
        {
            string dir = Path.Combine(Path.GetTempPath(), "ph-questionnaires-" + Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(dir);
            return dir;
        }

        static string Named(string id) => Definition(id: "\"" + id + "\"");

        [Test]
        public void AFolderIsReadDefaultPartsFirstThenTheOthersByFileName()
        {
            string dir = NewFolder();
            try
            {
                // Written out of order, so that the folder's own listing order is not the file-name order.
                foreach (var id in new[] { "zeta", "gamma", "alpha", "mu", "beta", "omega", "delta" })
                    File.WriteAllText(Path.Combine(dir, id + ".json"), Named(id));
                File.WriteAllText(Path.Combine(dir, "immersion.json"), Named("immersion"));
                File.WriteAllText(Path.Combine(dir, "notes.txt"), "not a definition");

                var ids = new List<string>();
                foreach (var q in QuestionnaireJson.LoadDirectory(dir).Questionnaires) ids.Add(q.Id);
                Assert.That(ids, Is.EqualTo(new[] { "immersion", "alpha", "beta", "delta", "gamma", "mu", "omega", "zeta" }));
            }
            finally { Directory.Delete(dir, true); }
        }

        [Test]
        public void AFolderWithTwoDefinitionsOfOneIdIsRefusedNamingBothFiles()
        {
            // A study folder with a copy of a definition (comfort.json saved again as comfort-v2.json): the copy read second is
            // named, with the file that gave the id first.
            string dir = NewFolder();
            try
            {
                File.WriteAllText(Path.Combine(dir, "comfort.json"), Named("comfort"));
                File.WriteAllText(Path.Combine(dir, "comfort-v2.json"), Named("comfort"));
                var e = Assert.Throws<EvaluationFormatException>(() => QuestionnaireJson.LoadDirectory(dir));
                Assert.That(e.SourceName, Is.EqualTo(Path.Combine(dir, "comfort.json")), "read by file name: comfort-v2.json first");
                Assert.That(e.Reason, Does.Contain("'comfort'").And.Contain("already defined in " + Path.Combine(dir, "comfort-v2.json")));
            }
            finally { Directory.Delete(dir, true); }
        }

        [Test]
        public void AFolderWithoutDefinitionsIsRefusedNamingIt()
        {
            string dir = NewFolder();
            try
            {
                File.WriteAllText(Path.Combine(dir, "notes.txt"), "not a definition");
                var e = Assert.Throws<EvaluationFormatException>(() => QuestionnaireJson.LoadDirectory(dir));
                Assert.That(e.SourceName, Is.EqualTo(dir));
                Assert.That(e.Reason, Does.Contain(".json"), "says what the folder should hold");
            }
            finally { Directory.Delete(dir, true); }
        }

        [Test]
        public void AMissingFolderIsRefusedNamingIt()
        {
            string dir = Path.Combine(Path.GetTempPath(), "ph-no-such-folder-" + Guid.NewGuid().ToString("N"));
            var e = Assert.Throws<EvaluationFormatException>(() => QuestionnaireJson.LoadDirectory(dir));
            Assert.That(e.SourceName, Is.EqualTo(dir));
            Assert.That(e.Reason, Does.Contain("not found"));
        }
    }
}
