namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>
    /// An effect defined only in this test assembly (issue 33): the weight's offset scaled by <see cref="Factor"/>. It has its
    /// own descriptor and is registered through the public API, as a scene's effect would be.
    /// </summary>
    public sealed class ScaledOffset : WeightEffect
    {
        public static readonly EffectDescriptor Descriptor = new EffectDescriptor("scaled-offset", EffectStage.ObjectMotion, typeof(ScaledOffset),
            "a test assembly", "the weight's offset times a factor",
            s => new ScaledOffset(s[0]),
            SettingDescriptor.Number<ScaledOffset>("factor", "", 1, 0, 4, "what the offset is multiplied by", e => e.Factor));

        public static void Register() => EffectRegistry.Register(Descriptor);

        public override string Name => Descriptor.Name;
        public override EffectStage Stage => Descriptor.Stage;

        public double Factor { get; }

        public ScaledOffset(double factor) { Factor = Descriptor.Settings[0].Check(factor); }

        protected override bool IsFunctionOfHand => true;

        protected override void Apply(ref MotionFrame frame, ref HoldState state, in SolverConstants constants) => frame.Offset *= Factor;
    }
}
