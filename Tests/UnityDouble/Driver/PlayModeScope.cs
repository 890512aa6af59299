// The tests' handle on the double (never part of the per-asmdef compile check, so package code cannot use it).
using System;
using NUnit.Framework;
using NUnit.Framework.Interfaces;
using UnityEngine;
using UnityEngine.TestTools.Logging;

namespace UnityDouble
{
    /// <summary>
    /// Put on a test assembly (<c>[assembly: PlayModeScope]</c>): each test starts in an empty scene with the clock at
    /// zero, inside a log scope (an unexpected error, assertion or exception logged fails it, and so does an expected
    /// message that never came, as in Unity's Test Framework), and its objects are destroyed after it. Unity keeps one
    /// scene for a whole play-mode run; here no test can disturb another through objects it left behind.
    /// </summary>
    [AttributeUsage(AttributeTargets.Assembly | AttributeTargets.Class | AttributeTargets.Method)]
    public sealed class PlayModeScopeAttribute : Attribute, ITestAction
    {
        [ThreadStatic] static LogScope s_scope;

        public ActionTargets Targets => ActionTargets.Test;

        public void BeforeTest(ITest test)
        {
            Engine.Reset();
            UnityEditor.EditorState.Reset();
            OVRProjectConfig.ResetForTests();
            Application.IsBatchModeState = false;
            s_scope = new LogScope();
        }

        public void AfterTest(ITest test)
        {
            LogScope scope = s_scope;
            s_scope = null;
            try
            {
                if (TestContext.CurrentContext.Result.Outcome.Status != TestStatus.Failed) scope?.Check(true);
            }
            finally
            {
                scope?.Dispose();
                Engine.Reset();
            }
        }
    }

    /// <summary>Runs the double's player loop.</summary>
    public static class Frames
    {
        /// <summary>90 Hz, the Quest 2's default refresh rate: a frame's duration when Time.captureDeltaTime is not set.</summary>
        public const float DefaultDuration = Engine.DefaultFrameTime;

        /// <summary><paramref name="count"/> frames of <paramref name="dt"/> seconds each (Time.captureDeltaTime wins when set).</summary>
        public static void Run(int count, float dt = Engine.DefaultFrameTime)
        {
            for (int i = 0; i < count; i++) Engine.Frame(dt);
        }

        /// <summary>An empty scene and the clock at zero, within a test (as at its start).</summary>
        public static void Reset() => Engine.Reset();

        /// <summary>Frames until <paramref name="seconds"/> of game time have passed.</summary>
        public static void For(double seconds, float dt = Engine.DefaultFrameTime)
        {
            double until = Time.timeAsDouble + seconds;
            while (Time.timeAsDouble < until - 1e-9) Engine.Frame(dt);
        }
    }

    /// <summary>Contacts a test supplies (the double has no physics engine beyond spheres and boxes overlapping).</summary>
    public static class Contacts
    {
        /// <summary>From the next fixed step on, the two colliders touch (or, with false, stop touching unless they overlap).</summary>
        public static void Declare(Collider a, Collider b, bool touching) => PhysicsScene.Declare(a, b, touching);
    }

    /// <summary>What the double counts, for tests of per-frame work.</summary>
    public static class Diagnostics
    {
        /// <summary>Component searches (GetComponent, GetComponents, GetComponentInParent, GetComponentsInChildren) so far.</summary>
        public static long ComponentSearches => GameObject.Searches;
    }

    /// <summary>The editor the tests run "in": batch mode, the active build target, pending delayed calls, what was built.</summary>
    public static class Editor
    {
        public static bool IsBatchMode { get => Application.IsBatchModeState; set => Application.IsBatchModeState = value; }

        public static UnityEditor.BuildTarget ActiveBuildTarget
        {
            get => UnityEditor.EditorUserBuildSettings.ActiveBuildTarget;
            set => UnityEditor.EditorUserBuildSettings.ActiveBuildTarget = value;
        }

        /// <summary>Runs the static constructors of the [InitializeOnLoad] classes of <paramref name="assembly"/>, as the editor does when scripts load.</summary>
        public static void LoadScripts(System.Reflection.Assembly assembly)
        {
            foreach (Type t in assembly.GetTypes())
                if (t.IsDefined(typeof(UnityEditor.InitializeOnLoadAttribute), false))
                    System.Runtime.CompilerServices.RuntimeHelpers.RunClassConstructor(t.TypeHandle);
        }

        /// <summary>Runs and clears EditorApplication.delayCall, as the editor does after its current work.</summary>
        public static void RunDelayCalls()
        {
            UnityEditor.EditorApplication.CallbackFunction calls = UnityEditor.EditorApplication.delayCall;
            UnityEditor.EditorApplication.delayCall = null;
            calls?.Invoke();
        }

        public static int? ExitCode => UnityEditor.EditorApplication.ExitCode;
        public static System.Collections.Generic.IReadOnlyList<UnityEditor.BuildPlayerOptions> Builds => UnityEditor.BuildPipeline.Builds;
        public static System.Collections.Generic.IReadOnlyCollection<string> SavedScenes => UnityEditor.SceneManagement.EditorSceneManager.Saved.Keys;
        public static System.Collections.Generic.IReadOnlyList<string> InspectorShown => UnityEditor.EditorGUILayout.Shown;

        /// <summary>Registers a prefab asset at <paramref name="path"/>: PrefabUtility.InstantiatePrefab of it builds an instance with <paramref name="make"/>.</summary>
        public static void Prefab(string path, Func<GameObject> make)
        {
            var placeholder = new GameObject(System.IO.Path.GetFileNameWithoutExtension(path)) { IsAsset = true };
            placeholder.SetActive(false);
            UnityEditor.AssetDatabase.Assets[path] = placeholder;
            UnityEditor.PrefabUtility.Prefabs[placeholder] = make;
        }
    }
}

namespace UnityDouble
{
    /// <summary>IMGUI: which button the "user" clicks next.</summary>
    public static class GUILayoutDriver
    {
        /// <summary>The next GUILayout.Button drawn with this text returns true, once.</summary>
        public static void Click(string buttonText) => UnityEngine.GUILayout.Clicked = buttonText;
    }
}
