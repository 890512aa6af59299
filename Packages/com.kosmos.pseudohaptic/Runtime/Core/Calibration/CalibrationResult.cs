namespace Kosmos.PseudoHaptic
{
    /// <summary>The user's standard speed v_std from one or more golf-ball lifts, or why it could not be had.</summary>
    public readonly struct CalibrationResult
    {
        public readonly bool IsAccepted;

        /// <summary>v_std, m/s: the median of the consistent lifts; NaN when rejected.</summary>
        public readonly double StandardSpeed;

        /// <summary>Lifts that entered the median (accepted and not outliers).</summary>
        public readonly int LiftsUsed;

        /// <summary>Lifts offered.</summary>
        public readonly int LiftsOffered;

        /// <summary>Median absolute deviation of the used lifts' speeds over their median (0 for one lift).</summary>
        public readonly double RelativeSpread;

        public readonly string Reason;

        public CalibrationResult(bool isAccepted, double standardSpeed, int liftsUsed, int liftsOffered, double relativeSpread, string reason)
        {
            IsAccepted = isAccepted;
            StandardSpeed = standardSpeed;
            LiftsUsed = liftsUsed;
            LiftsOffered = liftsOffered;
            RelativeSpread = relativeSpread;
            Reason = reason;
        }

        public override string ToString() => IsAccepted
            ? "v_std = " + StandardSpeed.ToString("0.000", System.Globalization.CultureInfo.InvariantCulture) + " m/s from " + LiftsUsed + " of " + LiftsOffered + " lifts"
            : "rejected: " + Reason;
    }
}
