namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// Optional (in no named profile): the hold in <see cref="WeightSolver3D"/> ends by itself when the hand pulls too far.
    /// What "too far" measures (<see cref="WeightSolver3D.BreakAwayMeasure"/>):
    /// <list type="bullet">
    /// <item>under <see cref="OffsetCorrection"/>, how far the hand has pulled beyond what the weight allows
    /// (<see cref="WeightSolver3D.Strain"/>: the lag an object that moves no faster than <see cref="SpeedCap"/>'s v_cap would
    /// have, and sideways how far <see cref="LateralInertia"/>'s lag exceeds the lag it shows). The offset the user sees
    /// stops at the correction's ceiling, so a distance could never be reached; a yank can. A profile with the correction
    /// and neither the cap nor lateral inertia is refused: break-away could never fire there;</item>
    /// <item>without it, the distance between the followed point (one hand, or the midpoint of both) and the object, less
    /// the one at the grab, in 3D.</item>
    /// </list>
    /// The hold ends at the second pose in a row past <see cref="Distance"/>: one pose interval at most after the first, and
    /// a one-pose tracking glitch never drops the object. Time while tracking is lost counts for nothing: the next pose
    /// seen decides. The solver reports it (<see cref="WeightSolver3D.BrokeAway"/>) and the object stays where it was let go.
    /// </summary>
    public sealed class BreakAway : WeightEffect
    {
        /// <summary>This effect's name, stage, summary and settings (<see cref="EffectRegistry"/>).</summary>
        public static readonly EffectDescriptor Descriptor = new EffectDescriptor("break-away", EffectStage.Hold, typeof(BreakAway),
            "issue 10 (in no named profile)",
            "in WeightSolver3D, the hold ends by itself when the hand pulls too far (the strain under the offset correction, else the distance), two poses in a row",
            s => new BreakAway(s[0]),
            SettingDescriptor.Positive<BreakAway>("distance", "m", 0.25, "how far the hand must pull for the hold to end", e => e.Distance));

        public override string Name => Descriptor.Name;
        public override EffectStage Stage => Descriptor.Stage;

        /// <summary>How far the hand must pull for the hold to end, m (see the class for what it measures).</summary>
        public double Distance { get; }

        public BreakAway(double distance)
        {
            Distance = Descriptor.Settings[0].Check(distance);
        }

        protected internal override void Apply(ref MotionFrame frame, ref HoldState state, in SolverConstants constants) { }
    }
}
