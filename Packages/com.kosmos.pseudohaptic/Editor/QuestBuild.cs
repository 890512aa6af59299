using System;
using System.Collections.Generic;
using System.IO;
using UnityEditor;
using UnityEditor.Build;
using UnityEditor.Build.Reporting;
using UnityEngine;

namespace Kosmos.PseudoHaptic.Editor
{
    /// <summary>
    /// Builds a Quest 2 APK: Android, IL2CPP, ARM64, ASTC, hand tracking declared through Meta's project
    /// settings (OVRProjectConfig, which Meta's build step writes into the manifest). From the menu, or
    /// headless:
    /// <c>Unity -batchmode -projectPath . -executeMethod Kosmos.PseudoHaptic.Editor.QuestBuild.Build -apkPath Build/Quest2/PseudoHapticWeight.apk</c>.
    /// Builds the enabled scenes of the build settings, or the sample scenes when there are none.
    /// In batch mode the editor exits with 0 on success and 1 on failure.
    /// </summary>
    public static class QuestBuild
    {
        public const string DefaultApkPath = "Build/Quest2/PseudoHapticWeight.apk";
        public const string ApkPathArgument = "-apkPath";

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

        /// <summary>Android target, IL2CPP, ARM64 only, API level ≥ 29, ASTC textures, hand tracking on.</summary>
        public static void ConfigureProject()
        {
            if (EditorUserBuildSettings.activeBuildTarget != BuildTarget.Android)
                EditorUserBuildSettings.SwitchActiveBuildTarget(BuildTargetGroup.Android, BuildTarget.Android);
            PlayerSettings.SetScriptingBackend(NamedBuildTarget.Android, ScriptingImplementation.IL2CPP);
            PlayerSettings.Android.targetArchitectures = AndroidArchitecture.ARM64;
            if (PlayerSettings.Android.minSdkVersion < AndroidSdkVersions.AndroidApiLevel29)
                PlayerSettings.Android.minSdkVersion = AndroidSdkVersions.AndroidApiLevel29;
            EditorUserBuildSettings.androidBuildSubtarget = MobileTextureSubtarget.ASTC;
#if KOSMOS_META_XR_CORE
            // Meta's Android build step declares the hand-tracking permission and feature from this setting.
            OVRProjectConfig config = OVRProjectConfig.CachedProjectConfig;
            if (config.handTrackingSupport == OVRProjectConfig.HandTrackingSupport.ControllersOnly)
                config.handTrackingSupport = OVRProjectConfig.HandTrackingSupport.ControllersAndHands;
            OVRProjectConfig.CommitProjectConfig(config);
#else
            Debug.LogWarning("Meta XR Core SDK (com.meta.xr.sdk.core) is not installed: hand tracking is not declared in the APK's manifest.");
#endif
            AssetDatabase.SaveAssets();
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
