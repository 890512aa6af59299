namespace Kosmos.PseudoHaptic
{
    /// <summary>One golf-ball lift found in a recording, or the reason none usable was found.</summary>
    public readonly struct LiftMeasurement
    {
        public readonly bool IsAccepted;

        /// <summary>Mean upward speed over the lift (10 % to 90 % of its rise), m/s; NaN when rejected.</summary>
        public readonly double Speed;

        /// <summary>Height gained from the lowest point before the lift to the highest after it, m.</summary>
        public readonly double Rise;

        /// <summary>Time from 10 % to 90 % of the rise, s.</summary>
        public readonly double Duration;

        /// <summary>Why the lift was rejected; null when accepted.</summary>
        public readonly string Reason;

        public LiftMeasurement(bool isAccepted, double speed, double rise, double duration, string reason)
        {
            IsAccepted = isAccepted;
            Speed = speed;
            Rise = rise;
            Duration = duration;
            Reason = reason;
        }

        public override string ToString() => IsAccepted
            ? "lift of " + Rise.ToString("0.000", System.Globalization.CultureInfo.InvariantCulture) + " m at " + Speed.ToString("0.000", System.Globalization.CultureInfo.InvariantCulture) + " m/s"
            : "rejected: " + Reason;
    }
}
