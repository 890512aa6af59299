using System;
using System.Collections.Generic;
using UnityEditor;
using UnityEditor.Build;
using UnityEngine;
#if KOSMOS_XR_MANAGEMENT && KOSMOS_XR_OCULUS
using UnityEditor.XR.Management;
using UnityEditor.XR.Management.Metadata;
using UnityEngine.XR.Management;
#endif

namespace Kosmos.PseudoHaptic.Editor
{
    /// <summary>
    /// The project settings a Quest 2 APK and Play over Link need, each set only where it is not already: colour space
    /// Linear (Meta XR Core's Android build refuses Gamma), IL2CPP, ARM64 only, API level ≥ 29, ASTC textures, XR Plug-in
    /// Management's Oculus loader initialised on startup for Android and for Standalone (Play over Link), and hand tracking
    /// in Meta's project config. Each call returns what it changed, in words, for the log.
    /// </summary>
    public static class QuestProjectSettings
    {
        /// <summary>The XR loader assigned for Android and Standalone: the Oculus XR Plugin's (com.unity.xr.oculus).</summary>
        public const string OculusLoaderType = "Unity.XR.Oculus.OculusLoader";

        /// <summary>Everything below; <paramref name="strict"/>: throw, saying what to do, when a loader or Meta's config cannot be set.</summary>
        public static List<string> Apply(bool strict)
        {
            var changes = new List<string>();
            ApplyPlayer(changes);
            ApplyXRLoader(BuildTargetGroup.Android, strict, changes);
            ApplyXRLoader(BuildTargetGroup.Standalone, strict, changes);
            ApplyHandTracking(strict, changes);
            if (changes.Count > 0) AssetDatabase.SaveAssets();
            return changes;
        }

        /// <summary>Colour space, scripting backend, architecture, API level and texture compression.</summary>
        public static void ApplyPlayer(List<string> changes)
        {
            if (PlayerSettings.colorSpace != ColorSpace.Linear)
            {
                changes.Add("colour space Linear (was " + PlayerSettings.colorSpace + ")");
                PlayerSettings.colorSpace = ColorSpace.Linear;
            }
            if (PlayerSettings.GetScriptingBackend(NamedBuildTarget.Android) != ScriptingImplementation.IL2CPP)
            {
                changes.Add("Android scripting backend IL2CPP");
                PlayerSettings.SetScriptingBackend(NamedBuildTarget.Android, ScriptingImplementation.IL2CPP);
            }
            if (PlayerSettings.Android.targetArchitectures != AndroidArchitecture.ARM64)
            {
                changes.Add("Android architecture ARM64 only (was " + PlayerSettings.Android.targetArchitectures + ")");
                PlayerSettings.Android.targetArchitectures = AndroidArchitecture.ARM64;
            }
            if (PlayerSettings.Android.minSdkVersion < AndroidSdkVersions.AndroidApiLevel29)
            {
                changes.Add("Android minimum API level 29");
                PlayerSettings.Android.minSdkVersion = AndroidSdkVersions.AndroidApiLevel29;
            }
            if (EditorUserBuildSettings.androidBuildSubtarget != MobileTextureSubtarget.ASTC)
            {
                changes.Add("Android textures ASTC");
                EditorUserBuildSettings.androidBuildSubtarget = MobileTextureSubtarget.ASTC;
            }
        }

