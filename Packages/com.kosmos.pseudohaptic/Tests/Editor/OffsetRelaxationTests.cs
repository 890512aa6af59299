using System;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>
    /// The offset relaxation in numbers: while the hand is still it takes dt/(τ + dt) of the offset each frame
    /// (dt at most the solver's longest frame), and while the hand moves — up or down, faster than
    /// StillFraction × the user's standard speed — it does nothing at all. Poses every frame at 90 Hz, no jitter,
    /// so the estimator reads the hand's speed exactly.
    /// </summary>
    public class OffsetRelaxationTests
    {
        const double Dt = 1 / 90.0;

        static WeightProfile Profile(bool relax, double tau = 1.0) => relax
            ? new WeightProfile("test", new WeightEffect[] { new WeightGain(), new OffsetRelaxation(tau) })
            : new WeightProfile("test", new WeightEffect[] { new WeightGain() });

        /// <summary>Object heights over a hand path given as a speed per frame (m/s), from 1 m.</summary>
        static double[] Drive(WeightSolver solver, Func<int, double> handSpeed, int frames, double startT = 0)
        {
            double hand = 1.0, t = startT;
            solver.BeginHold(hand, hand, t);
            var y = new double[frames];
            for (int i = 0; i < frames; i++)
            {
                t += Dt;
                hand += handSpeed(i) * Dt;
                y[i] = solver.Step(new HandSample(hand, true, true, t), Dt);
            }
            return y;
        }

        [Test]
        public void AStillHandsOffsetShrinksByTauOverTauPlusDtEachFrame()
        {
            const double tau = 1.0;
            var solver = new WeightSolver(WeightModel.FromMass(2), Profile(true, tau));
            double hand = 1.0, t = 0;
            solver.BeginHold(hand, hand, t);
            for (int i = 0; i < 45; i++) { t += Dt; hand += 0.6 * Dt; solver.Step(new HandSample(hand, true, true, t), Dt); } // 0.3 m up in 0.5 s
            for (int i = 0; i < 45; i++) { t += Dt; solver.Step(new HandSample(hand, true, true, t), Dt); }                   // the estimator comes to rest
            double before = hand - solver.ObjectY;
            Assert.That(before, Is.GreaterThan(0.05), "the gain left an offset to relax");
            for (int i = 0; i < 20; i++)
            {
                t += Dt;
                solver.Step(new HandSample(hand, true, true, t), Dt);
                double after = hand - solver.ObjectY;
                Assert.That(after / before, Is.EqualTo(tau / (tau + Dt)).Within(1e-9), "frame " + i);
                before = after;
            }

            // A long frame (a 20 Hz hitch) counts as the solver's longest frame, 25 ms.
            t += 0.05;
            solver.Step(new HandSample(hand, true, true, t), 0.05);
            Assert.That((hand - solver.ObjectY) / before, Is.EqualTo(tau / (tau + 0.025)).Within(1e-9));
        }

        [TestCase(+0.6)]
        [TestCase(-0.6)]
        [TestCase(+0.1)]
        [TestCase(-0.1)]
        public void AMovingHandIsNotRelaxedInEitherDirection(double speed)
        {
            // v_std = 0.5 m/s: "still" is below 0.1 × 0.5 = 0.05 m/s, so 0.1 m/s is moving.
            var with = Drive(new WeightSolver(WeightModel.FromMass(2), Profile(true), 0.5), i => i < 10 ? 0 : speed, 120);
            var without = Drive(new WeightSolver(WeightModel.FromMass(2), Profile(false), 0.5), i => i < 10 ? 0 : speed, 120);
            for (int i = 20; i < with.Length; i++) Assert.That(with[i], Is.EqualTo(without[i]).Within(1e-12), "frame " + i);
            Assert.That(Math.Abs(with[with.Length - 1] - with[20]), Is.GreaterThan(0.001), "the object moved");
        }

        [Test]
        public void ASlowHandIsRelaxedAndStillnessIsRelativeToTheUsersSpeed()
        {
            // 0.03 m/s: still for a user lifting at 0.5 m/s (threshold 0.05), moving for one at 0.2 m/s (0.02).
            Func<int, double> slow = i => i < 45 ? 0.6 : 0.03; // an offset first, then a slow drift up
            var relaxed = Drive(new WeightSolver(WeightModel.FromMass(2), Profile(true), 0.5), slow, 180);
            var held = Drive(new WeightSolver(WeightModel.FromMass(2), Profile(false), 0.5), slow, 180);
            Assert.That(relaxed[179] - held[179], Is.GreaterThan(0.02), "relaxed toward the hand while it drifts");

            var slowUser = Drive(new WeightSolver(WeightModel.FromMass(2), Profile(true), 0.2), slow, 180);
            var slowUserHeld = Drive(new WeightSolver(WeightModel.FromMass(2), Profile(false), 0.2), slow, 180);
            for (int i = 100; i < 180; i++) Assert.That(slowUser[i], Is.EqualTo(slowUserHeld[i]).Within(1e-12), "frame " + i);
        }

        [Test]
        public void AHandAtExactlyTheStillThresholdCountsAsMoving()
        {
            // "Still" is below StillFraction × v_std: 0.5 × 0.5 = 0.25 m/s. Poses every 1/16 s, 1/64 m apart, move the
            // hand at exactly 0.25 m/s (every number here is exact in binary), so the boundary itself is tested.
            var profile = new WeightProfile("test", new WeightEffect[] { new WeightGain(), new OffsetRelaxation(1.0, 0.5) });
            var withRelaxation = new WeightSolver(WeightModel.FromMass(2), profile, 0.5);
            var without = new WeightSolver(WeightModel.FromMass(2), Profile(false), 0.5);
            foreach (var s in new[] { withRelaxation, without }) s.BeginHold(1.0, 1.0, 0);
            for (int k = 1; k <= 32; k++)
            {
                var pose = new HandSample(1.0 + k / 64.0, true, true, k / 16.0);
                Assert.That(withRelaxation.Step(pose, 1 / 16.0), Is.EqualTo(without.Step(pose, 1 / 16.0)), "pose " + k);
            }
            Assert.That(withRelaxation.HandY - withRelaxation.ObjectY, Is.GreaterThan(0.05), "the gain left an offset it did not relax");
        }

        [Test]
        public void WhileTheSpeedLimitStillCarriesMotionItRelaxesWhereTheObjectIsHeaded()
        {
            // An object limited to 0.3 m/s lifted at 2 m/s: the speed limit carries much of the lift over to the next
            // frames. Once the hand is still, what shrinks by τ/(τ + dt) each frame is the offset from where the object
            // is headed (its height plus what is still carried), not from where it happens to be.
            const double tau = 0.3;
            var effects = new WeightEffect[] { new WeightGain(), new ExperimentalBlend(), new OffsetRelaxation(tau) };
            var solver = new WeightSolver(WeightModel.FromMass(0.5), new WeightProfile("test", effects, new SolverLimits(maxObjectSpeed: 0.3)), 0.5);
            double hand = 1.0, t = 0;
            solver.BeginHold(hand, hand, t);
            for (int i = 0; i < 18; i++) { t += Dt; hand += 2.0 * Dt; solver.Step(new HandSample(hand, true, true, t), Dt); }
            for (int i = 0; i < 3; i++) { t += Dt; solver.Step(new HandSample(hand, true, true, t), Dt); } // the estimator sees the stop
            double before = hand - solver.ObjectY - solver.State.Carry;
            Assert.That(solver.State.Carry, Is.GreaterThan(0.1), "the limit still carries motion");
            Assert.That(Math.Abs(before), Is.GreaterThan(0.02), "an offset is left to relax");
            for (int i = 0; i < 30; i++)
            {
                t += Dt;
                solver.Step(new HandSample(hand, true, true, t), Dt);
                double after = hand - solver.ObjectY - solver.State.Carry;
                Assert.That(after / before, Is.EqualTo(tau / (tau + Dt)).Within(1e-9), "frame " + i);
                before = after;
            }
        }

        [TestCase(+1)]
        [TestCase(-1)]
        public void WhatRelaxationMovesIsPaidFromTheSpeedCapsDebt(int direction)
        {
            // 5 kg lifted (or lowered) 0.45 m at 3 m/s by a user of v_std 0.3 m/s: the speed cap defers part of it and pays it at
            // v_cap once the hand stops. Relaxation drawing the object up meanwhile pays that debt too: every metre the
            // object rises while the hand is still comes off what is owed, so nothing is owed twice.
            var effects = new WeightEffect[] { new WeightGain(), new ExperimentalBlend(), new SpeedCap(), new OffsetRelaxation(1.0) };
            var solver = new WeightSolver(WeightModel.FromMass(5), new WeightProfile("test", effects), 0.3);
            double hand = 1.0, t = 0;
            solver.BeginHold(hand, hand, t);
            for (int i = 0; i < 15; i++) { t += Dt; hand += direction * 3.0 * Dt; solver.Step(new HandSample(hand, true, true, t), Dt); }
            Assert.That(direction * solver.State.CapDeferred, Is.GreaterThan(0.03), "the cap owes motion when the hand stops");
            int paid = 0;
            while (direction * solver.State.CapDeferred > 0 && paid < 200)
            {
                double owed = solver.State.CapDeferred, y = solver.ObjectY;
                t += Dt;
                double moved = solver.Step(new HandSample(hand, true, true, t), Dt) - y;
                Assert.That(direction * moved, Is.GreaterThan(0), "frame " + paid);
                Assert.That(direction * (owed - solver.State.CapDeferred), Is.EqualTo(Math.Min(direction * owed, direction * moved)).Within(1e-12), "frame " + paid);
                paid++;
            }
            Assert.That(paid, Is.InRange(2, 199), "the debt was paid over a few frames");
            for (int i = 0; i < 1200; i++) { t += Dt; solver.Step(new HandSample(hand, true, true, t), Dt); }
            Assert.That(direction * (hand - solver.ObjectY), Is.InRange(0.0, 0.002), "relaxed to the still hand, never past it");
        }

        [Test]
        public void ItIsNamedForProfiles()
        {
            Assert.That(new OffsetRelaxation().Name, Is.EqualTo("offset-relaxation"));
            Assert.That(new OffsetRelaxation().TimeConstant, Is.EqualTo(1.5));
            Assert.That(new OffsetRelaxation().StillFraction, Is.EqualTo(0.1));
        }
    }
}
