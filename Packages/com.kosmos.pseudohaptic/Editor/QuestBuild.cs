using System;
using System.Collections.Generic;
using System.IO;
using UnityEditor;
using UnityEditor.Build;
using UnityEditor.Build.Reporting;
using UnityEngine;
#if KOSMOS_XR_MANAGEMENT && KOSMOS_XR_OCULUS
using UnityEditor.XR.Management;
using UnityEditor.XR.Management.Metadata;
using UnityEngine.XR.Management;
#endif

namespace Kosmos.PseudoHaptic.Editor
{
    /// <summary>
    /// Builds a Quest 2 APK: Android, IL2CPP, ARM64, ASTC, XR Plug-in Management with the Oculus loader for
    /// Android (initialised on startup), hand tracking declared through Meta's project settings
    /// (OVRProjectConfig, which Meta's build step writes into the manifest). From the menu, or headless, with
    /// the build target given on the command line (switching it inside <c>-executeMethod</c> would recompile the
    /// scripts under the running method):
    /// <c>Unity -batchmode -projectPath . -buildTarget Android -executeMethod Kosmos.PseudoHaptic.Editor.QuestBuild.Build -apkPath Build/Quest2/PseudoHapticWeight.apk</c>.
    /// Builds the enabled scenes of the build settings, or the sample scenes when there are none.
    /// In batch mode the editor exits with 0 on success and 1 on failure.
    /// </summary>
    public static class QuestBuild
    {
        public const string DefaultApkPath = "Build/Quest2/PseudoHapticWeight.apk";
        public const string ApkPathArgument = "-apkPath";

        /// <summary>The XR loader assigned for Android: the Oculus XR Plugin's (com.unity.xr.oculus).</summary>
        public const string OculusLoaderType = "Unity.XR.Oculus.OculusLoader";

        [MenuItem("Tools/Kosmos Pseudo-Haptic/Build Quest 2 APK", priority = 100)]
        static void BuildFromMenu() => Build();

        [MenuItem("Tools/Kosmos Pseudo-Haptic/Configure Project for Quest 2", priority = 101)]
        static void ConfigureFromMenu() => ConfigureProject();

        /// <summary>Entry point for <c>-executeMethod</c>.</summary>
        public static void Build()
        {
            string apk = ArgumentValue(ApkPathArgument) ?? DefaultApkPath;
            bool ok;
            try
            {
                ok = BuildApk(apk);
            }
            catch (Exception e)
            {
                Debug.LogException(e);
                ok = false;
            }
            if (Application.isBatchMode) EditorApplication.Exit(ok ? 0 : 1);
        }

        /// <summary>Configures the project and builds <paramref name="apkPath"/>; true when the build succeeded.</summary>
        public static bool BuildApk(string apkPath)
        {
            ConfigureProject();
#if KOSMOS_XR_HANDS
            // Issue 14: Unity XR Hands reads hands through OpenXR (the Hand Tracking Subsystem feature); this build assigns the
            // Oculus loader, under which no XRHandSubsystem runs.
            Debug.LogWarning("Quest 2 build: com.unity.xr.hands is installed, but this build assigns the Oculus XR loader: XRHandPoseSource components will read no hand. Use OvrHandPoseSource (the sample scenes' default), or build with the OpenXR loader and its Hand Tracking Subsystem and Meta Quest features yourself.");
#endif
            string[] scenes = EnabledScenes();
            if (scenes.Length == 0)
            {
                SampleScenes.BuildAll();
                scenes = EnabledScenes();
            }
            string folder = Path.GetDirectoryName(Path.GetFullPath(apkPath));
            if (!string.IsNullOrEmpty(folder)) Directory.CreateDirectory(folder);

            var options = new BuildPlayerOptions
            {
                scenes = scenes,
                locationPathName = apkPath,
                target = BuildTarget.Android,
                targetGroup = BuildTargetGroup.Android,
                options = BuildOptions.None,
            };
            BuildReport report = BuildPipeline.BuildPlayer(options);
            BuildSummary summary = report.summary;
            bool ok = summary.result == BuildResult.Succeeded;
            string line = "Quest 2 build " + summary.result + ": " + apkPath + " (" + summary.totalSize + " bytes, "
                + summary.totalErrors + " errors) from " + string.Join(", ", scenes);
            if (ok) Debug.Log(line);
            else Debug.LogError(line);
            return ok;
        }

