// Test double of the editor's project, build and asset services, holding their state in memory: the player settings
// and build settings a build reads, an asset database of paths (no files), scenes as lists of root objects, a build
// that records what it was asked to build and succeeds. Transcribed from Unity-Technologies/UnityCsReference, branch 2022.3:
//   Editor/Mono/EditorSceneManager.cs + EditorSceneManager.bindings.cs (EditorSceneManager, NewSceneSetup, NewSceneMode),
//   Modules/AssetDatabase/Editor/ScriptBindings/AssetDatabase.bindings.cs, Editor/Mono/Prefabs/PrefabUtility.cs,
//   Editor/Mono/EditorBuildSettings.bindings.cs, Editor/Mono/EditorApplication.bindings.cs,
//   Editor/Mono/EditorUserBuildSettings.bindings.cs (EditorUserBuildSettings, MobileTextureSubtarget),
//   Editor/Mono/BuildTarget.cs, Editor/Mono/BuildTargetGroup.cs, Editor/Mono/BuildPipeline.bindings.cs
//   (BuildOptions, BuildPlayerOptions, BuildPipeline), Modules/BuildReportingEditor/Managed/BuildReport.bindings.cs,
//   BuildSummary.cs, BuildResult.cs, Editor/Mono/BuildPipeline/NamedBuildTarget.cs,
//   Editor/Mono/PlayerSettings.bindings.cs (ScriptingImplementation, SetScriptingBackend),
//   Editor/Mono/PlayerSettingsAndroid.bindings.cs (PlayerSettings.Android, AndroidArchitecture, AndroidSdkVersions),
//   Editor/Mono/PlayerSettings.bindings.cs (stereoRenderingPath, Get/SetUseDefaultGraphicsAPIs, Get/SetGraphicsAPIs), StereoRenderingPath
using System;
using System.Collections.Generic;
using UnityEditor.Build;
using UnityEditor.Build.Reporting;
using UnityEngine;
using UnityEngine.Rendering;
using UnityEngine.SceneManagement;
using Object = UnityEngine.Object;

namespace UnityEditor.SceneManagement
{
    public enum NewSceneSetup { EmptyScene, DefaultGameObjects }

    public enum NewSceneMode { Single, Additive }

    public sealed class EditorSceneManager
    {
        internal static readonly Dictionary<string, List<GameObject>> Saved = new Dictionary<string, List<GameObject>>();
        internal static int NewScenes;

        /// <summary>Empties the scene (Single), with a tagged main camera and a light for DefaultGameObjects.</summary>
        public static Scene NewScene(NewSceneSetup setup, NewSceneMode mode)
        {
            if (mode == NewSceneMode.Single) Engine.Reset(keepAssets: true);
            NewScenes++;
            if (setup == NewSceneSetup.DefaultGameObjects)
            {
                var camera = new GameObject("Main Camera") { tag = "MainCamera" };
                camera.AddComponent<Camera>();
                new GameObject("Directional Light");
            }
            return new Scene { name = "Untitled", path = "" };
        }

        /// <summary>Records the scene's root objects under the path.</summary>
        public static bool SaveScene(Scene scene, string dstScenePath)
        {
            var roots = new List<GameObject>();
            foreach (GameObject go in Engine.GameObjects)
                if (go.transform.parent == null && !go.IsAsset) roots.Add(go);
            Saved[dstScenePath] = roots;
            return true;
        }

        public static bool SaveCurrentModifiedScenesIfUserWantsTo() => true;
    }
}

namespace UnityEditor
{
    /// <summary>The static constructor of a class with this attribute runs when the editor loads the scripts (the project opens, or scripts recompile).</summary>
    [AttributeUsage(AttributeTargets.Class)]
    public class InitializeOnLoadAttribute : Attribute
    {
    }

    public sealed partial class AssetDatabase
    {
        internal static readonly Dictionary<string, Object> Assets = new Dictionary<string, Object>();
        internal static readonly HashSet<string> Folders = new HashSet<string> { "Assets" };
        internal static int Saves;

