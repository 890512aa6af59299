using System;

namespace Kosmos.PseudoHaptic.Evaluation
{
    /// <summary>
    /// One two-alternative forced-choice trial: a standard and a comparison (masses in kg, or gains: one unit
    /// per file), which of the two is presented first (on the left), whether it is a catch trial, and the
    /// answer once given (1 = the comparison was judged heavier, 0 = not, −1 = not yet answered).
    /// One row of the trials file (<see cref="TrialsCsv"/>).
    /// </summary>
    public sealed class Trial
    {
        public int Index { get; }
        public string Participant { get; }
        public string Condition { get; }
        public double Standard { get; }
        public double Comparison { get; }
        /// <summary>True when the comparison is presented first (on the left), false when the standard is.</summary>
        public bool ComparisonFirst { get; }
        public bool Catch { get; }
        public int Response { get; set; } = -1;

        public Trial(int index, string participant, string condition, double standard, double comparison, bool comparisonFirst, bool isCatch)
        {
            if (!IsFinite(standard)) throw new ArgumentException("standard must be finite", nameof(standard));
            if (!IsFinite(comparison)) throw new ArgumentException("comparison must be finite", nameof(comparison));
            Index = index;
            Participant = participant ?? "";
            Condition = condition ?? "";
            Standard = standard;
            Comparison = comparison;
            ComparisonFirst = comparisonFirst;
            Catch = isCatch;
        }

        static bool IsFinite(double v) => !double.IsNaN(v) && !double.IsInfinity(v);
    }
}
