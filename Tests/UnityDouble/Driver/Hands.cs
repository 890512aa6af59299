// The tests' handles on the hand-tracking SDKs' doubles: what the runtime would report this frame.
using UnityEngine;
using UnityEngine.XR.Hands;

namespace UnityDouble
{
    /// <summary>Meta XR Core SDK: an OVRHand's reported state, and an OVRCameraRig's tracked poses.</summary>
    public static class OvrHands
    {
        /// <summary>The hand's state as OVRHand reads it from the runtime: tracking, confidence, the index pinch.</summary>
        public static void Report(OVRHand hand, bool tracked, bool highConfidence = true, bool pinching = false, bool indexHighConfidence = true)
        {
            hand.IsDataValid = tracked;
            hand.IsTracked = tracked;
            hand.HandConfidence = tracked && highConfidence ? OVRHand.TrackingConfidence.High : OVRHand.TrackingConfidence.Low;
            hand.Pinching[(int)OVRHand.HandFinger.Index] = pinching;
            hand.FingerConfidence[(int)OVRHand.HandFinger.Index] = indexHighConfidence ? OVRHand.TrackingConfidence.High : OVRHand.TrackingConfidence.Low;
        }

        /// <summary>The pointer pose the runtime reports, in tracking space (written into PointerPose's local pose, as the SDK does).</summary>
        public static void ReportPointer(OVRHand hand, Vector3 trackingSpacePosition, bool valid = true)
        {
            hand.IsPointerPoseValid = valid;
            hand.PointerPose.localPosition = trackingSpacePosition;
        }

        /// <summary>Where the pointer pose's root is (OVRHand's serialized _pointerPoseRoot).</summary>
        public static void SetPointerPoseRoot(OVRHand hand, Transform root) => hand._pointerPoseRoot = root;

        /// <summary>
        /// The runtime gives the hand's skeleton (OVRSkeleton.Initialize): <paramref name="boneCount"/> bones (a hand has
        /// 24), the skeleton type the prefab serialized, the thumb and index tips where given (in the skeleton's local
        /// space). Again on an initialized skeleton: the skeleton changed and is re-initialized, its bone transforms
        /// kept unless the bone count differs.
        /// </summary>
        public static void InitializeSkeleton(OVRSkeleton skeleton, Vector3 thumbTip, Vector3 indexTip, OVRSkeleton.SkeletonType type = OVRSkeleton.SkeletonType.HandRight, int boneCount = OVRSkeleton.HandBoneCount)
        {
            skeleton.InitializeFromRuntime(type, boneCount);
            PoseSkeleton(skeleton, thumbTip, indexTip);
        }

        /// <summary>The fingers as the runtime posed them this frame: the thumb and index tips in the skeleton's local space.</summary>
        public static void PoseSkeleton(OVRSkeleton skeleton, Vector3 thumbTip, Vector3 indexTip)
        {
            foreach (OVRBone bone in skeleton.Bones)
            {
                if (bone.Id == OVRSkeleton.BoneId.Hand_ThumbTip) bone.Transform.localPosition = thumbTip;
                if (bone.Id == OVRSkeleton.BoneId.Hand_IndexTip) bone.Transform.localPosition = indexTip;
            }
        }

        /// <summary>The tracked hand and head poses, in tracking space, that the rig writes into its anchors on its next update.</summary>
        public static void Track(OVRCameraRig rig, Vector3 left, Vector3 right, Vector3 head = default)
        {
            rig.LeftHandLocal = new Pose(left, Quaternion.identity);
            rig.RightHandLocal = new Pose(right, Quaternion.identity);
            rig.HeadLocal = new Pose(head, Quaternion.identity);
        }
    }

    /// <summary>Unity XR Hands: a running hand subsystem and its joints.</summary>
    public static class XRHandsRuntime
    {
        /// <summary>A running XRHandSubsystem that SubsystemManager lists.</summary>
        public static XRHandSubsystem Start()
        {
            var subsystem = new XRHandSubsystemDescriptor().Create();
            subsystem.Start();
            return subsystem;
        }

        /// <summary>Sets a joint of a hand: its pose in the XR origin's space, and its tracking state.</summary>
        public static void Joint(XRHandSubsystem subsystem, Handedness side, XRHandJointID id, Vector3 position, XRHandJointTrackingState state)
        {
            ref XRHand hand = ref side == Handedness.Left ? ref subsystem.LeftHand : ref subsystem.RightHand;
            hand.IsTracked = true;
            hand.Joints[(int)id - 1].Pose = new Pose(position, Quaternion.identity);
            hand.Joints[(int)id - 1].State = state;
        }

        public static void Untrack(XRHandSubsystem subsystem, Handedness side)
        {
            if (side == Handedness.Left) subsystem.LeftHand.IsTracked = false;
            else subsystem.RightHand.IsTracked = false;
        }
    }
}
