using NUnit.Framework;
using static Kosmos.PseudoHaptic.Tests.EstimatorFrame;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>
    /// The estimator's two 0.1 s boundaries, for survivors of the estimation-poses mutation run (quality.md, "In pieces"):
    /// a pose that comes after exactly the gap time (SolverLimits.GapTime, 0.1 s) of frame time is not the end of a gap, one a
    /// hair later is; the hand's speed is kept for exactly 0.1 s without a new pose and is 0 beyond. Frames of 0.05 s add
    /// up to 0.1 exactly in binary (0.05 is 0.1 halved), so each boundary is met exactly, not approximately.
    /// </summary>
    public class PoseDeltaEstimatorBoundaryTests
    {
        const double Half = 0.05, NoTime = double.NaN; // poses without a time stamp: time is the frames'

        [Test]
        public void TheFrameTimesAddUpToTheBoundaryExactly()
        {
            Assert.That(0.0 + Half + Half, Is.EqualTo(0.1), "SolverLimits.GapTime, 0.1 s (internal)");
        }

        [Test]
        public void APoseAfterExactlyTheGapTimeIsNotTheEndOfAGapAndOneAfterMoreIs()
        {
            var e = new PoseDeltaEstimator();
            e.Reset(1.0, double.NaN);
            Assert.That(Frame(ref e, 1.0, NoTime, Half).NewPose, Is.False);
            var at = Frame(ref e, 1.01, NoTime, Half);
            Assert.That(at.NewPose, Is.True);
            Assert.That(at.AcrossGap, Is.False, "0.1 s since the last pose is not more than the gap time");

            var later = new PoseDeltaEstimator();
            later.Reset(1.0, double.NaN);
            Frame(ref later, 1.0, NoTime, Half);
            var beyond = Frame(ref later, 1.01, NoTime, Half + 1e-9);
            Assert.That(beyond.NewPose, Is.True);
            Assert.That(beyond.AcrossGap, Is.True, "more than 0.1 s since the last pose");
            Assert.That(beyond.Bridged, Is.False, "a gap in time, not a loss");
        }

        [Test]
        public void TheSpeedIsKeptForExactlyOneTenthOfASecondWithoutANewPoseAndIsZeroAfter()
        {
            var e = new PoseDeltaEstimator();
            e.Reset(1.0, double.NaN);
            var moved = Frame(ref e, 1.01, NoTime, Half);
            Assert.That(moved.HandSpeed, Is.EqualTo(0.01 / Half).Within(1e-12), "1 cm over the 50 ms since the last pose");
            double speed = e.Speed;
            Assert.That(speed, Is.EqualTo(moved.HandSpeed));

            Frame(ref e, 1.01, NoTime, Half);
            Frame(ref e, 1.01, NoTime, Half);
            Assert.That(e.Speed, Is.EqualTo(speed), "exactly 0.1 s without a new pose: not yet still");
            Frame(ref e, 1.01, NoTime, 1e-9);
            Assert.That(e.Speed, Is.EqualTo(0.0), "more than 0.1 s without a new pose: still");
        }
    }
}
