using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>
    /// <see cref="Reach"/> on its own (the 3D solver's judge of whether a hand could have got to a pose, P8), for the
    /// estimation piece's mutation run (quality.md, "In pieces"): the window's floor of one 30 Hz pose period, its
    /// ceiling of 50 ms plus the time unseen, a hitch counted as unseen, the exact edge of reach, a glitch that was
    /// accepted being overruled by the pose before it, and a hand seen twice at its new place.
    /// Speeds are 10 m/s (SolverLimits' default); the floor is then 10 × 1/30 = 0.333 m, the ceiling 0.5 m.
    /// </summary>
    public class ReachTests
    {
        const double Speed = 10, Longest = 0.025;

        static Reach At(double x)
        {
            var r = new Reach();
            Assert.That(r.HasPose, Is.False);
            Assert.That(Next(ref r, x), Is.True, "the first pose is always taken");
            Assert.That(r.HasPose, Is.True);
            return r;
        }

        /// <summary>One 11 ms frame, then whether the pose at <paramref name="x"/> is taken.</summary>
        static bool Next(ref Reach r, double x)
        {
            r.Tick(0.011, Longest);
            return r.TryAccept(x, 1, 0, Speed);
        }

        [Test]
        public void AStepWithinOnePosePeriodAtFullSpeedIsTaken()
        {
            var r = At(0);
            Assert.That(Next(ref r, 0.33), Is.True, "0.33 m < 10 m/s × 1/30 s, however short the frame");
            var s = At(0);
            Assert.That(Next(ref s, 0.34), Is.False, "0.34 m is out of reach");
        }

        [Test]
        public void AllThreeAxesCount()
        {
            var r = At(0);
            r.Tick(0.011, Longest);
            Assert.That(r.TryAccept(0.2, 1.2, 0.2, Speed), Is.False, "√(3 × 0.04) = 0.35 m");
            var s = At(0);
            s.Tick(0.011, Longest);
            Assert.That(s.TryAccept(0.1, 1.1, 0.3, Speed), Is.True, "√0.11 = 0.33 m");
        }

        [Test]
        public void TheWindowGrowsWithTimeUpTo50Milliseconds()
        {
            var r = At(0);
            for (int i = 0; i < 4; i++) r.Tick(0.011, Longest);
            Assert.That(r.TryAccept(0.43, 1, 0, Speed), Is.True, "44 ms since: 0.44 m");
            var s = At(0);
            for (int i = 0; i < 100; i++) s.Tick(0.011, Longest);
            Assert.That(s.TryAccept(0.51, 1, 0, Speed), Is.False, "1.1 s of a still, seen hand: still 50 ms, 0.5 m");
            Assert.That(s.TryAccept(0.49, 1, 0, Speed), Is.True);
        }

        [Test]
        public void TimeUnseenWidensTheWindow()
        {
            var r = At(0);
            for (int i = 0; i < 50; i++) { r.Tick(0.01, Longest); r.Miss(); }
            Assert.That(r.TryAccept(4.9, 1, 0, Speed), Is.True, "0.5 s lost: 0.5 s window (no more than the time since), 5 m");
            var s = At(0);
            for (int i = 0; i < 50; i++) s.Tick(0.01, Longest);
            Assert.That(s.TryAccept(4.9, 1, 0, Speed), Is.False, "0.5 s seen: 50 ms, 0.5 m");
            var t = At(0);
            for (int i = 0; i < 50; i++) { t.Tick(0.01, Longest); t.Miss(); }
            Assert.That(t.TryAccept(5.1, 1, 0, Speed), Is.False, "beyond 5 m");
        }

        [Test]
        public void OnlyTheFramesTheHandWasMissedInCountAsUnseen()
        {
            // 0.1 s seen, then 0.05 s missed: window min(0.15, 0.05 + 0.05) = 0.1 s, 1 m; not the whole 0.15 s.
            var r = At(0);
            for (int i = 0; i < 10; i++) r.Tick(0.01, Longest);
            for (int i = 0; i < 5; i++) { r.Tick(0.01, Longest); r.Miss(); }
            Assert.That(r.TryAccept(1.2, 1, 0, Speed), Is.False);
            var s = At(0);
            for (int i = 0; i < 10; i++) s.Tick(0.01, Longest);
            for (int i = 0; i < 5; i++) { s.Tick(0.01, Longest); s.Miss(); }
            Assert.That(s.TryAccept(0.95, 1, 0, Speed), Is.True);
        }

        [Test]
        public void AHitchCountsAsUnseenBeyondTheLongestFrame()
        {
            var r = At(0);
            r.Tick(0.5, Longest);
            Assert.That(r.TryAccept(4.9, 1, 0, Speed), Is.True, "0.475 s of the 0.5 s frame unseen: window 0.5 s");
            var s = At(0);
            s.Tick(0.5, 1.0);
            Assert.That(s.TryAccept(4.9, 1, 0, Speed), Is.False, "with a longest frame of 1 s the same frame is seen: 0.5 m");
        }

        [Test]
        public void MissCountsOnlyTheFramesOwnTimeUpToTheLongestFrame()
        {
            var r = At(0);
            r.Tick(0.02, Longest);
            r.Miss();
            r.Tick(0.02, Longest);
            r.Miss();
            // since 0.04 s, lost 0.04 s: window 0.04 s, 0.4 m.
            Assert.That(r.TryAccept(0.39, 1, 0, Speed), Is.True);
            var s = At(0);
            s.Tick(0.1, Longest);
            s.Miss();
            // A 0.1 s frame: 0.075 s unseen as a hitch, and Miss adds only the 0.025 s counted: lost 0.1 s, not 0.175 s.
            Assert.That(Next(ref s, 1.1), Is.True, "window min(0.111, 0.15) = 0.111 s: 1.11 m");
            var t = At(0);
            t.Tick(0.1, Longest);
            t.Miss();
            t.Tick(0.011, Longest);
            Assert.That(t.TryAccept(1.12, 1, 0, Speed), Is.False);
        }

        [Test]
        public void TheEdgeOfReachIsWithinReach()
        {
            // Exact in binary: 8 m/s × 0.0625 s = 0.5 m.
            var r = new Reach();
            r.TryAccept(0, 0, 0, 8);
            r.Tick(0.0625, 1);
            r.Miss();
            Assert.That(r.TryAccept(0.5, 0, 0, 8), Is.True);
            var s = new Reach();
            s.TryAccept(0, 0, 0, 8);
            s.Tick(0.0625, 1);
            s.Miss();
            Assert.That(s.TryAccept(0.5000001, 0, 0, 8), Is.False);
        }

        [Test]
        public void APoseThatDiffersAlongOneAxisAloneIsJudgedLikeAnyOther()
        {
            // The shortcut for the same pose again must need all three coordinates equal: 1 m along one axis is out of reach.
            var r = new Reach();
            r.TryAccept(0, 1, 0, Speed);
            r.Tick(0.011, Longest);
            Assert.That(r.TryAccept(0, 1, 1, Speed), Is.False, "1 m along z alone");
            var s = new Reach();
            s.TryAccept(0, 1, 0, Speed);
            s.Tick(0.011, Longest);
            Assert.That(s.TryAccept(0, 2, 0, Speed), Is.False, "1 m along y alone");
            var t = new Reach();
            t.TryAccept(0, 1, 0, Speed);
            t.Tick(0.011, Longest);
            Assert.That(t.TryAccept(1, 1, 0, Speed), Is.False, "1 m along x alone");
            Assert.That(t.TryAccept(0, 1, 0, Speed), Is.True, "and the same pose again is taken");
        }

        [Test]
        public void AnAcceptedGlitchIsOverruledByThePoseBeforeIt()
        {
            var r = At(0);
            for (int i = 0; i < 200; i++) { r.Tick(0.01, Longest); r.Miss(); }
            Assert.That(r.TryAccept(3, 1, 0, Speed), Is.True, "after 2 s lost, 3 m away is reachable (the glitch)");
            Assert.That(Next(ref r, 0.1), Is.True, "out of the glitch's reach, within the pose before it");
            Assert.That(Next(ref r, 2.9), Is.True, "the glitch stays the prior pose, as its outlier did not replace it");
            Assert.That(Next(ref r, 0.2), Is.True, "so the hand near 0.1 is taken again");
        }

        [Test]
        public void AHandSeenTwiceAtItsNewPlaceIsThere()
        {
            var r = At(0);
            Assert.That(Next(ref r, 1), Is.False);
            r.Miss();
            Assert.That(Next(ref r, 1), Is.False, "the same refused pose again is not a second sighting");
            r.Miss();
            Assert.That(Next(ref r, 1.01), Is.True, "a second, different pose within reach of the refused one");
            Assert.That(Next(ref r, 0), Is.False, "the old place has no standing as a prior any more");
        }

        [Test]
        public void ASightingMustBeNearTheLastRefusedPose()
        {
            var r = At(0);
            Assert.That(Next(ref r, 1), Is.False);
            r.Miss();
            Assert.That(Next(ref r, 2), Is.False, "1 m from the refused pose is no sighting");
            r.Miss();
            Assert.That(Next(ref r, 2.01), Is.True, "but near the newest refused pose it is");
        }

        [Test]
        public void TheRefusedPosesClockStartsWhenItIsFirstSeen()
        {
            var r = At(0);
            Assert.That(Next(ref r, 1), Is.False);
            // The same refused pose three frames more: its clock is not restarted, so after 44 ms a pose 0.4 m on is
            // within its reach (0.44 m), though not within one pose period's (0.333 m) nor the last accepted pose's.
            for (int i = 0; i < 3; i++) { r.Tick(0.011, Longest); Assert.That(r.TryAccept(1, 1, 0, Speed), Is.False); }
            Assert.That(Next(ref r, 1.4), Is.True);
        }

        [Test]
        public void ThePosesBeforeTheLastHasItsOwnClock()
        {
            // 0, then −0.3 (within reach of 0), then two frames unseen: 0.4 m from 0 is within the reach of 0's 44 ms (0.44 m),
            // though not within one pose period (0.333 m) nor of −0.3: the last pose is overruled by the one before it.
            var r = At(0);
            Assert.That(Next(ref r, -0.3), Is.True);
            for (int i = 0; i < 2; i++) { r.Tick(0.011, Longest); r.Miss(); }
            Assert.That(Next(ref r, 0.4), Is.True, "0.4 m from the pose before the last, 44 ms after it");
        }

        [Test]
        public void AfterASightingThePoseBeforeItNoLongerCounts()
        {
            // 0, 0.1, then 2.0 refused and 2.01 taken as a sighting: the hand is at its new place, and a pose back near 0 is
            // out of reach of it; the pose before the sighting (0) is not a place to go back to.
            var r = At(0);
            Assert.That(Next(ref r, 0.1), Is.True);
            Assert.That(Next(ref r, 2.0), Is.False);
            Assert.That(Next(ref r, 2.01), Is.True, "seen twice at its new place");
            Assert.That(Next(ref r, 0.05), Is.False, "back near the pose before the sighting");
        }

        [Test]
        public void AnAcceptedPoseForgetsTheRefusedOne()
        {
            // 2.0 refused, then 0.1 taken: the refused pose is forgotten, so 2.01 is no sighting of it.
            var r = At(0);
            Assert.That(Next(ref r, 2.0), Is.False);
            Assert.That(Next(ref r, 0.1), Is.True);
            Assert.That(Next(ref r, 2.01), Is.False, "near a pose refused before the last accepted one");
        }

        [Test]
        public void ResetForgetsEveryPose()
        {
            var r = At(0);
            r.Reset();
            Assert.That(r.HasPose, Is.False);
            Assert.That(Next(ref r, 100), Is.True);
        }
    }
}
