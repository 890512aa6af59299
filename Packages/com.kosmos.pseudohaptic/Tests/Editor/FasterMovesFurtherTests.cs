using System;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>
    /// Faster moves further in numbers: the exponent r = 1/√(pace/v_std) clamped to [0.5, 1.5], the gain G^r it gives
    /// an object lighter in gain than the standard, and that a steady lift moves the object by exactly that gain.
    /// </summary>
    public class FasterMovesFurtherTests
    {
        [Test]
        public void TheExponentIsOneOverTheRootOfTheRelativePaceWithinItsClamps()
        {
            var e = new FasterMovesFurther();
            Assert.That(e.Name, Is.EqualTo("faster-moves-further"));
            Assert.That(e.ExponentAt(0.5, 0.5), Is.EqualTo(1.0), "at the user's own speed G itself");
            Assert.That(e.ExponentAt(-0.5, 0.5), Is.EqualTo(1.0), "lowering counts like lifting");
            Assert.That(e.ExponentAt(1.0, 0.25), Is.EqualTo(0.5), "four times the user's speed: 1/√4, at the fast clamp");
            Assert.That(e.ExponentAt(3.0, 0.25), Is.EqualTo(0.5), "faster still: clamped");
            Assert.That(e.ExponentAt(0.72, 0.5), Is.EqualTo(1 / Math.Sqrt(1.44)).Within(1e-15));
            Assert.That(e.ExponentAt(0.32, 0.5), Is.EqualTo(1.25).Within(1e-15), "x = 0.64");
            Assert.That(e.ExponentAt(0.1, 0.5), Is.EqualTo(1.5), "slow: clamped");
            Assert.That(e.ExponentAt(0, 0.5), Is.EqualTo(1.5), "at rest: the slow clamp");
            var custom = new FasterMovesFurther(fastExponent: 0.8, slowExponent: 1.2);
            Assert.That(custom.ExponentAt(2.0, 0.5), Is.EqualTo(0.8));
            Assert.That(custom.ExponentAt(0.05, 0.5), Is.EqualTo(1.2));
        }

        [Test]
        public void TheGainIsGToThePowerROnlyForObjectsHeavierThanTheStandard()
        {
            var e = new FasterMovesFurther();
            Assert.That(e.GainAt(0.25, 2.0, 0.5), Is.EqualTo(0.5).Within(1e-15), "0.25^0.5: a fast lift moves it further");
            Assert.That(e.GainAt(0.25, 0.1, 0.5), Is.EqualTo(0.125).Within(1e-15), "0.25^1.5: a slow one less");
            Assert.That(e.GainAt(0.25, 0.5, 0.5), Is.EqualTo(0.25).Within(1e-15));
            Assert.That(e.GainAt(1.0, 2.0, 0.5), Is.EqualTo(1.0), "the standard weight is untouched");
            Assert.That(e.GainAt(2.5, 2.0, 0.5), Is.EqualTo(2.5), "lighter objects too");
            Assert.That(e.GainAt(0.0, 2.0, 0.5), Is.EqualTo(0.0), "no gain stays none");
        }

        [TestCase(2.0, 0.4)]
        [TestCase(5.0, 1.5)]
        [TestCase(5.0, 0.1)]
        [TestCase(0.5, 0.8)]
        [TestCase(2.0, -0.4)] // lowering: the same pace, the same gain
        [TestCase(5.0, -1.5)]
        public void ASteadyLiftMovesTheObjectByGainAtItsPace(double massKg, double handSpeed)
        {
            // One pose per 90 Hz frame at a constant speed: after a second the smoothed pace is the hand's speed, so
            // each frame the object moves GainAt(G, v, v_std) × the hand's step.
            var effect = new FasterMovesFurther();
            var solver = new WeightSolver(WeightModel.FromMass(massKg),
                new WeightProfile("test", new WeightEffect[] { new WeightGain(), new ExperimentalBlend(), effect }), 0.5);
            const double dt = 1 / 90.0;
            double hand = 0.2, t = 0, y = 0.2;
            solver.BeginHold(hand, hand, t);
            for (int i = 0; i < 90; i++) { t += dt; hand += handSpeed * dt; y = solver.Step(new HandSample(hand, true, true, t), dt); }
            Assert.That(solver.Gain, Is.LessThan(1), "an object heavier than the standard");
            double expected = effect.GainAt(solver.Gain, Math.Abs(handSpeed), 0.5);
            for (int i = 0; i < 10; i++)
            {
                t += dt; hand += handSpeed * dt;
                double next = solver.Step(new HandSample(hand, true, true, t), dt);
                Assert.That((next - y) / (handSpeed * dt), Is.EqualTo(expected).Within(1e-3 * expected), "frame " + i);
                y = next;
            }
        }
    }
}
