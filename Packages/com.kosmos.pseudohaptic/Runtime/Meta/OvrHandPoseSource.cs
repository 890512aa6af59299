using System.Collections.Generic;
using UnityEngine;

namespace Kosmos.PseudoHaptic.Meta
{
    /// <summary>
    /// The hand pose of Meta's <c>OVRHand</c> (Meta XR Core SDK) for the pseudo-haptic components. Tracked is
    /// <c>OVRHand.IsTracked</c> with valid data; high confidence is the hand's <c>HandConfidence</c> (and, for
    /// pinches, the index finger's); the pinch is <c>GetFingerIsPinching(Index)</c>. Quest tracks hands at
    /// 30 Hz (60 Hz in high-frequency mode) while frames render at 72–120 Hz: the same pose repeats over
    /// several frames, and the core's estimator tells repeats apart by value, as no pose timestamp is read here.
    /// Compiled only when com.meta.xr.sdk.core is installed.
    /// </summary>
    [AddComponentMenu("Kosmos/Pseudo-Haptic/OVR Hand Pose Source")]
    public sealed class OvrHandPoseSource : MonoBehaviour, IPinchHandPoseSource, IRigHandPoseSource
    {
        public enum PositionSource
        {
            /// <summary>The OVRHand's own transform (the hand anchor of OVRCameraRig: the wrist).</summary>
            HandTransform,
            /// <summary>OVRHand.PointerPose (between thumb and index), when the SDK says it is valid: its pose in tracking space
            /// (what the SDK writes into PointerPose's local pose) placed through the tracking space, never through the
            /// hand's transforms, which a hand drawn on the object offsets.</summary>
            PointerPose,
            /// <summary>Between the thumb and index tips of the hand's OVRSkeleton, where a pinch holds (the wrist is
            /// 14–18 cm from them). Measured from the OVRHand's transform and placed from the tracked one, so a hand
            /// drawn on the object does not move it; the wrist until the skeleton has its bones, and while untracked.</summary>
            PinchPoint,
        }

        [Tooltip("The OVRHand to read; found on this GameObject or its parents when empty.")]
        [SerializeField] OVRHand _hand;
        [Tooltip("Pinch Point: between the thumb and index tips (what a pinch grabs with); Hand Transform: the wrist; Pointer Pose: OVRHand.PointerPose.")]
        [SerializeField] PositionSource _position = PositionSource.PinchPoint;
        [Tooltip("Where the tracked hand is for Hand Transform and Pinch Point: the hand anchor, when the OVRHand sits under a visual root that a Pinch Grab offsets (hand drawn on the object); empty: the OVRHand's own transform.")]
        [SerializeField] Transform _tracked;
        [Tooltip("A pinch counts only while the index finger is tracked with high confidence.")]
        [SerializeField] bool _pinchNeedsHighConfidence = true;
        [Tooltip("The tracking space (OVRCameraRig ▸ TrackingSpace) the hand is tracked in; found from the OVRCameraRig above the hand when empty.")]
        [SerializeField] Transform _trackingSpace;

        // Pinch Point: the hand's skeleton and its two fingertips, found once and again only when the skeleton changes.
        OVRHand _skeletonOf;
        OVRSkeleton _skeleton;
        double _nextSkeletonSearch;
        IList<OVRBone> _tipsOf;
        int _tipsChangeCount;
        Transform _thumbTip, _indexTip;

        public OVRHand OvrHand => _hand;

        public void InjectHand(OVRHand hand) => _hand = hand;

        /// <summary>The transform read as the tracked hand (the hand anchor), above any offset visual root.</summary>
        public Transform Tracked { get => _tracked; set => _tracked = value; }

        public PositionSource Source { get => _position; set => _position = value; }

        /// <summary>The tracking space the hand is tracked in: the one set, else the OVRCameraRig's above the hand, else null (world).</summary>
        public Transform Rig
        {
            get
            {
                if (_trackingSpace == null && _hand != null)
                {
                    OVRCameraRig rig = _hand.GetComponentInParent<OVRCameraRig>();
                    if (rig != null) _trackingSpace = rig.trackingSpace;
                }
                return _trackingSpace;
            }
            set => _trackingSpace = value;
        }

