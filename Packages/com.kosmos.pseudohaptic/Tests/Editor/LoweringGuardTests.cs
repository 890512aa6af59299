using System;
using Kosmos.PseudoHaptic.Simulation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>
    /// The lowering guard moves the base the lift is measured from down with the steady hand (a slack above it): below the
    /// base the object moves with the hand, the next lift is weighed from where it starts, and neither jitter, a one-pose
    /// glitch nor a motion that comes back moves the base.
    /// </summary>
    public class LoweringGuardTests
    {
        static WeightSolver Heavy(params WeightEffect[] more)
        {
            var effects = new System.Collections.Generic.List<WeightEffect> { new WeightGain(), new LoweringGuard() };
            effects.AddRange(more);
            return new WeightSolver(WeightModel.FromMass(2), new WeightProfile("guarded", effects));
        }

        [Test]
        public void LoweredBelowTheBaseTheObjectMovesWithTheHandAndTheNextLiftIsWeighedFromThere()
        {
            var s = Heavy();
            var frames = Run.Headset(frameRate: 90).Render(HandPath.StartAt(1.0).Hold(0.3).MoveTo(0.6, 0.8).Hold(0.5).MoveTo(0.9, 1).Hold(0.5));
            var y = new double[frames.Length];
            s.BeginHold(frames[0].HandY, frames[0].HandY, frames[0].PoseTime);
            double lowest = double.PositiveInfinity;
            for (int i = 1; i < frames.Length; i++)
            {
                y[i] = s.Step(frames[i].ToSample(), frames[i].Time - frames[i - 1].Time);
                if (frames[i].Time < 1.6) Assert.That(Math.Abs(frames[i].HandY - y[i]), Is.LessThanOrEqualTo(0.005 + 1e-12), "lowering: with the hand, frame " + i);
                if (frames[i].Time < 1.6) lowest = Math.Min(lowest, y[i]);
            }
            Assert.That(s.State.Base, Is.EqualTo(0.6 + 0.005).Within(1e-9), "the base is where the hand rested, plus the slack");
            double lift = 0.9 - 0.605, gain = s.Gain;
            Assert.That(Run.Last(y) - lowest, Is.EqualTo(gain * lift).Within(0.006), "the next lift weighed from where it started");
        }

        [Test]
        public void WithoutItAHeavyObjectLoweredFloatsAboveTheHand()
        {
            var frames = Run.Headset(frameRate: 90).Render(HandPath.StartAt(1.0).Hold(0.3).MoveTo(0.6, 0.8).Hold(0.5));
            var without = Run.Replay(new WeightSolver(WeightModel.FromMass(2), new WeightProfile("bare", new WeightEffect[] { new WeightGain() })), frames);
            var with = Run.Replay(Heavy(), frames);
            Assert.That(Run.Last(without) - 0.6, Is.GreaterThan(0.2), "Eq. 4 alone: G × the lowering");
            Assert.That(Run.Last(with), Is.EqualTo(0.6).Within(1e-9));
        }

        [Test]
        public void JitterAGlitchAndAHeftNeverMoveTheBase([Range(1, 40)] int seed)
        {
            var rng = new Random(seed);
            var path = HandPath.StartAt(1.0).Hold(0.5).MoveTo(1.3, 1).Hold(0.5).MoveTo(1.42, 0.3).MoveTo(1.3, 0.3).Hold(1);
            var headset = new HeadsetSimulator { FrameRate = 90, JitterSd = 0.0015, Seed = seed }.Glitch(0.2 + rng.NextDouble(), -0.2).Glitch(2.5 + rng.NextDouble(), -0.2);
            var s = Heavy();
            Run.Replay(s, headset.Render(path));
            Assert.That(s.State.Base, Is.EqualTo(1.0).Within(0.0045), "seed " + seed + ": within the jitter of where the hold began");
        }

        [Test]
        public void TheSlackIsValidatedAndNamed()
        {
            Assert.That(new LoweringGuard().Slack, Is.EqualTo(0.005));
            Assert.That(() => new LoweringGuard(-0.001), Throws.InstanceOf<ArgumentOutOfRangeException>().With.Message.Contains("slack"));
            Assert.That(() => new LoweringGuard(double.NaN), Throws.InstanceOf<ArgumentOutOfRangeException>().With.Message.Contains("slack"));
            Assert.That(new LoweringGuard().Name, Is.EqualTo("lowering-guard"));
            Assert.That(new LoweringGuard().Stage, Is.EqualTo(EffectStage.Base));
        }
    }
}
