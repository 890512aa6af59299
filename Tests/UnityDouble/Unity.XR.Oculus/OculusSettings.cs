// Transcribed from XR Plug-in Management (com.unity.xr.management 4.4.0) and the Oculus XR Plugin (com.unity.xr.oculus 4.2.0),
// as mirrored in needle-mirror/com.unity.xr.management and needle-mirror/com.unity.xr.oculus at those tags.
// Runtime/OculusSettings.cs (assembly Unity.XR.Oculus).
using UnityEngine;

namespace Unity.XR.Oculus
{
    public class OculusSettings : ScriptableObject
    {
        public bool TargetQuest2 = true;
    }
}
