// Compile-only. Transcribed from XR Plug-in Management (com.unity.xr.management 4.4.0) and the Oculus XR Plugin
// (com.unity.xr.oculus 4.2.0), as mirrored in needle-mirror/com.unity.xr.management and needle-mirror/com.unity.xr.oculus
// at those tags: Runtime/XRGeneralSettings.cs, Runtime/XRManagerSettings.cs (assembly Unity.XR.Management),
// Editor/XRGeneralSettingsPerBuildTarget.cs, Editor/Metadata/XRPackageMetadataStore.cs (assembly
// Unity.XR.Management.Editor), Runtime/OculusSettings.cs (assembly Unity.XR.Oculus). Only the members the package calls.
using UnityEditor;
using UnityEngine;
using UnityEngine.XR.Management;

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

namespace UnityEditor.XR.Management
{
    public class XRGeneralSettingsPerBuildTarget : ScriptableObject
    {
        public bool HasManagerSettingsForBuildTarget(BuildTargetGroup targetGroup) => throw null;
        public void CreateDefaultManagerSettingsForBuildTarget(BuildTargetGroup targetGroup) => throw null;
        public XRGeneralSettings SettingsForBuildTarget(BuildTargetGroup targetGroup) => throw null;
    }
}

namespace UnityEditor.XR.Management.Metadata
{
    public class XRPackageMetadataStore
    {
        public static bool IsLoaderAssigned(string loaderTypeName, BuildTargetGroup buildTargetGroup) => throw null;
        public static bool AssignLoader(XRManagerSettings settings, string loaderTypeName, BuildTargetGroup buildTargetGroup) => throw null;
    }
}

namespace Unity.XR.Oculus
{
    public class OculusSettings : ScriptableObject
    {
        public bool TargetQuest2 = true;
    }
}
