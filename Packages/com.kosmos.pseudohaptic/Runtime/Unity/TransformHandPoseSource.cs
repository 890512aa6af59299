using UnityEngine;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// A hand pose source that follows any transform: a hand from another SDK, a simulated hand, a test
    /// rig. Tracking, confidence and pinch are fields that the driving code (or the inspector) sets.
    /// </summary>
    [AddComponentMenu("Kosmos/Pseudo-Haptic/Transform Hand Pose Source")]
    public sealed class TransformHandPoseSource : MonoBehaviour, IPinchHandPoseSource
    {
        [Tooltip("The transform whose position is the hand's; this object's own when empty.")]
        [SerializeField] Transform _hand;

        [SerializeField] bool _isTracked = true;
        [SerializeField] bool _isHighConfidence = true;
        [SerializeField] bool _isPinching;

        public Vector3 Position => Tracked.position;

        /// <summary>The transform followed: the one given, or this object's own.</summary>
        public Transform Tracked => _hand != null ? _hand : transform;
        public double PoseTime => double.NaN;

        public bool IsTracked { get => _isTracked; set => _isTracked = value; }
        public bool IsHighConfidence { get => _isHighConfidence; set => _isHighConfidence = value; }
        public bool IsPinching { get => _isPinching; set => _isPinching = value; }

        public void InjectHand(Transform hand) => _hand = hand;
    }
}
