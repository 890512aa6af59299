namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// Eq. 4 as meant (Son et al. 2022): v_virtual = v_hand · W_std / W. A golf ball moves with the hand,
    /// a heavier object less, a lighter one more (never beyond <see cref="SolverLimits.MaxGain"/>).
    /// Folded into the gain at configuration: nothing per frame.
    /// </summary>
    public sealed class WeightGain : WeightEffect
    {
        /// <summary>This effect's name, stage, summary and settings (<see cref="EffectRegistry"/>).</summary>
        public static readonly EffectDescriptor Descriptor = new EffectDescriptor("weight-gain", EffectStage.Gain, typeof(WeightGain),
            "Eq. 4",
            "the object moves W_std/W as far as the hand (G includes W_std/W); folded into the gain, nothing per frame",
            s => new WeightGain());

        public override string Name => Descriptor.Name;
        public override EffectStage Stage => Descriptor.Stage;
        protected internal override void Apply(ref MotionFrame frame, ref HoldState state, in SolverConstants constants) { }
    }
}
