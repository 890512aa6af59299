namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// Eq. 5–6 as adopted (Son et al. 2022; design note, open question 1): the final speed averages Eq. 4's
    /// speed with the experimental lift speed expressed relative to the golf ball,
    /// v_final = ½ · v_hand · (W_std/W + v_exp(m)/v_exp(m_std)), so heavy objects lag the way real ones do.
    /// Folded into the gain at configuration: the exponential is evaluated once per object, not per frame.
    /// </summary>
    public sealed class ExperimentalBlend : WeightEffect
    {
        /// <summary>This effect's name, stage, summary and settings (<see cref="EffectRegistry"/>).</summary>
        public static readonly EffectDescriptor Descriptor = new EffectDescriptor("experimental-blend", EffectStage.Gain, typeof(ExperimentalBlend),
            "Eq. 5–6",
            "G averages in the experimental lift speed of the mass relative to the golf ball, v_exp(m)/v_exp(m_std)",
            s => new ExperimentalBlend());

        public override string Name => Descriptor.Name;
        public override EffectStage Stage => Descriptor.Stage;
        protected internal override void Apply(ref MotionFrame frame, ref HoldState state, in SolverConstants constants) { }
    }
}
