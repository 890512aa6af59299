using System;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>The engine-free grab (pinch, nearest object, losses, break-away, two hands) on scripted Quest hands.</summary>
    public sealed class GrabTests
    {
        static readonly Vector3d Table = new Vector3d(0, 0.8, 0);

        [Test]
        public void ThePinchClosesAtItsThresholdAndFlickerInsideTheBandNeverOpensIt()
        {
            var pinch = new PinchDetector();
            pinch.Update(true, 0.85, 1 / 90.0);
            Assert.That(pinch.IsPinching, Is.False, "0.85 is below the default close threshold");
            pinch.Update(true, 0.95, 1 / 90.0);
            Assert.That(pinch.IsPinching && pinch.Began, Is.True);
            var random = new Random(3);
            for (int i = 0; i < 900; i++)
            {
                pinch.Update(true, 0.5 + 0.45 * random.NextDouble(), 1 / 90.0);
                Assert.That(pinch.IsPinching, Is.True, "frame " + i);
                Assert.That(pinch.Began, Is.False);
            }
        }

        [Test]
        public void AOneFrameDropOfThePinchKeepsItAndAnOpenHandOpensItWithinATenthOfASecond()
        {
            var pinch = new PinchDetector();
            pinch.Update(true, 1, 1 / 90.0);
            pinch.Update(true, 0, 1 / 90.0);
            pinch.Update(true, 1, 1 / 90.0);
            Assert.That(pinch.IsPinching, Is.True, "one dropped frame at 90 Hz");
            int frames = 0;
            while (pinch.IsPinching && frames < 100) { pinch.Update(true, 0.1, 1 / 90.0); frames++; }
            Assert.That(frames / 90.0, Is.LessThanOrEqualTo(0.1), "opened after " + frames + " frames");
            Assert.That(frames, Is.GreaterThan(1));
        }

        [Test]
        public void AnUntrackedHandKeepsItsPinchAndNaNStrengthCountsAsOpen()
        {
            var pinch = new PinchDetector();
            pinch.Update(true, 1, 0.011);
            for (int i = 0; i < 200; i++) pinch.Update(false, 0, 0.011);
            Assert.That(pinch.IsPinching, Is.True);
            for (int i = 0; i < 20; i++) pinch.Update(true, double.NaN, 0.011);
            Assert.That(pinch.IsPinching, Is.False);
        }

        [Test]
        public void InvalidPinchAndGrabSettingsThrowNamingTheSettingAndWhatItMustBe()
        {
            // The inspector shows the message: it says the allowed range, not only the name (which .NET appends anyway).
            var pinch = new PinchDetector();
            Assert.That(() => pinch.CloseAt = 1.5, Throws.InstanceOf<ArgumentOutOfRangeException>().With.Message.Contains("CloseAt must be in (0, 1]"));
            Assert.That(() => pinch.CloseAt = pinch.OpenBelow / 2, Throws.InstanceOf<ArgumentOutOfRangeException>()
                .With.Message.Contains("CloseAt must not be below OpenBelow (" + pinch.OpenBelow + ")"));
            Assert.That(() => pinch.OpenBelow = double.NaN, Throws.InstanceOf<ArgumentOutOfRangeException>().With.Message.Contains("OpenBelow must be in (0, CloseAt]"));
            Assert.That(() => pinch.OpenAfter = -1, Throws.InstanceOf<ArgumentOutOfRangeException>().With.Message.Contains("OpenAfter must be finite and >= 0"));
            Assert.That(() => new HandGrab().ReleaseAfterLost = double.PositiveInfinity, Throws.InstanceOf<ArgumentOutOfRangeException>()
                .With.Message.Contains("ReleaseAfterLost must be finite and >= 0"));
        }

        [Test]
        public void ThePinchSettingsAcceptTheirWholeDocumentedRangesAndNothingOutside()
        {
            // CloseAt in (0, 1] and not below OpenBelow; OpenBelow in (0, CloseAt]; OpenAfter finite and >= 0.
            var pinch = new PinchDetector();
            Assert.That(() => pinch.CloseAt = 0, Throws.InstanceOf<ArgumentOutOfRangeException>().With.Property("ParamName").EqualTo("CloseAt"));
            Assert.That(() => pinch.CloseAt = pinch.OpenBelow / 2, Throws.InstanceOf<ArgumentOutOfRangeException>().With.Property("ParamName").EqualTo("CloseAt"), "below OpenBelow");
            Assert.That(() => pinch.OpenBelow = 0, Throws.InstanceOf<ArgumentOutOfRangeException>().With.Property("ParamName").EqualTo("OpenBelow"));
            Assert.That(() => pinch.OpenBelow = (pinch.CloseAt + 1) / 2, Throws.InstanceOf<ArgumentOutOfRangeException>().With.Property("ParamName").EqualTo("OpenBelow"), "above CloseAt");
            pinch.CloseAt = 1;
            Assert.That(pinch.CloseAt, Is.EqualTo(1), "1 is in (0, 1]");
            pinch.OpenBelow = 1;
            Assert.That(pinch.OpenBelow, Is.EqualTo(1), "OpenBelow may equal CloseAt");
            pinch.OpenBelow = 0.25;
            pinch.CloseAt = 0.75;
            Assert.That(pinch.CloseAt, Is.EqualTo(0.75));
            pinch.CloseAt = 0.25;
            Assert.That(pinch.CloseAt, Is.EqualTo(0.25), "CloseAt may equal OpenBelow");
            pinch.OpenAfter = 0;
            Assert.That(pinch.OpenAfter, Is.EqualTo(0), "OpenAfter may be 0");
        }

        [Test]
        public void ThePinchClosesOnReachingCloseAtAndStaysClosedAtOpenBelow()
        {
            var pinch = new PinchDetector { OpenBelow = 0.5, CloseAt = 0.75, OpenAfter = 0 };
            pinch.Update(true, 0.75, 0.125);
            Assert.That(pinch.IsPinching && pinch.Began, Is.True, "the strength reached CloseAt");
            for (int i = 0; i < 10; i++) pinch.Update(true, 0.5, 0.125);
            Assert.That(pinch.IsPinching, Is.True, "0.5 is not below OpenBelow");
            pinch.Update(true, 1, 0.125);
            Assert.That(pinch.IsPinching, Is.True, "a closed strength never opens the pinch, even with OpenAfter 0");
            pinch.Update(true, 0.25, 0.125);
            Assert.That(pinch.IsPinching, Is.False, "below OpenBelow with OpenAfter 0");
        }

        [Test]
        public void ThePinchOpensAfterExactlyOpenAfterBelowOpenBelowAndBadFrameTimesCountForNothing()
        {
            // Frames of 1/32 s (exact in binary, under LongestCountedFrame): OpenAfter 0.25 s is 8 of them.
            const double frame = 1.0 / 32;
            var pinch = new PinchDetector { OpenAfter = 0.25 };
            pinch.Update(true, 1, frame);
            for (int i = 0; i < 7; i++) pinch.Update(true, 0, frame);
            Assert.That(pinch.IsPinching, Is.True, "7/32 s of 0.25");
            pinch.Update(true, 0, frame);
            Assert.That(pinch.IsPinching, Is.False, "stayed below OpenBelow for OpenAfter seconds");

            pinch.Update(true, 1, frame);
            pinch.Update(true, 0, double.PositiveInfinity);
            Assert.That(pinch.IsPinching, Is.True, "an infinite frame is not a long open hand");
            pinch.Update(true, 0, -1);
            for (int i = 0; i < 8; i++) pinch.Update(true, 0, frame);
            Assert.That(pinch.IsPinching, Is.False, "a negative frame does not delay the opening");
        }

        /// <summary>
        /// One long frame (a hitch, the first frame after the headset wakes) is one frame of evidence: with the pinch flag
        /// dropped in it, it counted in full and opened the pinch (the object fell out of the hand after a stutter). It counts
        /// as <see cref="PinchDetector.LongestCountedFrame"/> at most; frames of a 30 Hz app still count in full.
        /// </summary>
        [Test]
        public void OneLongFrameWithTheFlagDroppedDoesNotOpenThePinch()
        {
            var pinch = new PinchDetector();
            pinch.Update(true, 1, 0.011);
            pinch.Update(true, 0, 0.1);
            Assert.That(pinch.IsPinching, Is.True, "a 100 ms hitch");
            pinch.Update(true, 1, 0.011);
            pinch.Update(true, 0, 30);
            Assert.That(pinch.IsPinching, Is.True, "30 s asleep");
            pinch.Update(true, 0, 1.0 / 30);
            Assert.That(pinch.IsPinching, Is.False, "two frames of a 30 Hz app: 67 ms of 50");
        }

        [Test]
        public void OneLongUntrackedFrameDoesNotReleaseTheObject()
        {
            var scene = new Driver();
            HandGrab grab = Holding(scene);
            grab.Tick(false, 0, 30, scene); // the first frame after waking, before the hand is tracked again
            Assert.That(grab.IsHolding, Is.True);
            Assert.That(grab.LostFor, Is.EqualTo(PinchDetector.LongestCountedFrame));
            grab.Tick(true, 1, 0.011, scene);
            Assert.That(grab.IsHolding, Is.True);
            for (int i = 0; i < 29; i++) grab.Tick(false, 0, 1.0 / 30, scene);
            Assert.That(grab.IsHolding, Is.True, "29 frames at 30 Hz: under the second");
            grab.Tick(false, 0, 1.0 / 30, scene);
            grab.Tick(false, 0, 1.0 / 30, scene);
            Assert.That(grab.IsHolding, Is.False, "just over a second untracked at 30 Hz still lets go");
        }

        [Test]
        public void AResetPinchIsOpenAndHasNotBegun()
        {
            var pinch = new PinchDetector();
            pinch.Update(true, 1, 0.01);
            Assert.That(pinch.IsPinching && pinch.Began, Is.True);
            pinch.Reset();
            Assert.That(pinch.IsPinching, Is.False);
            Assert.That(pinch.Began, Is.False);
        }

        sealed class Driver : IGrabDriver
        {
            public bool Held = true;
            public int Grabs, Follows, Releases;
            public bool TryGrab() { Grabs++; return true; }
            public bool IsStillHeld => Held;
            public bool BrokeAway => false;
            public void Follow(bool tracked) => Follows++;
            public void Release() => Releases++;
        }

        static HandGrab Holding(Driver scene)
        {
            var grab = new HandGrab();
            grab.Tick(true, 1, 0.125, scene);
            Assert.That(grab.IsHolding, Is.True);
            return grab;
        }

        [Test]
        public void ReleaseAfterLostAcceptsZeroAndAnyFinitePositiveValue()
        {
            var grab = new HandGrab();
            grab.ReleaseAfterLost = 0;
            Assert.That(grab.ReleaseAfterLost, Is.EqualTo(0), "finite and >= 0");
            grab.ReleaseAfterLost = 0.5;
            Assert.That(grab.ReleaseAfterLost, Is.EqualTo(0.5));
            Assert.That(() => grab.ReleaseAfterLost = -0.5, Throws.InstanceOf<ArgumentOutOfRangeException>().With.Property("ParamName").EqualTo("ReleaseAfterLost"));
        }

        [Test]
        public void ALostHandReleasesAfterExactlyReleaseAfterLostAndBadFrameTimesCountForNothing()
        {
            var scene = new Driver();
            HandGrab grab = Holding(scene);
            grab.ReleaseAfterLost = 0.25;
            grab.Tick(false, 0, -1, scene);
            grab.Tick(false, 0, double.PositiveInfinity, scene);
            Assert.That(grab.LostFor, Is.EqualTo(0), "negative and infinite frames are no time lost");
            for (int i = 0; i < 7; i++) grab.Tick(false, 0, 1.0 / 32, scene); // exact in binary, under LongestCountedFrame
            Assert.That(grab.IsHolding, Is.True);
            grab.Tick(false, 0, 1.0 / 32, scene);
            Assert.That(grab.IsHolding, Is.False, "lost for ReleaseAfterLost seconds");
            Assert.That(grab.LastEnd, Is.EqualTo(GrabEnd.TrackingLost));
        }

        [Test]
        public void AnObjectGoneElsewhereIsNeitherFollowedNorReleasedAgain()
        {
            var scene = new Driver();
            HandGrab grab = Holding(scene);
            scene.Held = false;
            grab.Tick(true, 1, 0.125, scene);
            Assert.That(grab.LastEnd, Is.EqualTo(GrabEnd.Elsewhere));
            Assert.That(scene.Follows, Is.EqualTo(0));
            Assert.That(scene.Releases, Is.EqualTo(0), "it was released elsewhere");
        }

        [Test]
        public void ReleaseEndsAHoldOnceAndDoesNothingWhenIdle()
        {
            var scene = new Driver();
            var idle = new HandGrab();
            idle.Release(scene);
            Assert.That(scene.Releases, Is.EqualTo(0), "nothing held");
            Assert.That(idle.LastEnd, Is.EqualTo(GrabEnd.None));
            HandGrab grab = Holding(scene);
            grab.Release(scene);
            Assert.That(grab.IsHolding, Is.False);
            Assert.That(grab.LastEnd, Is.EqualTo(GrabEnd.Called));
            Assert.That(scene.Releases, Is.EqualTo(1));
        }

        sealed class Points : IGrabCandidates
        {
            public Vector3d[] At;
            public int[] Hands;
            public int Count => At.Length;
            public Vector3d ClosestPoint(int index, Vector3d hand) => At[index];
            public int HandsOn(int index) => Hands == null ? 0 : Hands[index];
        }

        [Test]
        public void TheNearestIsTheFirstOnATieAndReachIsInclusiveEvenAtZero()
        {
            var hand = new Vector3d(1, 1, 1);
            var tie = new Points { At = new[] { hand + new Vector3d(0.5, 0, 0), hand + new Vector3d(0, 0, -0.5), hand + new Vector3d(0, 0.5, 0) } };
            Assert.That(GrabSelection.Nearest(hand, 0.5, 2, tie), Is.EqualTo(0), "three at exactly the reach: the first");
            Assert.That(GrabSelection.Nearest(hand, 1, 2, tie), Is.EqualTo(0), "three equally near: the first");
            tie.Hands = new[] { 2, 0, 0 };
            Assert.That(GrabSelection.Nearest(hand, 1, 2, tie), Is.EqualTo(1), "the first is full: the next of the tie");
            var touching = new Points { At = new[] { hand + new Vector3d(0.25, 0, 0), hand } };
            Assert.That(GrabSelection.Nearest(hand, 0, 2, touching), Is.EqualTo(1), "reach 0 takes what the hand touches");
        }

        [Test]
        public void ANegativeReachNoCandidatesOrAnInfinitePointGrabNothing()
        {
            var hand = new Vector3d(1, 1, 1);
            var one = new Points { At = new[] { hand + new Vector3d(0.01, 0, 0) } };
            Assert.That(GrabSelection.Nearest(hand, -0.06, 2, one), Is.EqualTo(-1), "nothing is within a negative reach");
            Assert.That(GrabSelection.Nearest(hand, 0.06, 2, null), Is.EqualTo(-1));
            var infinite = new Points { At = new[] { new Vector3d(double.PositiveInfinity, 0, 0) } };
            Assert.That(GrabSelection.Nearest(hand, double.PositiveInfinity, 2, infinite), Is.EqualTo(-1), "an infinite point is no point, even in unlimited reach");
        }

        [Test]
        public void ThePinchTakesTheNearestObjectInReachAndNothingOutOfReach()
        {
            var scene = new BoxScene();
            BoxScene.Box near = scene.Add(Table);
            BoxScene.Box far = scene.Add(Table + new Vector3d(0.12, 0, 0));
            Assert.That(GrabSelection.Nearest(Table + new Vector3d(0.03, 0.05, 0), 0.06, 2, scene), Is.EqualTo(0));
            Assert.That(GrabSelection.Nearest(Table + new Vector3d(0.09, 0.05, 0), 0.06, 2, scene), Is.EqualTo(1));
            Assert.That(GrabSelection.Nearest(Table + new Vector3d(0, 0.5, 0), 0.06, 2, scene), Is.EqualTo(-1));
            Assert.That(GrabSelection.Nearest(Table + new Vector3d(0, 0.11, 0), 0.06, 2, scene), Is.EqualTo(0), "6 cm above the top face: reach is inclusive");
            Assert.That(GrabSelection.Nearest(Vector3d.NaN, 0.06, 2, scene), Is.EqualTo(-1));
            Assert.That(near.Hold.Begin(7, Table, double.NaN, near.Position, near.Position.Y), Is.True);
            Assert.That(near.Hold.Begin(8, Table, double.NaN, near.Position, near.Position.Y), Is.True);
            Assert.That(GrabSelection.Nearest(Table + new Vector3d(0.03, 0.05, 0), 0.06, 2, scene), Is.EqualTo(1), "two hands fill the near box");
            Assert.That(far.Hold.IsHeld, Is.False);
        }

        [Test]
        public void APinchNearABoxLiftsItAndOpeningTheHandDropsIt()
        {
            var scene = new BoxScene();
            BoxScene.Box box = scene.Add(Table, 2);
            var grab = new ScriptedGrab(scene);
            Vector3d start = Table + new Vector3d(0, 0.05, 0);
            var hand = new QuestHand { Path = t => QuestHand.Lift(start, 0.3, 0.3, 0.8)(t) + new Vector3d(0.1 * QuestHand.MinimumJerk((t - 0.3) / 0.8), 0, 0), Pinch = t => t < 1.6 ? 1 : 0 };
            foreach (HandFrame f in hand.Render(2.0)) grab.Tick(in f);
            Assert.That(grab.Grab.LastEnd, Is.EqualTo(GrabEnd.Opened));
            Assert.That(box.Hold.IsHeld, Is.False);
            Assert.That(box.Position.Y - Table.Y, Is.GreaterThan(0.02).And.LessThan(0.3 * 0.6), "2 kg lags the 0.3 m lift");
            Assert.That(box.Position.X, Is.EqualTo(0.1).Within(1e-9), "x followed the hand");
        }

        [Test]
        public void APinchClosedAwayFromEveryObjectGrabsNothingWhenItArrives()
        {
            var scene = new BoxScene();
            BoxScene.Box box = scene.Add(Table);
            var grab = new ScriptedGrab(scene);
            Vector3d away = Table + new Vector3d(0.4, 0.05, 0);
            var hand = new QuestHand { Path = t => away + (Table + new Vector3d(0, 0.05, 0) - away) * QuestHand.MinimumJerk(t / 0.5) };
            foreach (HandFrame f in hand.Render(1.0)) grab.Tick(in f);
            Assert.That(box.Hold.IsHeld, Is.False, "a grab needs the pinch to close in reach");
        }

        [Test]
        public void AShortLossHoldsTheObjectStillAndALongOneReleasesIt()
        {
            var scene = new BoxScene();
            BoxScene.Box box = scene.Add(Table, 0.5);
            var grab = new ScriptedGrab(scene);
            var hand = new QuestHand { Path = t => Table + new Vector3d(0, 0.05, 0) }.Lose(0.5, 0.5).Lose(1.5, 1.2);
            HandFrame[] frames = hand.Render(3.0);
            double yBefore = double.NaN;
            foreach (HandFrame f in frames)
            {
                grab.Tick(in f);
                if (f.Time < 0.5) yBefore = box.Position.Y;
                if (f.Time >= 0.5 && f.Time < 1.0) Assert.That(box.Position.Y, Is.EqualTo(yBefore), "held still while lost");
                if (f.Time > 1.0 && f.Time < 1.5) Assert.That(grab.Held, Is.SameAs(box), "held through a 0.5 s loss");
                if (f.Time > 1.5 + 1.0 + 0.02) Assert.That(grab.Held, Is.Null, "released after 1 s lost");
            }
            Assert.That(grab.Grab.LastEnd, Is.EqualTo(GrabEnd.TrackingLost));
            Assert.That(grab.LostFollows, Is.GreaterThan(0));
        }

        [Test]
        public void ABreakAwayReportedByTheSolverReleasesAndTheSamePinchDoesNotRegrab()
        {
            var scene = new BoxScene();
            BoxScene.Box box = scene.Add(Table, 5);
            var grab = new ScriptedGrab(scene);
            var hand = new QuestHand { Path = t => Table + new Vector3d(0, 0.05, 0) };
            foreach (HandFrame f in hand.Render(1.0))
            {
                grab.BreakAway = f.Time > 0.5;
                grab.Tick(in f);
            }
            Assert.That(grab.Grab.LastEnd, Is.EqualTo(GrabEnd.BrokeAway));
            Assert.That(box.Hold.IsHeld, Is.False);
        }

        [Test]
        public void AnObjectReleasedElsewhereEndsTheHandsHold()
        {
            var scene = new BoxScene();
            BoxScene.Box box = scene.Add(Table);
            var grab = new ScriptedGrab(scene);
            HandFrame[] frames = new QuestHand { Path = t => Table + new Vector3d(0, 0.05, 0) }.Render(0.5);
            for (int i = 0; i < 20; i++) grab.Tick(in frames[i]);
            box.Hold.EndAll();
            grab.Tick(in frames[20]);
            Assert.That(grab.Grab.IsHolding, Is.False);
            Assert.That(grab.Grab.LastEnd, Is.EqualTo(GrabEnd.Elsewhere));
        }

        /// <summary>Random Quest hands (pinch, flicker, losses, glitches): the grab's bookkeeping always agrees with the object's.</summary>
        [Test]
        public void OverRandomHandsTheGrabAndTheObjectAlwaysAgree([Range(1, 300)] int seed)
        {
            var random = new Random(seed);
            var scene = new BoxScene();
            BoxScene.Box box = scene.Add(Table, 0.01 + 5 * random.NextDouble());
            var grab = new ScriptedGrab(scene);
            double open = 0.5 + random.NextDouble(), close = 0.2 * random.NextDouble();
            var hand = new QuestHand
            {
                Seed = seed,
                FrameRate = new[] { 72.0, 90, 120 }[seed % 3],
                Path = QuestHand.Lift(Table + new Vector3d(0.03 * random.NextDouble(), 0.05, 0), 0.4 * random.NextDouble(), 0.2, 0.3 + random.NextDouble()),
                Pinch = t => t > close && t < close + open ? 1 : 0,
            };
            if (random.NextDouble() < 0.5) hand.Lose(0.1 + random.NextDouble(), random.NextDouble() * 1.5);
            if (random.NextDouble() < 0.5) hand.Glitch(0.2 + random.NextDouble());
            int grabs = 0;
            bool was = false;
            foreach (HandFrame f in hand.Render(2.5))
            {
                grab.Tick(in f);
                bool holding = grab.Grab.IsHolding;
                if (holding && !was) grabs++;
                was = holding;
                Assert.That(box.Hold.IsHeld, Is.EqualTo(holding), "t = " + f.Time);
                Assert.That(box.Hold.HandCount, Is.EqualTo(holding ? 1 : 0));
                Assert.That(box.Position.IsFinite, Is.True);
                Assert.That(box.Position.Y, Is.GreaterThanOrEqualTo(0), "below the floor");
            }
            Assert.That(grabs, Is.LessThanOrEqualTo(1), "one pinch, one grab");
            Assert.That(box.Hold.IsHeld, Is.False, "every hold ended: the pinch opened or the hand was lost");
        }

        [Test]
        public void TwoHandsHoldOneObjectUntilTheLastLetsGo()
        {
            var scene = new BoxScene();
            BoxScene.Box box = scene.Add(Table, 1);
            var left = new ScriptedGrab(scene, 1);
            var right = new ScriptedGrab(scene, 2);
            Vector3d l0 = Table + new Vector3d(-0.04, 0.05, 0), r0 = Table + new Vector3d(0.04, 0.05, 0);
            HandFrame[] lf = new QuestHand { Seed = 1, Path = QuestHand.Lift(l0, 0.2, 0.3, 0.6), Pinch = t => t < 1.2 ? 1 : 0 }.Render(2);
            HandFrame[] rf = new QuestHand { Seed = 2, Path = t => QuestHand.Lift(r0, 0.2, 0.3, 0.6)(t) + new Vector3d(0, 0, 0), Pinch = t => t > 0.1 && t < 1.6 ? 1 : 0 }.Render(2);
            int began = 0, ended = 0;
            box.Hold.Began += () => began++;
            box.Hold.Ended += () => ended++;
            for (int i = 0; i < lf.Length; i++)
            {
                left.Tick(in lf[i]);
                right.Tick(in rf[i]);
                double t = lf[i].Time;
                if (t > 0.2 && t < 1.2) Assert.That(box.Hold.HandCount, Is.EqualTo(2), "t = " + t);
                if (t > 1.3 && t < 1.6) Assert.That(box.Hold.HandCount, Is.EqualTo(1), "t = " + t);
            }
            Assert.That(began, Is.EqualTo(1), "the second hand joins the hold");
            Assert.That(ended, Is.EqualTo(1), "the hold ends once, with the last hand");
            Assert.That(box.Hold.IsHeld, Is.False);
        }

        /// <summary>Hands join, leave, lose and regain tracking: the point the solver follows never jumps.</summary>
        [Test]
        public void TheTwoHandPointNeverJumps([Range(1, 200)] int seed)
        {
            var random = new Random(seed);
            var box = new BoxScene.Box(Table, 1);
            HeldObject hold = box.Hold;
            var pos = new[] { Table + new Vector3d(-0.1, 0, 0), Table + new Vector3d(0.1, 0.05, 0) };
            bool[] on = { false, false };
            bool[] tracked = { true, true };
            Vector3d last = Vector3d.NaN;
            hold.Began += () => last = Vector3d.NaN; // a new hold starts where its hand is
            for (int frame = 0; frame < 600; frame++)
            {
                double maxMove = 0;
                for (int h = 0; h < 2; h++)
                {
                    Vector3d d = new Vector3d(random.NextDouble() - 0.5, random.NextDouble() - 0.5, random.NextDouble() - 0.5) * 0.01;
                    pos[h] += d;
                    maxMove = Math.Max(maxMove, d.Length);
                    if (random.NextDouble() < 0.02) tracked[h] = !tracked[h];
                    if (random.NextDouble() < 0.01)
                    {
                        if (on[h]) hold.End(h + 1);
                        else hold.Begin(h + 1, pos[h], double.NaN, box.Position, box.Position.Y);
                        on[h] = hold.Holds(h + 1);
                    }
                }
                bool followedLast = hold.IsHeld && hold.Solver3D.FollowedHands > 0;
                for (int h = 0; h < 2; h++)
                    if (on[h]) hold.Step(h + 1, tracked[h] ? pos[h] : Vector3d.NaN, tracked[h], true, double.NaN, 1 / 90.0);
                if (!hold.IsHeld) { last = Vector3d.NaN; continue; }
                Vector3d p = hold.HandPoint;
                // When no hand was followed (every hand lost, or waiting for steady tracking after a loss), the point follows
                // the hands' motion during their loss, as one hand alone does; otherwise it moves no more than the hands did,
                // also when a hand lets go and another takes its place.
                bool followedBefore = followedLast;
                if (last.IsFinite && followedBefore) Assert.That((p - last).Length, Is.LessThanOrEqualTo(maxMove + 1e-12), "frame " + frame);
                last = p;
            }
        }

        [Test]
        public void OneHandsPointIsTheHandAndTheSolverSeesWhatItWouldSeeAlone()
        {
            var box = new BoxScene.Box(Table, 2);
            WeightSolver alone = Run.Solver(2, NamedProfiles.Paper, 0.5);
            HandFrame[] frames = new QuestHand { Path = QuestHand.Lift(Table, 0.3, 0.2, 0.8) }.Lose(0.6, 0.2).Render(1.5);
            box.Hold.Begin(1, Table, double.NaN, Table, Table.Y);
            alone.BeginHold(Table.Y, Table.Y);
            foreach (HandFrame f in frames)
            {
                double y = box.Hold.Step(1, f.Position, f.Tracked, f.HighConfidence, double.NaN, f.Dt);
                var sample = new HandSample(f.Tracked ? f.Position.Y : double.NaN, f.Tracked, f.Tracked && f.HighConfidence);
                Assert.That(y, Is.EqualTo(alone.Step(in sample, f.Dt)), "t = " + f.Time);
                if (f.Tracked) Assert.That(box.Hold.HandPoint, Is.EqualTo(f.Position));
            }
        }

        [Test]
        public void AnUnconfiguredObjectCannotBeHeldAndStepsAnswerNaN()
        {
            var hold = new HeldObject(new BoxScene.Box(Table, 1));
            Assert.That(hold.Begin(1, Table, double.NaN, Table, Table.Y), Is.False);
            Assert.That(double.IsNaN(hold.Step(1, Table, true, true, double.NaN, 0.011)), Is.True);
            Assert.That(() => new HeldObject(null), Throws.ArgumentNullException);
        }

        [Test]
        public void StepsOfOneAndTwoHandsAllocateNothing()
        {
            var box = new BoxScene.Box(Table, 1);
            box.Hold.Begin(1, Table, double.NaN, Table, Table.Y);
            box.Hold.Begin(2, Table + new Vector3d(0.1, 0, 0), double.NaN, Table, Table.Y);
            var grab = new HandGrab();
            var drawing = new HandDrawing();
            var scene = new BoxScene();
            Allocation.AssertNone(n => Frames(box.Hold, grab, drawing, scene, n), "frames");
        }

        static void Frames(HeldObject hold, HandGrab grab, HandDrawing drawing, BoxScene scene, int n)
        {
            for (int i = 0; i < n; i++)
            {
                var p = Table + new Vector3d(0, 0.001 * (i % 100), 0);
                hold.Step(1, p, i % 7 != 0, true, double.NaN, 0.011);
                hold.Step(2, p, true, true, double.NaN, 0.011);
                hold.TrackObject(p);
                grab.Tick(true, i % 2, 0.011, null);
                drawing.Update(HandDrawingMode.HandOnObject, i % 50 < 25, new Vector3d(0, -0.05, 0), 0.011);
                GrabSelection.Nearest(p, 0.06, 2, scene);
            }
        }
    }
}
