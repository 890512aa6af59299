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
    
        // One pose a frame at 30 Hz, stamped; 5 kg (G < 1), v_std 0.5 m/s, unsmoothed pace so each pose's pace is exact.
        static WeightSolver PaceSolver(double smoothingTime = 0, double releaseDistance = 0.2, double standardSpeed = 0.5)
            => new WeightSolver(WeightModel.FromMass(5), new WeightProfile("test", new WeightEffect[]
                { new WeightGain(), new FasterMovesFurther(smoothingTime: smoothingTime, releaseDistance: releaseDistance) }), standardSpeed);

        [Test]
        public void ThePaceFollowsTheHandOnlyOnceItLeavesTheRestBandAndTheHeldPaceFallsWithTheDistanceTravelled()
        {
            var s = PaceSolver();
            double t = 0;
            s.BeginHold(0.2, 0.2, t);
            Assert.That(s.State.PaceReference, Is.EqualTo(0.2), "the grab anchors the band at the hand");
            // +3 cm: the band's lower edge (hand − 5 mm) drags the reference to 0.225; 25 mm in 1/30 s is 0.75 m/s.
            s.Step(new HandSample(0.23, true, true, t += 1 / 30.0), 1 / 30.0);
            Assert.That(s.State.PaceReference, Is.EqualTo(0.225).Within(1e-12));
            Assert.That(s.State.Pace, Is.EqualTo(0.75).Within(1e-9));
            Assert.That(s.State.HeldPace, Is.EqualTo(0.75).Within(1e-9), "a faster pace is held at once");
            // 3 mm back: within ±5 mm of the reference, which stays; the pace reads 0, the held pace is kept (no travel).
            s.Step(new HandSample(0.228, true, true, t += 1 / 30.0), 1 / 30.0);
            Assert.That(s.State.PaceReference, Is.EqualTo(0.225).Within(1e-12));
            Assert.That(s.State.Pace, Is.EqualTo(0).Within(1e-9));
            Assert.That(s.State.HeldPace, Is.EqualTo(0.75).Within(1e-9), "a resting hand keeps the pace of its latest motion");
            // Down to 0.214: the upper edge drags the reference to 0.219, 6 mm at 0.18 m/s; the held pace moves 6 mm / 0.2 m
            // = 3 % of the way toward it.
            s.Step(new HandSample(0.214, true, true, t += 1 / 30.0), 1 / 30.0);
            Assert.That(s.State.PaceReference, Is.EqualTo(0.219).Within(1e-12));
            Assert.That(s.State.Pace, Is.EqualTo(-0.18).Within(1e-9));
            Assert.That(s.State.HeldPace, Is.EqualTo(0.75 + 0.03 * (0.18 - 0.75)).Within(1e-9));
        }

        [Test]
        public void TheHeldPaceFallsNoFurtherThanTheSlowerPaceHoweverFarTheHandTravels()
        {
            // Release over 1 cm: a 2 cm step at 0.6 m/s travels twice the release distance, and the held pace becomes
            // that pace, not less.
            var s = PaceSolver(releaseDistance: 0.01);
            double t = 0;
            s.BeginHold(0.2, 0.2, t);
            s.Step(new HandSample(0.23, true, true, t += 1 / 30.0), 1 / 30.0); // 0.75 m/s, held
            s.Step(new HandSample(0.25, true, true, t += 1 / 30.0), 1 / 30.0);
            Assert.That(s.State.Pace, Is.EqualTo(0.6).Within(1e-9));
            Assert.That(s.State.HeldPace, Is.EqualTo(0.6).Within(1e-9));
        }

        [Test]
        public void ReanchoringForgetsThePace()
        {
            var s = PaceSolver(smoothingTime: 0.1);
            double t = 0, hand = 0.2;
            s.BeginHold(hand, hand, t);
            for (int i = 0; i < 15; i++) s.Step(new HandSample(hand += 0.03, true, true, t += 1 / 30.0), 1 / 30.0);
            Assert.That(s.State.HeldPace, Is.GreaterThan(0.5), "a fast lift");
            for (int i = 0; i < 15; i++) s.Step(HandSample.Lost, 1 / 30.0); // half a second lost: the hand comes back re-anchored
            s.Step(new HandSample(hand + 0.2, true, true, t += 0.5), 1 / 30.0);
            Assert.That(s.State.PaceReference, Is.EqualTo(hand + 0.2), "the band restarts at the hand");
            Assert.That(s.State.Pace, Is.EqualTo(0));
            Assert.That(s.State.HeldPace, Is.EqualTo(0));
        }

        [Test]
        public void JitterWithinTheRestBandMovesTheObjectBackAndForthByOneGainAndLeavesItWhereItWas()
        {
            // v_std 0.1 m/s: read as speed, a 4 mm step in one pose (0.12 m/s) and its return in two (0.06 m/s) would get
            // different gains and walk the object; within the ±5 mm band the pace is 0 and the gain G^1.5 every time.
            var s = PaceSolver(standardSpeed: 0.1);
            double t = 0;
            s.BeginHold(0.2, 0.2, t);
            double g = Math.Pow(s.Gain, 1.5);
            for (int cycle = 0; cycle < 50; cycle++)
            {
                double y0 = s.ObjectY;
                double up = s.Step(new HandSample(0.204, true, true, t += 1 / 30.0), 1 / 30.0);
                Assert.That(up - y0, Is.EqualTo(g * 0.004).Within(1e-12), "cycle " + cycle);
                s.Step(new HandSample(0.202, true, true, t += 1 / 30.0), 1 / 30.0);
                double back = s.Step(new HandSample(0.2, true, true, t += 1 / 30.0), 1 / 30.0);
                Assert.That(back, Is.EqualTo(y0).Within(1e-12), "cycle " + cycle);
            }
            Assert.That(s.ObjectY, Is.EqualTo(0.2).Within(1e-12), "nothing creeps at rest");
        }
}
}
