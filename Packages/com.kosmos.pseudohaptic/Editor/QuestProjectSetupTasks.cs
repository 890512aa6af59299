#if KOSMOS_META_XR_CORE
using System;
using System.Collections.Generic;
using UnityEditor;
using UnityEngine;
#if KOSMOS_XR_MANAGEMENT && KOSMOS_XR_OCULUS
using UnityEditor.XR.Management;
using UnityEngine.XR.Management;
#endif

namespace Kosmos.PseudoHaptic.Editor
{
    /// <summary>
    /// The package's own Quest requirements as tasks of Meta's Project Setup Tool (<c>OVRProjectSetup.AddTask</c>, Meta XR
    /// Core SDK 68.0.2), so they are listed, checked and fixed in Meta's own window (<i>Meta ▸ Tools ▸ Project Setup Tool</i>)
    /// beside Meta's: hand tracking allowed in Meta's project config (required, Android), XR initialised on startup for
    /// Android (required), ASTC textures (recommended, Android). Meta's own tasks already cover the rest of what
    /// <see cref="QuestProjectSettings"/> sets (colour space, IL2CPP, ARM64, API levels, the Oculus loader, graphics APIs,
    /// stereo rendering, Android TV). Registered once when the editor loads the scripts; compiled only with the Meta XR Core SDK.
    /// </summary>
    [InitializeOnLoad]
    public static class QuestProjectSetupTasks
    {
        public const string HandTrackingMessage = "Kosmos Pseudo-Haptic: hand tracking must be allowed (Hand Tracking Support: Controllers And Hands or Hands Only) for bare-hand weight";
        public const string InitializeXRMessage = "Kosmos Pseudo-Haptic: XR must be initialised on startup for Android, or the APK starts as a flat Android app";
        public const string TexturesMessage = "Kosmos Pseudo-Haptic: ASTC texture compression for Quest 2";

        static QuestProjectSetupTasks() => Register();

        /// <summary>Adds the tasks; a second call (or a task already there) changes nothing and logs nothing.</summary>
        public static void Register()
        {
            Add(OVRProjectSetup.TaskGroup.Features, OVRProjectSetup.TaskLevel.Required, HandTrackingMessage,
                _ => OVRProjectConfig.CachedProjectConfig != null && OVRProjectConfig.CachedProjectConfig.handTrackingSupport != OVRProjectConfig.HandTrackingSupport.ControllersOnly,
                _ => QuestProjectSettings.ApplyHandTracking(false, new List<string>()),
                "OVRProjectConfig.handTrackingSupport = ControllersAndHands");
#if KOSMOS_XR_MANAGEMENT && KOSMOS_XR_OCULUS
            Add(OVRProjectSetup.TaskGroup.Compatibility, OVRProjectSetup.TaskLevel.Required, InitializeXRMessage,
                _ => EditorBuildSettings.TryGetConfigObject(XRGeneralSettings.k_SettingsKey, out XRGeneralSettingsPerBuildTarget perTarget)
                     && perTarget.HasManagerSettingsForBuildTarget(BuildTargetGroup.Android)
                     && perTarget.SettingsForBuildTarget(BuildTargetGroup.Android).InitManagerOnStart,
                _ => QuestProjectSettings.ApplyXRLoader(BuildTargetGroup.Android, false, new List<string>()),
                "XR Plug-in Management > Android: Initialize XR on Startup, with the Oculus loader");
#endif
            Add(OVRProjectSetup.TaskGroup.Quality, OVRProjectSetup.TaskLevel.Recommended, TexturesMessage,
                _ => EditorUserBuildSettings.androidBuildSubtarget == MobileTextureSubtarget.ASTC,
                _ => EditorUserBuildSettings.androidBuildSubtarget = MobileTextureSubtarget.ASTC,
                "EditorUserBuildSettings.androidBuildSubtarget = ASTC");
        }

        static void Add(OVRProjectSetup.TaskGroup group, OVRProjectSetup.TaskLevel level, string message,
                        Func<BuildTargetGroup, bool> isDone, Action<BuildTargetGroup> fix, string fixMessage)
        {
            try
            {
                OVRProjectSetup.AddTask(group: group, isDone: isDone, platform: BuildTargetGroup.Android, fix: fix, level: level, message: message, fixMessage: fixMessage);
            }
            catch (ArgumentException)
            {
                // Already registered (the tool keys a task by its message): once is enough.
            }
        }
    }
}
#endif