        void Awake()
        {
            if (_hand == null) _hand = GetComponentInParent<OVRHand>();
            _ = Rig; // found once here, never per frame
            if (_hand == null) Debug.LogError("OVR Hand Pose Source on '" + name + "' has no OVRHand to read.", this);
        }

        public bool IsTracked => _hand != null && _hand.IsTracked && _hand.IsDataValid;

        public bool IsHighConfidence => IsTracked && _hand.HandConfidence == OVRHand.TrackingConfidence.High;

        public Vector3 Position
        {
            get
            {
                if (_hand == null) return new Vector3(float.NaN, float.NaN, float.NaN);
                if (_position == PositionSource.PointerPose && _hand.IsPointerPoseValid)
                {
                    Transform space = Rig;
                    Vector3 inSpace = _hand.PointerPose.localPosition; // the SDK writes the tracking-space pose there
                    return space != null ? space.TransformPoint(inSpace) : inSpace;
                }
                Transform tracked = _tracked != null ? _tracked : _hand.transform;
                if (_position == PositionSource.PinchPoint && IsTracked && FindTips())
                {
                    // Measured in the OVRHand's frame (the bones move with a visual root a Pinch Grab offsets), placed from the tracked one.
                    Vector3 local = _hand.transform.InverseTransformPoint((_thumbTip.position + _indexTip.position) * 0.5f);
                    return tracked.TransformPoint(local);
                }
                return tracked.position;
            }
        }

        /// <summary>The hand's skeleton's thumb and index tips, cached; false until it is initialized with both.</summary>
        bool FindTips()
        {
            if (!ReferenceEquals(_skeletonOf, _hand) || (_skeleton == null && Time.unscaledTimeAsDouble >= _nextSkeletonSearch))
            {
                // OVRHandPrefab puts OVRSkeleton beside OVRHand; other rigs may put it under or above. Looked for again once a second while missing.
                _skeletonOf = _hand;
                _skeleton = _hand.GetComponentInChildren<OVRSkeleton>();
                if (_skeleton == null) _skeleton = _hand.GetComponentInParent<OVRSkeleton>();
                _nextSkeletonSearch = Time.unscaledTimeAsDouble + 1;
                _tipsOf = null;
            }
            if (_skeleton == null || !_skeleton.IsInitialized) return false;
            OVRSkeleton.SkeletonType type = _skeleton.GetSkeletonType();
            // Hand_ThumbTip and Hand_IndexTip are the OVR hand skeleton's ids; other skeleton types number their bones otherwise.
            if (type != OVRSkeleton.SkeletonType.HandLeft && type != OVRSkeleton.SkeletonType.HandRight) return false;
            IList<OVRBone> bones = _skeleton.Bones;
            // Found again when the skeleton re-initialized (a new bone list, or the runtime's skeleton changed) or a tip was destroyed.
            if (_thumbTip == null || _indexTip == null || !ReferenceEquals(bones, _tipsOf) || _tipsChangeCount != _skeleton.SkeletonChangedCount)
            {
                _tipsOf = bones;
                _tipsChangeCount = _skeleton.SkeletonChangedCount;
                _thumbTip = Bone(bones, OVRSkeleton.BoneId.Hand_ThumbTip);
                _indexTip = Bone(bones, OVRSkeleton.BoneId.Hand_IndexTip);
            }
            return _thumbTip != null && _indexTip != null;
        }

        static Transform Bone(IList<OVRBone> bones, OVRSkeleton.BoneId id)
        {
            if (bones == null) return null;
            for (int i = 0; i < bones.Count; i++)
                if (bones[i] != null && bones[i].Id == id && bones[i].Transform != null) return bones[i].Transform;
            return null;
        }

        public double PoseTime => double.NaN;

        // The runtime's own pinch flag (its threshold on the strength is not documented): the grab's hysteresis
        // then holds it through a dropped frame (PinchDetector.OpenAfter).
        public bool IsPinching =>
            IsTracked
            && _hand.GetFingerIsPinching(OVRHand.HandFinger.Index)
            && (!_pinchNeedsHighConfidence || _hand.GetFingerConfidence(OVRHand.HandFinger.Index) == OVRHand.TrackingConfidence.High);
    }
}
