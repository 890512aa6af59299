// Test double (state in memory).
// Transcribed from XR Plug-in Management (com.unity.xr.management 4.4.0) and the Oculus XR Plugin (com.unity.xr.oculus 4.2.0),
// as mirrored in needle-mirror/com.unity.xr.management and needle-mirror/com.unity.xr.oculus at those tags.
// Runtime/XRGeneralSettings.cs, Runtime/XRManagerSettings.cs (assembly Unity.XR.Management).
using UnityEngine;

namespace UnityEngine.XR.Management
{
    public class XRGeneralSettings : ScriptableObject
    {
        public static string k_SettingsKey = "com.unity.xr.management.loader_settings";
        public XRManagerSettings Manager { get; set; }
        public bool InitManagerOnStart { get; set; } = true;
    }

    /// <summary>The loaders assigned for one build target, by loader type name.</summary>
    public sealed class XRManagerSettings : ScriptableObject
    {
        internal readonly System.Collections.Generic.List<string> LoaderTypes = new System.Collections.Generic.List<string>();
    }
}

