using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;
using Kosmos.PseudoHaptic.Editor;
using NUnit.Framework;
using UnityDouble;
using UnityEditor;
using UnityEditor.Build;
using UnityEngine;
using UnityEngine.Rendering;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>
    /// Issue 34 item 4: Meta's Project Setup Tool recommendations (Meta XR Core SDK 68.0.2) that the Quest settings apply, the
    /// package's own requirements registered as Project Setup Tool tasks, and the committed ProjectSettings that already hold
    /// what the code would set.
    /// </summary>
    public sealed class QuestRecommendationsTests
    {
        [Test]
        public void ANewProjectGetsMetasRecommendationsOnceAndSaysWhat()
        {
            var oculus = ScriptableObject.CreateInstance<global::Unity.XR.Oculus.OculusSettings>();
            oculus.m_StereoRenderingModeAndroid = global::Unity.XR.Oculus.OculusSettings.StereoRenderingModeAndroid.MultiPass;
            oculus.m_StereoRenderingModeDesktop = global::Unity.XR.Oculus.OculusSettings.StereoRenderingModeDesktop.MultiPass;
            EditorBuildSettings.AddConfigObject("Unity.XR.Oculus.Settings", oculus, true);

            var changes = new List<string>();
            QuestProjectSettings.ApplyRecommended(changes);
            Assert.That(changes, Is.EqualTo(new[]
            {
                "Android target API level 32 (was AndroidApiLevelAuto)",
                "Android TV compatibility off",
                "Android graphics APIs chosen explicitly: Vulkan",
                "stereo rendering Instancing (was MultiPass)",
                "Oculus stereo rendering on Android Multiview",
                "Oculus stereo rendering on desktop Single Pass Instanced",
            }));
            Assert.That((int)PlayerSettings.Android.targetSdkVersion, Is.EqualTo(32), "Meta's TargetAPILevel: AndroidApiLevel32");
            Assert.That(PlayerSettings.Android.androidTVCompatibility, Is.False);
            Assert.That(PlayerSettings.GetUseDefaultGraphicsAPIs(BuildTarget.Android), Is.False, "chosen, not Unity's default list");
            Assert.That(PlayerSettings.GetGraphicsAPIs(BuildTarget.Android), Is.EqualTo(new[] { GraphicsDeviceType.Vulkan }), "Meta's fix");
            Assert.That(PlayerSettings.stereoRenderingPath, Is.EqualTo(StereoRenderingPath.Instancing));
            Assert.That((int)oculus.m_StereoRenderingModeAndroid, Is.EqualTo(2), "Multiview");

            var again = new List<string>();
            QuestProjectSettings.ApplyRecommended(again);
            Assert.That(again, Is.Empty, "nothing left to set");
        }

        [Test]
        public void AnExplicitListWithOpenGLES3IsLeftAsItIsAndAListWithNeitherIsNot()
        {
            PlayerSettings.SetUseDefaultGraphicsAPIs(BuildTarget.Android, false);
            PlayerSettings.SetGraphicsAPIs(BuildTarget.Android, new[] { GraphicsDeviceType.OpenGLES3 });
            Assert.That(QuestProjectSettings.HasExplicitQuestGraphicsApi(), Is.True, "Meta's check: Vulkan or OpenGLES3, chosen explicitly");
            var changes = new List<string>();
            QuestProjectSettings.ApplyRecommended(changes);
            Assert.That(changes, Has.None.Contains("graphics"));
            Assert.That(PlayerSettings.GetGraphicsAPIs(BuildTarget.Android), Is.EqualTo(new[] { GraphicsDeviceType.OpenGLES3 }));

            PlayerSettings.SetGraphicsAPIs(BuildTarget.Android, new GraphicsDeviceType[0]);
            Assert.That(QuestProjectSettings.HasExplicitQuestGraphicsApi(), Is.False);
            PlayerSettings.SetUseDefaultGraphicsAPIs(BuildTarget.Android, true);
            PlayerSettings.SetGraphicsAPIs(BuildTarget.Android, new[] { GraphicsDeviceType.Vulkan });
            Assert.That(QuestProjectSettings.HasExplicitQuestGraphicsApi(), Is.False, "Unity's default list is not a choice, whatever it holds");
        }

        [Test]
        public void ThePackagesRequirementsAreProjectSetupToolTasksThatCheckAndFix()
        {
            UnityDouble.Editor.LoadScripts(typeof(QuestProjectSetupTasks).Assembly);
            QuestProjectSetupTasks.Register(); // a second registration adds nothing
            string[] ours = { QuestProjectSetupTasks.HandTrackingMessage, QuestProjectSetupTasks.InitializeXRMessage, QuestProjectSetupTasks.TexturesMessage };
            foreach (string message in ours)
            {
                Assert.That(ProjectSetupTool.Messages.Count(m => m == message), Is.EqualTo(1), message);
                Assert.That(ProjectSetupTool.Platform(message), Is.EqualTo(BuildTargetGroup.Android));
                Assert.That(ProjectSetupTool.CanFix(message), Is.True);
                Assert.That(ProjectSetupTool.IsDone(message, BuildTargetGroup.Android), Is.False, "a new project has none: " + message);
                ProjectSetupTool.Fix(message, BuildTargetGroup.Android);
                Assert.That(ProjectSetupTool.IsDone(message, BuildTargetGroup.Android), Is.True, "fixed: " + message);
            }
            Assert.That(ProjectSetupTool.Level(QuestProjectSetupTasks.HandTrackingMessage), Is.EqualTo(OVRProjectSetup.TaskLevel.Required));
            Assert.That(ProjectSetupTool.Group(QuestProjectSetupTasks.HandTrackingMessage), Is.EqualTo(OVRProjectSetup.TaskGroup.Features));
            Assert.That(ProjectSetupTool.Level(QuestProjectSetupTasks.InitializeXRMessage), Is.EqualTo(OVRProjectSetup.TaskLevel.Required));
            Assert.That(ProjectSetupTool.Level(QuestProjectSetupTasks.TexturesMessage), Is.EqualTo(OVRProjectSetup.TaskLevel.Recommended));
            Assert.That(OVRProjectConfig.CachedProjectConfig.handTrackingSupport, Is.EqualTo(OVRProjectConfig.HandTrackingSupport.ControllersAndHands));
            Assert.That(EditorUserBuildSettings.androidBuildSubtarget, Is.EqualTo(MobileTextureSubtarget.ASTC));
        }

        // --- The committed ProjectSettings (hand-written YAML in Unity's format) ---

        static string ProjectFile(string name)
        {
            string dir = TestContext.CurrentContext.TestDirectory;
            while (dir != null && !File.Exists(Path.Combine(dir, "PseudoHaptic.sln"))) dir = Path.GetDirectoryName(dir);
            Assert.That(dir, Is.Not.Null, "the repository's root");
            return Path.Combine(dir, "ProjectSettings", name);
        }

        /// <summary>The top-level keys of a ProjectSettings YAML document (indented two spaces), their values, and the lines of nested blocks.</summary>
        static (Dictionary<string, string> keys, Dictionary<string, List<string>> blocks, string[] header) Parse(string file)
        {
            string[] lines = File.ReadAllLines(file);
            var keys = new Dictionary<string, string>();
            var blocks = new Dictionary<string, List<string>>();
            string current = null;
            foreach (string line in lines.Skip(4))
            {
                if (line.StartsWith("  ", StringComparison.Ordinal) && !line.StartsWith("   ", StringComparison.Ordinal) && !line.StartsWith("  -", StringComparison.Ordinal))
                {
                    int colon = line.IndexOf(':');
                    current = line.Substring(2, colon - 2);
                    Assert.That(keys.ContainsKey(current), Is.False, "key given twice: " + current);
                    keys[current] = line.Substring(colon + 1).Trim();
                    blocks[current] = new List<string>();
                }
                else if (current != null) blocks[current].Add(line.Trim());
            }
            return (keys, blocks, lines.Take(4).ToArray());
        }

        [Test]
        public void TheCommittedProjectSettingsHoldWhatTheQuestSettingsSet()
        {
            var (keys, blocks, header) = Parse(ProjectFile("ProjectSettings.asset"));
            Assert.That(header, Is.EqualTo(new[] { "%YAML 1.1", "%TAG !u! tag:unity3d.com,2011:", "--- !u!129 &1", "PlayerSettings:" }), "Unity's header for PlayerSettings (class 129)");
            Assert.That(keys["serializedVersion"], Is.EqualTo("26"), "PlayerSettings' version in Unity 2022.3");
            Assert.That(keys["productGUID"], Does.Match("^[0-9a-f]{32}$"));

            // Load what the file says into the editor's settings, as Unity does when the project opens...
            PlayerSettings.colorSpace = (ColorSpace)int.Parse(keys["m_ActiveColorSpace"], CultureInfo.InvariantCulture);
            Assert.That(blocks["scriptingBackend"], Does.Contain("Android: 1"), "IL2CPP (ScriptingImplementation.IL2CPP = 1)");
            PlayerSettings.SetScriptingBackend(NamedBuildTarget.Android, ScriptingImplementation.IL2CPP);
            PlayerSettings.Android.targetArchitectures = (AndroidArchitecture)uint.Parse(keys["AndroidTargetArchitectures"], CultureInfo.InvariantCulture);
            PlayerSettings.Android.minSdkVersion = (AndroidSdkVersions)int.Parse(keys["AndroidMinSdkVersion"], CultureInfo.InvariantCulture);
            PlayerSettings.Android.targetSdkVersion = (AndroidSdkVersions)int.Parse(keys["AndroidTargetSdkVersion"], CultureInfo.InvariantCulture);
            PlayerSettings.Android.androidTVCompatibility = keys["AndroidTVCompatibility"] != "0";
            PlayerSettings.stereoRenderingPath = (StereoRenderingPath)int.Parse(keys["m_StereoRenderingPath"], CultureInfo.InvariantCulture);
            List<string> apis = blocks["m_BuildTargetGraphicsAPIs"];
            int android = apis.IndexOf("- m_BuildTarget: AndroidPlayer");
            Assert.That(android, Is.GreaterThanOrEqualTo(0), "Android's graphics APIs are listed");
            string hex = apis[android + 1].Substring("m_APIs: ".Length);
            var list = new List<GraphicsDeviceType>();
            for (int i = 0; i + 8 <= hex.Length; i += 8) // little-endian 32-bit integers, as Unity writes them
                list.Add((GraphicsDeviceType)BitConverter.ToInt32(Convert.FromHexString(hex.Substring(i, 8)), 0));
            PlayerSettings.SetGraphicsAPIs(BuildTarget.Android, list.ToArray());
            PlayerSettings.SetUseDefaultGraphicsAPIs(BuildTarget.Android, apis[android + 2] != "m_Automatic: 0");
            EditorUserBuildSettings.androidBuildSubtarget = MobileTextureSubtarget.ASTC; // a per-user setting (Library), not in ProjectSettings

            // ...then the Quest settings have nothing left to set in them.
            var changes = new List<string>();
            QuestProjectSettings.ApplyPlayer(changes);
            QuestProjectSettings.ApplyRecommended(changes);
            Assert.That(changes, Is.Empty, "the committed file already holds every player setting the code sets");
            Assert.That(list, Is.EqualTo(new[] { GraphicsDeviceType.Vulkan }));
        }

        [Test]
        public void TheCommittedEditorBuildSettingsAreUnitysFormat()
        {
            var (keys, _, header) = Parse(ProjectFile("EditorBuildSettings.asset"));
            Assert.That(header, Is.EqualTo(new[] { "%YAML 1.1", "%TAG !u! tag:unity3d.com,2011:", "--- !u!1045 &1", "EditorBuildSettings:" }));
            Assert.That(keys["serializedVersion"], Is.EqualTo("2"));
            Assert.That(keys["m_Scenes"], Is.EqualTo("[]"), "the sample scenes are added by the scene builder, which writes them");
            Assert.That(keys, Does.ContainKey("m_configObjects"), "where XR Plug-in Management registers its settings");
        }
    }
}
