namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>A scene's own input effect that keeps the last frame the solver showed it: what an effect author can
    /// rely on in <see cref="MotionFrame"/>.</summary>
    internal sealed class FrameProbe : WeightEffect
    {
        public MotionFrame Last;
        public override string Name => "frame-probe";
        public override EffectStage Stage => EffectStage.Input;
        protected override void Apply(ref MotionFrame frame, ref HoldState state, in SolverConstants constants) => Last = frame;
    }
}
