// Compile-only. Transcribed from Unity-Technologies/UnityCsReference, branch 2022.3:
//   Editor/Mono/EditorSceneManager.cs + EditorSceneManager.bindings.cs (EditorSceneManager, NewSceneSetup, NewSceneMode),
//   Modules/AssetDatabase/Editor/ScriptBindings/AssetDatabase.bindings.cs, Editor/Mono/Prefabs/PrefabUtility.cs,
//   Editor/Mono/EditorBuildSettings.bindings.cs, Editor/Mono/EditorApplication.bindings.cs,
//   Editor/Mono/EditorUserBuildSettings.bindings.cs (EditorUserBuildSettings, MobileTextureSubtarget),
//   Editor/Mono/BuildTarget.cs, Editor/Mono/BuildTargetGroup.cs, Editor/Mono/BuildPipeline.bindings.cs
//   (BuildOptions, BuildPlayerOptions, BuildPipeline), Modules/BuildReportingEditor/Managed/BuildReport.bindings.cs,
//   BuildSummary.cs, BuildResult.cs, Editor/Mono/BuildPipeline/NamedBuildTarget.cs,
//   Editor/Mono/PlayerSettings.bindings.cs (ScriptingImplementation, SetScriptingBackend),
//   Editor/Mono/PlayerSettingsAndroid.bindings.cs (PlayerSettings.Android, AndroidArchitecture, AndroidSdkVersions)
using System;
using UnityEditor.Build;
using UnityEditor.Build.Reporting;
using UnityEngine;
using UnityEngine.SceneManagement;
using Object = UnityEngine.Object;

namespace UnityEditor.SceneManagement
{
    public enum NewSceneSetup { EmptyScene, DefaultGameObjects }

    public enum NewSceneMode { Single, Additive }

    public sealed class EditorSceneManager
    {
        public static Scene NewScene(NewSceneSetup setup, NewSceneMode mode) => throw null;
        public static bool SaveScene(Scene scene, string dstScenePath) => throw null;
        public static bool SaveCurrentModifiedScenesIfUserWantsTo() => throw null;
    }
}

namespace UnityEditor
{
    public sealed partial class AssetDatabase
    {
        public static T LoadAssetAtPath<T>(string assetPath) where T : Object => throw null;
        public static void CreateAsset(Object asset, string path) => throw null;
        public static void SaveAssets() => throw null;
        public static bool IsValidFolder(string path) => throw null;
        public static string CreateFolder(string parentFolder, string newFolderName) => throw null;
    }

    public sealed partial class PrefabUtility
    {
        public static Object InstantiatePrefab(Object assetComponentOrGameObject) => throw null;
        public static Object InstantiatePrefab(Object assetComponentOrGameObject, Transform parent) => throw null;
    }

    public class EditorBuildSettingsScene
    {
        public EditorBuildSettingsScene(string path, bool enabled) => throw null;
        public bool enabled { get => throw null; set => throw null; }
        public string path { get => throw null; set => throw null; }
    }

    public partial class EditorBuildSettings : Object
    {
        public static EditorBuildSettingsScene[] scenes { get => throw null; set => throw null; }
        public static void AddConfigObject(string name, Object obj, bool overwrite) => throw null;
        public static bool TryGetConfigObject<T>(string name, out T result) where T : Object => throw null;
    }

    public sealed partial class EditorApplication
    {
        public static void Exit(int returnValue) => throw null;
    }

    public partial class EditorUserBuildSettings : Object
    {
        public static BuildTarget activeBuildTarget => throw null;
        public static MobileTextureSubtarget androidBuildSubtarget { get => throw null; set => throw null; }
    }

    public enum MobileTextureSubtarget
    {
        Generic = 0,
        DXT = 1,
        PVRTC = 2,
        ETC = 4,
        ETC2 = 5,
        ASTC = 6,
    }

    /// <summary>Only the targets the package names.</summary>
    public enum BuildTarget
    {
        Android = 13,
    }

    public enum BuildTargetGroup
    {
        Unknown = 0,
        Android = 7,
    }

    [Flags]
    public enum BuildOptions
    {
        None = 0,
    }

    public struct BuildPlayerOptions
    {
        public string[] scenes { get => throw null; set => throw null; }
        public string locationPathName { get => throw null; set => throw null; }
        public BuildTargetGroup targetGroup { get => throw null; set => throw null; }
        public BuildTarget target { get => throw null; set => throw null; }
        public BuildOptions options { get => throw null; set => throw null; }
    }

    public class BuildPipeline
    {
        public static BuildReport BuildPlayer(BuildPlayerOptions buildPlayerOptions) => throw null;
    }

    public enum ScriptingImplementation
    {
        Mono2x = 0,
        IL2CPP = 1,
        WinRTDotNET = 2,
    }

    [Flags]
    public enum AndroidArchitecture : uint
    {
        None = 0,
        ARMv7 = 1 << 0,
        ARM64 = 1 << 1,
        X86 = 1 << 2,
        X86_64 = 1 << 3,
    }

    /// <summary>Only the levels the package names.</summary>
    public enum AndroidSdkVersions
    {
        AndroidApiLevel29 = 29,
    }

    public sealed partial class PlayerSettings : Object
    {
        public static void SetScriptingBackend(NamedBuildTarget buildTarget, ScriptingImplementation backend) => throw null;

        public partial class Android
        {
            public static AndroidSdkVersions minSdkVersion { get => throw null; set => throw null; }
            public static AndroidArchitecture targetArchitectures { get => throw null; set => throw null; }
        }
    }
}

namespace UnityEditor.Build
{
    public readonly struct NamedBuildTarget : IEquatable<NamedBuildTarget>
    {
        public static readonly NamedBuildTarget Android;
        public bool Equals(NamedBuildTarget other) => throw null;
        public override bool Equals(object obj) => throw null;
        public override int GetHashCode() => throw null;
    }
}

namespace UnityEditor.Build.Reporting
{
    public sealed class BuildReport : Object
    {
        public BuildSummary summary => throw null;
    }

    public struct BuildSummary
    {
        public ulong totalSize => throw null;
        public int totalErrors => throw null;
        public BuildResult result => throw null;
    }

    public enum BuildResult
    {
        Unknown = 0,
        Succeeded = 1,
        Failed = 2,
        Cancelled = 3,
    }
}
