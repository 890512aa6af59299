using System;
using System.Collections.Generic;
using System.IO;
using UnityEditor;
using UnityEditor.Build.Reporting;
using UnityEngine;

namespace Kosmos.PseudoHaptic.Editor
{
    /// <summary>
    /// Builds a Quest 2 APK: Android, colour space Linear, IL2CPP, ARM64, ASTC, XR Plug-in Management with the Oculus loader for
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
        public const string OculusLoaderType = QuestProjectSettings.OculusLoaderType;

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
        /// Colour space Linear, IL2CPP, ARM64 only, API level ≥ 29, ASTC textures, the Oculus XR loader for Android (and for
        /// Standalone, Play over Link) initialised on startup, hand tracking on (<see cref="QuestProjectSettings"/>). Throws,
        /// saying what to do, when the active target is not Android or a required package is missing.
        /// </summary>
        public static void ConfigureProject()
        {
            if (EditorUserBuildSettings.activeBuildTarget != BuildTarget.Android)
                throw new InvalidOperationException("The active build target is " + EditorUserBuildSettings.activeBuildTarget
                    + ", not Android. Start Unity with -buildTarget Android, or in the editor choose File > Build Settings > Android > Switch Platform, then build again.");
            var changes = QuestProjectSettings.Apply(strict: true);
            Debug.Log("Quest 2 project settings: " + (changes.Count > 0 ? string.Join("; ", changes) : "already set") + ".");
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
