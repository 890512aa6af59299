using System;
using Kosmos.PseudoHaptic.Simulation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>Issue 31: the model from a person's JND to a cue strength (<see cref="CueStrengthTuning"/>, ALGORITHM.md §12).</summary>
    public class CueStrengthTuningTests
    {
        static readonly double[] Boxes = CueStrengthTuning.ExperimentOneBoxes;

        [TestCase(2.0, 0.3), TestCase(1.0, 0.1), TestCase(0.5, 0.2), TestCase(2.0, 0.9)]
        public void TheTunedStrengthIsTheSmallestThatPutsAdjacentMassesOneJndApart(double standard, double jnd)
        {
            var t = CueStrengthTuning.Solve(standard, jnd, Boxes);
            var frames = ReferenceLift.Frames();
            double Cue(double m, double s) => ReferenceLift.Cue(NamedProfiles.PaperExperiment, m, WeightSolver.DefaultStandardSpeed, s, frames);
            Assert.That(t.ThresholdCue, Is.EqualTo(Math.Abs(Cue(standard + jnd, 1) - Cue(standard, 1))));
            double Least(double s) => Math.Min(Math.Abs(Cue(0.6, s) - Cue(1.0, s)), Math.Abs(Cue(1.0, s) - Cue(2.0, s)));
            Assert.That(t.Reached, Is.True);
            Assert.That(Least(t.CueStrength), Is.GreaterThanOrEqualTo(t.ThresholdCue), "one JND apart at the tuned strength");
            if (t.CueStrength > WeightSolver.MinCueStrength)
                Assert.That(Least(t.CueStrength - 1e-3), Is.LessThan(t.ThresholdCue), "and not at a strength 0.001 weaker: the least offset still felt");
        }

        [Test]
        public void TheCueIsTheLogOfTheRiseRatioAboutSTimesLnG()
        {
            var frames = ReferenceLift.Frames();
            foreach (double m in new[] { 0.6, 1.0, 2.0 })
                foreach (double s in new[] { 1.0 / 3, 1, 3 })
                {
                    double g = new WeightSolver(WeightModel.FromMass(m), NamedProfiles.PaperExperiment).Gain;
                    double cue = ReferenceLift.Cue(NamedProfiles.PaperExperiment, m, WeightSolver.DefaultStandardSpeed, s, frames);
                    // The reference lift is close to the standard pace: faster-moves-further's exponent stays within 10 % of 1.
                    Assert.That(cue / (s * Math.Log(g)), Is.InRange(0.9, 1.1), $"{m} kg at s = {s}");
                }
        }

        [Test]
        public void TheStrengthGrowsWithTheJndAndStopsAtTheBounds()
        {
            double last = 0;
            for (double jnd = 0.01; jnd < 4; jnd *= 1.3)
            {
                var t = CueStrengthTuning.Solve(2, jnd, Boxes);
                Assert.That(t.CueStrength, Is.GreaterThanOrEqualTo(last));
                Assert.That(t.CueStrength, Is.InRange(WeightSolver.MinCueStrength, WeightSolver.MaxCueStrength));
                last = t.CueStrength;
            }
            Assert.That(CueStrengthTuning.Solve(2, 0.01, Boxes).CueStrength, Is.EqualTo(WeightSolver.MinCueStrength), "a very sensitive person: the weakest strength suffices");
            var hopeless = CueStrengthTuning.Solve(2, 50, Boxes);
            Assert.That(hopeless.Reached, Is.False);
            Assert.That(hopeless.CueStrength, Is.EqualTo(WeightSolver.MaxCueStrength));
            Assert.That(hopeless.AdjacentCue, Is.LessThan(hopeless.ThresholdCue));
        }

        [Test]
        public void BadArgumentsThrowNamingThem()
        {
            Assert.That(() => CueStrengthTuning.Solve(0, 0.1, Boxes), Throws.TypeOf<ArgumentOutOfRangeException>().With.Message.Contains("standardKg"));
            Assert.That(() => CueStrengthTuning.Solve(1, double.NaN, Boxes), Throws.TypeOf<ArgumentOutOfRangeException>().With.Message.Contains("jndKg"));
            Assert.That(() => CueStrengthTuning.Solve(1, 0.1, new[] { 1.0 }), Throws.ArgumentException.With.Message.Contains("masses"));
            Assert.That(() => CueStrengthTuning.Solve(1, 0.1, new[] { 1.0, -2 }), Throws.TypeOf<ArgumentOutOfRangeException>().With.Message.Contains("masses"));
        }
    }
}
