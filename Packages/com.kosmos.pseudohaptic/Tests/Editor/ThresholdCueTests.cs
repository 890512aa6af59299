using System;
using Kosmos.PseudoHaptic.Simulation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>
    /// A threshold measured in the cue itself (<see cref="CueStrengthTuning.SolveForThresholdCue"/>, ALGORITHM.md §12): the
    /// JND in kg it stands for is the mass above the standard whose cue lies Δc* below the standard's (at most 1000 × the
    /// standard), so that <see cref="CueStrengthTuning.Solve"/> with that JND gives the same strength; and the stimulus
    /// <see cref="CueStrengthTuning.CueDifference"/>, NaN when an object does not rise.
    /// </summary>
    public class ThresholdCueTests
    {
        static readonly double[] Boxes = CueStrengthTuning.ExperimentOneBoxes;
        static double Speed => WeightSolver.DefaultStandardSpeed;

        // The last case: a light standard (10 g) and a threshold whose JND is about 1/8000 of it, found to the same precision.
        [TestCase(2.0, 0.1), TestCase(0.5, 0.3), TestCase(1.0, 2.0), TestCase(0.2, 0.05), TestCase(0.01, 1e-4)]
        public void TheJndIsTheMassWhoseCueLiesTheThresholdBelowTheStandards(double standard, double thresholdCue)
        {
            var t = CueStrengthTuning.SolveForThresholdCue(standard, thresholdCue, Boxes);
            var frames = ReferenceLift.Frames();
            Assert.That(t.ThresholdCue, Is.EqualTo(thresholdCue));
            Assert.That(t.JndKg, Is.GreaterThan(0));
            Assert.That(CueStrengthTuning.CueDifference(standard, standard + t.JndKg, Speed, frames), Is.EqualTo(thresholdCue).Within(1e-6 * thresholdCue));
            var again = CueStrengthTuning.Solve(standard, t.JndKg, Boxes);
            Assert.That(again.ThresholdCue, Is.EqualTo(thresholdCue).Within(1e-6 * thresholdCue), "Solve(standard, JndKg) sees the same threshold");
            Assert.That(again.CueStrength, Is.EqualTo(t.CueStrength).Within(1e-6), "and gives the same strength");
        }

        [TestCase(4.0), TestCase(3.0)]
        public void AComparisonWhoseCueLiesExactlyTheThresholdBelowGivesExactlyItsJnd(double comparison)
        {
            // Δc* taken from a comparison of 4 kg (twice the standard, where the search first brackets the JND) or 3 kg
            // (the first midpoint of that bracket): the search meets a mass whose cue lies exactly Δc* below the standard's,
            // and that mass is the answer: the JND is exactly comparison − standard, neither above nor below it.
            var frames = ReferenceLift.Frames();
            double threshold = CueStrengthTuning.CueDifference(2, comparison, Speed, frames);
            var t = CueStrengthTuning.SolveForThresholdCue(2, threshold, Boxes);
            Assert.That(t.JndKg, Is.EqualTo(comparison - 2));
        }

        [Test]
        public void AJndOfManyTimesTheStandardIsFoundToo()
        {
            // The mass 300 kg is 150 × a standard of 2 kg: still under the 1000 × bound.
            var frames = ReferenceLift.Frames();
            double threshold = CueStrengthTuning.CueDifference(2, 300, Speed, frames);
            var t = CueStrengthTuning.SolveForThresholdCue(2, threshold, Boxes);
            Assert.That(t.JndKg, Is.EqualTo(298).Within(1e-6 * 298));
        }

        [TestCase(2.0), TestCase(0.5)]
        public void AThresholdNoMassReachesStopsAtAThousandTimesTheStandard(double standard)
        {
            // The cue of a mass on the reference lift stays above −40 (its rise stays positive): a threshold of 1000 is out of reach.
            var t = CueStrengthTuning.SolveForThresholdCue(standard, 1000, Boxes);
            Assert.That(t.JndKg, Is.EqualTo(999 * standard).Within(1e-9 * standard), "the mass is at most 1000 × the standard");
        }

        [Test]
        public void TheCueDifferenceIsPositiveForHeavierAndNaNWhenAnObjectDoesNotRise()
        {
            var frames = ReferenceLift.Frames();
            Assert.That(CueStrengthTuning.CueDifference(1, 2, Speed, frames), Is.GreaterThan(0), "heavier looks heavier");
            Assert.That(CueStrengthTuning.CueDifference(1, 1, Speed, frames), Is.EqualTo(0));
            // A hand lifting 0.3 m from the floor: an object of 10¹² kg barely moves, so it ends more than the reference
            // lift's 0.2 m behind the hand: it did not rise (cue −∞), and the difference is NaN, not infinite.
            var path = HandPath.StartAt(0).Hold(ReferenceLift.RestBefore).MoveTo(0.3, ReferenceLift.DefaultSeconds).Hold(ReferenceLift.RestAfter);
            var high = new HeadsetSimulator { FrameRate = 90, PoseRate = 90, Latency = 0, JitterSd = 0 }.Render(path);
            Assert.That(ReferenceLift.Cue(NamedProfiles.PaperExperiment, 1e12, Speed, 1, high), Is.EqualTo(double.NegativeInfinity));
            Assert.That(CueStrengthTuning.CueDifference(1, 1e12, Speed, high), Is.NaN);
        }
    }
}
