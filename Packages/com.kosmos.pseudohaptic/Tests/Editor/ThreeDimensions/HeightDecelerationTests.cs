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
        public void FactorIsTheDocumentedCurve()
        {
            // φ + (1 − φ)/(1 + w·h/H), w = 1 − G: H = 0.5 m, φ = 0.5 by default.
            var e = new HeightDeceleration();
            Assert.That(e.Factor(0.5, 0.5), Is.EqualTo(0.5 + 0.5 / 1.5).Within(1e-15), "w·h/H = 0.5 · 0.5 / 0.5");
            Assert.That(e.Factor(1.0, 0.2), Is.EqualTo(0.5 + 0.5 / 2.6).Within(1e-15), "0.8 · 1 / 0.5");
            var custom = new HeightDeceleration(height: 2, minFraction: 0.25);
            Assert.That(custom.Factor(1.0, 0.5), Is.EqualTo(0.25 + 0.75 / 1.25).Within(1e-15));
            Assert.That(new HeightDeceleration().Name, Is.EqualTo("height-deceleration"));
        }

        [Test]
        public void EachPoseOfALiftIsSlowedByTheFactorAtTheHeightAboveWhereTheHoldBegan()
        {
            // Poses every 1/32 s, 2 cm each, from a hold begun 1.2 m up: each step is G × Factor(object − start) × 2 cm.
            var e = new HeightDeceleration();
            var solver = new WeightSolver(WeightModel.FromMass(2), Bare(e));
            double g = solver.Gain, t = 0, hand = 1.2, y = 1.2;
            solver.BeginHold(hand, hand, t);
            for (int i = 0; i < 20; i++)
            {
                t += 1 / 32.0; hand += 0.02;
                double next = solver.Step(new HandSample(hand, true, true, t), 1 / 32.0);
                Assert.That(next - y, Is.EqualTo(g * e.Factor(y - 1.2, g) * 0.02).Within(1e-12), "pose " + i);
                y = next;
            }
            Assert.That(y - 1.2, Is.LessThan(0.4 * g), "slowed");
            for (int i = 0; i < 5; i++)
            {
                t += 1 / 32.0; hand -= 0.02;
                double next = solver.Step(new HandSample(hand, true, true, t), 1 / 32.0);
                Assert.That(next - y, Is.EqualTo(-g * 0.02).Within(1e-12), "lowering is not slowed, pose " + i);
                y = next;
            }
        }

        [Test]
        public void WhileTheHandIsStillTheSpeedCapsCatchUpIsNotSlowed()
        {
            // 5 kg lifted fast by a user of 0.3 m/s: the cap owes part of the lift and pays it at v_cap per pose once
            // the hand stops, high above the start or not.
            var cap = new SpeedCap();
            var solver = new WeightSolver(WeightModel.FromMass(5),
                new WeightProfile("capped", new WeightEffect[] { new WeightGain(), new ExperimentalBlend(), new HeightDeceleration(), cap }), 0.3);
            double t = 0, hand = 1.0;
            solver.BeginHold(hand, hand, t);
            for (int i = 0; i < 10; i++) { t += 1 / 32.0; hand += 0.1; solver.Step(new HandSample(hand, true, true, t), 1 / 32.0); }
            Assert.That(solver.State.CapDeferred, Is.GreaterThan(0.05), "owed");
            double perPose = solver.Constants.CapSpeed / 32.0, y = solver.ObjectY;
            t += 1 / 32.0;
            Assert.That(solver.Step(new HandSample(hand, true, true, t), 1 / 32.0) - y, Is.EqualTo(perPose).Within(1e-12));
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
