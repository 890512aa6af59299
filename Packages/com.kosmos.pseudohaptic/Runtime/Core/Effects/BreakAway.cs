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
        public override string Name => "break-away";
        public override EffectStage Stage => EffectStage.Hold;

        /// <summary>How far the hand must pull for the hold to end, m (see the class for what it measures).</summary>
        public double Distance { get; }

        public BreakAway(double distance)
        {
            Distance = ConfigurationGuard.Positive(distance, nameof(distance));
        }

        protected internal override void Apply(ref MotionFrame frame, ref HoldState state, in SolverConstants constants) { }
    }
}
