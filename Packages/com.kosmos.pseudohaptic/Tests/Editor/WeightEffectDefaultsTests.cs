using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>
    /// A scene's own effect that overrides nothing but <c>Apply</c> is called on every frame, even when the hand repeats
    /// its pose (WeightEffect.IsStill is false by default); one that says it is still but not that it advances when still
    /// never has <c>AdvanceStill</c> called (WeightEffect.AdvancesWhenStill is false by default).
    /// </summary>
    public class WeightEffectDefaultsTests
    {
        sealed class CountsCalls : WeightEffect
        {
            public int Applied;
            public override string Name => "counts-calls";
            public override EffectStage Stage => EffectStage.Input;
            protected override void Apply(ref MotionFrame frame, ref HoldState state, in SolverConstants constants) => Applied++;
        }

        sealed class StillButDoesNotAdvance : WeightEffect
        {
            public int Advanced;
            public override string Name => "still-not-advancing";
            public override EffectStage Stage => EffectStage.Position;
            protected override void Apply(ref MotionFrame frame, ref HoldState state, in SolverConstants constants) { }
            protected override bool IsStill(in HoldState state, in SolverConstants constants) => true;
            protected override void AdvanceStill(ref HoldState state, in SolverConstants constants, double dt) => Advanced++;
        }

        static void RunStill(WeightProfile profile)
        {
            var solver = new WeightSolver(WeightModel.FromMass(0.5), profile);
            var pose = new HandSample(1.0, true, true, 0.0);
            solver.BeginHold(1.0, 1.0, 0.0);
            for (int i = 0; i < 90; i++) solver.Step(pose, 1 / 90.0);
        }

        [Test]
        public void AnEffectThatDoesNotSayItIsStillIsCalledOnEveryFrame()
        {
            var counts = new CountsCalls();
            RunStill(NamedProfiles.Paper.With(counts));
            Assert.That(counts.Applied, Is.EqualTo(90), "90 frames of one repeated pose: 90 calls");
        }

        [Test]
        public void AnEffectThatDoesNotSayItAdvancesWhenStillIsNeverAdvanced()
        {
            var effect = new StillButDoesNotAdvance();
            RunStill(NamedProfiles.Paper.With(effect));
            Assert.That(effect.Advanced, Is.Zero);
        }
    }
}
