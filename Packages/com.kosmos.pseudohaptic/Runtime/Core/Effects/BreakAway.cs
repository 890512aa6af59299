namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// Optional (in no named profile): the hold in <see cref="WeightSolver3D"/> ends by itself once the followed
    /// hand (the midpoint with two hands) has been more than <see cref="Distance"/> from where it grabbed the
    /// object, in 3D, for <see cref="Dwell"/> of frame time. The solver reports it
    /// (<see cref="WeightSolver3D.BrokeAway"/>) so a grab driver can drop the object. The dwell keeps a one-pose
    /// tracking glitch (33 ms at 30 Hz) from dropping it.
    /// </summary>
    public sealed class BreakAway : WeightEffect
    {
        public override string Name => "break-away";
        public override EffectStage Stage => EffectStage.Hold;

        /// <summary>Hand-to-grab-point distance at which the hold ends, m.</summary>
        public double Distance { get; }

        /// <summary>How long the distance must be exceeded, s (0: at once).</summary>
        public double Dwell { get; }

        public BreakAway(double distance, double dwell = 0.1)
        {
            Distance = ConfigurationGuard.Positive(distance, nameof(distance));
            Dwell = ConfigurationGuard.InRange(dwell, 0, 5, nameof(dwell));
        }

        protected internal override void Apply(ref MotionFrame frame, ref HoldState state, in SolverConstants constants) { }
    }
}
