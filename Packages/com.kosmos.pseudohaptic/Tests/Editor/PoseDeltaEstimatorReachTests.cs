using NUnit.Framework;
using static Kosmos.PseudoHaptic.Tests.EstimatorFrame;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>
    /// The estimator's reach after a (re)start, for two survivors of the estimation piece's mutation run (quality.md,
    /// "In pieces"): the first pose after an untracked start is where a glitch is judged from, and a new hold forgets
    /// the last hold's poses.
    /// </summary>
    public class PoseDeltaEstimatorReachTests
    {
        [Test]
        public void AJumpRightAfterTheFirstPoseOfAnUntrackedStartIsRefused()
        {
            var e = new PoseDeltaEstimator();
            e.Reset(double.NaN, double.NaN, 0.7);
            Assert.That(Frame(ref e, 1.2, 0.5, 0.01).Reanchored, Is.True);
            var glitch = Frame(ref e, 3.0, 0.51, 0.01);
            Assert.That(glitch.Usable, Is.False, "1.8 m in 10 ms is out of any hand's reach");
            Assert.That(e.HandY, Is.EqualTo(1.2));
        }

        [Test]
        public void ANewHoldForgetsTheLastHoldsPoses()
        {
            var e = new PoseDeltaEstimator();
            e.Reset(1.0, 0);
            e.Reset(0.5, 1.0);
            var back = Frame(ref e, 1.0, 1.01, 0.01);
            Assert.That(back.Usable, Is.False, "0.5 m in 10 ms; the last hold's pose at 1.0 is no prior of this one");
        }
    }
}