        public static T LoadAssetAtPath<T>(string assetPath) where T : Object =>
            Assets.TryGetValue(assetPath, out Object o) && o is T t && !o.IsDestroyed ? t : null;

        /// <summary>Refuses a path whose folder does not exist, as Unity does (with an error).</summary>
        public static void CreateAsset(Object asset, string path)
        {
            int slash = path.LastIndexOf('/');
            if (slash < 0 || !Folders.Contains(path.Substring(0, slash)))
            {
                Debug.LogError("Couldn't create asset file: " + path + " (its folder does not exist)");
                return;
            }
            Assets[path] = asset;
            if (string.IsNullOrEmpty(asset.name)) asset.name = System.IO.Path.GetFileNameWithoutExtension(path);
        }

        public static void SaveAssets() => Saves++;

        /// <summary>Real (2020.3+): writes one asset to disk if it is dirty. Here: counted per object, its dirty mark cleared.</summary>
        public static void SaveAssetIfDirty(Object obj)
        {
            if (obj != null && EditorUtility.Dirty.Remove(obj)) Saved.Add(obj);
        }

        internal static readonly List<Object> Saved = new List<Object>();
        public static bool IsValidFolder(string path) => Folders.Contains(path);

        public static string CreateFolder(string parentFolder, string newFolderName)
        {
            if (!Folders.Contains(parentFolder)) return "";
            Folders.Add(parentFolder + "/" + newFolderName);
            return Guid.NewGuid().ToString("N");
        }
    }

    public sealed partial class PrefabUtility
    {
        public static Object InstantiatePrefab(Object assetComponentOrGameObject) => InstantiatePrefab(assetComponentOrGameObject, null);

        /// <summary>A copy of the prefab (built by the test as a factory registered with the asset database), under the parent.</summary>
        public static Object InstantiatePrefab(Object assetComponentOrGameObject, Transform parent)
        {
            if (!(assetComponentOrGameObject is GameObject prefab) || !Prefabs.TryGetValue(prefab, out Func<GameObject> make)) return null;
            GameObject instance = make();
            if (parent != null) instance.transform.SetParent(parent, false);
            return instance;
        }

        /// <summary>Prefab assets: a placeholder object and the factory that builds an instance.</summary>
        internal static readonly Dictionary<GameObject, Func<GameObject>> Prefabs = new Dictionary<GameObject, Func<GameObject>>();
    }

    public class EditorBuildSettingsScene
    {
        public EditorBuildSettingsScene(string path, bool enabled)
        {
            this.path = path;
            this.enabled = enabled;
        }

        public bool enabled { get; set; }
        public string path { get; set; }
    }

    public partial class EditorBuildSettings : Object
    {
        internal static readonly Dictionary<string, Object> ConfigObjects = new Dictionary<string, Object>();
        static EditorBuildSettingsScene[] s_scenes = new EditorBuildSettingsScene[0];

        public static EditorBuildSettingsScene[] scenes { get => s_scenes; set => s_scenes = value ?? new EditorBuildSettingsScene[0]; }

        public static void AddConfigObject(string name, Object obj, bool overwrite)
        {
            if (overwrite || !ConfigObjects.ContainsKey(name)) ConfigObjects[name] = obj;
        }

        public static bool TryGetConfigObject<T>(string name, out T result) where T : Object
        {
            result = ConfigObjects.TryGetValue(name, out Object o) ? o as T : null;
            return result != null;
        }
    }

    public sealed partial class EditorApplication
    {
        public delegate void CallbackFunction();

        /// <summary>Called once after the editor's current work (the driver runs it: UnityDouble.Editor.RunDelayCalls).</summary>
        public static CallbackFunction delayCall;

        /// <summary>The exit code asked for; the double's editor does not exit.</summary>
        public static void Exit(int returnValue) => ExitCode = returnValue;

        internal static int? ExitCode;
    }

