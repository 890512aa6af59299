using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>What a sample's setup says about the scene's hands (issue 34): nothing with a hand, one warning naming what is missing without.</summary>
    public sealed class RigHandsTests
    {
        [TestCase(1, true, 0)]
        [TestCase(2, true, 2)]
        [TestCase(1, false, 0)]
        public void AHandToGrabWithMeansNoWarning(int sources, bool ovrLookedFor, int ovrHands) =>
            Assert.That(RigHands.MissingHandsWarning("Playground sample", sources, ovrLookedFor, ovrHands), Is.Null);

        [Test]
        public void WithTheMetaSdkAndNoHandItNamesTheStockRigsPlaces()
        {
            string w = RigHands.MissingHandsWarning("Experiment 1 sample", 0, true, 0);
            Assert.That(w, Does.StartWith("Experiment 1 sample: no hand to grab with"));
            Assert.That(w, Does.Contain("no enabled OVRHand").And.Contain("OVRCameraRig").And.Contain("TrackingSpace/LeftHandAnchor").And.Contain("TrackingSpace/RightHandAnchor"));
            Assert.That(w, Does.Not.Contain("not installed"));
            Assert.That(w, Does.Not.Contain("\n"), "one line");
        }

        [Test]
        public void WithoutTheMetaSdkItSaysSo()
        {
            string w = RigHands.MissingHandsWarning(null, 0, false, 0);
            Assert.That(w, Does.StartWith("Kosmos Pseudo-Haptic sample: no hand"));
            Assert.That(w, Does.Contain("com.meta.xr.sdk.core").And.Contain("not installed").And.Contain("XR Hands Pose Source"));
        }

        [Test]
        public void HandsThatGotNoSourceAreNamedAsSuch() =>
            Assert.That(RigHands.MissingHandsWarning("S", 0, true, 2), Does.Contain("could not be given a pose source"));
    }
}
