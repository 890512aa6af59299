namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// Safety limits that hold in every profile: they keep bad frame data (lost tracking, glitches, hitches)
    /// from ever becoming a jump, and cap the gain of very light objects (property P3).
    /// </summary>
    public sealed class SolverLimits
    {
        public static readonly SolverLimits Default = new SolverLimits();

        /// <summary>Largest gain on the hand's motion. Eq. 4 alone would move a 1 g object 45× as far as the hand.</summary>
        public double MaxGain { get; }

        /// <summary>The object never moves faster than this, m/s; faster motion is carried over to the next frames.</summary>
        public double MaxObjectSpeed { get; }

        /// <summary>A frame (or the pose interval it brings) counts for at most this long when the speed limit is applied, s,
        /// so no step moves the object more than MaxObjectSpeed × MaxFrameTime (10 cm by default), whatever the hitch.</summary>
        public double MaxFrameTime { get; }

        /// <summary>A pose that implies a faster hand is a tracking glitch: the solver re-anchors instead of following.</summary>
        public double MaxHandSpeed { get; }

        /// <summary>After a loss or a hitch up to this long the object catches up with the hand; after a longer one it re-anchors, s.</summary>
        public double MaxCatchUpGap { get; }

        /// <summary>Displacement carried over by the speed limit is bounded by this, m (at most 0.125 s of gliding
        /// at the speed limit after the hand stops).</summary>
        public double MaxCarry { get; }

        public SolverLimits(double maxGain = 3.0, double maxObjectSpeed = 4.0, double maxFrameTime = 0.025,
            double maxHandSpeed = 6.0, double maxCatchUpGap = 0.25, double maxCarry = 0.5)
        {
            MaxGain = ConfigurationGuard.InRange(maxGain, 1.0, 100.0, nameof(maxGain));
            MaxObjectSpeed = ConfigurationGuard.Positive(maxObjectSpeed, nameof(maxObjectSpeed));
            MaxFrameTime = ConfigurationGuard.Positive(maxFrameTime, nameof(maxFrameTime));
            MaxHandSpeed = ConfigurationGuard.Positive(maxHandSpeed, nameof(maxHandSpeed));
            MaxCatchUpGap = ConfigurationGuard.Positive(maxCatchUpGap, nameof(maxCatchUpGap));
            MaxCarry = ConfigurationGuard.NonNegative(maxCarry, nameof(maxCarry));
        }

        /// <summary>Pose-to-pose motion is judged over at most this window, s, so a long still spell does not license a teleport.</summary>
        internal const double JumpWindow = 0.05;

        /// <summary>…and over at least one 30 Hz pose period, s: a pose step under 6 m/s × 33 ms = 20 cm is never a glitch.</summary>
        internal const double MinJumpWindow = 1.0 / 30;
    }
}