    public partial class EditorUserBuildSettings : Object
    {
        public static BuildTarget activeBuildTarget => ActiveBuildTarget;
        public static MobileTextureSubtarget androidBuildSubtarget { get; set; } = MobileTextureSubtarget.Generic;
        internal static BuildTarget ActiveBuildTarget = BuildTarget.Android;
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
        StandaloneWindows64 = 19,
        Android = 13,
    }

    public enum BuildTargetGroup
    {
        Unknown = 0,
        Standalone = 1,
        Android = 7,
    }

    [Flags]
    public enum BuildOptions
    {
        None = 0,
    }

    public struct BuildPlayerOptions
    {
        public string[] scenes { get; set; }
        public string locationPathName { get; set; }
        public BuildTargetGroup targetGroup { get; set; }
        public BuildTarget target { get; set; }
        public BuildOptions options { get; set; }
    }

    public class BuildPipeline
    {
        /// <summary>Records the options and what the project's settings were, and succeeds (nothing is compiled or packaged).</summary>
        public static BuildReport BuildPlayer(BuildPlayerOptions buildPlayerOptions)
        {
            Builds.Add(buildPlayerOptions);
            return new BuildReport(new BuildSummary(BuildResult.Succeeded, 0, 0));
        }

        internal static readonly List<BuildPlayerOptions> Builds = new List<BuildPlayerOptions>();
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
    /// <summary>As in Unity 2022.3.0f1, the oldest the package supports: its last member is AndroidApiLevel30
    /// (AndroidApiLevel32 came in 2022.3.21f1; a level above 30 is used by its number).</summary>
    public enum AndroidSdkVersions
    {
        AndroidApiLevelAuto = 0,
        AndroidApiLevel22 = 22,
        AndroidApiLevel29 = 29,
        AndroidApiLevel30 = 30,
    }

    /// <summary>Editor/Mono/PlayerSettings.bindings.cs.</summary>
    public enum StereoRenderingPath
    {
        MultiPass = 0,
        SinglePass = 1,
        Instancing = 2,
    }

    public sealed partial class PlayerSettings : Object
    {
        internal static readonly Dictionary<string, ScriptingImplementation> Backends = new Dictionary<string, ScriptingImplementation>();

        /// <summary>A new project's is Gamma.</summary>
        public static ColorSpace colorSpace { get; set; } = ColorSpace.Gamma;

        public static ScriptingImplementation GetScriptingBackend(NamedBuildTarget buildTarget) =>
            Backends.TryGetValue(buildTarget.TargetName, out ScriptingImplementation b) ? b : ScriptingImplementation.Mono2x;

        public static void SetScriptingBackend(NamedBuildTarget buildTarget, ScriptingImplementation backend) => Backends[buildTarget.TargetName] = backend;

        /// <summary>A new project's: multi pass.</summary>
        public static StereoRenderingPath stereoRenderingPath { get; set; } = StereoRenderingPath.MultiPass;

        internal static readonly Dictionary<BuildTarget, GraphicsDeviceType[]> GraphicsApis = new Dictionary<BuildTarget, GraphicsDeviceType[]>();
        internal static readonly HashSet<BuildTarget> ExplicitGraphicsApis = new HashSet<BuildTarget>();

        /// <summary>A new project's: automatic (Unity picks the list).</summary>
        public static bool GetUseDefaultGraphicsAPIs(BuildTarget platform) => !ExplicitGraphicsApis.Contains(platform);

        public static void SetUseDefaultGraphicsAPIs(BuildTarget platform, bool automatic)
        {
            if (automatic) ExplicitGraphicsApis.Remove(platform);
            else ExplicitGraphicsApis.Add(platform);
        }

        /// <summary>With automatic selection, Unity's default list (for Android in 2022.3: Vulkan, then OpenGLES3).</summary>
        public static GraphicsDeviceType[] GetGraphicsAPIs(BuildTarget platform) =>
            (GraphicsApis.TryGetValue(platform, out GraphicsDeviceType[] apis) ? apis : new[] { GraphicsDeviceType.Vulkan, GraphicsDeviceType.OpenGLES3 }).Clone() as GraphicsDeviceType[];

