// Compile-only. Transcribed from the Meta XR Core SDK (com.meta.xr.sdk.core 68.0.2), as mirrored in
// icosa-mirror/com.meta.xr.sdk.core: Editor/OVRProjectConfig.cs (global namespace, assembly Oculus.VR.Editor).
using UnityEngine;

public class OVRProjectConfig : ScriptableObject
{
    public enum HandTrackingSupport
    {
        ControllersOnly = 0,
        ControllersAndHands = 1,
        HandsOnly = 2,
    }

    public HandTrackingSupport handTrackingSupport;

    public static OVRProjectConfig CachedProjectConfig => throw null;
    public static void CommitProjectConfig(OVRProjectConfig projectConfig) => throw null;
}
