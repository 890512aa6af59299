// Test double of the Meta XR Core SDK 68.0.2's OVRManager, only what the package calls (icosa-mirror/com.meta.xr.sdk.core,
// tag 68.0.2: Scripts/OVRManager.cs; enum values from Scripts/OVRPlugin.cs, OVRPlugin.TrackingOrigin), global namespace,
// assembly Oculus.VR. As the SDK: `instance` is set in Awake (and not cleared on destroy); the serialized tracking origin defaults to EyeLevel (and
// Meta's OVRCameraRig.prefab ships it so, `_trackingOriginType: 0`); `trackingOriginType` reads and writes it. The SDK
// applies a write through OVRPlugin only while a headset is present (without one the setter returns): here the test is
// the headset and the write always lands.
using UnityEngine;

public class OVRManager : MonoBehaviour
{
    public enum TrackingOrigin
    {
        EyeLevel = 0,
        FloorLevel = 1,
        Stage = 2,
    }

    public static OVRManager instance { get; private set; }

    [SerializeField] TrackingOrigin _trackingOriginType = TrackingOrigin.EyeLevel;

    public TrackingOrigin trackingOriginType
    {
        get => _trackingOriginType;
        set => _trackingOriginType = value;
    }

    void Awake() => instance = this;
}