        /// <summary>
        /// XR Plug-in Management for <paramref name="group"/>: the settings asset (created under Assets/XR and registered
        /// when the project has none), the Oculus loader assigned, XR initialised on startup. Without it an APK starts as a
        /// flat Android app, and Play mode shows no headset.
        /// </summary>
        public static void ApplyXRLoader(BuildTargetGroup group, bool strict, List<string> changes)
        {
#if KOSMOS_XR_MANAGEMENT && KOSMOS_XR_OCULUS
            if (!EditorBuildSettings.TryGetConfigObject(XRGeneralSettings.k_SettingsKey, out XRGeneralSettingsPerBuildTarget perTarget))
            {
                perTarget = ScriptableObject.CreateInstance<XRGeneralSettingsPerBuildTarget>();
                if (!AssetDatabase.IsValidFolder("Assets/XR")) AssetDatabase.CreateFolder("Assets", "XR");
                AssetDatabase.CreateAsset(perTarget, "Assets/XR/XRGeneralSettingsPerBuildTarget.asset");
                EditorBuildSettings.AddConfigObject(XRGeneralSettings.k_SettingsKey, perTarget, true);
                changes.Add("XR Plug-in Management settings created (Assets/XR)");
            }
            if (!perTarget.HasManagerSettingsForBuildTarget(group)) perTarget.CreateDefaultManagerSettingsForBuildTarget(group);
            XRGeneralSettings settings = perTarget.SettingsForBuildTarget(group);
            if (!settings.InitManagerOnStart)
            {
                settings.InitManagerOnStart = true;
                changes.Add(group + ": Initialize XR on Startup");
            }
            if (!XRPackageMetadataStore.IsLoaderAssigned(OculusLoaderType, group))
            {
                if (XRPackageMetadataStore.AssignLoader(settings.Manager, OculusLoaderType, group) && XRPackageMetadataStore.IsLoaderAssigned(OculusLoaderType, group))
                    changes.Add(group + ": the Oculus XR loader");
                else if (strict)
                    throw new InvalidOperationException("The Oculus XR loader (" + OculusLoaderType + ") could not be assigned for " + group + " in XR Plug-in Management: "
                        + "the build would not start in VR. Enable it in Project Settings > XR Plug-in Management > " + group + " > Oculus, then build again.");
            }
            EditorUtility.SetDirty(settings);
            EditorUtility.SetDirty(perTarget);
            // The Oculus plug-in's own settings exist once its settings page has been opened; they default to Quest 2.
            if (EditorBuildSettings.TryGetConfigObject("Unity.XR.Oculus.Settings", out global::Unity.XR.Oculus.OculusSettings oculus) && !oculus.TargetQuest2)
            {
                oculus.TargetQuest2 = true;
                EditorUtility.SetDirty(oculus);
                changes.Add("Oculus target device Quest 2");
            }
#else
            if (strict)
                throw new InvalidOperationException("XR Plug-in Management (com.unity.xr.management 4.4.0 or later) and the Oculus XR Plugin (com.unity.xr.oculus 4.2.0 or later) "
                    + "must be installed to build for Quest: without an XR loader the APK starts as a flat Android app. Add both (the project's Packages/manifest.json pins them).");
#endif
        }

        /// <summary>Hand tracking in Meta's project config, from which Meta's Android build step writes the manifest's permission and feature.</summary>
        public static void ApplyHandTracking(bool strict, List<string> changes)
        {
#if KOSMOS_META_XR_CORE
            OVRProjectConfig config = OVRProjectConfig.CachedProjectConfig;
            if (config == null)
            {
                if (strict)
                    throw new InvalidOperationException("Meta's project config (OVRProjectConfig.CachedProjectConfig) could not be loaded or created, so hand tracking cannot be declared in the APK. "
                        + "Open Meta > Tools > Project Setup Tool once (it creates Assets/Oculus/OculusProjectConfig.asset), then build again.");
                return;
            }
            if (config.handTrackingSupport != OVRProjectConfig.HandTrackingSupport.ControllersOnly) return;
            config.handTrackingSupport = OVRProjectConfig.HandTrackingSupport.ControllersAndHands;
            OVRProjectConfig.CommitProjectConfig(config);
            changes.Add("hand tracking support Controllers And Hands");
#else
            if (strict) Debug.LogWarning("Meta XR Core SDK (com.meta.xr.sdk.core) is not installed: hand tracking is not declared in the APK's manifest.");
#endif
        }
    }
}
