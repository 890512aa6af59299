namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// Limits that hold in every profile: they keep bad frame data (garbage poses, hitches) from ever becoming a
    /// jump, and cap the gain of very light objects (property P3).
    /// </summary>
    public sealed class SolverLimits
    {
        public static readonly SolverLimits Default = new SolverLimits();

        /// <summary>Largest gain on the hand's motion. Eq. 4 alone would move a 1 g object 45× as far as the hand.</summary>
        public double MaxGain { get; }

        /// <summary>A pose that implies a faster hand is not followed, m/s: it is treated as lost (a tracking glitch),
        /// until enough time has passed for a hand to have got there.</summary>
        public double MaxHandSpeed { get; }

        /// <summary>A frame counts for at most this long in anything the solver does with time (the glide, the speed cap's
        /// allowance, relaxation), s, so a hitch is never a jump.</summary>
        public double MaxFrameTime { get; }

        /// <summary>How fast an offset the hand's motion did not make (a change of mass or profile during the hold, such as
        /// a second hand joining) glides back to the weight's own, m/s.</summary>
        public double GlideSpeed { get; }

        public SolverLimits(double maxGain = 3.0, double maxHandSpeed = 10.0, double maxFrameTime = 0.025, double glideSpeed = 0.3)
        {
            MaxGain = ConfigurationGuard.InRange(maxGain, 1.0, 100.0, nameof(maxGain));
            MaxHandSpeed = ConfigurationGuard.Positive(maxHandSpeed, nameof(maxHandSpeed));
            MaxFrameTime = ConfigurationGuard.Positive(maxFrameTime, nameof(maxFrameTime));
            GlideSpeed = ConfigurationGuard.Positive(glideSpeed, nameof(glideSpeed));
        }

        /// <summary>Pose-to-pose motion is judged over at most this window (plus any time tracking was lost or a frame
        /// hitched), s, so a long still spell without pose timestamps does not license a teleport.</summary>
        internal const double JumpWindow = 0.05;

        /// <summary>…and over at least one 30 Hz pose period, s: a pose step under 10 m/s × 33 ms = 33 cm is never rejected.</summary>
        internal const double MinJumpWindow = 1.0 / 30;
    }
}
