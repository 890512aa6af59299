// The tests' handle on the double (never part of the per-asmdef compile check, so package code cannot use it).
using System;
using NUnit.Framework;
using NUnit.Framework.Interfaces;
using UnityEngine;
using UnityEngine.TestTools.Logging;

namespace UnityDouble
{
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

        /// <summary>The items of the last context menu shown (GenericMenu.ShowAsContext): text, tooltip, enabled.</summary>
        public static System.Collections.Generic.IReadOnlyList<(string Text, string Tooltip, bool Enabled)> MenuShown
        {
            get
            {
                var items = new System.Collections.Generic.List<(string, string, bool)>();
                if (UnityEditor.GenericMenu.Shown != null)
                    foreach (var i in UnityEditor.GenericMenu.Shown.Items) items.Add((i.Text, i.Tooltip, i.Enabled));
                return items;
            }
        }

        /// <summary>The "user" picks the enabled item of the last menu with this text: its function runs.</summary>
        public static void ChooseMenuItem(string text)
        {
            foreach (var i in UnityEditor.GenericMenu.Shown.Items)
                if (i.Text == text && i.Enabled) { i.Function(); return; }
            throw new ArgumentException("no enabled menu item '" + text + "'");
        }

        /// <summary>The next EditorGUILayout field drawn with this label returns <paramref name="value"/> (the user typed it), once.</summary>
        public static void Type(string label, double value) => UnityEditor.EditorGUILayout.Typed[label] = value;

        /// <summary>Registers a prefab asset at <paramref name="path"/>: PrefabUtility.InstantiatePrefab of it builds an instance with <paramref name="make"/>.</summary>
        public static void Prefab(string path, Func<GameObject> make)
        {
            var placeholder = new GameObject(System.IO.Path.GetFileNameWithoutExtension(path)) { IsAsset = true };
            placeholder.SetActive(false);
            UnityEditor.AssetDatabase.Assets[path] = placeholder;
            UnityEditor.PrefabUtility.Prefabs[placeholder] = make;
        }
    }

    /// <summary>IMGUI: which button the "user" clicks next.</summary>
    public static class GUILayoutDriver
    {
        /// <summary>The next GUILayout.Button drawn with this text returns true, once.</summary>
        public static void Click(string buttonText) => UnityEngine.GUILayout.Clicked = buttonText;
    }
}

namespace UnityDouble
{
    /// <summary>Meta's Project Setup Tool: the tasks registered with OVRProjectSetup.AddTask, by message.</summary>
    public static class ProjectSetupTool
    {
        public static System.Collections.Generic.IEnumerable<string> Messages
        {
            get { foreach (OVRProjectSetup.Task t in OVRProjectSetup.Tasks) yield return t.Message; }
        }

        static OVRProjectSetup.Task Find(string message)
        {
            foreach (OVRProjectSetup.Task t in OVRProjectSetup.Tasks)
                if (t.Message == message) return t;
            throw new System.ArgumentException("no task '" + message + "'");
        }

        public static bool IsDone(string message, UnityEditor.BuildTargetGroup group) => Find(message).IsDone(group);
        public static void Fix(string message, UnityEditor.BuildTargetGroup group) => Find(message).Fix(group);
        public static bool CanFix(string message) => Find(message).Fix != null;
        public static OVRProjectSetup.TaskLevel Level(string message) => Find(message).Level;
        public static OVRProjectSetup.TaskGroup Group(string message) => Find(message).Group;
        public static UnityEditor.BuildTargetGroup Platform(string message) => Find(message).Platform;
    }
}
