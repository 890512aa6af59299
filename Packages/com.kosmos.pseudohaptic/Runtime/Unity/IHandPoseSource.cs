using UnityEngine;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// Where the tracked hand is this frame: the one thing the Unity layer needs from a hand-tracking SDK.
    /// Implementations read their SDK's state and never allocate or throw; any value may be garbage
    /// (NaN while untracked): the solver absorbs it.
    /// </summary>
    public interface IHandPoseSource
    {
        /// <summary>The hand's position in world space, metres (its y is the height the solver follows).</summary>
        Vector3 Position { get; }

        /// <summary>The hand is tracked this frame.</summary>
        bool IsTracked { get; }

        /// <summary>The tracker reports high confidence in this pose.</summary>
        bool IsHighConfidence { get; }

        /// <summary>When this pose was sampled, seconds, if the SDK says; <see cref="double.NaN"/> when unknown.</summary>
        double PoseTime { get; }
    }

    /// <summary>A hand pose source that also reports an index pinch, for <see cref="PinchGrab"/>.</summary>
    public interface IPinchHandPoseSource : IHandPoseSource
    {
        /// <summary>The index finger and thumb are pinching this frame.</summary>
        bool IsPinching { get; }
    }

    /// <summary>
    /// A hand pose source that knows the tracking space its hand is tracked in (OVRCameraRig's TrackingSpace, the XR
    /// Origin's Camera Offset): the rig whose motion (walking, turning, teleports, platforms) is not the hand's.
    /// </summary>
    public interface IRigHandPoseSource : IHandPoseSource
    {
        /// <summary>The tracking space, or null when the hand's positions are plain world positions.</summary>
        Transform Rig { get; }
    }
}
