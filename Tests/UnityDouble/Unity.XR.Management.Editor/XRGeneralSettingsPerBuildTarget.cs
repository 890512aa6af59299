// Transcribed from XR Plug-in Management (com.unity.xr.management 4.4.0) and the Oculus XR Plugin (com.unity.xr.oculus 4.2.0),
// as mirrored in needle-mirror/com.unity.xr.management and needle-mirror/com.unity.xr.oculus at those tags.
// Editor/XRGeneralSettingsPerBuildTarget.cs, Editor/Metadata/XRPackageMetadataStore.cs (assembly Unity.XR.Management.Editor).
using UnityEditor;
using UnityEngine;
using UnityEngine.XR.Management;

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

