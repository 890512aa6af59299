using System;
using System.Collections.Generic;
using Kosmos.PseudoHaptic.Simulation;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// From a person's weight-discrimination threshold to a cue strength (issue 31; ALGORITHM.md §12). The model: a person
    /// judges weight by how far the object rises relative to the hand, and tells two objects apart when the ratio of their
    /// rises differs enough (Weber's law on the visible motion). The cue of an object is therefore
    /// c(m, s) = ln(rise_object / rise_hand) on the <see cref="ReferenceLift"/> (≈ s · ln G(m)). The person's JND in kg at
    /// the fitted standard m₀, measured with the cue as rendered (s = 1), gives the cue difference this person sees at
    /// threshold, Δc* = |c(m₀ + JND, 1) − c(m₀, 1)|; the tuned s is the smallest strength within
    /// [<see cref="WeightSolver.MinCueStrength"/>, <see cref="WeightSolver.MaxCueStrength"/>] at which every pair of
    /// adjacent masses of the scene differs by at least Δc* (the least offset still felt), or the upper bound when even it
    /// does not (<see cref="Reached"/> false). Why the rise ratio and not the lag in millimetres: the lag of a heavy object
    /// saturates at the lift itself as s grows (at 1 and 2 kg the lag difference is largest near s = 1 and shrinks beyond),
    /// so no strength could make heavy objects more distinct in millimetres, while the ratio of their rises grows with s.
    /// </summary>
    public sealed class CueStrengthTuning
    {
        /// <summary>Experiment 1's boxes (<see cref="PaperExperiment1"/>: A, C, B, lightest first), kg: the scene a person's cue is
        /// tuned for unless another is given.</summary>
        public static readonly double[] ExperimentOneBoxes =
        {
            PaperExperiment1.Mass(PaperExperiment1.BoxADensity), PaperExperiment1.Mass(PaperExperiment1.BoxCDensity), PaperExperiment1.Mass(PaperExperiment1.BoxBDensity),
        };

        /// <summary>The profile the tuning measures the cue under: the one the paper's experiments ran.</summary>
        public static WeightProfile Profile => NamedProfiles.PaperExperiment;

        public double StandardKg { get; private set; }
        public double JndKg { get; private set; }
        public double StandardSpeed { get; private set; }

        /// <summary>Δc*: the cue difference this person sees at threshold (rendered at s = 1).</summary>
        public double ThresholdCue { get; private set; }

        /// <summary>The tuned strength.</summary>
        public double CueStrength { get; private set; }

        /// <summary>Whether the adjacent masses reach Δc* within the bounds (false: <see cref="CueStrength"/> is the upper bound).</summary>
        public bool Reached { get; private set; }

        /// <summary>The smallest cue difference between adjacent masses at the tuned strength.</summary>
        public double AdjacentCue { get; private set; }

        public IReadOnlyList<double> Masses { get; private set; }

        /// <summary>
        /// Tunes for a person whose JND is <paramref name="jndKg"/> at the standard <paramref name="standardKg"/> (both finite,
        /// &gt; 0, their sum finite), for a scene of <paramref name="masses"/> (at least two, each finite and &gt; 0; sorted
        /// here), a user of standard speed <paramref name="standardSpeed"/>: the threshold cue is Δc* = |c(m₀ + JND, 1) − c(m₀, 1)|. Bad
        /// arguments throw naming the argument. A JND measured in kg by a Gaussian in kg is not the model's (the cue is not
        /// linear in kg); <c>tune</c> and the headset staircase measure Δc* in the cue itself (<see cref="SolveForThresholdCue"/>).
        /// </summary>
        public static CueStrengthTuning Solve(double standardKg, double jndKg, IReadOnlyList<double> masses, double standardSpeed = WeightSolver.DefaultStandardSpeed)
        {
            ConfigurationGuard.Positive(standardKg, nameof(standardKg));
            ConfigurationGuard.Positive(jndKg, nameof(jndKg));
            ConfigurationGuard.InRange(standardSpeed, WeightSolver.MinStandardSpeed, WeightSolver.MaxStandardSpeed, nameof(standardSpeed));
            // The comparison's mass must exist: named here, or the solver built for it would name its own massKg.
            if (double.IsInfinity(standardKg + jndKg))
                throw new ArgumentOutOfRangeException(nameof(jndKg), jndKg, "standardKg + jndKg must be a finite mass, got standardKg " + standardKg.ToString("R", System.Globalization.CultureInfo.InvariantCulture) + " and jndKg " + jndKg.ToString("R", System.Globalization.CultureInfo.InvariantCulture) + ".");
            var frames = ReferenceLift.Frames();
            double threshold = Math.Abs(ReferenceLift.Cue(Profile, standardKg + jndKg, standardSpeed, 1, frames) - ReferenceLift.Cue(Profile, standardKg, standardSpeed, 1, frames));
            return Tune(standardKg, jndKg, threshold, masses, standardSpeed, frames);
        }

        /// <summary>
        /// Tunes for a person whose threshold, measured in the cue itself at the standard <paramref name="standardKg"/> (finite,
        /// &gt; 0, at most <see cref="MaxStandardKgOfThresholdCue"/>) and
        /// s = 1, is <paramref name="thresholdCue"/> = Δc* (the 75 % point's distance in c, finite, &gt; 0): the psychometric
        /// function fitted on <see cref="CueDifference"/> rather than on kg. <see cref="JndKg"/> is then the mass above the
        /// standard whose cue lies Δc* below the standard's (the JND in kg this threshold means there), so that
        /// <see cref="Solve"/>(standardKg, JndKg) gives the same strength.
        /// </summary>
        public static CueStrengthTuning SolveForThresholdCue(double standardKg, double thresholdCue, IReadOnlyList<double> masses, double standardSpeed = WeightSolver.DefaultStandardSpeed)
        {
            ConfigurationGuard.Positive(standardKg, nameof(standardKg));
            ConfigurationGuard.Positive(thresholdCue, nameof(thresholdCue));
            // The search for the JND goes up to 1000 × the standard, which must be a finite mass.
            ConfigurationGuard.InRange(standardKg, 0, MaxStandardKgOfThresholdCue, nameof(standardKg));
            ConfigurationGuard.InRange(standardSpeed, WeightSolver.MinStandardSpeed, WeightSolver.MaxStandardSpeed, nameof(standardSpeed));
            var frames = ReferenceLift.Frames();
            return Tune(standardKg, JndKgOfCue(standardKg, thresholdCue, standardSpeed, frames), thresholdCue, masses, standardSpeed, frames);
        }

        /// <summary>The largest standard <see cref="SolveForThresholdCue"/> takes, kg: its search for the JND reaches 1000 × the
        /// standard, a finite mass up to here.</summary>
        public const double MaxStandardKgOfThresholdCue = double.MaxValue / 1000;

        /// <summary>
        /// The stimulus of the model's observer: c(standard, 1) − c(comparison, 1) on the reference lift, the cue by which a
        /// comparison rendered at s = 1 looks heavier than the standard (positive when heavier, 0 at the standard). NaN when
        /// either object does not rise on the lift.
        /// </summary>
        public static double CueDifference(double standardKg, double comparisonKg, double standardSpeed, TraceFrame[] frames)
        {
            double d = ReferenceLift.Cue(Profile, standardKg, standardSpeed, 1, frames) - ReferenceLift.Cue(Profile, comparisonKg, standardSpeed, 1, frames);
            return double.IsInfinity(d) ? double.NaN : d;
        }

        /// <summary>The mass above <paramref name="standardKg"/> whose cue (s = 1) lies <paramref name="thresholdCue"/> below the
        /// standard's, by bisection (the cue falls with mass); at most 1000 × the standard.</summary>
        static double JndKgOfCue(double standardKg, double thresholdCue, double standardSpeed, TraceFrame[] frames)
        {
            double c0 = ReferenceLift.Cue(Profile, standardKg, standardSpeed, 1, frames);
            double lo = standardKg, hi = standardKg;
            while (true)
            {
                hi *= 2;
                if (hi > 1000 * standardKg) return 1000 * standardKg - standardKg;
                if (c0 - ReferenceLift.Cue(Profile, hi, standardSpeed, 1, frames) >= thresholdCue) break;
                lo = hi;
            }
            for (int i = 0; i < 60 && hi - lo > 1e-12 * hi; i++)
            {
                double mid = 0.5 * (lo + hi);
                if (c0 - ReferenceLift.Cue(Profile, mid, standardSpeed, 1, frames) >= thresholdCue) hi = mid; else lo = mid;
            }
            return hi - standardKg;
        }

        static CueStrengthTuning Tune(double standardKg, double jndKg, double threshold, IReadOnlyList<double> masses, double standardSpeed, TraceFrame[] frames)
        {
            if (masses == null || masses.Count < 2) throw new ArgumentException("masses needs at least two masses.", nameof(masses));
            var sorted = new List<double>(masses.Count);
            foreach (double m in masses) sorted.Add(ConfigurationGuard.Positive(m, nameof(masses)));
            sorted.Sort();
            var t = new CueStrengthTuning { StandardKg = standardKg, JndKg = jndKg, StandardSpeed = standardSpeed, ThresholdCue = threshold, Masses = sorted };
            double lo = WeightSolver.MinCueStrength, hi = WeightSolver.MaxCueStrength;
            if (AdjacentCueAt(sorted, lo, standardSpeed, frames) >= threshold) t.Set(lo, true, sorted, frames);
            else if (AdjacentCueAt(sorted, hi, standardSpeed, frames) < threshold) t.Set(hi, false, sorted, frames);
            else
            {
                // The adjacent cue grows with s (≈ s · |Δ ln G|): bisection keeps hi where the criterion holds.
                for (int i = 0; i < 48 && hi - lo > 1e-9; i++)
                {
                    double mid = 0.5 * (lo + hi);
                    if (AdjacentCueAt(sorted, mid, standardSpeed, frames) >= threshold) hi = mid; else lo = mid;
                }
                t.Set(hi, true, sorted, frames);
            }
            return t;
        }

        void Set(double s, bool reached, List<double> sorted, TraceFrame[] frames)
        {
            CueStrength = s;
            Reached = reached;
            AdjacentCue = AdjacentCueAt(sorted, s, StandardSpeed, frames);
        }

        /// <summary>The smallest |c(m_{i+1}, s) − c(m_i, s)| over adjacent masses (sorted).</summary>
        public static double AdjacentCueAt(IReadOnlyList<double> sortedMasses, double cueStrength, double standardSpeed, TraceFrame[] frames)
        {
            double least = double.PositiveInfinity, previous = double.NaN;
            for (int i = 0; i < sortedMasses.Count; i++)
            {
                double c = ReferenceLift.Cue(Profile, sortedMasses[i], standardSpeed, cueStrength, frames);
                if (i > 0) least = Math.Min(least, Math.Abs(c - previous));
                previous = c;
            }
            return least;
        }
    }
}
