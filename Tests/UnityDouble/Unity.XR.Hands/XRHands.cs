// Test double (the hands' data is what the test set, UnityDouble.XRHands). Transcribed from Unity XR Hands (com.unity.xr.hands) 1.5.0, as mirrored in needle-mirror/com.unity.xr.hands,
// tag 1.5.0: Runtime/XRHandSubsystem.cs, Runtime/XRHandSubsystemDescriptor.cs, Runtime/XRHandSubsystemProvider.cs,
// Runtime/XRHand.cs, Runtime/XRHandJoint.cs, Runtime/Enums.cs. Assembly Unity.XR.Hands. Only what the package uses.
using System;
using UnityEngine.SubsystemsImplementation;
using UnityEngine.XR.Hands.ProviderImplementation;

namespace UnityEngine.XR.Hands
{
    public partial class XRHandSubsystem : SubsystemWithProvider<XRHandSubsystem, XRHandSubsystemDescriptor, XRHandSubsystemProvider>
    {
        public XRHandSubsystem() { }

        public XRHand leftHand => LeftHand;
        public XRHand rightHand => RightHand;
        public UpdateSuccessFlags updateSuccessFlags { get; protected set; }
        internal XRHand LeftHand = new XRHand(Handedness.Left), RightHand = new XRHand(Handedness.Right);

        [Flags]
        public enum UpdateSuccessFlags
        {
            None = 0,
            LeftHandRootPose = 1 << 0,
            LeftHandJoints = 1 << 1,
            RightHandRootPose = 1 << 2,
            RightHandJoints = 1 << 3,
            All = LeftHandRootPose | LeftHandJoints | RightHandRootPose | RightHandJoints,
        }

        public enum UpdateType
        {
            Dynamic,
            BeforeRender,
        }

        public Action<XRHandSubsystem, UpdateSuccessFlags, UpdateType> updatedHands;
    }

    public class XRHandSubsystemDescriptor : SubsystemDescriptorWithProvider<XRHandSubsystem, XRHandSubsystemProvider>
    {
    }

    /// <summary>A hand's joints; the default value is an untracked hand with no joint (as a hand the subsystem never saw).</summary>
    public struct XRHand : IEquatable<XRHand>
    {
        internal XRHandJoint[] Joints;
        internal bool IsTracked;
        internal Handedness Side;
        internal Pose RootPose;

        internal XRHand(Handedness side)
        {
            Side = side;
            IsTracked = false;
            RootPose = Pose.identity;
            Joints = new XRHandJoint[(int)XRHandJointID.EndMarker - 1];
            for (int i = 0; i < Joints.Length; i++) Joints[i] = new XRHandJoint { Id = (XRHandJointID)(i + 1), Side = side };
        }

        /// <summary>The joint of that id; an invalid joint (no pose) for an id outside the hand or a default hand.</summary>
        public XRHandJoint GetJoint(XRHandJointID id)
        {
            int i = (int)id - 1;
            return Joints != null && i >= 0 && i < Joints.Length ? Joints[i] : new XRHandJoint { Id = id, Side = Side };
        }

        public Pose rootPose => RootPose;
        public Handedness handedness => Side;
        public bool isTracked => IsTracked;

        public bool Equals(XRHand other) => ReferenceEquals(Joints, other.Joints) && IsTracked == other.IsTracked && Side == other.Side;
        public override bool Equals(object obj) => obj is XRHand h && Equals(h);
        public override int GetHashCode() => (int)Side ^ (IsTracked ? 1 : 0);
    }

    /// <summary>One joint: a pose in the XR origin's space, valid when its tracking state has Pose.</summary>
    public struct XRHandJoint : IEquatable<XRHandJoint>
    {
        internal XRHandJointID Id;
        internal Handedness Side;
        internal XRHandJointTrackingState State;
        internal Pose Pose;

        public XRHandJointID id => Id;
        public Handedness handedness => Side;
        public XRHandJointTrackingState trackingState => State;

        public bool TryGetPose(out Pose pose)
        {
            pose = (State & XRHandJointTrackingState.Pose) != 0 ? Pose : Pose.identity;
            return (State & XRHandJointTrackingState.Pose) != 0;
        }

        public bool Equals(XRHandJoint other) => Id == other.Id && Side == other.Side && State == other.State && Pose.Equals(other.Pose);
        public override bool Equals(object obj) => obj is XRHandJoint j && Equals(j);
        public override int GetHashCode() => (int)Id ^ ((int)Side << 8) ^ ((int)State << 12);
        public static bool operator ==(XRHandJoint lhs, XRHandJoint rhs) => lhs.Equals(rhs);
        public static bool operator !=(XRHandJoint lhs, XRHandJoint rhs) => !lhs.Equals(rhs);
    }

    [Flags]
    public enum XRHandJointTrackingState
    {
        None = 0,
        Radius = 1 << 0,
        Pose = 1 << 1,
        LinearVelocity = 1 << 2,
        AngularVelocity = 1 << 3,
        WillNeverBeValid = 1 << 4,
        HighFidelityPose = 1 << 5,
    }

    public enum XRHandJointID
    {
        Invalid = 0,
        BeginMarker = 1,
        Wrist = BeginMarker,
        Palm = 2,
        ThumbMetacarpal = 3,
        ThumbProximal = 4,
        ThumbDistal = 5,
        ThumbTip = 6,
        IndexMetacarpal = 7,
        IndexProximal = 8,
        IndexIntermediate = 9,
        IndexDistal = 10,
        IndexTip = 11,
        MiddleMetacarpal = 12,
        MiddleProximal = 13,
        MiddleIntermediate = 14,
        MiddleDistal = 15,
        MiddleTip = 16,
        RingMetacarpal = 17,
        RingProximal = 18,
        RingIntermediate = 19,
        RingDistal = 20,
        RingTip = 21,
        LittleMetacarpal = 22,
        LittleProximal = 23,
        LittleIntermediate = 24,
        LittleDistal = 25,
        LittleTip = 26,
        EndMarker = 27,
    }

    public enum Handedness
    {
        Invalid,
        Left,
        Right,
    }
}

namespace UnityEngine.XR.Hands.ProviderImplementation
{
    public abstract class XRHandSubsystemProvider : SubsystemProvider<XRHandSubsystem>
    {
    }
}