        /// <summary>
        /// IL2CPP, ARM64 only, API level ≥ 29, ASTC textures, the Oculus XR loader for Android initialised on
        /// startup, hand tracking on. Throws, saying what to do, when the active target is not Android or a
        /// required package is missing.
        /// </summary>
        public static void ConfigureProject()
        {
            if (EditorUserBuildSettings.activeBuildTarget != BuildTarget.Android)
                throw new InvalidOperationException("The active build target is " + EditorUserBuildSettings.activeBuildTarget
                    + ", not Android. Start Unity with -buildTarget Android, or in the editor choose File > Build Settings > Android > Switch Platform, then build again.");
            PlayerSettings.SetScriptingBackend(NamedBuildTarget.Android, ScriptingImplementation.IL2CPP);
            PlayerSettings.Android.targetArchitectures = AndroidArchitecture.ARM64;
            if (PlayerSettings.Android.minSdkVersion < AndroidSdkVersions.AndroidApiLevel29)
                PlayerSettings.Android.minSdkVersion = AndroidSdkVersions.AndroidApiLevel29;
            EditorUserBuildSettings.androidBuildSubtarget = MobileTextureSubtarget.ASTC;
            ConfigureXRLoader();
#if KOSMOS_META_XR_CORE
            // Meta's Android build step declares the hand-tracking permission and feature from this setting.
            OVRProjectConfig config = OVRProjectConfig.CachedProjectConfig;
            if (config == null)
                throw new InvalidOperationException("Meta's project config (OVRProjectConfig.CachedProjectConfig) could not be loaded or created, so hand tracking cannot be declared in the APK. "
                    + "Open Meta > Tools > Project Setup Tool once (it creates Assets/Oculus/OculusProjectConfig.asset), then build again.");
            if (config.handTrackingSupport == OVRProjectConfig.HandTrackingSupport.ControllersOnly)
                config.handTrackingSupport = OVRProjectConfig.HandTrackingSupport.ControllersAndHands;
            OVRProjectConfig.CommitProjectConfig(config);
#else
            Debug.LogWarning("Meta XR Core SDK (com.meta.xr.sdk.core) is not installed: hand tracking is not declared in the APK's manifest.");
#endif
            AssetDatabase.SaveAssets();
        }

        /// <summary>
        /// XR Plug-in Management for Android: the settings asset (created under Assets/XR and registered when the
        /// project has none), the Oculus loader assigned, XR initialised on startup. Without it the APK starts
        /// as a flat Android app.
        /// </summary>
        static void ConfigureXRLoader()
        {
#if KOSMOS_XR_MANAGEMENT && KOSMOS_XR_OCULUS
            if (!EditorBuildSettings.TryGetConfigObject(XRGeneralSettings.k_SettingsKey, out XRGeneralSettingsPerBuildTarget perTarget))
            {
                perTarget = ScriptableObject.CreateInstance<XRGeneralSettingsPerBuildTarget>();
                if (!AssetDatabase.IsValidFolder("Assets/XR")) AssetDatabase.CreateFolder("Assets", "XR");
                AssetDatabase.CreateAsset(perTarget, "Assets/XR/XRGeneralSettingsPerBuildTarget.asset");
                EditorBuildSettings.AddConfigObject(XRGeneralSettings.k_SettingsKey, perTarget, true);
            }
            if (!perTarget.HasManagerSettingsForBuildTarget(BuildTargetGroup.Android))
                perTarget.CreateDefaultManagerSettingsForBuildTarget(BuildTargetGroup.Android);
            XRGeneralSettings android = perTarget.SettingsForBuildTarget(BuildTargetGroup.Android);
            android.InitManagerOnStart = true;
            if (!XRPackageMetadataStore.AssignLoader(android.Manager, OculusLoaderType, BuildTargetGroup.Android)
                || !XRPackageMetadataStore.IsLoaderAssigned(OculusLoaderType, BuildTargetGroup.Android))
                throw new InvalidOperationException("The Oculus XR loader (" + OculusLoaderType + ") could not be assigned for Android in XR Plug-in Management: "
                    + "the APK would not start in VR. Enable it in Project Settings > XR Plug-in Management > Android > Oculus, then build again.");
            EditorUtility.SetDirty(android);
            EditorUtility.SetDirty(perTarget);
            // The Oculus plug-in's own settings exist once its settings page has been opened; they default to Quest 2.
            if (EditorBuildSettings.TryGetConfigObject("Unity.XR.Oculus.Settings", out global::Unity.XR.Oculus.OculusSettings oculus) && !oculus.TargetQuest2)
            {
                oculus.TargetQuest2 = true;
                EditorUtility.SetDirty(oculus);
            }
#else
            throw new InvalidOperationException("XR Plug-in Management (com.unity.xr.management 4.4.0 or later) and the Oculus XR Plugin (com.unity.xr.oculus 4.2.0 or later) "
                + "must be installed to build for Quest: without an XR loader the APK starts as a flat Android app. Add both (the project's Packages/manifest.json pins them).");
#endif
        }

        static string[] EnabledScenes()
        {
            var list = new List<string>();
            foreach (EditorBuildSettingsScene s in EditorBuildSettings.scenes)
                if (s.enabled && !string.IsNullOrEmpty(s.path)) list.Add(s.path);
            return list.ToArray();
        }

        static string ArgumentValue(string name)
        {
            string[] args = Environment.GetCommandLineArgs();
            for (int i = 0; i + 1 < args.Length; i++)
                if (args[i] == name) return args[i + 1];
            return null;
        }
    }
}
