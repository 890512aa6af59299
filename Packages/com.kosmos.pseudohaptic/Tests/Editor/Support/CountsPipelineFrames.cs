namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>Counts the frames that run the pipeline (its Apply), and is still whenever asked: a still frame does not call it.</summary>
    internal sealed class CountsPipelineFrames : WeightEffect
    {
        public int Calls;
        public override string Name => "counts-pipeline-frames";
        public override EffectStage Stage => EffectStage.Input;
        protected override void Apply(ref MotionFrame frame, ref HoldState state, in SolverConstants constants) => Calls++;
        protected override bool IsStill(in HoldState state, in SolverConstants constants) => true;
    }
}
