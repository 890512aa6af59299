namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>Does nothing, and never says it is still: a profile with it runs the pipeline every frame (no still frames).</summary>
    internal sealed class NeverStill : WeightEffect
    {
        public override string Name => "never-still";
        public override EffectStage Stage => EffectStage.Input;
        protected override void Apply(ref MotionFrame frame, ref HoldState state, in SolverConstants constants) { }
    }
}
