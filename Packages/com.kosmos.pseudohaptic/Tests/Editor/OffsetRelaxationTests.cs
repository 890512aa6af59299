using System;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>
    /// The offset relaxation (design note, open question 4) frame by frame: while the hand is still, the lift — and the
    /// offset it carries — shrinks by dt/(τ + dt) of itself per frame, a frame counting for at most the limits' frame time;
    /// a hand moving at or above the still fraction of the user's standard speed is not relaxed, and a still fraction of 0
    /// turns the relaxation off. (EffectTests holds the end state: a held offset gone after 8 s.)
    /// </summary>
    public class OffsetRelaxationTests
    {
        const double Mass = 2, StandardSpeed = 0.5, Tau = 1.5;

        static WeightSolver Relaxing(double stillFraction = 0.1)
            => new WeightSolver(WeightModel.FromMass(Mass),
                new WeightProfile("relaxing", new WeightEffect[] { new WeightGain(), new OffsetRelaxation(Tau, stillFraction) }), StandardSpeed);

        /// <summary>A 0.3 m lift in 1 s, a new pose every 90 Hz frame, then the same pose for <paramref name="stillSeconds"/>.</summary>
        static double LiftThenRest(WeightSolver s, ref double t, double stillSeconds)
        {
            const double dt = 1 / 90.0;
            s.BeginHold(1.0, 1.0, t);
            for (int i = 1; i <= 90; i++) { t += dt; s.Step(new HandSample(1.0 + 0.3 * i / 90, true, true, t), dt); }
            for (int i = 0; i < stillSeconds * 90; i++) { t += dt; s.Step(new HandSample(1.3, true, true, t), dt); }
            return 1.3;
        }

        [Test]
        public void AtRestTheOffsetShrinksByDtOverTauPlusDtOfItselfEachFrameAHitchCountingAsTheFrameTimeLimit()
        {
            var s = Relaxing();
            double t = 0, hand = LiftThenRest(s, ref t, 0.5);
            double before = hand - s.ObjectY;
            Assert.That(before, Is.GreaterThan(0.1), "a 2 kg object hangs well below the hand half a second into the rest");
            double maxFrame = s.Profile.Limits.MaxFrameTime;
            // Frame times of 90, 72 and 60 Hz, and hitches of 0.1 s and 0.5 s (each counted as the frame-time limit).
            var dts = new[] { 1 / 90.0, 1 / 72.0, 1 / 60.0, 0.1, 1 / 90.0, 0.5, 1 / 72.0 };
            for (int k = 0; k < 60; k++)
            {
                double dt = dts[k % dts.Length];
                t += dt;
                s.Step(new HandSample(hand, true, true, t), dt);
                double after = hand - s.ObjectY, counted = Math.Min(dt, maxFrame);
                Assert.That(after / before, Is.EqualTo(Tau / (Tau + counted)).Within(1e-9), "frame " + k + " (dt " + dt + " s)");
                before = after;
            }
        }

        [Test]
        public void AHandMovingAtTwiceTheStillSpeedIsNotRelaxedTheOffsetGrowsWithItsLift()
        {
            // Still is below 0.1 × 0.5 m/s = 0.05 m/s; this hand rises at 0.1 m/s, well under the user's standard speed. The base
            // stays where it was, so every millimetre the hand rises adds (1 − G) of it to the offset.
            var s = Relaxing();
            const double dt = 1 / 90.0, speed = 0.1;
            double t = 0, hand = 1.0;
            s.BeginHold(hand, hand, t);
            for (int i = 0; i < 45; i++) { t += dt; hand += speed * dt; s.Step(new HandSample(hand, true, true, t), dt); }
            double g = s.Gain, before = hand - s.ObjectY;
            for (int i = 0; i < 90; i++)
            {
                t += dt;
                hand += speed * dt;
                s.Step(new HandSample(hand, true, true, t), dt);
                double after = hand - s.ObjectY;
                Assert.That(after - before, Is.EqualTo((1 - g) * speed * dt).Within(1e-12), "frame " + i + ": the offset grows by its share of the hand's step");
                before = after;
            }
        }

        [Test]
        public void AStillFractionOfZeroNeverRelaxesEvenAPerfectlyStillHand()
        {
            var off = Relaxing(stillFraction: 0);
            double t = 0, hand = LiftThenRest(off, ref t, 0.5);
            double held = hand - off.ObjectY;
            for (int i = 0; i < 270; i++) { t += 1 / 90.0; off.Step(new HandSample(hand, true, true, t), 1 / 90.0); }
            Assert.That(hand - off.ObjectY, Is.EqualTo(held), "3 s of a hand whose poses do not move by a bit: the offset is held");
            Assert.That(held, Is.GreaterThan(0.25), "and it is the whole 2 kg offset, never relaxed");
        }
    }
}
