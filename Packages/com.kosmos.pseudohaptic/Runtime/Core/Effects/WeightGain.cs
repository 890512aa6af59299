namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// Eq. 4 as meant (Son et al. 2022): v_virtual = v_hand · W_std / W. A golf ball moves with the hand,
    /// a heavier object less, a lighter one more (never beyond <see cref="SolverLimits.MaxGain"/>).
    /// Folded into the gain at configuration: nothing per frame.
    /// </summary>
    public sealed class WeightGain : WeightEffect
    {
        public override string Name => "weight-gain";
        public override EffectStage Stage => EffectStage.Gain;
        protected internal override void Apply(ref MotionFrame frame, ref HoldState state, in SolverConstants constants) { }
    }
}
