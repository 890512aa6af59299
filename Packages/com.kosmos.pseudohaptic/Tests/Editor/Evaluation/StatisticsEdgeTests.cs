using System;
using System.Collections.Generic;
using Kosmos.PseudoHaptic.Evaluation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests.Evaluation
{
    /// <summary>
    /// Cronbach's α, the summary statistics and the scores at their boundaries: two participants or two
    /// items, empty input, totals that do not vary, answers far from zero (a variance must not be taken as
    /// Σx² − n·mean²), refused arguments and the messages a study designer reads. Expected values by hand.
    /// </summary>
    public class StatisticsEdgeTests
    {
        const string Immersion = QuestionnaireCatalog.ImmersionId;
        const string Self = QuestionnaireCatalog.SelfAssessmentId;

        // ---- Cronbach's α ----

        [Test]
        public void AlphaOfTwoParticipantsAndTwoItemsIsDefined()
        {
            // Items (1,2) and (2,4): variances ½ and 2; totals 3 and 6, variance 4.5.
            // α = 2/1 · (1 − 2.5/4.5) = 8/9.
            var alpha = CronbachAlpha.Compute(new[] { new[] { 1.0, 2.0 }, new[] { 2.0, 4.0 } });
            Assert.That(alpha.Alpha, Is.EqualTo(8.0 / 9).Within(1e-12));
            Assert.That(alpha.Participants, Is.EqualTo(2));
            Assert.That(alpha.Items, Is.EqualTo(2));
        }

        [Test]
        public void AlphaIsUndefinedWhenTotalsDoNotVaryThoughItemsDo()
        {
            // Items (1,2) and (2,1): each varies, every total is 3: s²ₜ = 0, α undefined (not −∞).
            var alpha = CronbachAlpha.Compute(new[] { new[] { 1.0, 2.0 }, new[] { 2.0, 1.0 } });
            Assert.That(alpha.IsDefined, Is.False);
            Assert.That(alpha.Alpha, Is.NaN);
        }

        [Test]
        public void AlphaDoesNotChangeWhenEveryAnswerIsScaledAndShiftedFarFromZero()
        {
            // α depends on variances only, and they all scale alike: 1e15 + 3·x for CronbachAlphaTests' example
            // (exact integers in a double, 1e15 < 2⁵³) must leave it at 32.25/34. A variance taken as Σ(x + m)(x − m),
            // i.e. Σx² − n·m², loses the few units that matter to rounding at 6e15·d.
            var shifted = new double[4][];
            double[][] example = { new[] { 1.0, 2.0, 2.0 }, new[] { 2.0, 3.0, 3.0 }, new[] { 3.0, 3.0, 4.0 }, new[] { 4.0, 5.0, 4.0 } };
            for (int r = 0; r < 4; r++)
            {
                shifted[r] = new double[3];
                for (int i = 0; i < 3; i++) shifted[r][i] = 1e15 + 3 * example[r][i];
            }
            Assert.That(CronbachAlpha.Compute(shifted).Alpha, Is.EqualTo(32.25 / 34).Within(1e-9));
        }

        [Test]
        public void AlphaOfNoRowsIsUndefinedWithNoItems()
        {
            var alpha = CronbachAlpha.Compute(new double[0][]);
            Assert.That(alpha.IsDefined, Is.False);
            Assert.That(alpha.Participants, Is.EqualTo(0));
            Assert.That(alpha.Items, Is.EqualTo(0));
        }

        [Test]
        public void AlphaRefusesRaggedOrMissingRowsNamingTheRow()
        {
            var ragged = Assert.Throws<ArgumentException>(() => CronbachAlpha.Compute(new[] { new[] { 1.0, 2.0, 3.0 }, new[] { 2.0, 3.0, 4.0 }, new[] { 1.0, 2.0 } }));
            Assert.That(ragged.Message, Does.StartWith("row 2 does not have 3 items"));
            Assert.That(ragged.ParamName, Is.EqualTo("rows"));
            var missing = Assert.Throws<ArgumentException>(() => CronbachAlpha.Compute(new[] { new[] { 1.0, 2.0 }, null }));
            Assert.That(missing.Message, Does.StartWith("row 1 does not have 2 items"));
            Assert.That(Assert.Throws<ArgumentNullException>(() => CronbachAlpha.Compute(null)).ParamName, Is.EqualTo("rows"));
        }

        [Test]
        public void AlphaFromSheetsKnowsTheItemCountEvenWithoutACompleteSheet()
        {
            var three = SampleQuestionnaires.Part("three", 3, 1, 5);
            var set = new ResponseSet(new QuestionnaireCatalog(new[] { three }));
            SampleQuestionnaires.Answer(set, "A", "three", 1, 2); // item 3 unanswered
            var alpha = CronbachAlpha.FromSheets(set.SheetsOf("three"));
            Assert.That(alpha.IsDefined, Is.False);
            Assert.That(alpha.Participants, Is.EqualTo(0));
            Assert.That(alpha.Items, Is.EqualTo(3));

            var none = CronbachAlpha.FromSheets(new AnswerSheet[0]);
            Assert.That(none.IsDefined, Is.False);
            Assert.That(none.Items, Is.EqualTo(0));
            Assert.That(Assert.Throws<ArgumentNullException>(() => CronbachAlpha.FromSheets(null)).ParamName, Is.EqualTo("sheets"));
        }

        [Test]
        public void AlphaRefusesSheetsOfTwoQuestionnairesNamingBoth()
        {
            var set = new ResponseSet(SampleQuestionnaires.Paper());
            SampleQuestionnaires.Answer(set, "P1", Immersion, 1, 2, 3, 4, 5, 1, 2, 3, 4, 5);
            SampleQuestionnaires.Answer(set, "P1", Self, 7);
            var e = Assert.Throws<ArgumentException>(() => CronbachAlpha.FromSheets(new[] { set.Find("P1", Immersion), set.Find("P1", Self) }));
            Assert.That(e.Message, Does.StartWith("sheets of different questionnaires ('" + Immersion + "', '" + Self + "')"));
        }

        [Test]
        public void AlphaOfAQuestionnaireNobodyAnsweredOrNoCatalogHas()
        {
            var set = new ResponseSet(SampleQuestionnaires.Paper());
            var unknown = CronbachAlpha.Of(set, "presence");
            Assert.That(unknown.IsDefined, Is.False);
            Assert.That(unknown.Items, Is.EqualTo(0));
            Assert.That(Assert.Throws<ArgumentNullException>(() => CronbachAlpha.Of(null, Immersion)).ParamName, Is.EqualTo("responses"));
        }

        // ---- Summary statistics ----

        [Test]
        public void SummarySpreadScalesAndIgnoresAShiftFarFromZero()
        {
            // 1e15 + 7·(1..5), exact integers in a double: SD 7·√2.5 and SE 7·√0.5 as for 1..5
            // (StatisticsTests.SummaryOfOneToFive), which Σx² − n·mean² would lose to rounding.
            var s = SummaryStatistics.Compute(new[] { 1e15 + 28, 1e15 + 14, 1e15 + 35, 1e15 + 7, 1e15 + 21 });
            Assert.That(s.Mean, Is.EqualTo(1e15 + 21));
            Assert.That(s.StandardDeviation, Is.EqualTo(7 * Math.Sqrt(2.5)).Within(1e-9));
            Assert.That(s.StandardError, Is.EqualTo(7 * Math.Sqrt(0.5)).Within(1e-9));
        }

        [TestCase(0.0)]
        [TestCase(1.0)]
        [TestCase(1.5)]
        [TestCase(-0.5)]
        [TestCase(double.NaN)]
        public void SummaryRefusesAConfidenceOutsideTheOpenInterval(double confidence)
        {
            // One value: no interval is computed, so the refusal must come from Compute itself.
            var e = Assert.Throws<ArgumentOutOfRangeException>(() => SummaryStatistics.Compute(new[] { 3.0 }, confidence));
            Assert.That(e.ParamName, Is.EqualTo("confidence"));
            Assert.That(e.Message, Does.StartWith("confidence must be in (0, 1)"));
        }

        [Test]
        public void SummaryRefusalsNameTheArgument()
        {
            var e = Assert.Throws<ArgumentException>(() => SummaryStatistics.Compute(new[] { 1.0, double.PositiveInfinity }));
            Assert.That(e.Message, Does.StartWith("values must be finite"));
            Assert.That(e.ParamName, Is.EqualTo("values"));
            Assert.That(Assert.Throws<ArgumentNullException>(() => SummaryStatistics.Compute(null)).ParamName, Is.EqualTo("values"));
            Assert.That(Assert.Throws<ArgumentNullException>(() => SummaryStatistics.OfScores(null)).ParamName, Is.EqualTo("scores"));
        }

        // ---- Participant scores ----

        [Test]
        public void AScoreWithoutAConditionHasTheEmptyOneAndKeepsAGivenOne()
        {
            Assert.That(new ParticipantScore("P1", Immersion, 4.0).Condition, Is.EqualTo(""));
            Assert.That(new ParticipantScore("P1", null, Immersion, 4.0).Condition, Is.EqualTo(""));
            var heavy = new ParticipantScore("P1", "heavy", Immersion, 4.0);
            Assert.That(heavy.Condition, Is.EqualTo("heavy"));
            Assert.That(heavy.QuestionnaireId, Is.EqualTo(Immersion));
        }

        [Test]
        public void AScoreMustBeFinite()
        {
            var e = Assert.Throws<ArgumentException>(() => new ParticipantScore("P1", Immersion, double.NaN));
            Assert.That(e.Message, Does.StartWith("score must be finite"));
            Assert.That(e.ParamName, Is.EqualTo("score"));
        }

        [Test]
        public void AScoreReadsAsACsvRowThatRoundTrips()
        {
            Assert.That(new ParticipantScore("P1", Immersion, 4.4).ToString(), Is.EqualTo("P1," + Immersion + ",4.4"));
            Assert.That(new ParticipantScore("P2", Immersion, null, new[] { 3 }).ToString(), Is.EqualTo("P2," + Immersion + ",incomplete"));
            // 1/3 needs 16 significant digits to read back as the same double (15 would lose it).
            string third = new ParticipantScore("P3", Self, 1.0 / 3).ToString();
            Assert.That(double.Parse(third.Split(',')[2], System.Globalization.CultureInfo.InvariantCulture), Is.EqualTo(1.0 / 3));
        }

        [Test]
        public void ScoresByConditionCarryTheirCondition()
        {
            var light = new ResponseSet(SampleQuestionnaires.Paper());
            var heavy = new ResponseSet(SampleQuestionnaires.Paper());
            SampleQuestionnaires.Answer(light, "P10", Self, 3);
            SampleQuestionnaires.Answer(light, "P2", Self, 4);
            SampleQuestionnaires.Answer(heavy, "P2", Self, 8);
            SampleQuestionnaires.Answer(heavy, "P2", Immersion, 1, 1, 1, 1, 1, 1, 1, 1, 1); // item 10 unanswered
            var scores = ScoreCalculator.ScoreAll(new[]
            {
                new KeyValuePair<string, ResponseSet>("light", light),
                new KeyValuePair<string, ResponseSet>("heavy", heavy),
            });
            Assert.That(scores.Count, Is.EqualTo(4));
            var rows = new List<string>();
            foreach (var s in scores) rows.Add(s.Participant + " " + s.Condition + " " + s.QuestionnaireId + " " + (s.Score.HasValue ? s.Score.Value.ToString(System.Globalization.CultureInfo.InvariantCulture) : "-"));
            Assert.That(rows, Is.EqualTo(new[]
            {
                "P2 light " + Self + " 4",
                "P2 heavy " + Immersion + " -",
                "P2 heavy " + Self + " 8",
                "P10 light " + Self + " 3",
            }));
            Assert.That(scores[1].MissingItems, Is.EqualTo(new[] { 10 }));
        }

        [Test]
        public void ScoringRefusesNothingToScore()
        {
            Assert.That(Assert.Throws<ArgumentNullException>(() => ScoreCalculator.Score(null)).ParamName, Is.EqualTo("sheet"));
            Assert.That(Assert.Throws<ArgumentNullException>(() => ScoreCalculator.ScoreAll((ResponseSet)null)).ParamName, Is.EqualTo("responses"));
            Assert.That(Assert.Throws<ArgumentNullException>(() => ScoreCalculator.ScoreAll((IReadOnlyList<KeyValuePair<string, ResponseSet>>)null)).ParamName, Is.EqualTo("byCondition"));
            Assert.That(Assert.Throws<ArgumentNullException>(() => ScoreCalculator.ScoreAll(SampleQuestionnaires.Paper(), null)).ParamName, Is.EqualTo("responses"));
        }
    }
}
