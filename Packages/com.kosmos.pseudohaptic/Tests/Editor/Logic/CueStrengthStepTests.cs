using System;
using System.Collections.Generic;
using System.Linq;
using Kosmos.PseudoHaptic.Evaluation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>Issue 31: the calibration's cue-strength staircase and its tuning, engine-free (<see cref="CueStrengthStep"/>).</summary>
    public class CueStrengthStepTests
    {
        [Test]
        public void AOneUpTwoDownThresholdIsTurnedIntoTheSeventyFivePercentJnd()
        {
            // The 1-up-2-down point lies Φ⁻¹(√½) σ above the standard, the JND Φ⁻¹(0.75) σ: checked with the textbook values.
            double sigma = 0.4;
            Assert.That(CueStrengthStep.JndFromThreshold(2 + 0.5449 * sigma, 2), Is.EqualTo(0.6745 * sigma).Within(2e-4));
            Assert.That(CueStrengthStep.JndFromThreshold(2, 2), Is.NaN, "no threshold above the standard");
            Assert.That(CueStrengthStep.JndFromThreshold(1.5, 2), Is.NaN);
            Assert.That(CueStrengthStep.JndFromThreshold(double.NaN, 2), Is.NaN);
        }

        static double[] Run(double sigma, int runs)
        {
            var s = new List<double>();
            for (int seed = 1; seed <= runs; seed++)
            {
                var settings = CueStrengthStep.Settings(seed);
                var staircase = settings.MakeStaircase("sim", CueStrengthStep.Condition);
                var observer = new SimulatedObserver(CueStrengthStep.StandardKg, sigma, 1000 + seed);
                while (!staircase.Finished) staircase.Record(observer.Answer(staircase.Next().Comparison));
                var t = CueStrengthStep.Tune(staircase, CueStrengthTuning.ExperimentOneBoxes, WeightSolver.DefaultStandardSpeed, out string reason);
                if (t != null) s.Add(t.CueStrength);
            }
            return s.ToArray();
        }

        static double Median(double[] v) { var o = v.OrderBy(x => x).ToArray(); return o[o.Length / 2]; }

        [Test]
        public void TheShortStaircaseGivesAboutTheStrengthTheTrueJndGivesAndMoreForTheLessSensitive()
        {
            // Observers judging mass with σ = 0.15, 0.4 and 0.8 kg at the 2 kg standard (Weber 0.05, 0.13, 0.27).
            double previous = 0;
            foreach (double sigma in new[] { 0.15, 0.4, 0.8 })
            {
                var tuned = Run(sigma, 40);
                Assert.That(tuned.Length, Is.GreaterThanOrEqualTo(36), $"σ {sigma}: most runs give a threshold above the standard");
                double truth = CueStrengthTuning.Solve(CueStrengthStep.StandardKg, PsychometricFit.JndFactor * sigma, CueStrengthTuning.ExperimentOneBoxes).CueStrength;
                double median = Median(tuned);
                Assert.That(median, Is.InRange(truth * 0.7, truth * 1.3), $"σ {sigma}: the median of 40 short staircases against the true JND's strength {truth:F3}");
                Assert.That(median, Is.GreaterThanOrEqualTo(previous), $"σ {sigma}: a less sensitive observer gets at least as strong a cue");
                previous = median;
            }
        }

        [Test]
        public void AnUnfinishedStaircaseOrOneBelowTheStandardGivesNoStrength()
        {
            var staircase = CueStrengthStep.Settings().MakeStaircase("p", CueStrengthStep.Condition);
            Assert.That(CueStrengthStep.Tune(staircase, null, 0.5, out string reason), Is.Null);
            Assert.That(reason, Does.Contain("not finished"));
            // Someone who always calls the standard heavier: the staircase climbs to its maximum of trials... and one who
            // always calls the comparison heavier descends below the standard.
            while (!staircase.Finished) staircase.Record(1);
            Assert.That(CueStrengthStep.Tune(staircase, null, 0.5, out reason), Is.Null);
            Assert.That(reason, Does.Contain("not above the standard"));
        }

        [Test]
        public void TheStaircaseIsShortAndRunsAtTheDiscriminationTasksProcedure()
        {
            var settings = CueStrengthStep.Settings();
            Assert.That(settings.Procedure, Is.EqualTo(DiscriminationProcedure.Staircase1Up2Down));
            Assert.That(settings.MaxTrials, Is.LessThanOrEqualTo(60), "short: at most 60 trials");
            Assert.That(settings.StandardKg, Is.EqualTo(2.0));
            Assert.That(CueStrengthStep.Message(CueStrengthTuning.Solve(2, 0.4, CueStrengthTuning.ExperimentOneBoxes)), Does.StartWith("Your weight threshold: 20 % at 2 kg. Cue strength "));
        }
    }
}
