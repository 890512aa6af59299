using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>
    /// The XRI 3 transformer's reading of a TrackedPoseDriver (<see cref="PoseDriverTracking"/>), case by case against the
    /// Input System 1.8.1 driver's rule for moving its transform.
    /// </summary>
    public sealed class PoseDriverTrackingTests
    {
        const int None = 0, Position = 1, Rotation = 2;

        [TestCase(false, false, true, true, 1, None, true, TestName = "No driver: the attach transform is taken as tracked")]
        [TestCase(true, true, true, true, 1, None, true, TestName = "A driver that ignores the tracking state always moves the transform")]
        [TestCase(true, false, false, false, 0, None, true, TestName = "No tracking-state action: the driver always moves the transform")]
        [TestCase(true, false, true, false, 1, Position | Rotation, false, TestName = "A disabled tracking-state action reads as None")]
        [TestCase(true, false, true, true, 0, None, true, TestName = "No control bound: the driver keeps its first state, tracked")]
        [TestCase(true, false, true, true, 1, None, false, TestName = "A bound action reporting None: lost")]
        [TestCase(true, false, true, true, 1, Rotation, false, TestName = "Rotation alone: the position is not tracked")]
        [TestCase(true, false, true, true, 1, Position, true, TestName = "Position: tracked")]
        [TestCase(true, false, true, true, 2, Position | Rotation | 4, true, TestName = "Position among other bits: tracked")]
        public void TheDriversRule(bool hasDriver, bool ignore, bool hasAction, bool enabled, int controls, int state, bool tracked)
        {
            Assert.That(PoseDriverTracking.PositionTracked(hasDriver, ignore, hasAction, enabled, controls, state), Is.EqualTo(tracked));
        }

        [Test]
        public void ThePositionBitIsInputTrackingStatesPosition()
        {
            // UnityEngine.XR.InputTrackingState (UnityCsReference 2022.3, Modules/XR/ScriptBindings/XRInput.bindings.cs): Position = 1 << 0.
            Assert.That(PoseDriverTracking.Position, Is.EqualTo(1 << 0));
        }
    }
}
