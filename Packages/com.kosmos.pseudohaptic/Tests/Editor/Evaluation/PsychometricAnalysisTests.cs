using System;
using System.Collections.Generic;
using Kosmos.PseudoHaptic.Evaluation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests.Evaluation
{
    /// <summary>
    /// psychometric's analysis (<see cref="PsychometricAnalysis"/>, <see cref="PsychometricRow"/>): one fit per
    /// participant × condition × standard, in participant order, conditions as first seen, standards ascending;
    /// each group fitted on its own answers with the lapse given, bootstrapped with the group's seed drawn in
    /// that order from the seed; progress after each group; Weber = JND / standard.
    /// </summary>
    public class PsychometricAnalysisTests
    {
        const int Resamples = 20;

        struct Group
        {
            public string Participant, Condition;
            public double Standard, Pse, Sigma;
        }

        // The file's first answer is P10 in "b": condition b comes before a; P2 sorts before P10.
        static readonly Group[] Groups =
        {
            new Group { Participant = "P10", Condition = "b", Standard = 0.6, Pse = 0.62, Sigma = 0.08 },
            new Group { Participant = "P10", Condition = "a", Standard = 0.4, Pse = 0.38, Sigma = 0.05 },
            new Group { Participant = "P2", Condition = "a", Standard = 0.6, Pse = 0.58, Sigma = 0.07 },
            new Group { Participant = "P2", Condition = "b", Standard = 0.6, Pse = 0.65, Sigma = 0.09 },
            new Group { Participant = "P2", Condition = "b", Standard = 0.4, Pse = 0.41, Sigma = 0.06 },
        };

        // Expected order: participant, then condition as first seen (b, a), then standard ascending.
        static readonly int[] ExpectedOrder = { 4, 3, 2, 0, 1 };

        /// <summary>Answers of simulated observers, the groups interleaved trial by trial.</summary>
        static List<TrialAnswer> Answers()
        {
            var observers = new SimulatedObserver[Groups.Length];
            for (int g = 0; g < Groups.Length; g++) observers[g] = new SimulatedObserver(Groups[g].Pse, Groups[g].Sigma, 100 + g);
            double[] factors = { 0.7, 0.85, 1.0, 1.15, 1.3 };
            var answers = new List<TrialAnswer>();
            int line = 2;
            for (int rep = 0; rep < 12; rep++)
                foreach (double f in factors)
                    for (int g = 0; g < Groups.Length; g++)
                    {
                        double x = Groups[g].Standard * f;
                        answers.Add(new TrialAnswer(Groups[g].Participant, Groups[g].Condition, Groups[g].Standard, x, observers[g].Answer(x), line++));
                    }
            return answers;
        }

        static void GroupOf(IReadOnlyList<TrialAnswer> answers, Group g, out double[] x, out int[] y)
        {
            var xs = new List<double>();
            var ys = new List<int>();
            foreach (var a in answers)
                if (a.Participant == g.Participant && a.Condition == g.Condition && a.Standard == g.Standard)
                {
                    xs.Add(a.Comparison);
                    ys.Add(a.Response);
                }
            x = xs.ToArray();
            y = ys.ToArray();
        }

        [Test]
        public void NullAnswersAreRefused()
        {
            var e = Assert.Throws<ArgumentNullException>(() => PsychometricAnalysis.Fit(null, 0, 10, 1));
            Assert.That(e.ParamName, Is.EqualTo("answers"));
        }

        [Test]
        public void NoAnswersAreNoRowsAndNoProgress()
        {
            int calls = 0;
            Assert.That(PsychometricAnalysis.Fit(new TrialAnswer[0], 0, 10, 1, (done, all) => calls++), Is.Empty);
            Assert.That(calls, Is.EqualTo(0));
        }

        [TestCase(0.0)]
        [TestCase(0.02)]
        public void EachGroupIsFittedAndBootstrappedOnItsOwnInOrder(double lapse)
        {
            var answers = Answers();
            var progress = new List<int[]>();
            var rows = PsychometricAnalysis.Fit(answers, lapse, Resamples, 42, (done, all) => progress.Add(new[] { done, all }));
            Assert.That(rows.Count, Is.EqualTo(Groups.Length));
            var seeds = new SeededRandom(42);
            for (int i = 0; i < rows.Count; i++)
            {
                var g = Groups[ExpectedOrder[i]];
                var row = rows[i];
                Assert.That(row.Participant, Is.EqualTo(g.Participant), "row " + i);
                Assert.That(row.Condition, Is.EqualTo(g.Condition), "row " + i);
                Assert.That(row.Standard, Is.EqualTo(g.Standard), "row " + i);

                double[] x;
                int[] y;
                GroupOf(answers, g, out x, out y);
                Assert.That(x.Length, Is.EqualTo(60));
                var fit = PsychometricFit.Fit(x, y, lapse);
                // P2's "a" (0, 0, 9, 11 and 12 of 12 heavier) is explained best by a step at 0.6 once a lapse of 0.02
                // takes the 11 of 12: no σ; its bootstrap still draws its seed.
                bool step = lapse > 0 && g.Participant == "P2" && g.Condition == "a";
                Assert.That(fit.Estimable, Is.EqualTo(!step), "the simulated data fit: " + fit.Reason);
                Assert.That(row.Fit.Reason, Is.EqualTo(fit.Reason), "row " + i);
                Assert.That(row.Fit.Trials, Is.EqualTo(60));
                Assert.That(row.Fit.Lapse, Is.EqualTo(lapse));
                var boot = PsychometricBootstrap.Run(fit, Resamples, unchecked((long)seeds.NextUInt64()));
                if (step)
                {
                    Assert.That(row.Bootstrap.HasIntervals, Is.False, "row " + i);
                    continue;
                }
                Assert.That(row.Fit.Mu, Is.EqualTo(fit.Mu), "row " + i);
                Assert.That(row.Fit.Sigma, Is.EqualTo(fit.Sigma), "row " + i);
                Assert.That(row.Fit.Deviance, Is.EqualTo(fit.Deviance), "row " + i);
                Assert.That(row.Weber, Is.EqualTo(fit.Jnd / g.Standard), "row " + i);

                Assert.That(row.Bootstrap.Resamples, Is.EqualTo(Resamples));
                Assert.That(row.Bootstrap.HasIntervals, Is.True);
                Assert.That(row.Bootstrap.PseLow, Is.EqualTo(boot.PseLow), "row " + i + ": the group's seed is the i-th draw");
                Assert.That(row.Bootstrap.PseHigh, Is.EqualTo(boot.PseHigh), "row " + i);
                Assert.That(row.Bootstrap.JndLow, Is.EqualTo(boot.JndLow), "row " + i);
                Assert.That(row.Bootstrap.JndHigh, Is.EqualTo(boot.JndHigh), "row " + i);
                Assert.That(row.Bootstrap.Failed, Is.EqualTo(boot.Failed), "row " + i);
            }
            Assert.That(progress.Count, Is.EqualTo(Groups.Length));
            for (int i = 0; i < progress.Count; i++) Assert.That(progress[i], Is.EqualTo(new[] { i + 1, Groups.Length }));
        }

        [Test]
        public void TheSameAnswersAndSeedGiveTheSameNumbersAnotherSeedOnlyOtherIntervals()
        {
            var answers = Answers();
            var a = PsychometricAnalysis.Fit(answers, 0, Resamples, 7);
            var b = PsychometricAnalysis.Fit(answers, 0, Resamples, 7, null);
            var c = PsychometricAnalysis.Fit(answers, 0, Resamples, 8);
            int differ = 0;
            for (int i = 0; i < a.Count; i++)
            {
                Assert.That(b[i].Bootstrap.PseLow, Is.EqualTo(a[i].Bootstrap.PseLow));
                Assert.That(b[i].Bootstrap.JndHigh, Is.EqualTo(a[i].Bootstrap.JndHigh));
                Assert.That(c[i].Fit.Mu, Is.EqualTo(a[i].Fit.Mu), "the fit does not depend on the seed");
                if (c[i].Bootstrap.PseLow != a[i].Bootstrap.PseLow) differ++;
            }
            Assert.That(differ, Is.GreaterThan(0), "the seed reaches the bootstrap");
        }

        [Test]
        public void StandardsApartByOneUlpAreTwoGroups()
        {
            double s = 0.5, t = 0.5000000000000001;
            var answers = new List<TrialAnswer>();
            int line = 2;
            foreach (double standard in new[] { t, s })
                for (int i = 0; i < 10; i++) answers.Add(new TrialAnswer("P1", "", standard, 0.3 + 0.05 * i, i % 2, line++));
            var rows = PsychometricAnalysis.Fit(answers, 0, 0, 1);
            Assert.That(rows.Count, Is.EqualTo(2));
            Assert.That(rows[0].Standard, Is.EqualTo(s), "ascending");
            Assert.That(rows[1].Standard, Is.EqualTo(t));
            Assert.That(rows[0].Fit.Trials, Is.EqualTo(10));
            Assert.That(rows[0].Bootstrap.Resamples, Is.EqualTo(0));
        }

        [Test]
        public void AGroupThatCannotBeFittedStillHasItsRow()
        {
            var answers = new List<TrialAnswer>();
            for (int i = 0; i < 6; i++) answers.Add(new TrialAnswer("P1", "on", 0.5, 0.4 + 0.05 * i, 1, i + 2));
            var rows = PsychometricAnalysis.Fit(answers, 0, Resamples, 3);
            Assert.That(rows.Count, Is.EqualTo(1));
            Assert.That(rows[0].Fit.Estimable, Is.False, "all answers alike");
            Assert.That(rows[0].Bootstrap.HasIntervals, Is.False);
            Assert.That(rows[0].Bootstrap.Failed, Is.EqualTo(Resamples));
        }

        [Test]
        public void ARowKeepsWhatItWasGivenAndItsWeberIsJndOverStandard()
        {
            var fit = PsychometricFit.Fit(new[] { 0.4, 0.4, 0.5, 0.5, 0.6, 0.6, 0.4, 0.6 }, new[] { 0, 0, 1, 0, 1, 1, 1, 0 });
            var boot = PsychometricBootstrap.Run(fit, 0, 1);
            var row = new PsychometricRow("P1", "on", 0.5, fit, boot);
            Assert.That(row.Participant, Is.EqualTo("P1"));
            Assert.That(row.Condition, Is.EqualTo("on"));
            Assert.That(row.Standard, Is.EqualTo(0.5));
            Assert.That(row.Fit, Is.SameAs(fit));
            Assert.That(row.Bootstrap, Is.SameAs(boot));
            Assert.That(fit.Estimable, Is.True);
            Assert.That(row.Weber, Is.EqualTo(fit.Sigma * Normal.Quantile(0.75) / 0.5).Within(1e-12));
        }
    }
}
