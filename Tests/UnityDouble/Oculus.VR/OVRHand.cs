// Test double of the Meta XR Core SDK 68.0.2's OVRHand (icosa-mirror/com.meta.xr.sdk.core, Scripts/Util/OVRHand.cs;
// enum values from Scripts/OVRPlugin.cs), global namespace, assembly Oculus.VR. As the SDK: the hand's state is what
// the runtime reported this frame (here: what the test set through the driver, UnityDouble.OvrHands); PointerPose is a
// transform under the pointer-pose root (the tracking space, when set) or else under the hand itself, whose local
// position and rotation are the pointer pose in tracking space.
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

    [SerializeField] internal Transform _pointerPoseRoot = null;
    GameObject _pointerPoseGO;
    internal readonly bool[] Pinching = new bool[(int)HandFinger.Max];
    internal readonly TrackingConfidence[] FingerConfidence = new TrackingConfidence[(int)HandFinger.Max];

    public bool IsDataValid { get; internal set; }
    public bool IsTracked { get; internal set; }
    public bool IsPointerPoseValid { get; internal set; }
    public TrackingConfidence HandConfidence { get; internal set; }

    public Transform PointerPose
    {
        get
        {
            if (_pointerPoseGO == null)
            {
                _pointerPoseGO = new GameObject("PointerPose");
                _pointerPoseGO.transform.SetParent(_pointerPoseRoot != null ? _pointerPoseRoot : transform, false);
            }
            return _pointerPoseGO.transform;
        }
    }

    public bool GetFingerIsPinching(HandFinger finger) => IsDataValid && Pinching[(int)finger];
    public TrackingConfidence GetFingerConfidence(HandFinger finger) => IsDataValid ? FingerConfidence[(int)finger] : TrackingConfidence.Low;
}
