// Compile-only. Transcribed from Unity XR Hands (com.unity.xr.hands) 1.5.0, as mirrored in needle-mirror/com.unity.xr.hands,
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

        public XRHand leftHand => throw null;
        public XRHand rightHand => throw null;
        public UpdateSuccessFlags updateSuccessFlags { get => throw null; protected set => throw null; }

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

    public struct XRHand : IEquatable<XRHand>
    {
        public XRHandJoint GetJoint(XRHandJointID id) => throw null;
        public Pose rootPose => throw null;
        public Handedness handedness => throw null;
        public bool isTracked => throw null;

        public bool Equals(XRHand other) => throw null;
        public override bool Equals(object obj) => throw null;
        public override int GetHashCode() => throw null;
    }

    public struct XRHandJoint : IEquatable<XRHandJoint>
    {
        public XRHandJointID id => throw null;
        public Handedness handedness => throw null;
        public XRHandJointTrackingState trackingState => throw null;
        public bool TryGetPose(out Pose pose) => throw null;

        public bool Equals(XRHandJoint other) => throw null;
        public override bool Equals(object obj) => throw null;
        public override int GetHashCode() => throw null;
        public static bool operator ==(XRHandJoint lhs, XRHandJoint rhs) => throw null;
        public static bool operator !=(XRHandJoint lhs, XRHandJoint rhs) => throw null;
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
