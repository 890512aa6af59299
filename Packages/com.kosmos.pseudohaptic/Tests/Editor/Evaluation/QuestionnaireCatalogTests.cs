using System;
using System.IO;
using Kosmos.PseudoHaptic.Evaluation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests.Evaluation
{
    /// <summary>
    /// The questionnaires of a study in report order (evaluation.md §1): refused when they cannot be told apart,
    /// listed in messages as the CLI prints them, read from a folder as weight-detection, immersion,
    /// self-assessment, then any other *.json by file name.
    /// </summary>
    public class QuestionnaireCatalogTests
    {
        static Questionnaire Part(string id) => SampleQuestionnaires.Part(id, 2, 1, 5);

        [Test]
        public void IdsAreListedForMessagesInReportOrder()
        {
            // evaluation.md §4: "unknown questionnaire 'presence' (expected one of 'weight-detection', 'immersion', 'self-assessment')".
            Assert.That(SampleQuestionnaires.Paper().DescribeIds(), Is.EqualTo("'weight-detection', 'immersion', 'self-assessment'"));
            Assert.That(new QuestionnaireCatalog(new[] { Part("only") }).DescribeIds(), Is.EqualTo("'only'"));
        }

        [Test]
        public void ACatalogThatCannotTellItsQuestionnairesApartIsRefusedSayingWhy()
        {
            Assert.Throws<ArgumentNullException>(() => new QuestionnaireCatalog(null));
            var e = Assert.Throws<ArgumentException>(() => new QuestionnaireCatalog(new[] { Part("a"), null }));
            Assert.That(e.Message, Does.Contain("null questionnaire"));
            Assert.That(e.ParamName, Is.EqualTo("questionnaires"));
            e = Assert.Throws<ArgumentException>(() => new QuestionnaireCatalog(new[] { Part("immersion"), Part("a"), Part("immersion") }));
            Assert.That(e.Message, Does.Contain("questionnaire id 'immersion' appears twice"));
            e = Assert.Throws<ArgumentException>(() => new QuestionnaireCatalog(new Questionnaire[0]));
            Assert.That(e.Message, Does.Contain("no questionnaires"));
            Assert.That(e.ParamName, Is.EqualTo("questionnaires"));
        }

        [Test]
        public void TheDefaultFileNamesAreThePapersThreePartsInReportOrder()
        {
            Assert.That(QuestionnaireCatalog.DefaultFileNames, Is.EqualTo(new[]
            {
                QuestionnaireCatalog.WeightDetectionId + ".json", QuestionnaireCatalog.ImmersionId + ".json", QuestionnaireCatalog.SelfAssessmentId + ".json",
            }));
            string package = EvaluationFiles.QuestionnaireDirectory();
            foreach (string name in QuestionnaireCatalog.DefaultFileNames) Assert.That(File.Exists(Path.Combine(package, name)), Is.True, name);
        }

        [Test]
        public void AFolderIsReadThePapersPartsFirstThenOthersByName()
        {
            string package = EvaluationFiles.QuestionnaireDirectory();
            string dir = Path.Combine(Path.GetTempPath(), "ph-catalog-" + Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(dir);
            try
            {
                foreach (string name in new[] { "immersion.json", "self-assessment.json", "weight-detection.json" })
                    File.Copy(Path.Combine(package, name), Path.Combine(dir, name));
                // "anchoring" sorts before all three by name; it still comes after them.
                File.WriteAllText(Path.Combine(dir, "anchoring.json"),
                    "{ \"id\": \"anchoring\", \"scale\": { \"min\": 1, \"max\": 5 }, \"items\": [ { \"number\": 1, \"text\": \"How heavy?\" } ] }");
                var catalog = QuestionnaireJson.LoadDirectory(dir);
                Assert.That(catalog.DescribeIds(), Is.EqualTo("'weight-detection', 'immersion', 'self-assessment', 'anchoring'"));
            }
            finally
            {
                Directory.Delete(dir, true);
            }
        }
    }
}
