using System;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>
    /// The solver's own duties, apart from the effects: where a hold begins (with a grab offset, below the floor,
    /// before the hand is tracked), its speed limit's carry limit, and its hand filter restarting wherever the hand
    /// is re-anchored or the profile changes, so nothing creeps when tracking returns.
    /// </summary>
    public class WeightSolverTests
    {
        const double Pose = 1 / 32.0;

        static readonly WeightProfile NoEffects = new WeightProfile("none", new WeightEffect[0]);

        static WeightSolver GolfBall(WeightProfile profile = null)
            => new WeightSolver(WeightModel.FromMass(PhysicalConstants.StandardMassKg), profile ?? NoEffects);

        [Test]
        public void AHoldBegunWithAGrabOffsetFollowsThePathOfAHoldBegunAtTheHandLessTheOffset()
        {
            var atHand = new WeightSolver(WeightModel.FromMass(2), NamedProfiles.Paper);
            var offset = new WeightSolver(WeightModel.FromMass(2), NamedProfiles.Paper);
            atHand.BeginHold(1.0, 1.0, 0);
            offset.BeginHoldWithGrabOffset(1.0, 0.08, 0);
            Assert.That(offset.ObjectY, Is.EqualTo(0.92).Within(1e-15));
            Assert.That(offset.GrabOffset, Is.EqualTo(0.08), "kept exactly as given");
            double t = 0;
            for (int i = 1; i <= 60; i++)
            {
                t += Pose;
                var pose = new HandSample(1.0 + 0.4 * Math.Min(1, i / 16.0), true, true, t);
                Assert.That(offset.Step(pose, Pose), Is.EqualTo(atHand.Step(pose, Pose) - 0.08).Within(1e-12), "pose " + i);
            }
        }

        [Test]
        public void EffectsSeeTheHeldHeightOnTheHoldsFirstFrame([Values(0.1, -0.05)] double handAbovePivot)
        {
            // MotionFrame.ObjectY is the held height before the frame (pivot + grab offset): on the first frame of a hold, the
            // hand where it grabbed. No effect of the package reads it; a scene's own can (here a probe in the input stage).
            var probe = new FrameProbe();
            var solver = new WeightSolver(WeightModel.FromMass(1), NamedProfiles.Paper.With(probe, "paper+probe"));
            solver.BeginHold(1.0, 1.0 - handAbovePivot, 0);
            solver.Step(new HandSample(1.01, true, true, Pose), Pose);
            Assert.That(probe.Last.ObjectY, Is.EqualTo(1.0).Within(1e-12));
        }

        [Test]
        public void TheHoldsClockKeepsTheNanosecondOverTenHoursOfFrames()
        {
            // 3,240,000 frames of 1/90 s, the same pose throughout (still frames: only the clocks move). Summed plainly the
            // clock ends 0.49 µs short, each addition's rounding gathered; the compensated (Kahan) sum is within 10⁻¹² s.
            var solver = new WeightSolver(WeightModel.FromMass(1), NamedProfiles.Paper);
            solver.BeginHold(1.0, 1.0, 0);
            const double dt = 1 / 90.0;
            const int frames = 3240000;
            var sample = new HandSample(1.0, true, true, 0);
            for (int i = 0; i < frames; i++) solver.Step(sample, dt);
            Assert.That(solver.State.Time, Is.EqualTo(frames * dt).Within(1e-9));
        }

        [Test]
        public void AGrabOffsetNeedsAUsableHandAndAPlausibleOffset()
        {
            var s = GolfBall();
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => s.BeginHoldWithGrabOffset(double.NaN, 0.1)).ParamName, Is.EqualTo("handY"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => s.BeginHoldWithGrabOffset(2e5, 0.1)).ParamName, Is.EqualTo("handY"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => s.BeginHoldWithGrabOffset(2e5, 0.1)).Message,
                Does.Contain("handY must be a usable height (finite, within ±100000 m)"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => s.BeginHoldWithGrabOffset(1, 2e5)).ParamName, Is.EqualTo("grabOffset"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => s.BeginHoldWithGrabOffset(1, -2e5)).ParamName, Is.EqualTo("grabOffset"));
            Assert.That(s.IsHolding, Is.False, "nothing began");
            s.BeginHoldWithGrabOffset(1, -0.05);
            Assert.That(s.ObjectY, Is.EqualTo(1.05), "a negative offset: above the hand");
        }

        [Test]
        public void AnObjectBelowTheFloorStartsOnItAndItsGrabOffsetIsWhatIsLeft()
        {
            var s = GolfBall(new WeightProfile("floor", new WeightEffect[] { new FloorClamp() }));
            s.BeginHoldWithGrabOffset(0.1, 0.15);
            Assert.That(s.ObjectY, Is.EqualTo(0.0), "raised to the floor");
            Assert.That(s.GrabOffset, Is.EqualTo(0.1).Within(1e-15), "the hand is now 0.1 m above it");
            s.BeginHoldWithGrabOffset(0.3, 0.15);
            Assert.That(s.GrabOffset, Is.EqualTo(0.15), "above the floor the offset is kept exactly");
            s.BeginHold(0.3, 0.0);
            Assert.That(s.ObjectY, Is.EqualTo(0.0), "exactly on the floor is not below it");
            Assert.That(s.GrabOffset, Is.EqualTo(0.3));
        }

        [Test]
        public void AnObjectExactlyOnTheFloorKeepsItsGrabOffsetExactly()
        {
            // The floor is not in the way of an object resting exactly on it, so the offset is kept as given, not recomputed
            // from the heights: 1.0 − (1.0 − 0.1) is 0.09999999999999998 in doubles, not 0.1.
            double floor = 1.0 - 0.1;
            Assert.That(1.0 - floor, Is.Not.EqualTo(0.1), "the fixture needs an offset the heights do not give back");
            var s = GolfBall(new WeightProfile("floor", new WeightEffect[] { new FloorClamp(floor) }));
            s.BeginHoldWithGrabOffset(1.0, 0.1);
            Assert.That(s.ObjectY, Is.EqualTo(floor), "on the floor, not raised");
            Assert.That(s.GrabOffset, Is.EqualTo(0.1), "kept exactly as given");
        }

        // Found by a surviving mutant: a hold begun with no tracked hand took the hand to be at height 0, and under the
        // paper profile the offset correction pulled the object 0.5 m down toward it in the first second.
        [Test]
        public void AHoldBegunBeforeTheHandIsTrackedStaysPutUntilAHandComesUnderEveryProfile([ValueSource(typeof(NamedProfiles), nameof(NamedProfiles.PipelineNames))] string profile)
        {
            var s = new WeightSolver(WeightModel.FromMass(5), NamedProfiles.Get(profile));
            s.BeginHold(double.NaN, 0.7);
            for (int i = 0; i < 90; i++) Assert.That(s.Step(HandSample.Lost, 1 / 90.0), Is.EqualTo(0.7), "frame " + i);
            Assert.That(s.HandY, Is.EqualTo(0.7));
            // The hand appears 2 cm off, a step a hand could make: it is anchored on (after settling, where the profile
            // settles), not followed.
            for (int i = 0; i < 30; i++) Assert.That(s.Step(new HandSample(0.72, true, true, 1.0 + i / 90.0), 1 / 90.0), Is.EqualTo(0.7), "anchored, no jump: frame " + i);
            Assert.That(s.HandY, Is.EqualTo(0.72));
        }

        [Test]
        public void AHoldBegunWithAnUnusableHandHeightDoesNotFollowFromIt()
        {
            // Beyond ±100 km a height is not usable: the hold starts as if the hand were not tracked, and a usable pose
            // 15 cm from that height anchors instead of moving the object.
            var s = GolfBall();
            s.BeginHold(100000.1, 99999.9, 0);
            Assert.That(s.Step(new HandSample(99999.95, true, true, Pose), Pose), Is.EqualTo(99999.9));
        }

        [Test]
        public void WithAHandFilterTheObjectHoldsWhileTrackingIsLost()
        {
            // The filtered hand lags a fast lift; when the hand is lost mid-lift the object stays where it is (the filter
            // does not keep converging on the last pose) and catches up only when a pose comes back.
            var s = GolfBall(new WeightProfile("filtered", new WeightEffect[0]).WithHandFilter(new ExponentialSmoothing(0.1)));
            double t = 0, hand = 1.0;
            s.BeginHold(hand, hand, t);
            for (int i = 0; i < 8; i++) s.Step(new HandSample(hand += 0.01, true, true, t += Pose), Pose);
            double y = s.ObjectY;
            Assert.That(hand - y, Is.GreaterThan(0.01), "the filter lags");
            for (int i = 0; i < 4; i++) Assert.That(s.Step(HandSample.Lost, Pose), Is.EqualTo(y), "lost frame " + i);
        }

        [Test]
        public void AHoldBegunBeforeTheHandIsTrackedKeepsTheObjectAndFollowsFromThere()
        {
            var s = GolfBall();
            s.BeginHold(double.NaN, 0.7);
            Assert.That(s.ObjectY, Is.EqualTo(0.7));
            Assert.That(s.HandY, Is.EqualTo(0.7), "no hand yet: the object's height stands in for it");
            Assert.That(s.GrabOffset, Is.EqualTo(0.0));
            double t = Pose;
            Assert.That(s.Step(HandSample.Lost, Pose), Is.EqualTo(0.7), "still no hand");
            Assert.That(s.HandY, Is.EqualTo(0.7), "and still stood in for by the object");
            t += Pose;
            Assert.That(s.Step(new HandSample(1.2, true, true, t), Pose), Is.EqualTo(0.7), "the hand appears: anchored, no jump");
            t += Pose;
            Assert.That(s.Step(new HandSample(1.25, true, true, t), Pose), Is.EqualTo(0.75).Within(1e-12), "then followed from where the object is");
        }

        [TestCase(1.25, 1.25)]
        [TestCase(double.NaN, double.NaN)]
        [TestCase(double.PositiveInfinity, double.NaN)]
        [TestCase(double.NegativeInfinity, double.NaN)]
        public void AnEffectSeesThePoseTimeFiniteOrNaNNeverInfinite(double given, double seen)
        {
            // MotionFrame.PoseTime's contract for a scene's own effects: a source without a usable clock reads as NaN.
            var probe = new FrameProbe();
            var s = new WeightSolver(WeightModel.FromMass(2), new WeightProfile("probe", new WeightEffect[] { probe }));
            s.BeginHold(1.0, 1.0, 0);
            s.Step(new HandSample(1.01, true, true, given), Pose);
            Assert.That(probe.Last.PoseTime, Is.EqualTo(seen));
        }

        [Test]
        public void ConfigurationWithoutAModelOrAProfileFailsNamingIt()
        {
            var s = GolfBall();
            Assert.That(Assert.Throws<ArgumentNullException>(() => s.Configure(null, NoEffects, 0.5)).ParamName, Is.EqualTo("model"));
            Assert.That(Assert.Throws<ArgumentNullException>(() => s.Configure(WeightModel.FromMass(1), null, 0.5)).ParamName, Is.EqualTo("profile"));
        }


        [Test]
        public void WithAHandFilterTheObjectComesBackToTheHandAfterALossAndNothingCreeps()
        {
            var s = GolfBall(new WeightProfile("filtered", new WeightEffect[0], null, new ExponentialSmoothing(0.1)));
            double t = 0;
            s.BeginHold(1.0, 1.0, t);
            for (int i = 0; i < 10; i++) { t += Pose; s.Step(HandSample.Lost, Pose); }   // lost for 0.31 s
            double previous = s.ObjectY;
            for (int i = 0; i < 60; i++)
            {
                t += Pose;
                double y = s.Step(new HandSample(1.3, true, true, t), Pose);
                Assert.That(y, Is.GreaterThanOrEqualTo(previous).And.LessThanOrEqualTo(1.3 + 1e-12), "back 30 cm higher: the filter brings it up, never past: pose " + i);
                previous = y;
            }
            Assert.That(previous, Is.EqualTo(1.3).Within(1e-6), "in the hand, and still");
        }

        [Test]
        public void AFilterSwitchedOnMidHoldStartsAtTheHand()
        {
            var s = GolfBall();
            double t = 0;
            s.BeginHold(1.0, 1.0, t);
            for (int i = 0; i < 5; i++) { t += Pose; s.Step(new HandSample(1.2, true, true, t), Pose); }
            double y = s.ObjectY;
            s.Configure(s.Model, new WeightProfile("filtered", new WeightEffect[0], null, new ExponentialSmoothing(0.1)), 0.5);
            for (int i = 0; i < 30; i++)
            {
                t += Pose;
                Assert.That(s.Step(new HandSample(1.2, true, true, t), Pose), Is.EqualTo(y).Within(1e-12), "a still hand, pose " + i);
            }
        }

        sealed class BrokenFilter : IHandFilter
        {
            public int Resets;
            public string Name => "broken";
            public IHandFilter Create() => this;
            public void Reset(double handY) => Resets++;
            public double Filter(double poseY, bool isNewPose, double poseInterval, double dt) => double.NaN;
        }

        [Test]
        public void AFilterThatReturnsNonFiniteIsIgnoredForThatFrameAndReset()
        {
            var broken = new BrokenFilter();
            var s = GolfBall(new WeightProfile("broken", new WeightEffect[0], null, broken));
            s.BeginHold(1.0, 1.0, 0);
            int resets = broken.Resets;
            double y = s.Step(new HandSample(1.02, true, true, Pose), Pose);
            Assert.That(y, Is.EqualTo(1.02).Within(1e-12), "the raw hand is followed");
            Assert.That(broken.Resets, Is.EqualTo(resets + 1), "and the filter reset");
        }
    }
}
