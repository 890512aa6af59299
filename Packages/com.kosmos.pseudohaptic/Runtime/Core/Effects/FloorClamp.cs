namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// Son et al. 2022, §3.1, confinement condition 2: the object's local y never goes below 0 (P5).
    /// Acts on the final height, after the speed limit, so nothing can push the object through.
    /// </summary>
    public sealed class FloorClamp : WeightEffect
    {
        public override string Name => "floor-clamp";
        public override EffectStage Stage => EffectStage.Position;

        /// <summary>Lowest local height, m.</summary>
        public double Floor { get; }

        public FloorClamp(double floor = 0)
        {
            Floor = ConfigurationGuard.Finite(floor, nameof(floor));
        }

        protected internal override void Apply(ref MotionFrame frame, ref HoldState state, in SolverConstants constants)
        {
            if (frame.NewObjectY >= Floor) return;
            frame.NewObjectY = Floor;
            if (state.Carry < 0) state.Carry = 0; // do not keep pushing into the floor
        }
    }
}