        public static void SetGraphicsAPIs(BuildTarget platform, GraphicsDeviceType[] apis) => GraphicsApis[platform] = (GraphicsDeviceType[])apis.Clone();

        public partial class Android
        {
            /// <summary>A new 2022.3 project's: API level 22, ARMv7 only, target API Automatic, Android TV compatible (older projects' default; the check that follows turns it off).</summary>
            public static AndroidSdkVersions minSdkVersion { get; set; } = AndroidSdkVersions.AndroidApiLevel22;
            public static AndroidArchitecture targetArchitectures { get; set; } = AndroidArchitecture.ARMv7;
            public static AndroidSdkVersions targetSdkVersion { get; set; } = AndroidSdkVersions.AndroidApiLevelAuto;
            public static bool androidTVCompatibility { get; set; } = true;
        }
    }
}

namespace UnityEditor.Build
{
    public readonly struct NamedBuildTarget : IEquatable<NamedBuildTarget>
    {
        public static readonly NamedBuildTarget Android = new NamedBuildTarget("Android");
        public static readonly NamedBuildTarget Standalone = new NamedBuildTarget("Standalone");

        public string TargetName { get; }

        NamedBuildTarget(string name) => TargetName = name;

        public bool Equals(NamedBuildTarget other) => TargetName == other.TargetName;
        public override bool Equals(object obj) => obj is NamedBuildTarget n && Equals(n);
        public override int GetHashCode() => TargetName != null ? TargetName.GetHashCode() : 0;
    }
}

namespace UnityEditor.Build.Reporting
{
    public sealed class BuildReport : Object
    {
        internal BuildReport(BuildSummary summary) => this.summary = summary;

        public BuildSummary summary { get; }
    }

    public struct BuildSummary
    {
        internal BuildSummary(BuildResult result, ulong size, int errors)
        {
            this.result = result;
            totalSize = size;
            totalErrors = errors;
        }

        public ulong totalSize { get; }
        public int totalErrors { get; }
        public BuildResult result { get; }
    }

    public enum BuildResult
    {
        Unknown = 0,
        Succeeded = 1,
        Failed = 2,
        Cancelled = 3,
    }
}

namespace UnityEditor
{
    /// <summary>The editor double's state, back to a new project's (the driver resets it before each test).</summary>
    internal static class EditorState
    {
        internal static void Reset()
        {
            PlayerSettings.colorSpace = ColorSpace.Gamma;
            PlayerSettings.Backends.Clear();
            PlayerSettings.Android.minSdkVersion = AndroidSdkVersions.AndroidApiLevel22;
            PlayerSettings.Android.targetArchitectures = AndroidArchitecture.ARMv7;
            PlayerSettings.Android.targetSdkVersion = AndroidSdkVersions.AndroidApiLevelAuto;
            PlayerSettings.Android.androidTVCompatibility = true;
            PlayerSettings.stereoRenderingPath = StereoRenderingPath.MultiPass;
            PlayerSettings.GraphicsApis.Clear();
            PlayerSettings.ExplicitGraphicsApis.Clear();
            EditorUserBuildSettings.ActiveBuildTarget = BuildTarget.Android;
            EditorUserBuildSettings.androidBuildSubtarget = MobileTextureSubtarget.Generic;
            EditorBuildSettings.scenes = new EditorBuildSettingsScene[0];
            EditorBuildSettings.ConfigObjects.Clear();
            AssetDatabase.Assets.Clear();
            AssetDatabase.Folders.Clear();
            AssetDatabase.Folders.Add("Assets");
            AssetDatabase.Saves = 0;
            PrefabUtility.Prefabs.Clear();
            SceneManagement.EditorSceneManager.Saved.Clear();
            SceneManagement.EditorSceneManager.NewScenes = 0;
            BuildPipeline.Builds.Clear();
            EditorApplication.delayCall = null;
            EditorApplication.ExitCode = null;
            EditorUtility.Dirty.Clear();
            AssetDatabase.Saved.Clear();
            EditorGUILayout.Shown.Clear();
        }
    }
}
