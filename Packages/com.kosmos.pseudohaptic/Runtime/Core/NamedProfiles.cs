using System;
using System.Collections.Generic;

namespace Kosmos.PseudoHaptic
{
    /// <summary>The named presets. Each call returns the shared immutable instance.</summary>
    public static class NamedProfiles
    {
        public const string PaperName = "paper";
        public const string PaperExperimentName = "paper-experiment";
        public const string GainName = "gain";

        /// <summary>
        /// All of the paper's effects: Eq. 4–6 gain, faster moves further (§3.1), the offset correction past 0.2 m,
        /// the floor, plus what a headset needs to feed them (deadband for light objects, speed cap relative to the
        /// user, lowering guard, tracking-loss hold).
        /// </summary>
        public static readonly WeightProfile Paper = new WeightProfile(PaperName, new WeightEffect[]
        {
            new TrackingLossHold(), new MotionDeadband(), new WeightGain(), new ExperimentalBlend(),
            new FasterMovesFurther(), new SpeedCap(), new LoweringGuard(), new OffsetCorrection(), new FloorClamp(),
        });

        /// <summary>As the paper's Experiments 1 and 2 ran: everything in <see cref="Paper"/> but the offset correction.</summary>
        public static readonly WeightProfile PaperExperiment = Paper.Without<OffsetCorrection>(PaperExperimentName);

        /// <summary>
        /// Eq. 4 alone, within what every reading must keep: the floor (P5) and the deadband that keeps tracking
        /// jitter, multiplied by a light object's gain, from moving it at rest (P4; it is 0 at gains up to 1); and the
        /// safety limits.
        /// </summary>
        public static readonly WeightProfile Gain = new WeightProfile(GainName, new WeightEffect[] { new MotionDeadband(), new WeightGain(), new FloorClamp() });

        public static IReadOnlyList<string> Names { get; } = new[] { PaperName, PaperExperimentName, GainName };

        /// <summary>The preset of that name; throws naming the value and the known names otherwise.</summary>
        public static WeightProfile Get(string name)
        {
            switch (name)
            {
                case PaperName: return Paper;
                case PaperExperimentName: return PaperExperiment;
                case GainName: return Gain;
                default:
                    throw new ArgumentException("profile '" + name + "' is unknown; known profiles: " + string.Join(", ", Names) + ".", "profile");
            }
        }
    }
}
