// Test double (state in memory).
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
        readonly System.Collections.Generic.Dictionary<BuildTargetGroup, XRGeneralSettings> _settings = new System.Collections.Generic.Dictionary<BuildTargetGroup, XRGeneralSettings>();

        public bool HasManagerSettingsForBuildTarget(BuildTargetGroup targetGroup) => _settings.TryGetValue(targetGroup, out XRGeneralSettings s) && s.Manager != null;

        public void CreateDefaultManagerSettingsForBuildTarget(BuildTargetGroup targetGroup)
        {
            XRGeneralSettings s = SettingsForBuildTarget(targetGroup) ?? (_settings[targetGroup] = CreateInstance<XRGeneralSettings>());
            if (s.Manager == null) s.Manager = CreateInstance<XRManagerSettings>();
        }

        public XRGeneralSettings SettingsForBuildTarget(BuildTargetGroup targetGroup) => _settings.TryGetValue(targetGroup, out XRGeneralSettings s) ? s : null;
    }
}

namespace UnityEditor.XR.Management.Metadata
{
    public class XRPackageMetadataStore
    {
        /// <summary>Whether the project's settings for that target (EditorBuildSettings' config object) have the loader.</summary>
        public static bool IsLoaderAssigned(string loaderTypeName, BuildTargetGroup buildTargetGroup) =>
            EditorBuildSettings.TryGetConfigObject(XRGeneralSettings.k_SettingsKey, out XRGeneralSettingsPerBuildTarget all)
            && all.SettingsForBuildTarget(buildTargetGroup)?.Manager?.LoaderTypes.Contains(loaderTypeName) == true;

        /// <summary>Adds the loader (a loader type the installed packages provide: the Oculus XR Plugin's here).</summary>
        public static bool AssignLoader(XRManagerSettings settings, string loaderTypeName, BuildTargetGroup buildTargetGroup)
        {
            if (settings == null || !KnownLoaders.Contains(loaderTypeName)) return false;
            if (!settings.LoaderTypes.Contains(loaderTypeName)) settings.LoaderTypes.Add(loaderTypeName);
            return true;
        }

        internal static readonly System.Collections.Generic.HashSet<string> KnownLoaders = new System.Collections.Generic.HashSet<string> { "Unity.XR.Oculus.OculusLoader" };
    }
}

