using System.Collections.Generic;
using Unity.XR.CoreUtils;
using UnityEngine;
using UnityEngine.XR.Hands;

namespace Kosmos.PseudoHaptic.XRHands
{
    /// <summary>
    /// The hand pose of Unity XR Hands (<c>com.unity.xr.hands</c> 1.5.0 or later, OpenXR) for the pseudo-haptic
    /// components, beside <c>OvrHandPoseSource</c>: one per hand. It reads the running <see cref="XRHandSubsystem"/>'s
    /// left or right <see cref="XRHand"/>: tracked is <see cref="XRHand.isTracked"/> with a pose for the chosen joint;
    /// high confidence is that joint's <see cref="XRHandJointTrackingState.HighFidelityPose"/> (tracked, not inferred);
    /// the pinch strength comes from the thumb–index tip distance (<see cref="GrabFollow.PinchStrength"/>: 1 at 1.5 cm,
    /// 0 at 4 cm), the pinch itself at <see cref="PinchDetector.DefaultCloseAt"/>. Joint poses are in the XR origin's
    /// space: give the origin's tracking-space transform (the XR Origin's Camera Offset), or none for world space.
    /// XR Hands gives no pose timestamp. On Quest it needs the OpenXR loader with the Hand Tracking Subsystem
    /// feature; with the Oculus loader there is no subsystem and the hand reads as untracked.
    /// Compiled only when com.unity.xr.hands is installed. Reading allocates nothing after the subsystem is found.
    /// </summary>
    [AddComponentMenu("Kosmos/Pseudo-Haptic/XR Hands Pose Source")]
    public sealed class XRHandPoseSource : MonoBehaviour, IPinchHandPoseSource, IPinchStrengthSource, IRigHandPoseSource
    {
        public enum PositionJoint
        {
            /// <summary>The wrist (what OVRHand's transform is).</summary>
            Wrist,
            /// <summary>The palm's centre.</summary>
            Palm,
            /// <summary>Between the thumb and index tips, where a pinch holds.</summary>
            PinchPoint,
        }

        [SerializeField] Handedness _handedness = Handedness.Right;
        [Tooltip("The XR origin's tracking space (XR Origin ▸ Camera Offset); found from the scene's XR Origin when empty; none: joint poses are world positions.")]
        [SerializeField] Transform _trackingSpace;
        [SerializeField] PositionJoint _position = PositionJoint.Wrist;

        static readonly List<XRHandSubsystem> s_subsystems = new List<XRHandSubsystem>(1);
        XRHandSubsystem _subsystem;
        double _nextSearch;

        public Handedness HandSide { get => _handedness; set => _handedness = value; }
        public PositionJoint PositionFrom { get => _position; set => _position = value; }
        public Transform TrackingSpace { get => _trackingSpace; set => _trackingSpace = value; }

        /// <summary>The tracking space the joints are in: the one set, else the scene's XR Origin's Camera Offset (looked for once, at Awake).</summary>
        public Transform Rig => _trackingSpace;

        void Awake()
        {
            if (_trackingSpace != null) return;
            XROrigin origin = FindFirstObjectByType<XROrigin>();
            if (origin != null && origin.CameraFloorOffsetObject != null) _trackingSpace = origin.CameraFloorOffsetObject.transform;
        }

        /// <summary>The running hand subsystem, looked for at most twice a second until one runs.</summary>
        public XRHandSubsystem Subsystem
        {
            get
            {
                if ((_subsystem == null || !_subsystem.running) && Time.unscaledTimeAsDouble >= _nextSearch)
                {
                    _nextSearch = Time.unscaledTimeAsDouble + 0.5;
                    SubsystemManager.GetSubsystems(s_subsystems);
                    // The running one: a project may hold several (a simulator's beside OpenXR's), the first not running.
                    _subsystem = null;
                    for (int i = 0; i < s_subsystems.Count && _subsystem == null; i++)
                        if (s_subsystems[i].running) _subsystem = s_subsystems[i];
                }
                return _subsystem != null && _subsystem.running ? _subsystem : null;
            }
        }

        XRHand Hand
        {
            get
            {
                XRHandSubsystem s = Subsystem;
                if (s == null) return default;
                return _handedness == Handedness.Left ? s.leftHand : s.rightHand;
            }
        }

        public bool IsTracked => Hand.isTracked && Joint(JointId, out _);

        /// <summary>Every joint the position is made of (the wrist, the palm, or both tips for the pinch point) has a high-fidelity pose.</summary>
        public bool IsHighConfidence
        {
            get
            {
                if (!IsTracked) return false;
                XRHand hand = Hand;
                if (_position != PositionJoint.PinchPoint) return HighFidelity(hand, JointId);
                return HighFidelity(hand, XRHandJointID.ThumbTip) && HighFidelity(hand, XRHandJointID.IndexTip);
            }
        }

        static bool HighFidelity(XRHand hand, XRHandJointID id) => (hand.GetJoint(id).trackingState & XRHandJointTrackingState.HighFidelityPose) != 0;

        public Vector3 Position => Joint(JointId, out Vector3 p) ? p : new Vector3(float.NaN, float.NaN, float.NaN);

        public double PoseTime => double.NaN;

        public float PinchStrength =>
            Joint(XRHandJointID.ThumbTip, out Vector3 thumb) && Joint(XRHandJointID.IndexTip, out Vector3 index)
                ? (float)GrabFollow.PinchStrength((thumb - index).ToDouble().Length) : 0f;

        public bool IsPinching => PinchStrength >= PinchDetector.DefaultCloseAt;

        XRHandJointID JointId => _position == PositionJoint.Palm ? XRHandJointID.Palm : XRHandJointID.Wrist;

        /// <summary>A joint's position in world space; for the pinch point, the mean of the thumb and index tips.</summary>
        bool Joint(XRHandJointID id, out Vector3 world)
        {
            world = default;
            if (_position == PositionJoint.PinchPoint && id != XRHandJointID.ThumbTip && id != XRHandJointID.IndexTip)
                return Joint(XRHandJointID.ThumbTip, out Vector3 a) & Joint(XRHandJointID.IndexTip, out Vector3 b) && Mid(a, b, out world);
            XRHand hand = Hand;
            if (!hand.isTracked || !hand.GetJoint(id).TryGetPose(out Pose pose)) return false;
            world = _trackingSpace != null ? _trackingSpace.TransformPoint(pose.position) : pose.position;
            return true;
        }

        static bool Mid(Vector3 a, Vector3 b, out Vector3 mid)
        {
            mid = (a + b) * 0.5f;
            return true;
        }
    }
}
