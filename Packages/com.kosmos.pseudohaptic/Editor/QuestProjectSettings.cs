using System;
using System.Collections.Generic;
using UnityEditor;
using UnityEditor.Build;
using UnityEngine;
using UnityEngine.Rendering;
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
    /// in Meta's project config; and Meta's Project Setup Tool recommendations that a build can take without a choice of
    /// the user (<see cref="ApplyRecommended"/>). Each call returns what it changed, in words, for the log.
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
            ApplyRecommended(changes);
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

        /// <summary>The Android target API level Meta's Project Setup Tool recommends (Meta XR Core SDK 68.0.2: 32). By its
        /// number: the enum's AndroidApiLevel32 first appears in Unity 2022.3.21f1, and the package supports 2022.3.0f1.</summary>
        public const AndroidSdkVersions TargetApiLevel = (AndroidSdkVersions)32;

        /// <summary>
        /// Meta's Project Setup Tool recommendations (Meta XR Core SDK 68.0.2, OVRProjectSetupCompatibilityTasks and
        /// OVRProjectSetupRenderingTasks), each where it is not met yet: Android target API level 32; Android TV compatibility
        /// off (Meta: required, the Store refuses it); Android graphics APIs chosen explicitly, Vulkan, unless the list is
        /// already explicit and holds Vulkan or OpenGLES3 (Meta's check, and its fix); stereo rendering Instancing, with the
        /// Oculus plug-in's Multiview on Android and Single Pass Instanced on desktop (when its settings exist).
        /// </summary>
        public static void ApplyRecommended(List<string> changes)
        {
            if (PlayerSettings.Android.targetSdkVersion != TargetApiLevel)
            {
                changes.Add("Android target API level 32 (was " + PlayerSettings.Android.targetSdkVersion + ")");
                PlayerSettings.Android.targetSdkVersion = TargetApiLevel;
            }
            if (PlayerSettings.Android.androidTVCompatibility)
            {
                changes.Add("Android TV compatibility off");
                PlayerSettings.Android.androidTVCompatibility = false;
            }
            if (!HasExplicitQuestGraphicsApi())
            {
                changes.Add("Android graphics APIs chosen explicitly: Vulkan");
                PlayerSettings.SetUseDefaultGraphicsAPIs(BuildTarget.Android, false);
                PlayerSettings.SetGraphicsAPIs(BuildTarget.Android, new[] { GraphicsDeviceType.Vulkan });
            }
            if (PlayerSettings.stereoRenderingPath != StereoRenderingPath.Instancing)
            {
                changes.Add("stereo rendering Instancing (was " + PlayerSettings.stereoRenderingPath + ")");
                PlayerSettings.stereoRenderingPath = StereoRenderingPath.Instancing;
            }
#if KOSMOS_XR_OCULUS
            if (EditorBuildSettings.TryGetConfigObject("Unity.XR.Oculus.Settings", out global::Unity.XR.Oculus.OculusSettings oculus))
            {
                if (oculus.m_StereoRenderingModeAndroid != global::Unity.XR.Oculus.OculusSettings.StereoRenderingModeAndroid.Multiview)
                {
                    oculus.m_StereoRenderingModeAndroid = global::Unity.XR.Oculus.OculusSettings.StereoRenderingModeAndroid.Multiview;
                    EditorUtility.SetDirty(oculus);
                    changes.Add("Oculus stereo rendering on Android Multiview");
                }
                if (oculus.m_StereoRenderingModeDesktop != global::Unity.XR.Oculus.OculusSettings.StereoRenderingModeDesktop.SinglePassInstanced)
                {
                    oculus.m_StereoRenderingModeDesktop = global::Unity.XR.Oculus.OculusSettings.StereoRenderingModeDesktop.SinglePassInstanced;
                    EditorUtility.SetDirty(oculus);
                    changes.Add("Oculus stereo rendering on desktop Single Pass Instanced");
                }
            }
#endif
        }

        /// <summary>Meta's check: the Android graphics APIs are chosen explicitly (not Unity's default list) and hold Vulkan or OpenGLES3.</summary>
        public static bool HasExplicitQuestGraphicsApi()
        {
            if (PlayerSettings.GetUseDefaultGraphicsAPIs(BuildTarget.Android)) return false;
            foreach (GraphicsDeviceType api in PlayerSettings.GetGraphicsAPIs(BuildTarget.Android))
                if (api == GraphicsDeviceType.Vulkan || api == GraphicsDeviceType.OpenGLES3) return true;
            return false;
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
