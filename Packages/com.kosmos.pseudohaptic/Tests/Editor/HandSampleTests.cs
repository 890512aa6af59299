using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>What the solver takes as a hand: a lost one is neither tracked nor confident; a usable height is finite and
    /// strictly within ±10⁵ m (ALGORITHM.md §3 step 1).</summary>
    public class HandSampleTests
    {
        [Test]
        public void ALostHandIsNeitherTrackedNorConfidentNorUsable()
        {
            Assert.That(HandSample.Lost.IsTracked, Is.False);
            Assert.That(HandSample.Lost.IsHighConfidence, Is.False);
            Assert.That(HandSample.Lost.IsUsable, Is.False);
            Assert.That(HandPose.Lost.IsTracked, Is.False);
            Assert.That(HandPose.Lost.IsHighConfidence, Is.False);
            Assert.That(HandPose.Lost.IsUsable, Is.False);
        }

        [TestCase(0.0, true)]
        [TestCase(99999.99, true)]
        [TestCase(-99999.99, true)]
        [TestCase(1e5, false)]
        [TestCase(-1e5, false)]
        [TestCase(double.NaN, false)]
        [TestCase(double.PositiveInfinity, false)]
        public void AUsableHeightIsFiniteAndStrictlyWithinTenToTheFiveMetres(double y, bool usable)
        {
            Assert.That(HandSample.IsUsableHeight(y), Is.EqualTo(usable));
            Assert.That(new HandSample(y).IsUsable, Is.EqualTo(usable));
            Assert.That(new HandSample(y, isTracked: false).IsUsable, Is.False, "untracked: never");
            Assert.That(new HandPose(0, y, 0).IsUsable, Is.EqualTo(usable));
            Assert.That(new HandPose(y, 0, 0).IsUsable, Is.EqualTo(usable), "x too");
            Assert.That(new HandPose(0, 0, y).IsUsable, Is.EqualTo(usable), "z too");
        }
    }
}
