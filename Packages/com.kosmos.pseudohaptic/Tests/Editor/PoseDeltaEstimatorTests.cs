using NUnit.Framework;
using static Kosmos.PseudoHaptic.Tests.EstimatorFrame;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>
    /// The pose-delta estimator on its own, frame by frame: what a new pose is, the interval its speed is measured
    /// over (the poses' clock, else the frames' time since the last pose, at least a 60 Hz period), when it reads the
    /// hand as still, what it follows across a gap (everything: a loss, a long frame, a clock that steps back), and which
    /// pose it refuses (one no hand could have reached in the frames' time since the last one it accepted).
    /// </summary>
    public class PoseDeltaEstimatorTests
    {
        static PoseDeltaEstimator Started(double y = 1.0, double poseTime = 0)
        {
            var e = new PoseDeltaEstimator();
            e.Reset(y, poseTime);
            return e;
        }

        [Test]
        public void ANewPoseIsMeasuredOverThePosesOwnClock()
        {
            var e = Started(1.0, 10.0);
            var f = Frame(ref e, 1.02, 10.04, 1 / 90.0); // the frame is 11 ms, the poses 40 ms apart
            Assert.That(f.Reanchored, Is.False);
            Assert.That(f.HandBefore, Is.EqualTo(1.0));
            Assert.That(f.HandAfter, Is.EqualTo(1.02));
            Assert.That(f.HandDelta, Is.EqualTo(1.02 - 1.0));
            Assert.That(f.MotionInterval, Is.EqualTo(10.04 - 10.0));
            Assert.That(f.HandSpeed, Is.EqualTo((1.02 - 1.0) / (10.04 - 10.0)));
            Assert.That(e.Speed, Is.EqualTo(f.HandSpeed));
            Assert.That(e.HandY, Is.EqualTo(1.02));
        }

        [Test]
        public void WithoutTimestampsItIsMeasuredOverTheFramesSinceTheLastPoseAtLeastASixtiethOfASecond()
        {
            var e = Started(1.0, double.NaN);
            var same = Frame(ref e, 1.0, double.NaN, 0.01);
            Assert.That(same.HandDelta, Is.EqualTo(0));
            Assert.That(same.MotionInterval, Is.EqualTo(0), "the same pose again is no motion");
            Assert.That(same.HandAfter, Is.EqualTo(1.0));
            var next = Frame(ref e, 1.03, double.NaN, 0.02);
            Assert.That(next.MotionInterval, Is.EqualTo(0.03).Within(1e-15), "both frames since the last new pose");
            Assert.That(next.HandSpeed, Is.EqualTo(next.HandDelta / next.MotionInterval));
            var quick = Frame(ref e, 1.04, double.NaN, 0.004);
            Assert.That(quick.MotionInterval, Is.EqualTo(1 / 60.0), "two poses in one short frame: a 60 Hz period");
        }

        [Test]
        public void AStuckTimestampWithANewValueIsStillANewPose()
        {
            var e = Started(1.0, 5.0);
            Frame(ref e, 1.0, 5.0, 0.02);
            var f = Frame(ref e, 1.01, 5.0, 0.02);
            Assert.That(f.HandDelta, Is.EqualTo(1.01 - 1.0), "followed");
            Assert.That(f.MotionInterval, Is.EqualTo(0.04).Within(1e-15), "over the frames since the last pose");
            var repeated = Frame(ref e, 1.01, 5.0, 0.02);
            Assert.That(repeated.MotionInterval, Is.EqualTo(0), "the same value and timestamp: not a new pose");
            var newTime = Frame(ref e, 1.01, 5.1, 0.02);
            Assert.That(newTime.MotionInterval, Is.EqualTo(5.1 - 5.0).Within(1e-12), "a new timestamp is a new pose, even at the same height");
            Assert.That(newTime.HandDelta, Is.EqualTo(0));
        }

        [Test]
        public void TheSpeedReadsZeroWhenNoPoseCameForATenthOfASecondOrTrackingIsLost()
        {
            var e = Started(1.0, 0);
            Frame(ref e, 1.01, 1 / 30.0, 1 / 30.0);
            Assert.That(e.Speed, Is.EqualTo(0.01 * 30).Within(1e-12));
            Frame(ref e, 1.01, 1 / 30.0, 0.09);
            Assert.That(e.Speed, Is.EqualTo(0.01 * 30).Within(1e-12), "90 ms without a pose: still the last speed");
            Frame(ref e, 1.01, 1 / 30.0, 0.02);
            Assert.That(e.Speed, Is.EqualTo(0), "110 ms: the hand is still");

            var lost = Started(1.0, 0);
            Frame(ref lost, 1.01, 1 / 30.0, 1 / 30.0);
            Frame(ref lost, double.NaN, double.NaN, 0.001, usable: false);
            Assert.That(lost.Speed, Is.EqualTo(0), "lost");
            var f = Frame(ref lost, 1.0, double.NaN, 0.001, usable: false);
            Assert.That(f.HandAfter, Is.EqualTo(1.01), "a lost frame keeps the last pose");
            Assert.That(f.HandDelta, Is.EqualTo(0));
        }

        [TestCase(0.33, false)]  // a 90 Hz pose step is judged over a 30 Hz period: 10 m/s × 1/30 s = 0.333 m
        [TestCase(0.34, true)]
        public void AStepFasterThanAnyHandIsRefusedJudgedOverAtLeastAThirtiethOfASecond(double step, bool refused)
        {
            var e = Started(1.0, 0);
            var f = Frame(ref e, 1.0 + step, 1 / 90.0, 1 / 90.0);
            Assert.That(f.Usable, Is.EqualTo(!refused));
            Assert.That(f.HandDelta, Is.EqualTo(refused ? 0 : step).Within(1e-15));
            Assert.That(f.HandAfter, Is.EqualTo(refused ? 1.0 : 1.0 + step), "a refused pose is not followed");
            Assert.That(e.Speed, Is.EqualTo(refused ? 0 : step * 90).Within(1e-9));
        }

        [Test]
        public void ARefusedPoseSeenAgainIsTheHandAndAGlitchAfterALossDoesNotLockItOut()
        {
            // A hand really is 0.5 m away: refused once, followed at the next pose that agrees with it.
            var moved = Started(1.0, 0);
            Assert.That(Frame(ref moved, 1.5, 1 / 90.0, 1 / 90.0).Usable, Is.False);
            var seen = Frame(ref moved, 1.51, 2 / 90.0, 1 / 90.0);
            Assert.That(seen.Usable, Is.True, "seen twice in a row at its new place");
            Assert.That(seen.HandDelta, Is.EqualTo(0.51).Within(1e-12));
            Assert.That(seen.Bridged, Is.True, "the refused frame was a gap: the motion is followed in full");

            // After a loss a glitched pose is accepted (a hand lost for a second may be anywhere); the real hand, back next
            // pose, is out of reach of the glitch but within reach of the pose before it: followed.
            var glitched = Started(1.0, 0);
            Frame(ref glitched, double.NaN, double.NaN, 1.0, usable: false);
            Assert.That(Frame(ref glitched, 1.9, 1.0, 0.01).Usable, Is.True);
            var real = Frame(ref glitched, 1.02, 1.0 + 1 / 30.0, 1 / 30.0);
            Assert.That(real.Usable, Is.True);
            Assert.That(real.HandAfter, Is.EqualTo(1.02));
        }

        [TestCase(0.0, 0.49, false)] // after a still spell, at most 50 ms count: 10 m/s × 0.05 s = 0.5 m
        [TestCase(0.0, 0.51, true)]
        [TestCase(0.1, 1.45, false)] // after a 0.1 s loss, 0.15 s count: 1.5 m
        [TestCase(0.1, 1.55, true)]
        public void AfterAStillSpellOnlyFiftyMillisecondsCountPlusTheTimeTrackingWasLost(double lostFor, double step, bool refused)
        {
            var e = Started(1.0, 0);
            for (int i = 0; i < 10; i++) Frame(ref e, 1.0, 0, 0.01); // 100 ms of frames without a new pose
            if (lostFor > 0) Frame(ref e, double.NaN, double.NaN, lostFor, usable: false);
            var f = Frame(ref e, 1.0 + step, 0.2, 0.01);
            Assert.That(f.Usable, Is.EqualTo(!refused));
            if (!refused) Assert.That(f.HandDelta, Is.EqualTo(step).Within(1e-12), "caught up over the loss");
            if (!refused) Assert.That(f.Bridged, Is.EqualTo(lostFor > 0));
        }

        [Test]
        public void ALongFrameALongLossOrAClockThatStepsBackIsFollowedInFull()
        {
            var longFrame = Started(1.0, 0);
            var hitch = Frame(ref longFrame, 1.6, 10.0, 10.0);
            Assert.That(hitch.HandDelta, Is.EqualTo(0.6).Within(1e-12), "a 10 s frame: the hand may have gone anywhere a hand goes in 10 s");
            Assert.That(hitch.MotionInterval, Is.EqualTo(10.0).Within(1e-12));

            var longLoss = Started(1.0, 0);
            for (int i = 0; i < 30; i++) Frame(ref longLoss, double.NaN, double.NaN, 0.1, usable: false);
            var back = Frame(ref longLoss, 1.4, 3.01, 0.01);
            Assert.That(back.Bridged, Is.True, "lost for 3 s");
            Assert.That(back.HandDelta, Is.EqualTo(0.4).Within(1e-12), "the hand's motion across the loss is followed");
            Assert.That(back.MotionInterval, Is.EqualTo(3.01).Within(1e-12));

            var stepBack = Started(1.0, 2.0);
            var f = Frame(ref stepBack, 1.001, 1.9, 0.01);
            Assert.That(f.Usable, Is.True, "the pose clock stepped back: still the hand");
            Assert.That(f.HandDelta, Is.EqualTo(0.001).Within(1e-15));
            Assert.That(f.MotionInterval, Is.EqualTo(1 / 60.0).Within(1e-15), "measured over the frames, at least a 60 Hz period");
        }

        [Test]
        public void WithoutAStartingPoseTheFirstUsableOneAnchors()
        {
            var e = Started(double.NaN, double.NaN);
            Assert.That(e.HasPose, Is.False);
            var f = Frame(ref e, 1.2, 0.5, 0.01);
            Assert.That(f.Reanchored, Is.True);
            Assert.That(e.HasPose, Is.True);
            Assert.That(e.HandY, Is.EqualTo(1.2));
            var next = Frame(ref e, 1.21, 0.52, 0.02);
            Assert.That(next.Reanchored, Is.False, "then it follows");
            Assert.That(next.MotionInterval, Is.EqualTo(0.52 - 0.5).Within(1e-15));
        }

        [Test]
        public void WithoutAStartingPoseTheHandIsTakenToBeWhereTheCallerSays()
        {
            var e = new PoseDeltaEstimator();
            e.Reset(double.NaN, double.NaN, 0.7);
            Assert.That(e.HasPose, Is.False);
            Assert.That(e.HandY, Is.EqualTo(0.7));
            var lost = Frame(ref e, double.NaN, double.NaN, 0.01, usable: false);
            Assert.That(lost.HandBefore, Is.EqualTo(0.7));
            Assert.That(lost.HandAfter, Is.EqualTo(0.7), "no motion toward a hand never seen");
            var f = Frame(ref e, 0.72, 0.5, 0.01);
            Assert.That(f.Reanchored, Is.True, "the first pose anchors even 2 cm away");
            Assert.That(f.HandDelta, Is.EqualTo(0));
        }

        [TestCase(0.39, false)] // 40 ms since the last pose (between the 1/30 s floor and the 50 ms ceiling): 10 m/s × 0.04 s = 0.4 m
        [TestCase(0.41, true)]
        public void BetweenAThirtiethOfASecondAndFiftyMillisecondsAStepIsJudgedOverItsOwnTime(double step, bool refused)
        {
            var e = Started(1.0, 0);
            Assert.That(Frame(ref e, 1.0 + step, 0.04, 0.04).Usable, Is.EqualTo(!refused));
        }

        [Test]
        public void AnInfinitePoseTimeIsNoTimeAtAll()
        {
            var ahead = Started(1.0, 0);
            var f = Frame(ref ahead, 1.01, double.PositiveInfinity, 1 / 30.0);
            Assert.That(f.Reanchored, Is.False);
            Assert.That(f.MotionInterval, Is.EqualTo(1 / 30.0).Within(1e-15), "measured over the frames since the last pose");
            Assert.That(f.HandSpeed, Is.EqualTo(0.01 * 30).Within(1e-9));
            var behind = Started(1.0, 0);
            var g = Frame(ref behind, 1.01, double.NegativeInfinity, 1 / 30.0);
            Assert.That(g.Reanchored, Is.False, "not a clock stepping back");
            Assert.That(g.HandDelta, Is.EqualTo(0.01).Within(1e-15));
        }

        [Test]
        public void PosesMicrosecondsApartAreMeasuredOverATenthOfAMillisecond()
        {
            var e = Started(1.0, 0);
            var f = Frame(ref e, 1.0001, 1e-6, 0.01);
            Assert.That(f.MotionInterval, Is.EqualTo(1e-4));
            Assert.That(f.HandSpeed, Is.EqualTo((1.0001 - 1.0) / 1e-4).Within(1e-9));
        }
    }
}
