using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using Kosmos.PseudoHaptic.Evaluation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests.Evaluation
{
    /// <summary>
    /// The paper's published per-participant means (Tables 1–3, shared/data/paper-tables.csv) through the
    /// scores reader and the statistics: the paper's summary means 4.28, 4.05 and 8.42 come back.
    /// </summary>
    public class PaperTablesTests
    {
        static readonly string[] TableToQuestionnaire =
        {
            null, QuestionnaireCatalog.WeightDetectionId, QuestionnaireCatalog.ImmersionId, QuestionnaireCatalog.SelfAssessmentId,
        };

        /// <summary>paper-tables.csv (participant,table,value) rewritten as a scores file.</summary>
        static string PaperScoresCsv()
        {
            string path = EvaluationFiles.SharedFile(Path.Combine("data", "paper-tables.csv"));
            var table = CsvTable.Parse(File.ReadAllText(path), path, "participant", "table", "value");
            var scores = new List<ParticipantScore>();
            foreach (var row in table.Rows)
                scores.Add(new ParticipantScore(row[0], TableToQuestionnaire[int.Parse(row[1], CultureInfo.InvariantCulture)],
                    double.Parse(row[2], CultureInfo.InvariantCulture)));
            return ScoresCsv.Format(scores);
        }

        [TestCase(QuestionnaireCatalog.WeightDetectionId, 4.28, 2.9, 5.0)]
        [TestCase(QuestionnaireCatalog.ImmersionId, 4.05, 2.1, 4.8)]
        [TestCase(QuestionnaireCatalog.SelfAssessmentId, 8.42, 5.0, 10.0)]
        public void ThePapersMeansComeBack(string questionnaireId, double paperMean, double min, double max)
        {
            var scores = ScoresCsv.Parse(PaperScoresCsv(), "paper-tables", EvaluationFiles.PackageCatalog());
            var part = new List<ParticipantScore>();
            foreach (var s in scores) if (s.QuestionnaireId == questionnaireId) part.Add(s);

            var stats = SummaryStatistics.OfScores(part);
            Assert.That(stats.N, Is.EqualTo(12));
            Assert.That(Math.Round(stats.Mean, 2, MidpointRounding.AwayFromZero), Is.EqualTo(paperMean));
            Assert.That(stats.Min, Is.EqualTo(min));
            Assert.That(stats.Max, Is.EqualTo(max));
            Assert.That(stats.ConfidenceLow, Is.LessThan(stats.Mean));
            Assert.That(stats.ConfidenceHigh, Is.GreaterThan(stats.Mean));
        }

        [Test]
        public void TheFullSummaryOfTable1()
        {
            // Independently (Python's statistics module, t(0.975, 11) = 2.2009852): SD 0.7171070,
            // median 4.55, 95 % CI [3.8277053, 4.7389614].
            var scores = ScoresCsv.Parse(PaperScoresCsv(), "paper-tables", EvaluationFiles.PackageCatalog());
            var part = new List<ParticipantScore>();
            foreach (var s in scores) if (s.QuestionnaireId == QuestionnaireCatalog.WeightDetectionId) part.Add(s);
            var stats = SummaryStatistics.OfScores(part);
            Assert.That(stats.StandardDeviation, Is.EqualTo(0.7171070).Within(1e-6));
            Assert.That(stats.Median, Is.EqualTo(4.55).Within(1e-12));
            Assert.That(stats.ConfidenceLow, Is.EqualTo(3.8277053).Within(1e-6));
            Assert.That(stats.ConfidenceHigh, Is.EqualTo(4.7389614).Within(1e-6));
        }
    }
}
