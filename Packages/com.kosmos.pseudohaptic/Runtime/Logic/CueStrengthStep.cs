using System;
using System.Collections.Generic;
using System.Globalization;
using Kosmos.PseudoHaptic.Evaluation;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// The calibration's second step (issue 31), engine-free: after the golf-ball lifts, a short 1-up-2-down staircase on
    /// the comparison's mass against a 2 kg standard, at the default cue strength (the discrimination task's procedure,
    /// <see cref="Settings"/>), then the cue strength tuned from the threshold it finds (<see cref="Tune"/>). A 1-up-2-down
    /// staircase converges on the level judged heavier 70.7 % of the time, Φ⁻¹(0.707) = 0.545 σ above the standard. The
    /// model's observer is Gaussian in the cue c (the rise ratio, <see cref="CueStrengthTuning"/>), not in kg, so the
    /// distance is taken in the cue: Δc(threshold) = c(standard) − c(threshold) at s = 1, and the JND (the 75 % point,
    /// 0.674 σ) is Δc* = Δc(threshold) × 0.674 / 0.545 (<see cref="ThresholdCueFromThreshold"/>), which
    /// <see cref="CueStrengthTuning.SolveForThresholdCue"/> turns into s for the scene's masses (Experiment 1's boxes by
    /// default). Above the standard the cue is nearly linear in kg, so the earlier kg reading gave nearly the same Δc* (within
    /// 0.3 % for thresholds 2.25–4 kg, <c>CueStrengthStepTests</c>); the cue reading keeps one model for tune and the headset. The Unity glue (<c>CueStrengthCalibrator</c>) runs the task and
    /// stores the result beside the user's standard speed.
    /// </summary>
    public static class CueStrengthStep
    {
        /// <summary>The standard the staircase compares against, kg (Experiment 1's heaviest box).</summary>
        public const double StandardKg = 2.0;

        /// <summary>The condition the staircase's trials are written under.</summary>
        public const string Condition = "cue-strength";

        /// <summary>
        /// The staircase: 1-up-2-down from 3 kg in steps of 0.5 kg, halved at the first two reversals (never below 0.05 kg),
        /// stopping after 12 reversals (the threshold the mean of the last 8) or 60 trials: about 40 trials, a few minutes'
        /// lifting. Measured on simulated observers who perceive the model's cue (<c>CueStrengthStepTests</c>): the median
        /// tuned strength of 40 runs lies within 30 % of the strength the observer's true JND gives. A single short run is a
        /// point estimate with no confidence margin: about half of the runs tune a little below the true JND's strength.
        /// </summary>
        public static DiscriminationSettings Settings(int seed = 31) => new DiscriminationSettings
        {
            Procedure = DiscriminationProcedure.Staircase1Up2Down,
            StandardKg = StandardKg,
            ComparisonKg = new double[0],
            CatchKg = new double[0],
            Seed = seed,
            StaircaseStartKg = 3.0,
            StaircaseStepKg = 0.5,
            HalvingReversals = 2,
            MinStepKg = 0.05,
            StopAfterReversals = 12,
            LastReversals = 8,
            MaxTrials = 60,
        };

        /// <summary>The JND (the 75 % point's distance from the standard) from a 1-up-2-down threshold, in the threshold's own
        /// units for a function Gaussian in them: NaN when the threshold is not above the standard (no usable threshold).
        /// <see cref="Tune"/> applies it in the cue (<see cref="ThresholdCueFromThreshold"/>).</summary>
        public static double JndFromThreshold(double threshold, double standardKg)
        {
            double above = threshold - standardKg;
            if (!(above > 0) || double.IsInfinity(above)) return double.NaN;
            return above * Normal.Quantile(0.75) / Normal.Quantile(Math.Sqrt(0.5));
        }

        /// <summary>
        /// Δc*, the threshold in the cue (s = 1, the reference lift at <paramref name="standardSpeed"/>): the cue distance of
        /// the 1-up-2-down threshold from the standard, × Φ⁻¹(0.75) / Φ⁻¹(√½); NaN when the threshold is not above the standard
        /// or does not rise on the lift.
        /// </summary>
        public static double ThresholdCueFromThreshold(double threshold, double standardKg, double standardSpeed)
        {
            if (!(threshold > standardKg) || double.IsInfinity(threshold)) return double.NaN;
            double d = CueStrengthTuning.CueDifference(standardKg, threshold, standardSpeed, ReferenceLift.Frames());
            if (!(d > 0)) return double.NaN;
            return d * Normal.Quantile(0.75) / Normal.Quantile(Math.Sqrt(0.5));
        }

        /// <summary>
        /// The tuned strength from a finished staircase, or null with <paramref name="reason"/> when it gives none (not
        /// finished, or a threshold at or below the standard: answers the staircase could not converge on).
        /// </summary>
        public static CueStrengthTuning Tune(Staircase staircase, IReadOnlyList<double> masses, double standardSpeed, out string reason)
        {
            reason = null;
            if (staircase == null || !staircase.Finished) { reason = "the staircase has not finished"; return null; }
            double thresholdCue = ThresholdCueFromThreshold(staircase.Threshold, staircase.Standard, standardSpeed);
            if (double.IsNaN(thresholdCue))
            {
                reason = "the staircase's threshold (" + staircase.Threshold.ToString("0.###", CultureInfo.InvariantCulture) + " kg) is not above the standard";
                return null;
            }
            return CueStrengthTuning.SolveForThresholdCue(staircase.Standard, thresholdCue, masses ?? CueStrengthTuning.ExperimentOneBoxes, standardSpeed);
        }

        /// <summary>What the participant is told when the strength is stored.</summary>
        public static string Message(CueStrengthTuning t) =>
            "Your weight threshold: " + (t.JndKg / t.StandardKg * 100).ToString("0", CultureInfo.InvariantCulture) + " % at "
            + t.StandardKg.ToString("0.#", CultureInfo.InvariantCulture) + " kg. Cue strength "
            + t.CueStrength.ToString("0.00", CultureInfo.InvariantCulture) + (t.Reached ? "." : " (the strongest; the boxes stay closer than your threshold).");
    }
}
