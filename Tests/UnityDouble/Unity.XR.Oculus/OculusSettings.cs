// Transcribed from XR Plug-in Management (com.unity.xr.management 4.4.0) and the Oculus XR Plugin (com.unity.xr.oculus 4.2.0),
// as mirrored in needle-mirror/com.unity.xr.management and needle-mirror/com.unity.xr.oculus at those tags.
// Runtime/OculusSettings.cs (assembly Unity.XR.Oculus).
using UnityEngine;

namespace Unity.XR.Oculus
{
    public class OculusSettings : ScriptableObject
    {
        public enum StereoRenderingModeDesktop
        {
            MultiPass = 0,
            SinglePassInstanced = 1,
        }

        public enum StereoRenderingModeAndroid
        {
            MultiPass = 0,
            Multiview = 2,
        }

        /// <summary>The defaults of Unity 2021.2 and later (UNITY_2021_2_OR_NEWER in the source).</summary>
        public StereoRenderingModeDesktop m_StereoRenderingModeDesktop = StereoRenderingModeDesktop.SinglePassInstanced;
        public StereoRenderingModeAndroid m_StereoRenderingModeAndroid = StereoRenderingModeAndroid.Multiview;

        public bool TargetQuest2 = true;
    }
}
