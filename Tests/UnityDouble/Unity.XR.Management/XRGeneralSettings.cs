// Transcribed from XR Plug-in Management (com.unity.xr.management 4.4.0) and the Oculus XR Plugin (com.unity.xr.oculus 4.2.0),
// as mirrored in needle-mirror/com.unity.xr.management and needle-mirror/com.unity.xr.oculus at those tags.
// Runtime/XRGeneralSettings.cs, Runtime/XRManagerSettings.cs (assembly Unity.XR.Management).
using UnityEngine;

namespace UnityEngine.XR.Management
{
    public class XRGeneralSettings : ScriptableObject
    {
        public static string k_SettingsKey = "com.unity.xr.management.loader_settings";
        public XRManagerSettings Manager { get => throw null; set => throw null; }
        public bool InitManagerOnStart { get => throw null; set => throw null; }
    }

    public sealed class XRManagerSettings : ScriptableObject
    {
    }
}

