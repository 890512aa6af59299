namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// Limits that hold in every profile: they keep bad frame data (garbage poses, hitches) from ever becoming a
    /// jump, and cap the gain of very light objects (property P3).
    /// </summary>
    public sealed class SolverLimits
    {
        /// <summary>The limits' settings, as profile files and the docs name them (declared before <see cref="Default"/>, which
        /// they validate).</summary>
        public static readonly System.Collections.Generic.IReadOnlyList<SettingDescriptor> Settings = new[]
        {
            SettingDescriptor.Number<SolverLimits>("maxGain", "", 3.0, 1.0, 100.0, "largest gain on the hand's motion (P3)", l => l.MaxGain),
            SettingDescriptor.Positive<SolverLimits>("maxHandSpeed", "m/s", 10.0, "a pose that implies a faster hand is not followed", l => l.MaxHandSpeed),
            SettingDescriptor.Positive<SolverLimits>("maxFrameTime", "s", 0.025, "a frame counts for at most this long in anything done with time", l => l.MaxFrameTime),
            SettingDescriptor.Number<SolverLimits>("glideSpeed", "m/s", 0.3, MinGlideSpeed, double.PositiveInfinity, "how fast an offset the hand's motion did not make glides away", l => l.GlideSpeed),
            SettingDescriptor.Number<SolverLimits>("workspaceRadius", "m", DefaultWorkspaceRadius, MinWorkspaceRadius, WeightSolver.MaxCoordinate, "a pose farther than this from where the hold began is not tracked", l => l.WorkspaceRadius),
        };

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

        /// <summary>The slowest glide, m/s: a centimetre a second, so a change of a few centimetres glides away within a hold.
        /// Slower, the glide outlasts the hold and keeps what it takes in: the base's own small moves at rest (the lowering
        /// guard following jitter down, the relaxation pulling it up) pile up in it and move the object at rest (1 kg under a
        /// guard at slack 0 and a fast relaxation, 5e-324 m/s let the object creep 6.4 mm in 10 s; at 0.01 m/s it rests within
        /// a millimetre of where the default leaves it: ComposedProfileTests).</summary>
        public const double MinGlideSpeed = 0.01;

        /// <summary>The plausibility gate's workspace, m: a pose farther than this from where the hold began (the hand that
        /// grabbed, or the first one seen) is no hand's and is treated as not tracked, however long tracking was lost
        /// (ALGORITHM.md §5 gives the reason for the default: the largest play area a Quest user can set up, corner to corner,
        /// plus an arm's reach at each end).</summary>
        public double WorkspaceRadius { get; }

        public SolverLimits(double maxGain = 3.0, double maxHandSpeed = 10.0, double maxFrameTime = 0.025, double glideSpeed = 0.3,
            double workspaceRadius = DefaultWorkspaceRadius)
        {
            MaxGain = Settings[0].Check(maxGain);
            MaxHandSpeed = Settings[1].Check(maxHandSpeed);
            MaxFrameTime = Settings[2].Check(maxFrameTime);
            GlideSpeed = Settings[3].Check(glideSpeed);
            WorkspaceRadius = Settings[4].Check(workspaceRadius);
        }

        /// <summary>The default <see cref="WorkspaceRadius"/>, m: a 7 m × 7 m play area corner to corner (9.9 m) plus an arm's
        /// reach of about 1 m at each end.</summary>
        public const double DefaultWorkspaceRadius = 12.0;

        /// <summary>The smallest <see cref="WorkspaceRadius"/> accepted, m: a seated user's reach, both arms.</summary>
        public const double MinWorkspaceRadius = 1.0;

        /// <summary>A frame's time counts for at most this long, s: a finite frame time beyond it (a clock that jumps to 1e308) is
        /// taken as a hitch of this length, as an infinite one is.</summary>
        internal const double LongestHitch = 3600;

        /// <summary>More frame time than this since the last accepted pose makes the next one the end of a gap, s (three 30 Hz
        /// pose periods: a pose or two dropped in motion are not a gap): the hand's motion across it is followed as far as the
        /// hand went and never amplified (a light object's lead glides).</summary>
        internal const double GapTime = 0.1;

        /// <summary>A pose shown unchanged for this long is the hand seen there again, s: what the hold remembers of the hand
        /// (the median of its last three poses) takes it again, so that whatever it drives advances with time when a source
        /// repeats its last pose exactly (a simulator, a controller at rest, tracking that holds its last pose).</summary>
        internal const double RepeatTime = 0.1;

        /// <summary>Pose-to-pose motion is judged over at most this window (plus any time tracking was lost or a frame
        /// hitched), s, so a long still spell without pose timestamps does not license a teleport.</summary>
        internal const double JumpWindow = 0.05;

        /// <summary>…and over at least one 30 Hz pose period, s: a pose step under 10 m/s × 33 ms = 33 cm is never rejected.</summary>
        internal const double MinJumpWindow = 1.0 / 30;
    }
}
