using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>
    /// The lowering guard pose by pose (1/32 s poses, so the pose clock's sums are exact): while the hand lowers, the
    /// object ends no further from the hand than it was (at least the slack, 5 mm, is allowed); what the guard added is
    /// given back when the hand turns up within 0.2 s of pose time, the object moving at most as the hand does.
    /// </summary>
    public class LoweringGuardTests
    {
        const double Pose = 1 / 32.0;

        static WeightSolver Solver(double massKg)
            => new WeightSolver(WeightModel.FromMass(massKg), new WeightProfile("test", new WeightEffect[] { new WeightGain(), new LoweringGuard() }));

        sealed class Hand
        {
            public double Y = 1.0, T;
            public double Move(WeightSolver s, double dy) { T += Pose; Y += dy; return s.Step(new HandSample(Y, true, true, T), Pose); }
        }

        [Test]
        public void AGiveBackExactlyTwoTenthsOfASecondAfterTheGuardActedIsStillMade()
        {
            // Poses 0.2 s apart (0.4 − 0.2 is exactly 0.2 in binary): the window includes its end.
            var s = Solver(5);
            double g = s.Gain;
            s.BeginHold(1.0, 1.0, 0);
            Assert.That(s.Step(new HandSample(0.99, true, true, 0.2), 0.2), Is.EqualTo(0.995).Within(1e-12), "the guard acts");
            Assert.That(s.Step(new HandSample(1.0, true, true, 0.4), 0.2) - 0.995, Is.EqualTo(0.005).Within(1e-12),
                "given back: where the gain alone would have put it, not " + (0.01 * g));
        }

        [Test]
        public void AHeavyObjectIsBroughtDownWithTheHandThenGivenBackAsTheHandRises()
        {
            var s = Solver(5);
            double g = s.Gain;
            Assert.That(g, Is.LessThan(0.1), "heavy");
            var hand = new Hand();
            s.BeginHold(hand.Y, hand.Y, 0);
            // Lowering 1 cm: the gain would move it 0.1 mm and leave it 9.9 mm above the hand; the slack allows 5 mm.
            Assert.That(hand.Move(s, -0.01), Is.EqualTo(0.995).Within(1e-12));
            Assert.That(hand.Move(s, -0.01), Is.EqualTo(0.985).Within(1e-12), "then no further from the hand than it was");
            double debt = (1.0 - 0.985) - 0.02 * g; // what the guard added beyond the gain's own motion
            Assert.That(s.State.GuardDebt, Is.EqualTo(-debt).Within(1e-12));
            // Turning up: the debt comes back, but the object moves no more than the hand does (1 cm) in a pose.
            Assert.That(hand.Move(s, 0.01), Is.EqualTo(0.995).Within(1e-12));
            double rest = debt - 0.01 * (1 - g);
            Assert.That(hand.Move(s, 0.01), Is.EqualTo(0.995 + 0.01 * g + rest).Within(1e-12), "the rest of the debt");
            double y = s.ObjectY;
            Assert.That(hand.Move(s, 0.01) - y, Is.EqualTo(0.01 * g).Within(1e-12), "then the gain alone");
            Assert.That(s.State.GuardDebt, Is.EqualTo(0));
        }

        [TestCase(5, false)] // up 6/32 s of poses after the guard acted: given back (0.1 mm by the gain, 4.9 mm of debt)
        [TestCase(6, true)]  // 7/32 s > 0.2 s: expired
        public void WhatTheGuardAddedIsGivenBackOnlyWithinTwoTenthsOfASecondOfPoses(int stillPoses, bool expired)
        {
            var s = Solver(5);
            double g = s.Gain;
            var hand = new Hand();
            s.BeginHold(hand.Y, hand.Y, 0);
            hand.Move(s, -0.01);
            for (int i = 0; i < stillPoses; i++) hand.Move(s, 0);
            double y = s.ObjectY;
            double up = hand.Move(s, 0.01) - y;
            Assert.That(up, Is.EqualTo(expired ? 0.01 * g : 0.005).Within(1e-12), expired ? "the gain alone" : "back to where the gain alone would have put it");
        }

        [Test]
        public void TheGiveBackWindowCountsFromWhenTheGuardActedNotFromTheGrab()
        {
            // Held still for half a second, then lowered 1 cm (the guard adds 4.9 mm) and raised 1 cm a pose later:
            // what the guard added comes back, however long the hold had lasted.
            var s = Solver(5);
            var hand = new Hand();
            s.BeginHold(hand.Y, hand.Y, 0);
            for (int i = 0; i < 16; i++) hand.Move(s, 0);
            hand.Move(s, -0.01);
            double y = s.ObjectY;
            Assert.That(hand.Move(s, 0.01) - y, Is.EqualTo(0.005).Within(1e-12), "back to where the gain alone would have put it");
            Assert.That(s.State.GuardDebt, Is.EqualTo(0).Within(1e-15));
        }

        [Test]
        public void ALightObjectIsHeldBackWhileLoweringAndCatchesUpAsTheHandRises()
        {
            var s = Solver(0.01);
            Assert.That(s.Gain, Is.EqualTo(3.0), "light: gain 3");
            var hand = new Hand();
            s.BeginHold(hand.Y, hand.Y, 0);
            // Lowering 1 cm: the gain would drop it 3 cm, 2 cm below the hand; the slack allows 5 mm.
            Assert.That(hand.Move(s, -0.01), Is.EqualTo(0.985).Within(1e-12));
            Assert.That(s.State.GuardDebt, Is.EqualTo(0.015).Within(1e-12));
            Assert.That(hand.Move(s, -0.01), Is.EqualTo(0.975).Within(1e-12), "5 mm below the hand, as before");
            Assert.That(s.State.GuardDebt, Is.EqualTo(0.035).Within(1e-12));
            // Up 1 cm a pose: the gain's 3 cm less what the guard added, but never less than the hand's own 1 cm.
            Assert.That(hand.Move(s, 0.01), Is.EqualTo(0.985).Within(1e-12), "with the hand: 2 of the 3.5 cm given back");
            Assert.That(hand.Move(s, 0.01), Is.EqualTo(1.0).Within(1e-12), "3 cm less the last 1.5 cm");
            Assert.That(s.State.GuardDebt, Is.EqualTo(0).Within(1e-15));
            Assert.That(hand.Move(s, 0.01), Is.EqualTo(1.03).Within(1e-12), "then the gain alone");
        }

        [Test]
        public void WhatTheGuardAddsPaysTheSpeedCapsDebtSoTheObjectNeverEndsBelowTheHand()
        {
            // 5 kg lowered 0.3 m at 2.4 m/s by a user of 0.3 m/s: the cap defers the gain's downward motion, the guard
            // brings the object down with the hand anyway; that pays what the cap owed, or the cap would later lower
            // it past the still hand.
            var s = new WeightSolver(WeightModel.FromMass(5),
                new WeightProfile("test", new WeightEffect[] { new WeightGain(), new ExperimentalBlend(), new SpeedCap(), new LoweringGuard() }), 0.3);
            var hand = new Hand();
            s.BeginHold(hand.Y, hand.Y, 0);
            for (int i = 0; i < 4; i++) hand.Move(s, -0.075);
            Assert.That(s.ObjectY - hand.Y, Is.InRange(0.0, 0.005 + 1e-12), "brought down with the hand, within the slack");
            for (int i = 0; i < 64; i++)
            {
                double y = hand.Move(s, 0);
                Assert.That(y - hand.Y, Is.InRange(0.0, 0.005 + 1e-12), "still hand, pose " + i + ": nothing owed pushes it lower");
            }
        }

        [Test]
        public void ReanchoringForgetsWhatTheGuardAdded()
        {
            // Lowered (the guard adds 4.9 mm), then tracking lost for 0.31 s: the hand comes back elsewhere and the hold
            // re-anchors; rising from there moves the object by the gain alone, nothing is given back.
            var s = Solver(5);
            double g = s.Gain;
            var hand = new Hand();
            s.BeginHold(hand.Y, hand.Y, 0);
            hand.Move(s, -0.01);
            Assert.That(s.State.GuardDebt, Is.LessThan(-0.004));
            for (int i = 0; i < 10; i++) { hand.T += Pose; s.Step(HandSample.Lost, Pose); }
            hand.Y = 1.2;
            hand.Move(s, 0);
            Assert.That(s.State.GuardDebt, Is.EqualTo(0), "forgotten");
            double y = s.ObjectY;
            Assert.That(hand.Move(s, 0.01) - y, Is.EqualTo(0.01 * g).Within(1e-12));
        }

        [Test]
        public void LoweringWithinTheOffsetOrAStillHandLeavesTheGainAlone()
        {
            var s = Solver(5);
            double g = s.Gain;
            var hand = new Hand();
            s.BeginHold(hand.Y, hand.Y, 0);
            hand.Move(s, 0.1); // lifted 10 cm: the object hangs about 10 cm below the hand
            double y = s.ObjectY;
            Assert.That(hand.Move(s, -0.01) - y, Is.EqualTo(-0.01 * g).Within(1e-12), "lowering toward it: the gain alone");
            y = s.ObjectY;
            Assert.That(hand.Move(s, 0) - y, Is.EqualTo(0), "a still hand: nothing");
            Assert.That(s.State.GuardDebt, Is.EqualTo(0));
            Assert.That(new LoweringGuard().Name, Is.EqualTo("lowering-guard"));
        }
    }
}
