using System;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>
    /// What the play-mode PseudoHapticWeight tests assert that is not engine-specific, through the engine-free
    /// <see cref="HeldObject"/> the component delegates to, on scripted Quest hands.
    /// </summary>
    public sealed class HeldObjectTests
    {
        sealed class Floor : IParentSpace
        {
            public double HeightOf(Vector3d world) => world.Y;
        }

        static HeldObject Object(double massKg, double standardSpeed = 0.5, WeightProfile profile = null)
        {
            var hold = new HeldObject(new Floor());
            Assert.That(hold.Configure(WeightModel.FromMass(massKg), profile ?? NamedProfiles.Paper, standardSpeed), Is.True, hold.Error);
            return hold;
        }

        /// <summary>Lifts from the floor by <paramref name="rise"/> m over <paramref name="seconds"/> s, then holds 0.3 s; the last height.</summary>
        static double Lift(HeldObject hold, double rise, double seconds, int seed = 1, double frameRate = 90)
        {
            var start = new Vector3d(0, 0, 0);
            HandFrame[] frames = new QuestHand { Seed = seed, FrameRate = frameRate, Path = QuestHand.Lift(start, rise, 0.1, seconds) }.Render(seconds + 0.4);
            Assert.That(hold.Begin(1, start, double.NaN, start, 0), Is.True, hold.Error);
            double y = double.NaN;
            foreach (HandFrame f in frames)
            {
                y = hold.Step(1, f.Position, f.Tracked, f.HighConfidence, double.NaN, f.Dt);
                Assert.That(double.IsFinite(y) && y >= 0, Is.True, "t = " + f.Time + ": " + y);
            }
            return y;
        }

        [Test]
        public void TheGolfBallStaysWithTheHand([Values(72.0, 90.0, 120.0)] double frameRate)
        {
            HeldObject ball = Object(PhysicalConstants.StandardMassKg);
            Assert.That(Lift(ball, 0.25, 0.75, frameRate: frameRate), Is.EqualTo(0.25).Within(0.005));
        }

        [Test]
        public void HeavierObjectsEndLowerAfterTheSameLift([Range(1, 20)] int seed)
        {
            double previous = double.PositiveInfinity;
            foreach (double mass in new[] { 0.01, 0.045, 0.2, 0.5, 1, 2, 5 })
            {
                double y = Lift(Object(mass), 0.3, 0.8, seed);
                Assert.That(y, Is.LessThanOrEqualTo(previous + 1e-4), mass + " kg ended higher than a lighter object");
                previous = y;
            }
            Assert.That(previous, Is.LessThan(0.3 * 0.5), "5 kg lags well behind the hand");
        }

        [Test]
        public void LighterThanTheGolfBallLeadsTheHandWithinTheGainCap()
        {
            double y = Lift(Object(0.01), 0.1, 0.6);
            Assert.That(y, Is.GreaterThan(0.1));
            Assert.That(y, Is.LessThanOrEqualTo(0.1 * SolverLimits.Default.MaxGain + 1e-3));
        }

        [Test]
        public void AnInvalidConfigurationKeepsTheLastValidOneAndSaysWhy()
        {
            HeldObject hold = Object(1);
            Assert.That(hold.Configure(WeightModel.FromMass(2), NamedProfiles.Paper, double.NaN), Is.False);
            Assert.That(hold.Error, Does.Contain("standardSpeed"));
            Assert.That(hold.Solver.Model.MassKg, Is.EqualTo(1), "the last valid configuration");
            Assert.That(hold.Configure(WeightModel.FromMass(2), NamedProfiles.Paper, 0.5), Is.True);
            Assert.That(hold.Error, Is.Null);
        }

        [Test]
        public void LostTrackingAndGarbagePosesNeverReachTheAnswer()
        {
            HeldObject hold = Object(1);
            Assert.That(hold.Begin(1, new Vector3d(0, 0.05, 0), double.NaN, Vector3d.Zero, 0), Is.True);
            var random = new Random(5);
            double[] garbage = { double.NaN, double.PositiveInfinity, double.NegativeInfinity, 1e30, -1e30 };
            for (int i = 0; i < 2000; i++)
            {
                double g = garbage[random.Next(garbage.Length)];
                var p = i % 3 == 0 ? new Vector3d(0, g, 0) : new Vector3d(0, 0.05 + 0.2 * random.NextDouble(), 0);
                double y = hold.Step(1, p, i % 5 != 0, true, double.NaN, i % 11 == 0 ? double.NaN : 1 / 90.0);
                Assert.That(double.IsFinite(y) && y >= 0, Is.True, "frame " + i + ": " + y);
                Assert.That(Math.Abs(hold.HandPoint.Y), Is.LessThan(1), "a garbage pose never becomes the hand point");
            }
            // After all that, the point is the hand again: no precision lost to a huge pose.
            for (int i = 0; i < 3; i++) hold.Step(1, new Vector3d(0, 0.123, 0), true, true, double.NaN, 1 / 90.0);
            Assert.That(hold.HandPoint.Y, Is.EqualTo(0.123).Within(1e-9));
        }

        static readonly Vector3d Table = new Vector3d(0, 0.8, 0);
        const double Frame = 1 / 90.0;

        /// <summary>One frame of each hand in <paramref name="hands"/> at its pose; the value of the call that stepped (NaN if none did).</summary>
        static double Frame2(HeldObject hold, int[] hands, Vector3d[] at, bool[] tracked = null, bool[] confident = null, double dt = Frame)
        {
            double y = double.NaN;
            for (int i = 0; i < hands.Length; i++)
            {
                double r = hold.Step(hands[i], at[i], tracked == null || tracked[i], confident == null || confident[i], double.NaN, dt);
                if (!double.IsNaN(r)) y = r;
            }
            return y;
        }

        [Test]
        public void BeforeAConfigurationTheHoldHasNoMassHeightOrOffsetAndTakesNoHand()
        {
            var hold = new HeldObject(new Floor());
            Assert.That(double.IsNaN(hold.MassKg), Is.True, "MassKg");
            Assert.That(double.IsNaN(hold.ObjectY), Is.True, "ObjectY");
            Assert.That(double.IsNaN(hold.Offset), Is.True, "Offset");
            Assert.That(hold.Begin(1, Table, double.NaN, Table, Table.Y), Is.False);
            Assert.That(hold.HandCount, Is.Zero);
        }

        [Test]
        public void OutsidePaperLiteralTheHeightAndOffsetAreTheSolversThroughoutTheHold()
        {
            HeldObject hold = Object(2);
            Vector3d hand = Table + new Vector3d(0, 0.05, 0);
            Assert.That(hold.Begin(1, hand, double.NaN, Table, Table.Y), Is.True, hold.Error);
            Assert.That(hold.ObjectY, Is.EqualTo(Table.Y), "the object is where it was grabbed");
            for (int i = 0; i < 60; i++)
            {
                hold.Step(1, hand + new Vector3d(0, 0.004 * i, 0), true, true, double.NaN, Frame);
                Assert.That(hold.ObjectY, Is.EqualTo(hold.Solver3D.ObjectY), "frame " + i);
                Assert.That(hold.Offset, Is.EqualTo(hold.Solver.Offset), "frame " + i);
            }
            Assert.That(hold.ObjectY, Is.GreaterThan(Table.Y), "the lift moved it");
        }

        [Test]
        public void ARefusedConfigurationNamesTheFieldAndChangesNothing()
        {
            HeldObject hold = Object(1);
            Assert.That(hold.Configure(WeightModel.FromMass(2), null, 0.5), Is.False, "a null profile is refused, not thrown");
            Assert.That(hold.Error, Does.Contain("profile"));
            foreach (double cue in new[] { double.NaN, WeightSolver.MinCueStrength * 0.999, WeightSolver.MaxCueStrength * 1.001, double.NegativeInfinity, double.PositiveInfinity })
            {
                Assert.That(hold.Configure(WeightModel.FromMass(2), NamedProfiles.Paper, 0.5, cue), Is.False, "cue strength " + cue);
                Assert.That(hold.Error, Does.Contain("ueStrength"), "cue strength " + cue);
                Assert.That(hold.Error, Does.Contain("CueStrength must lie in [" + WeightSolver.MinCueStrength + ", " + WeightSolver.MaxCueStrength + "]"), "the range is said");
                Assert.That(hold.MassKg, Is.EqualTo(1), "cue strength " + cue + ": the last valid configuration is kept whole");
                Assert.That(hold.Solver3D.CueStrength, Is.EqualTo(WeightSolver.DefaultCueStrength));
            }
            foreach (double cue in new[] { WeightSolver.MinCueStrength, WeightSolver.MaxCueStrength })
            {
                Assert.That(hold.Configure(WeightModel.FromMass(2), NamedProfiles.Paper, 0.5, cue), Is.True, "the range is inclusive: " + cue);
                Assert.That(hold.Solver3D.CueStrength, Is.EqualTo(cue));
            }
        }

        /// <summary>An inspector re-applying the same settings every frame (OnValidate, a settings refresh) does not disturb the hold.</summary>
        [Test]
        public void ReapplyingTheSameProfileMidHoldChangesNothing()
        {
            WeightProfile filtered = NamedProfiles.Paper.WithHandFilter(new OneEuroFilter());
            var model = WeightModel.FromMass(2);
            var heights = new double[2];
            for (int run = 0; run < 2; run++)
            {
                HeldObject hold = Object(2, profile: filtered);
                Assert.That(hold.Begin(1, Table, double.NaN, Table, Table.Y), Is.True, hold.Error);
                for (int i = 0; i < 90; i++)
                {
                    if (run == 1) Assert.That(hold.Configure(model, filtered, 0.5), Is.True, hold.Error);
                    heights[run] = hold.Step(1, Table + new Vector3d(0, 0.3 * QuestHand.MinimumJerk(i / 60.0), 0), true, true, double.NaN, Frame);
                }
            }
            Assert.That(heights[1], Is.EqualTo(heights[0]).Within(1e-9));
        }

        [Test]
        public void WithBothHandsLetsEveryHandCarryTheWholeWeightUnlessTheProfileSharesIt()
        {
            TwoHands added = HeldObject.WithBothHands(NamedProfiles.Paper).Find<TwoHands>();
            Assert.That(added, Is.Not.Null);
            Assert.That(added.Share, Is.EqualTo(1));
            WeightProfile shared = NamedProfiles.Paper.With(new TwoHands(0.5));
            Assert.That(HeldObject.WithBothHands(shared), Is.SameAs(shared));
        }

        [Test]
        public void BeginRefusesAHandAlreadyOnItAThirdHandAndAnyHandAfterABreakAway()
        {
            HeldObject hold = Object(1);
            Assert.That(hold.Begin(1, Table, double.NaN, Table, Table.Y), Is.True);
            Assert.That(hold.Begin(1, Table, double.NaN, Table, Table.Y), Is.False, "the first hand again");
            Assert.That(hold.HandCount, Is.EqualTo(1));
            Assert.That(hold.Begin(2, Table, double.NaN, Table, Table.Y), Is.True);
            Assert.That(hold.Begin(2, Table, double.NaN, Table, Table.Y), Is.False, "the second hand again");
            Assert.That(hold.Begin(3, Table, double.NaN, Table, Table.Y), Is.False, "a third hand");
            Assert.That(hold.HandCount, Is.EqualTo(2));
            Assert.That(hold.Holds(1) && hold.Holds(2) && !hold.Holds(3), Is.True);

            // A yank tears a heavy object with break-away loose; until its hand lets go, no other hand can take it.
            var heavy = new HeldObject(new Floor());
            Assert.That(heavy.Configure(WeightModel.FromMass(5), NamedProfiles.Xyz.With(new BreakAway(0.3)), 0.5), Is.True, heavy.Error);
            Assert.That(heavy.Begin(1, Table, double.NaN, Table, Table.Y), Is.True);
            for (int i = 0; i < 90 && !heavy.BrokeAway; i++)
                heavy.Step(1, Table + new Vector3d(0, QuestHand.MinimumJerk(i / 27.0), 0), true, true, double.NaN, Frame);
            Assert.That(heavy.BrokeAway, Is.True, "a 1 m yank in 0.3 s on 5 kg");
            Assert.That(heavy.Begin(2, Table, double.NaN, Table, Table.Y), Is.False);
            Assert.That(heavy.HandCount, Is.EqualTo(1));
        }

        [Test]
        public void RightAfterBeginTheHandIsTheGrabbingOneAndTheGrabMovesNothing()
        {
            HeldObject hold = Object(1);
            Vector3d hand = new Vector3d(0.1, 0.85, 0.2), obj = new Vector3d(-0.2, 0.8, 0.3);
            Assert.That(hold.Begin(1, hand, double.NaN, obj, obj.Y), Is.True);
            Assert.That(hold.HandPoint, Is.EqualTo(hand));
            Assert.That(hold.LastHand.IsTracked, Is.True);
            Assert.That(hold.LastHand.Y, Is.EqualTo(0.85));
            Assert.That(hold.GrabTarget.X, Is.EqualTo(obj.X).Within(1e-12), "grabbing moves nothing");
            Assert.That(hold.GrabTarget.Z, Is.EqualTo(obj.Z).Within(1e-12));
            Assert.That((hold.Horizontal(obj, grabMoves: true) - obj).Length, Is.LessThan(1e-12));

            // A grab whose pose is unusable (a finite position far outside any workspace) gives no hand.
            HeldObject far = Object(1);
            Assert.That(far.Begin(1, new Vector3d(2e5, 0.85, 0), double.NaN, obj, obj.Y), Is.True, far.Error);
            Assert.That(far.LastHand.IsTracked || double.IsFinite(far.LastHand.Y) || far.HandPoint.IsFinite, Is.False);
        }

        /// <summary>Two hands move together by (dx, dz): the grab's x/z move with them, whichever joined last and however they got there.</summary>
        [Test]
        public void TheGrabFollowsTheMeanOfTheHandsFromWhereTheObjectWasWhenTheyChanged([Range(1, 20)] int seed)
        {
            var random = new Random(seed);
            HeldObject hold = Object(1);
            Vector3d l = Table + new Vector3d(-0.1, 0.02, 0.05 * random.NextDouble()), r = Table + new Vector3d(0.1, 0.02, -0.05 * random.NextDouble());
            Vector3d obj = Table + new Vector3d(0.03, 0, 0.04);
            Assert.That(hold.Begin(1, l, double.NaN, obj, obj.Y), Is.True);
            // The object was moved (by physics, by the solver) before the second hand joined: the grab starts from there.
            Vector3d moved = obj + new Vector3d(0.02 * random.NextDouble(), 0, -0.02 * random.NextDouble());
            hold.TrackObject(moved);
            Assert.That(hold.Begin(2, r, double.NaN, moved, moved.Y), Is.True);
            Assert.That(hold.GrabTarget.X, Is.EqualTo(moved.X).Within(1e-12), "a hand joining moves nothing");
            Assert.That(hold.GrabTarget.Z, Is.EqualTo(moved.Z).Within(1e-12));
            var d = new Vector3d(0.2 * (random.NextDouble() - 0.5), 0, 0.2 * (random.NextDouble() - 0.5));
            Frame2(hold, new[] { 2, 1 }, new[] { r + d, l + d });
            Assert.That(hold.GrabTarget.X, Is.EqualTo(moved.X + d.X).Within(1e-12));
            Assert.That(hold.GrabTarget.Z, Is.EqualTo(moved.Z + d.Z).Within(1e-12));
            // One hand alone moving by e moves the mean by e / 2.
            var e = new Vector3d(0.1 * random.NextDouble(), 0, 0.1 * random.NextDouble());
            Frame2(hold, new[] { 1, 2 }, new[] { l + d + e, r + d });
            Assert.That(hold.GrabTarget.X, Is.EqualTo(moved.X + d.X + e.X / 2).Within(1e-12));
            Assert.That(hold.GrabTarget.Z, Is.EqualTo(moved.Z + d.Z + e.Z / 2).Within(1e-12));
        }

        [Test]
        public void AnUntrackedHandNeitherMovesTheGrabNorKeepsItAfterTheOtherLetsGo()
        {
            HeldObject hold = Object(1);
            Vector3d l = Table + new Vector3d(-0.1, 0.02, 0), r = Table + new Vector3d(0.1, 0.02, 0);
            hold.Begin(1, l, double.NaN, Table, Table.Y);
            hold.Begin(2, r, double.NaN, Table, Table.Y);
            Frame2(hold, new[] { 1, 2 }, new[] { l, r });
            // The right hand's tracking is lost: its (finite, stale) position is far off; the grab stays with the left hand.
            Frame2(hold, new[] { 1, 2 }, new[] { l, r + new Vector3d(0.5, 0, 0.5) }, tracked: new[] { true, false });
            Assert.That(hold.GrabTarget.X, Is.EqualTo(Table.X).Within(1e-12));
            Assert.That(hold.GrabTarget.Z, Is.EqualTo(Table.Z).Within(1e-12));
            // Now the left hand is lost and the right lets go: no hand is usable, the grab has no target.
            Frame2(hold, new[] { 1, 2 }, new[] { l, r }, tracked: new[] { false, true });
            Assert.That(hold.End(2), Is.False, "the left hand still holds");
            Assert.That(hold.GrabTarget.IsFinite, Is.False);
            Assert.That(hold.Horizontal(Table + new Vector3d(0.3, 0, 0), grabMoves: true), Is.EqualTo(Table + new Vector3d(0.3, 0, 0)));
        }

        [Test]
        public void OnlyTheHandsOnTheObjectStepItAndLetGo()
        {
            HeldObject hold = Object(1);
            hold.Begin(1, Table, double.NaN, Table, Table.Y);
            hold.Begin(2, Table, double.NaN, Table, Table.Y);
            int ended = 0;
            hold.Ended += () => ended++;
            Assert.That(double.IsNaN(hold.Step(9, Table, true, true, double.NaN, Frame)), Is.True, "a stranger's frame");
            Assert.That(hold.Holds(int.MinValue), Is.False);
            Assert.That(hold.End(9), Is.False);
            Assert.That(hold.End(int.MinValue), Is.False);
            Assert.That(hold.HandCount, Is.EqualTo(2));
            Assert.That(hold.End(1), Is.False, "the other hand still holds");
            Assert.That(ended, Is.Zero);
            Assert.That(hold.End(2), Is.True, "the last hand ended the hold");
            Assert.That(ended, Is.EqualTo(1));
        }

        /// <summary>Hand 2 gave its frame, let go, and hand 3 took its place: the frame is complete only when hand 3 gives its own.</summary>
        [Test]
        public void AHandThatJoinsMidFrameIsWaitedForAndTheOneThatLeftIsNot()
        {
            HeldObject hold = Object(1);
            hold.Begin(1, Table, double.NaN, Table, Table.Y);
            hold.Begin(2, Table, double.NaN, Table, Table.Y);
            Assert.That(double.IsNaN(hold.Step(2, Table, true, true, double.NaN, Frame)), Is.True);
            hold.End(2);
            Assert.That(hold.Begin(3, Table, double.NaN, Table, Table.Y), Is.True);
            Assert.That(double.IsNaN(hold.Step(1, Table, true, true, double.NaN, Frame)), Is.True, "hand 3 has not given this frame's pose");
            Assert.That(double.IsNaN(hold.Step(3, Table, true, true, double.NaN, Frame)), Is.False, "now the frame is complete");
            // And a hand that left with its pose not given is not waited for.
            Assert.That(double.IsNaN(hold.Step(1, Table, true, true, double.NaN, Frame)), Is.True);
            hold.End(3);
            Assert.That(double.IsNaN(hold.Step(1, Table, true, true, double.NaN, Frame)), Is.False);
        }

        [Test]
        public void ARegrabStartsFromRest()
        {
            HeldObject hold = Object(1);
            hold.Begin(1, Table, double.NaN, Table, Table.Y);
            for (int i = 1; i <= 30; i++)
            {
                hold.Step(1, Table + new Vector3d(0.01 * i, 0, 0), true, true, double.NaN, Frame);
                hold.TrackObject(Table + new Vector3d(0.01 * i, 0, 0));
            }
            Assert.That(hold.HandVelocity.X, Is.GreaterThan(0.5), "thrown");
            Assert.That(hold.ObjectVelocity.X, Is.GreaterThan(0.5));
            hold.End(1);
            Vector3d there = Table + new Vector3d(0.5, 0, 0);
            Assert.That(hold.Begin(1, there, double.NaN, there, there.Y), Is.True);
            Assert.That(hold.HandVelocity, Is.EqualTo(Vector3d.Zero));
            Assert.That(hold.ObjectVelocity, Is.EqualTo(Vector3d.Zero));
            Assert.That(hold.ReleaseVelocity(ReleaseVelocity.Hand), Is.EqualTo(Vector3d.Zero));
        }

        [Test]
        public void AFrameWithoutAUsableTimeNeitherStopsNorSpeedsUpTheHandsVelocity([Values(double.NaN, double.PositiveInfinity, -1 / 90.0, 0)] double badDt)
        {
            HeldObject hold = Object(1);
            hold.Begin(1, Table, double.NaN, Table, Table.Y);
            Vector3d hand = Table;
            for (int i = 0; i < 40; i++)
            {
                hand += new Vector3d(0.01, 0, 0); // 0.9 m/s at 90 Hz
                hold.Step(1, hand, true, true, double.NaN, Frame);
                if (i == 20) hold.Step(1, hand, true, true, double.NaN, badDt); // a repeated frame with a bad time
            }
            Assert.That(hold.HandVelocity.X, Is.EqualTo(0.9).Within(0.05));
        }

        /// <summary>The sample the recorder reads is confident when every hand followed is, whichever slot a lost hand is in.</summary>
        [Test]
        public void TheHandSampleIsConfidentExactlyWhenEveryFollowedHandIs()
        {
            HeldObject one = Object(1);
            one.Begin(1, Table, double.NaN, Table, Table.Y);
            one.Step(1, Table, true, false, double.NaN, Frame);
            Assert.That(one.LastHand.IsTracked && !one.LastHand.IsHighConfidence, Is.True, "one hand, low confidence");
            one.Step(1, Table, true, true, double.NaN, Frame);
            Assert.That(one.LastHand.IsTracked && one.LastHand.IsHighConfidence, Is.True, "one hand, high confidence");
            one.Step(1, Table, false, false, double.NaN, Frame);
            Assert.That(one.LastHand.IsTracked || one.LastHand.IsHighConfidence, Is.False, "every hand lost");
            Assert.That(double.IsNaN(one.LastHand.Y), Is.True, "no height for a lost hand");

            foreach (int lost in new[] { 1, 2 })
            {
                HeldObject two = Object(1);
                Vector3d l = Table + new Vector3d(-0.1, 0, 0), r = Table + new Vector3d(0.1, 0, 0);
                two.Begin(1, l, double.NaN, Table, Table.Y);
                two.Begin(2, r, double.NaN, Table, Table.Y);
                for (int i = 0; i < 90; i++) Frame2(two, new[] { 1, 2 }, new[] { l, r });
                Assert.That(two.Solver3D.FollowedHands, Is.EqualTo(2), "both joined");
                Frame2(two, new[] { 1, 2 }, new[] { l, r }, tracked: new[] { lost != 1, lost != 2 }, confident: new[] { lost != 1, lost != 2 });
                Assert.That(two.LastHand.IsTracked && two.LastHand.IsHighConfidence, Is.True, "hand " + lost + " lost, the other confident");
                for (int i = 0; i < 90; i++) Frame2(two, new[] { 1, 2 }, new[] { l, r });
                Frame2(two, new[] { 1, 2 }, new[] { l, r }, confident: new[] { lost != 1, lost != 2 });
                Assert.That(two.LastHand.IsTracked && !two.LastHand.IsHighConfidence, Is.True, "hand " + lost + " low confidence");
            }
        }
    }
}
