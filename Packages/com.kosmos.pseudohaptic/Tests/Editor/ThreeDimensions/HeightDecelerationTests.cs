using System;
using NUnit.Framework;
using Kosmos.PseudoHaptic.Simulation;

namespace Kosmos.PseudoHaptic.Tests.ThreeDimensions
{
    /// <summary>Issue 10, height deceleration: on the way up, heavier than the standard rises more slowly the higher it
    /// already is above where the hold began and the heavier it is (strictly, from the start), continuously, never below
    /// the documented floor of 0.5 of its starting gain; lowering and the standard weight are untouched.</summary>
    public class HeightDecelerationTests
    {
        // Only the gain and this effect: each frame's object step is G × f × the hand's step, nothing else shapes it.
        static WeightProfile Bare(HeightDeceleration effect = null) =>
            new WeightProfile("bare", new WeightEffect[] { new WeightGain(), new ExperimentalBlend(), effect ?? new HeightDeceleration() });

        static readonly WeightProfile NoDeceleration = new WeightProfile("bare-none", new WeightEffect[] { new WeightGain(), new ExperimentalBlend() });

        [Test]
        public void FactorIsOneAtTheStartStrictlyDecreasingInHeightAndMassAndNeverBelowTheFloor()
        {
            var e = new HeightDeceleration();
            double[] gains = { 0.9, 0.72, 0.49, 0.42, 0.32, 0.16, 0.01 };
            for (int g = 0; g < gains.Length; g++)
            {
                Assert.That(e.Factor(0, gains[g]), Is.EqualTo(1.0), "no deceleration at the start height");
                double previous = 1;
                for (double h = 0.001; h <= 5; h += 0.001)
                {
                    double f = e.Factor(h, gains[g]);
                    Assert.That(f, Is.LessThan(previous), $"strictly decreasing in height at G {gains[g]}, h {h}");
                    Assert.That(previous - f, Is.LessThan(0.002), "continuous: a millimetre changes it by under 0.2 %");
                    Assert.That(f, Is.GreaterThanOrEqualTo(0.5), "the documented floor");
                    if (g > 0) Assert.That(f, Is.LessThan(e.Factor(h, gains[g - 1])), $"heavier (G {gains[g]}) decelerates more at h {h}");
                    previous = f;
                }
            }
            Assert.That(e.Factor(1e9, 0), Is.GreaterThanOrEqualTo(0.5));
            Assert.That(e.Factor(0.5, 1.0), Is.EqualTo(1.0), "the standard weight is untouched");
            Assert.That(e.Factor(0.5, 2.0), Is.EqualTo(1.0), "lighter is untouched");
            Assert.That(e.Factor(-0.3, 0.3), Is.EqualTo(1.0), "below the start there is nothing to decelerate");
        }

        static double[] Lift(double massKg, WeightProfile profile, HandPath path, double fps = 90)
            => Run.Replay(Run.Solver(massKg, profile), Run.Headset(fps).Render(path));

        [Test]
        public void HigherLiftsOfHeavierObjectsEndLowerThanWithoutIt()
        {
            var path = HandPath.StartAt(0.8).Hold(0.3).MoveTo(1.6, 1.5).Hold(0.5);
            double previousRise = double.PositiveInfinity;
            foreach (double m in new[] { 0.1, 0.5, 1, 2, 5 })
            {
                double with = Run.Last(Lift(m, Bare(), path)) - 0.8, without = Run.Last(Lift(m, NoDeceleration, path)) - 0.8;
                Assert.That(with, Is.LessThan(without - 0.001), $"{m} kg rises less with the deceleration");
                Assert.That(with, Is.GreaterThanOrEqualTo(0.5 * without - 1e-9), "never less than half the undecelerated rise");
                Assert.That(with, Is.LessThan(previousRise), "heavier rises less");
                previousRise = with;
            }
        }

        [Test]
        public void StepsShrinkWithHeightFromTheFirstMillimetreAndLoweringIsUntouched()
        {
            var solver = Run.Solver(2, Bare());
            double g = solver.Gain, y = 1.0;
            solver.BeginHold(y, y, 0);
            double previousRatio = 1.0 + 1e-12, obj = solver.ObjectY, t = 0;
            for (int i = 1; i <= 100; i++)
            {
                y += 0.005; t += 1 / 30.0;
                double next = solver.Step(new HandSample(y, true, true, t), 1 / 30.0);
                double ratio = (next - obj) / (g * 0.005);
                Assert.That(ratio, Is.LessThan(previousRatio), $"each 5 mm step up moves the object less than the one before (step {i})");
                Assert.That(ratio, Is.GreaterThanOrEqualTo(0.5));
                previousRatio = ratio;
                obj = next;
            }
            for (int i = 1; i <= 100; i++)
            {
                y -= 0.005; t += 1 / 30.0;
                double next = solver.Step(new HandSample(y, true, true, t), 1 / 30.0);
                Assert.That(next - obj, Is.EqualTo(-g * 0.005).Within(1e-12), $"lowering step {i} is the gain's, undecelerated");
                obj = next;
            }
        }

        [Test]
        public void TheStandardWeightAndLighterAreByteIdenticalWithAndWithoutIt([Values(0.001, 0.02, 0.045)] double massKg)
        {
            var path = HandPath.StartAt(0.8).Hold(0.3).MoveTo(1.7, 1.2).Hold(0.3).MoveTo(0.9, 1).Hold(0.3);
            var frames = Run.Headset(90, jitterSd: 0.002, seed: 5).Render(path);
            var with = Run.Replay(Run.Solver(massKg, NamedProfiles.Paper.With(new HeightDeceleration())), frames);
            var without = Run.Replay(Run.Solver(massKg, NamedProfiles.Paper), frames);
            Assert.That(with, Is.EqualTo(without));
        }

        [Test]
        public void NoJumpAndTheSameEndAtAnyFrameClock()
        {
            var path = HandPath.StartAt(0.8).Hold(0.3).MoveTo(1.5, 1.2).Hold(1.0);
            double? reference = null;
            foreach (double fps in new[] { 30.0, 60, 72, 90, 120 })
            {
                var frames = Run.Headset(fps).Render(path);
                var y = Run.Replay(Run.Solver(3, NamedProfiles.Xyz), frames);
                var hand = new double[frames.Length];
                for (int i = 0; i < hand.Length; i++) hand[i] = frames[i].HandY;
                Assert.That(Run.MaxStep(y), Is.LessThanOrEqualTo(Run.MaxStep(hand) + 1e-12), $"no step larger than the hand's at {fps} Hz");
                reference = reference ?? Run.Last(y);
                Assert.That(Run.Last(y), Is.EqualTo(reference.Value).Within(0.01), $"end at {fps} Hz");
            }
        }

        [Test]
        public void InvalidSettingsNameTheField()
        {
            Assert.That(() => new HeightDeceleration(height: 0), Throws.InstanceOf<ArgumentOutOfRangeException>().With.Message.Contains("height"));
            Assert.That(() => new HeightDeceleration(height: double.NaN), Throws.InstanceOf<ArgumentOutOfRangeException>().With.Message.Contains("height"));
            Assert.That(() => new HeightDeceleration(minFraction: 0), Throws.InstanceOf<ArgumentOutOfRangeException>().With.Message.Contains("minFraction"));
            Assert.That(() => new HeightDeceleration(minFraction: 1.5), Throws.InstanceOf<ArgumentOutOfRangeException>().With.Message.Contains("minFraction"));
        }
    }
}
