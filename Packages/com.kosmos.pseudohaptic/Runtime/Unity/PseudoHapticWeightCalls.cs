using UnityEngine;

namespace Kosmos.PseudoHaptic
{
    /// <summary>The one-hand calls of <see cref="PseudoHapticWeight"/> (hand id 0), for drivers and tests that hold with one hand.</summary>
    public static class PseudoHapticWeightCalls
    {
        public static bool BeginHold(this PseudoHapticWeight weight, Vector3 handWorld, double poseTime = double.NaN, RigidbodyControl rigidbody = RigidbodyControl.ByThisComponent)
            => weight.BeginHold(0, handWorld, poseTime, rigidbody);

        public static bool BeginHold(this PseudoHapticWeight weight, IHandPoseSource hand, RigidbodyControl rigidbody = RigidbodyControl.ByThisComponent)
            => hand != null && weight.BeginHold(0, hand.Position, hand.PoseTime, rigidbody);

        public static float Step(this PseudoHapticWeight weight, Vector3 handWorld, bool isTracked, bool isHighConfidence, double poseTime, float dt)
            => weight.Step(0, handWorld, isTracked, isHighConfidence, poseTime, dt);

        public static float Step(this PseudoHapticWeight weight, IHandPoseSource hand, float dt) => hand == null
            ? weight.Step(0, default, false, false, double.NaN, dt)
            : weight.Step(0, hand.Position, hand.IsTracked, hand.IsHighConfidence, hand.PoseTime, dt);
    }
}
