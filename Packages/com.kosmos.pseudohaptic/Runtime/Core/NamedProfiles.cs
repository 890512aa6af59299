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
        public const string XyzName = "xyz";
        public const string PaperLiteralName = "paper-literal";

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

        /// <summary>
        /// As the paper's Experiments 1 and 2 ran: everything in <see cref="Paper"/> but the offset correction ("no correction
        /// was made according to the … distance"), and both hands sharing the weight as the participants lifted Experiment 2's
        /// bottles (<see cref="TwoHands"/>, which acts in <see cref="WeightSolver3D"/>; the y solver holds one hand).
        /// </summary>
        public static readonly WeightProfile PaperExperiment = Paper.Without<OffsetCorrection>(PaperExperimentName).With(new TwoHands(), PaperExperimentName);

        /// <summary>
        /// Eq. 4 alone, within what every reading must keep: the floor (P5) and the deadband that keeps tracking
        /// jitter, multiplied by a light object's gain, from moving it at rest (P4; it is 0 at gains up to 1); and the
        /// safety limits.
        /// </summary>
        public static readonly WeightProfile Gain = new WeightProfile(GainName, new WeightEffect[] { new MotionDeadband(), new WeightGain(), new FloorClamp() });

        /// <summary>
        /// <see cref="Paper"/> in three dimensions and with both hands (for <see cref="WeightSolver3D"/>): height
        /// deceleration (in the lift stage, before the position effects, so the speed cap, the lowering guard and the offset
        /// correction act on its result), lateral inertia and two hands, at their defaults.
        /// </summary>
        public static readonly WeightProfile Xyz = BuildXyz();

        /// <summary>
        /// The paper as printed (issue 31): Eq. 4–6 per frame in the package's relative reading, the hand's speed averaged
        /// over the paper's unit time of 1 s, no offset correction, no floor beyond y ≥ 0. What runs it is
        /// <see cref="PaperLiteralSolver"/> (the accuracy page's baseline), not the package's pipeline: this profile names
        /// the paper's effects (<see cref="WeightGain"/>, <see cref="ExperimentalBlend"/>, <see cref="FloorClamp"/> at 0) and
        /// the 1 s window (<see cref="OneSecondAverage"/>) so that a profile asset, a listing or a <see cref="WeightSolver"/>
        /// given it shows the same effects; <see cref="IsPaperLiteral"/> tells a host (replay, demo, the Unity component's
        /// <c>HeldObject</c>) to run the literal solver instead.
        /// </summary>
        public static readonly WeightProfile PaperLiteral = new WeightProfile(PaperLiteralName,
            new WeightEffect[] { new WeightGain(), new ExperimentalBlend(), new FloorClamp() }, SolverLimits.Default, new OneSecondAverage());

        public static IReadOnlyList<string> Names { get; } = new[] { PaperName, PaperExperimentName, GainName, XyzName, PaperLiteralName };

        /// <summary>The named profiles the package's pipeline (<see cref="WeightSolver"/>) is built for: every name but
        /// <see cref="PaperLiteralName"/>, which <see cref="PaperLiteralSolver"/> runs.</summary>
        public static IReadOnlyList<string> PipelineNames { get; } = new[] { PaperName, PaperExperimentName, GainName, XyzName };

        /// <summary>Whether <paramref name="profile"/> is <see cref="PaperLiteral"/>, or a profile named <c>paper-literal</c> (a
        /// Unity profile asset set to that preset, with a hand joining it): what <see cref="PaperLiteralSolver"/> runs.</summary>
        public static bool IsPaperLiteral(WeightProfile profile) => ReferenceEquals(profile, PaperLiteral) || (profile != null && profile.Name == PaperLiteralName);

        static WeightProfile BuildXyz()
        {
            var effects = new List<WeightEffect> { new HeightDeceleration() };
            effects.AddRange(Paper.Effects);
            effects.Add(new LateralInertia());
            effects.Add(new TwoHands());
            return new WeightProfile(XyzName, effects, Paper.Limits, Paper.HandFilter);
        }

        /// <summary>The preset of that name; throws naming the value and the known names otherwise.</summary>
        public static WeightProfile Get(string name)
        {
            switch (name)
            {
                case PaperName: return Paper;
                case PaperExperimentName: return PaperExperiment;
                case GainName: return Gain;
                case XyzName: return Xyz;
                case PaperLiteralName: return PaperLiteral;
                default:
                    throw new ArgumentException("profile '" + name + "' is unknown; known profiles: " + string.Join(", ", Names) + ".", "profile");
            }
        }
    }
}
