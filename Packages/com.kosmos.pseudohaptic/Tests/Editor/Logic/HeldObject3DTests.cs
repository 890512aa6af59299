using System;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>
    /// The held object on the 3D solver (issue 10, item 5), engine-free, on scripted Quest hands (poses at 30 Hz,
    /// 45 ms late, confidence drops in fast motion): two hands each carrying a share, x/z from lateral inertia,
    /// a hand lost and returning without a step, a break-away that releases both grabs.
    /// </summary>
    public sealed class HeldObject3DTests
    {
        static readonly Vector3d Table = new Vector3d(0, 0.8, 0);
        static readonly Vector3d LeftGrip = new Vector3d(-0.1, 0, 0), RightGrip = new Vector3d(0.1, 0, 0);

        sealed class Space : IParentSpace
        {
            public double HeightOf(Vector3d world) => world.Y;
        }

        static HeldObject Object(double massKg, WeightProfile profile)
        {
            var hold = new HeldObject(new Space());
            Assert.That(hold.Configure(WeightModel.FromMass(massKg), profile, 0.5), Is.True, hold.Error);
            return hold;
        }

        static HandFrame[] Hand(Func<double, Vector3d> path, double seconds, int seed, double loseAt = -1, double loseFor = 0)
        {
            var hand = new QuestHand { Seed = seed, Path = path };
            if (loseAt >= 0) hand.Lose(loseAt, loseFor);
            return hand.Render(seconds);
        }

        /// <summary>Lifts with one hand or both (each on its side of the object); the object's last height.</summary>
        static double Lift(HeldObject hold, bool twoHands, double rise, int seed)
        {
            HandFrame[] left = Hand(QuestHand.Lift(Table + LeftGrip, rise, 0.4, 0.8), 1.8, seed);
            HandFrame[] right = Hand(QuestHand.Lift(Table + RightGrip, rise, 0.4, 0.8), 1.8, seed + 1000);
            Assert.That(hold.Begin(1, Table + LeftGrip, double.NaN, Table, Table.Y), Is.True, hold.Error);
            if (twoHands) Assert.That(hold.Begin(2, Table + RightGrip, double.NaN, Table, Table.Y), Is.True);
            double y = Table.Y;
            for (int i = 0; i < left.Length; i++)
            {
                double a = hold.Step(1, left[i].Position, left[i].Tracked, left[i].HighConfidence, double.NaN, left[i].Dt);
                double b = twoHands ? hold.Step(2, right[i].Position, right[i].Tracked, right[i].HighConfidence, double.NaN, right[i].Dt) : double.NaN;
                Assert.That(double.IsNaN(a) || double.IsNaN(b), Is.True, "one solver step per frame");
                y = double.IsNaN(a) ? b : a;
                Assert.That(double.IsFinite(y), Is.True, "frame " + i);
            }
            return y;
        }

        [Test]
        public void EachOfTwoHandsCarriesHalfTheWeight([Range(1, 10)] int seed)
        {
            WeightProfile shared = NamedProfiles.Paper.With(new TwoHands(0.5));
            double twoHands2kg = Lift(Object(2, shared), true, 0.3, seed) - Table.Y;
            double oneHand1kg = Lift(Object(1, shared), false, 0.3, seed) - Table.Y;
            double oneHand2kg = Lift(Object(2, shared), false, 0.3, seed) - Table.Y;
            Assert.That(twoHands2kg, Is.EqualTo(oneHand1kg).Within(0.01), "2 kg in two hands lifts as 1 kg in one");
            // Under the paper profile this lift reaches the offset correction, which keeps weights apart by the
            // issue's 5 mm at least (1 kg settles ~1 cm above 2 kg), not by the gain's whole difference.
            Assert.That(twoHands2kg, Is.GreaterThan(oneHand2kg + 0.005), "two hands lift 2 kg higher than one hand");
        }

        [Test]
        public void WithoutTwoHandsInTheProfileBothHandsAreFollowedAndEachCarriesTheWholeWeight()
        {
            double two = Lift(Object(2, NamedProfiles.Paper), true, 0.3, 4);
            double one = Lift(Object(2, NamedProfiles.Paper), false, 0.3, 4);
            Assert.That(two, Is.EqualTo(one).Within(0.01), "the paper's weight is unchanged by a second hand");

            // The second hand is followed: with the first lost for most of the lift, the lift goes on with the second.
            HeldObject hold = Object(0.5, NamedProfiles.Paper);
            HandFrame[] left = Hand(QuestHand.Lift(Table + LeftGrip, 0.3, 0.4, 0.8), 1.8, 5, loseAt: 0.45, loseFor: 1.3);
            HandFrame[] right = Hand(QuestHand.Lift(Table + RightGrip, 0.3, 0.4, 0.8), 1.8, 6);
            hold.Begin(1, Table + LeftGrip, double.NaN, Table, Table.Y);
            hold.Begin(2, Table + RightGrip, double.NaN, Table, Table.Y);
            double y = Table.Y;
            for (int i = 0; i < left.Length; i++)
            {
                double a = hold.Step(1, left[i].Position, left[i].Tracked, left[i].HighConfidence, double.NaN, left[i].Dt);
                double b = hold.Step(2, right[i].Position, right[i].Tracked, right[i].HighConfidence, double.NaN, right[i].Dt);
                y = double.IsNaN(a) ? b : a;
            }
            Assert.That(y - Table.Y, Is.GreaterThan(0.1), "the object went up with the hand still tracked");
        }

        /// <summary>A sideways carry of 0.4 m: x/z are the solver's with lateral inertia, heavier lags more, and it ends at the hand.</summary>
        [Test]
        public void ASidewaysCarryLagsByMassAndEndsAtTheHand([Values(1, 2, 3)] int seed)
        {
            double previousLag = -1;
            foreach (double mass in new[] { 0.2, 1.0, 3.0 })
            {
                HeldObject hold = Object(mass, NamedProfiles.Xyz);
                Assert.That(hold.MovesHorizontal, Is.True);
                Vector3d start = Table + RightGrip;
                Func<double, Vector3d> path = t => start + new Vector3d(0, 0, 0.4 * QuestHand.MinimumJerk((t - 0.3) / 0.7));
                HandFrame[] frames = Hand(path, 2.5, seed);
                Vector3d obj = Table;
                Assert.That(hold.Begin(1, start, double.NaN, obj, obj.Y), Is.True);
                double maxLag = 0;
                foreach (HandFrame f in frames)
                {
                    double y = hold.Step(1, f.Position, f.Tracked, f.HighConfidence, double.NaN, f.Dt);
                    obj = hold.Horizontal(new Vector3d(obj.X, y, obj.Z));
                    Assert.That(obj.IsFinite, Is.True);
                    maxLag = Math.Max(maxLag, path(f.Time).Z - obj.Z);
                }
                Assert.That(obj.Z, Is.EqualTo(0.4).Within(0.005), mass + " kg ends where the hand put it");
                Assert.That(obj.X, Is.EqualTo(0).Within(0.005));
                Assert.That(maxLag, Is.GreaterThan(previousLag + 0.002), mass + " kg lags more than the lighter one");
                previousLag = maxLag;
            }
            Assert.That(Object(1, NamedProfiles.Paper).MovesHorizontal, Is.False, "without lateral inertia the grab moves x/z");
            Vector3d here = new Vector3d(1, 2, 3);
            Assert.That(Object(1, NamedProfiles.Paper).Horizontal(here), Is.EqualTo(here));
        }

        /// <summary>Two hands lift; one is lost for 0.4 s mid-lift and comes back where it moved to: the object never steps.</summary>
        [Test]
        public void AHandLostAndReturningMovesTheObjectNoMoreThanTheHandsDo([Range(1, 40)] int seed, [Values(0.4, 1.5)] double lostFor)
        {
            HeldObject hold = Object(2, NamedProfiles.Xyz);
            var random = new Random(seed);
            double side = 0.1 * random.NextDouble();
            Func<double, Vector3d> lift = t => new Vector3d(side * QuestHand.MinimumJerk((t - 0.4) / 1.2), 0.35 * QuestHand.MinimumJerk((t - 0.4) / 1.2), 0);
            HandFrame[] left = Hand(t => Table + LeftGrip + lift(t), 3.5, seed);
            HandFrame[] right = Hand(t => Table + RightGrip + lift(t), 3.5, seed + 500, 0.6 + 0.3 * random.NextDouble(), lostFor);
            Assert.That(hold.Begin(1, Table + LeftGrip, double.NaN, Table, Table.Y), Is.True);
            Assert.That(hold.Begin(2, Table + RightGrip, double.NaN, Table, Table.Y), Is.True);
            Vector3d obj = Table, lastLeft = left[0].Position, lastRight = right[0].Position;
            double maxHandStep = 0, maxObjectStep = 0;
            for (int i = 0; i < left.Length; i++)
            {
                // Steps in either order: the solver steps once, on the call that completes the frame.
                double a = i % 2 == 0 ? hold.Step(1, left[i].Position, left[i].Tracked, left[i].HighConfidence, double.NaN, left[i].Dt) : double.NaN;
                double b = hold.Step(2, right[i].Position, right[i].Tracked, right[i].HighConfidence, double.NaN, right[i].Dt);
                if (i % 2 == 1) a = hold.Step(1, left[i].Position, left[i].Tracked, left[i].HighConfidence, double.NaN, left[i].Dt);
                double y = double.IsNaN(a) ? b : a;
                Assert.That(double.IsFinite(y), Is.True, "frame " + i);
                Vector3d next = hold.Horizontal(new Vector3d(obj.X, y, obj.Z));
                maxObjectStep = Math.Max(maxObjectStep, (next - obj).Length);
                obj = next;
                maxHandStep = Math.Max(maxHandStep, (left[i].Position - lastLeft).Length);
                lastLeft = left[i].Position;
                if (right[i].Tracked) { maxHandStep = Math.Max(maxHandStep, (right[i].Position - lastRight).Length); lastRight = right[i].Position; }
            }
            Assert.That(hold.HandCount, Is.EqualTo(2));
            Assert.That(hold.Solver3D.FollowedHands, Is.EqualTo(2), "the returned hand is followed again");
            Assert.That(maxObjectStep, Is.LessThanOrEqualTo(maxHandStep + 1e-9), "the object stepped further than any hand pose did");
            Assert.That(obj.Y - Table.Y, Is.GreaterThan(0.1), "the lift went on with the other hand");
        }

        /// <summary>
        /// Two hands hold; the second hand's driver stops stepping it without ending its hold (a third-party driver disabled
        /// mid-hold) while the first lifts. The second hand's last pose is stale, not a hand held still: it is taken as lost,
        /// so the object is lifted as when both hands lift together (the followed point rises with the first hand, each hand
        /// still carrying its share), not half as far, and the first hand's step completes every frame.
        /// </summary>
        [Test]
        public void AHandWhoseDriverStopsSteppingItIsLostNotHeldWhereItWasLastSeen([Range(1, 20)] int seed)
        {
            const double rise = 0.3;
            const int stopAt = 27; // 0.3 s: both hands still at the table
            HandFrame[] left = Hand(QuestHand.Lift(Table + LeftGrip, rise, 0.6, 0.8), 3.0, seed);
            HandFrame[] right = Hand(QuestHand.Lift(Table + RightGrip, rise, 0.6, 0.8), 3.0, seed + 700);
            HandFrame[] rightStill = Hand(t => Table + RightGrip, 3.0, seed + 700);

            HeldObject Run(bool rightStops)
            {
                HeldObject hold = Object(1, NamedProfiles.PaperExperiment);
                Assert.That(hold.Begin(1, Table + LeftGrip, double.NaN, Table, Table.Y), Is.True, hold.Error);
                Assert.That(hold.Begin(2, Table + RightGrip, double.NaN, Table, Table.Y), Is.True, hold.Error);
                for (int i = 0; i < left.Length; i++)
                {
                    HandFrame r = rightStops ? rightStill[i] : right[i];
                    if (!rightStops || i < stopAt) hold.Step(2, r.Position, r.Tracked, r.HighConfidence, double.NaN, r.Dt);
                    double y = hold.Step(1, left[i].Position, left[i].Tracked, left[i].HighConfidence, double.NaN, left[i].Dt);
                    if (rightStops && i > stopAt) Assert.That(double.IsFinite(y), Is.True, "frame " + i + ": the first hand's step completes the frame");
                }
                return hold;
            }

            HeldObject both = Run(rightStops: false), one = Run(rightStops: true);
            Assert.That(one.Solver3D.FollowedHands, Is.EqualTo(1), "the hand whose driver stopped is not followed");
            Assert.That(one.Solver3D.HoldingHands, Is.EqualTo(2), "it still holds: it was not released");
            Assert.That(one.HandPoint.Y - Table.Y, Is.EqualTo(rise).Within(0.02),
                "the followed point rises with the first hand (half the rise: the stale hand is still averaged in)");
            Assert.That(one.ObjectY, Is.EqualTo(both.ObjectY).Within(0.02), "lifted as when both hands lift");
            Assert.That(one.Solver.State.Time, Is.EqualTo(both.Solver.State.Time).Within(1e-9), "every frame's time was stepped");
        }

        /// <summary>
        /// The same stop mid-lift, against a driver that goes on stepping the hand but reports it lost from that frame: the
        /// object moves the same, bit for bit, frame by frame. The frame the first hand stepped alone (its step then waits for
        /// the other hand) is stepped with the first hand's pose when the stop is noticed a frame later, not with both hands
        /// taken as lost.
        /// </summary>
        [Test]
        public void AHandWhoseDriverStopsIsSteppedAsALostHandFromTheFrameItStopped([Range(1, 20)] int seed)
        {
            const int stopAt = 81; // 0.9 s: mid-lift
            HandFrame[] left = Hand(QuestHand.Lift(Table + LeftGrip, 0.3, 0.6, 0.8), 2.0, seed);
            HandFrame[] right = Hand(QuestHand.Lift(Table + RightGrip, 0.3, 0.6, 0.8), 2.0, seed + 700);

            double[] Run(bool rightStops, out HeldObject hold)
            {
                hold = Object(1, NamedProfiles.PaperExperiment);
                Assert.That(hold.Begin(1, Table + LeftGrip, double.NaN, Table, Table.Y), Is.True, hold.Error);
                Assert.That(hold.Begin(2, Table + RightGrip, double.NaN, Table, Table.Y), Is.True, hold.Error);
                var ys = new double[left.Length];
                for (int i = 0; i < left.Length; i++)
                {
                    HandFrame r = right[i];
                    if (i < stopAt) hold.Step(2, r.Position, r.Tracked, r.HighConfidence, double.NaN, r.Dt);
                    else if (!rightStops) hold.Step(2, r.Position, false, false, double.NaN, r.Dt);
                    ys[i] = hold.Step(1, left[i].Position, left[i].Tracked, left[i].HighConfidence, double.NaN, left[i].Dt);
                }
                return ys;
            }

            double[] stopped = Run(rightStops: true, out HeldObject one), lost = Run(rightStops: false, out HeldObject reported);
            Assert.That(stopped[stopAt], Is.NaN, "the first hand's step at the stop waits for the other hand");
            for (int i = stopAt + 1; i < left.Length; i++) Assert.That(stopped[i], Is.EqualTo(lost[i]), "frame " + i);
            Assert.That(one.ObjectY, Is.EqualTo(reported.ObjectY));
            Assert.That(one.HandPoint.Y, Is.EqualTo(reported.HandPoint.Y));
            Assert.That(one.Solver.State.Time, Is.EqualTo(reported.Solver.State.Time));
        }

        /// <summary>A hand lets go and another grasp takes its slot elsewhere: the object does not move to the new hand.</summary>
        [Test]
        public void AHandThatLetsGoAndGraspsElsewhereIsNotTakenForAHandReturning()
        {
            HeldObject hold = Object(1, NamedProfiles.Xyz);
            Vector3d l = Table + LeftGrip, r = Table + RightGrip;
            hold.Begin(1, l, double.NaN, Table, Table.Y);
            hold.Begin(2, r, double.NaN, Table, Table.Y);
            Vector3d obj = Table;
            for (int i = 0; i < 90; i++) { hold.Step(1, l, true, true, double.NaN, 1 / 90.0); obj = hold.Horizontal(new Vector3d(obj.X, hold.Step(2, r, true, true, double.NaN, 1 / 90.0), obj.Z)); }
            hold.End(1);
            Vector3d elsewhere = Table + new Vector3d(-0.05, 0.06, 0.04);
            Assert.That(hold.Begin(1, elsewhere, double.NaN, obj, obj.Y), Is.True);
            for (int i = 0; i < 90; i++)
            {
                double a = hold.Step(1, elsewhere, true, true, double.NaN, 1 / 90.0);
                double b = hold.Step(2, r, true, true, double.NaN, 1 / 90.0);
                Vector3d next = hold.Horizontal(new Vector3d(obj.X, double.IsNaN(a) ? b : a, obj.Z));
                Assert.That((next - obj).Length, Is.LessThan(1e-6), "frame " + i + ": still hands, still object");
                obj = next;
            }
        }

        /// <summary>A yank (1 m in 0.3 s) on a heavy object with break-away tears it loose: both grabs end with BrokeAway, the
        /// hold ends once.</summary>
        [Test]
        public void ABreakAwayReleasesBothHandsAndEndsTheHoldOnce([Values(1, 2, 3)] int seed)
        {
            WeightProfile profile = NamedProfiles.Xyz.With(new BreakAway(0.3));
            foreach (double mass in new[] { 2 * PhysicalConstants.StandardMassKg, 5.0 }) // two hands: the first carries one standard mass each
            {
                var scene = new BoxScene();
                BoxScene.Box box = scene.Add(Table, mass, profile);
                var left = new ScriptedGrab(scene, 1);
                var right = new ScriptedGrab(scene, 2);
                Vector3d l0 = Table + new Vector3d(-0.04, 0.02, 0), r0 = Table + new Vector3d(0.04, 0.02, 0);
                HandFrame[] lf = Hand(QuestHand.Lift(l0, 1.0, 0.5, 0.3), 1.5, seed);
                HandFrame[] rf = Hand(QuestHand.Lift(r0, 1.0, 0.5, 0.3), 1.5, seed + 100);
                int ended = 0;
                box.Hold.Ended += () => ended++;
                for (int i = 0; i < lf.Length; i++)
                {
                    left.Tick(in lf[i]);
                    right.Tick(in rf[i]);
                    Assert.That(box.Position.IsFinite, Is.True);
                }
                if (mass < 1) // the standard mass in each hand (gain 1)
                {
                    Assert.That(box.Hold.IsHeld && box.Hold.HandCount == 2, Is.True, "the standard object (gain 1) follows the yank: " + left.Grab.LastEnd + " " + right.Grab.LastEnd + " " + box.Hold.HandCount + " " + box.Position);
                    continue;
                }
                Assert.That(left.Grab.LastEnd, Is.EqualTo(GrabEnd.BrokeAway));
                Assert.That(right.Grab.LastEnd, Is.EqualTo(GrabEnd.BrokeAway));
                Assert.That(left.Grab.IsHolding || right.Grab.IsHolding, Is.False);
                Assert.That(box.Hold.HandCount, Is.EqualTo(0));
                Assert.That(ended, Is.EqualTo(1), "the hold ends once, when the last hand lets go");
                Assert.That(box.Hold.BrokeAway, Is.False, "nothing left to release");
            }
        }

        [Test]
        public void TwoHandedStepsOnTheXyzProfileAllocateNothing()
        {
            HeldObject hold = Object(2, NamedProfiles.Xyz);
            hold.Begin(1, Table + LeftGrip, double.NaN, Table, Table.Y);
            hold.Begin(2, Table + RightGrip, double.NaN, Table, Table.Y);
            Allocation.AssertNone(n =>
            {
                for (int i = 0; i < n; i++)
                {
                    double w = 0.05 * Math.Sin(i * 0.01);
                    hold.Step(1, Table + LeftGrip + new Vector3d(w, w, 0), i % 50 != 0, true, double.NaN, 1 / 90.0);
                    hold.Step(2, Table + RightGrip + new Vector3d(w, w, 0), true, i % 7 != 0, double.NaN, 1 / 90.0);
                    hold.Horizontal(Table);
                }
            }, "two-hand frames");
        }
    }
}
