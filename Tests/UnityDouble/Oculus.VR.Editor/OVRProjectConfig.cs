// Test double (the config lives in memory). Transcribed from the Meta XR Core SDK (com.meta.xr.sdk.core 68.0.2), as mirrored in
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

    static OVRProjectConfig s_cached;
    internal static int Commits;

    /// <summary>The project's config, created with the SDK's default (controllers only) the first time.</summary>
    public static OVRProjectConfig CachedProjectConfig => s_cached != null ? s_cached : (s_cached = CreateInstance<OVRProjectConfig>());

    public static void CommitProjectConfig(OVRProjectConfig projectConfig) => Commits++;

    internal static void ResetForTests()
    {
        s_cached = null;
        Commits = 0;
    }
}
