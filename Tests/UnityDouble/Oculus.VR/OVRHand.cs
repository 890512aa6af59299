// Compile-only. Transcribed from the Meta XR Core SDK (com.meta.xr.sdk.core 68.0.2), as mirrored in
// icosa-mirror/com.meta.xr.sdk.core: Scripts/Util/OVRHand.cs (OVRHand; enum values resolved through
// Scripts/OVRPlugin.cs: OVRPlugin.HandFinger, OVRPlugin.TrackingConfidence) and Editor/OVRProjectConfig.cs.
// Both are in the global namespace, in the assemblies Oculus.VR and Oculus.VR.Editor.
using UnityEngine;

public class OVRHand : MonoBehaviour
{
    public enum HandFinger
    {
        Thumb = 0,
        Index = 1,
        Middle = 2,
        Ring = 3,
        Pinky = 4,
        Max = 5,
    }

    public enum TrackingConfidence
    {
        Low = 0,
        High = 0x3f800000,
    }

    public bool IsDataValid => throw null;
    public bool IsTracked => throw null;
    public bool IsPointerPoseValid => throw null;
    public Transform PointerPose => throw null;
    public TrackingConfidence HandConfidence => throw null;
    public bool GetFingerIsPinching(HandFinger finger) => throw null;
    public TrackingConfidence GetFingerConfidence(HandFinger finger) => throw null;
}
