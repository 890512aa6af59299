using System;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;
using Kosmos.PseudoHaptic.Editor;
using NUnit.Framework;
using UnityDouble;
using UnityEditor;
using UnityEditor.Build;
using UnityEditor.XR.Management.Metadata;
using UnityEngine;
using UnityEngine.TestTools;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>Issue 24 item 3: the first open and the first build get the Quest settings, whether or not a menu item ran.</summary>
    public sealed class QuestSettingsTests
    {
        string _project;

        [SetUp]
        public void Project() => _project = Directory.CreateTempSubdirectory("kosmos-project-").FullName;

        [TearDown]
        public void RemoveProject() => Directory.Delete(_project, true);

        void OptIn()
        {
            string file = Path.Combine(_project, QuestSettingsOnOpen.OptInFile);
            Directory.CreateDirectory(Path.GetDirectoryName(file));
            File.WriteAllText(file, "{}");
        }

        static void AssertQuestSettings()
        {
            Assert.That(PlayerSettings.colorSpace, Is.EqualTo(ColorSpace.Linear), "Meta's Android build refuses Gamma");
            Assert.That(PlayerSettings.GetScriptingBackend(NamedBuildTarget.Android), Is.EqualTo(ScriptingImplementation.IL2CPP));
            Assert.That(PlayerSettings.Android.targetArchitectures, Is.EqualTo(AndroidArchitecture.ARM64));
            Assert.That(PlayerSettings.Android.minSdkVersion, Is.GreaterThanOrEqualTo(AndroidSdkVersions.AndroidApiLevel29));
            Assert.That(EditorUserBuildSettings.androidBuildSubtarget, Is.EqualTo(MobileTextureSubtarget.ASTC));
            Assert.That(XRPackageMetadataStore.IsLoaderAssigned(QuestProjectSettings.OculusLoaderType, BuildTargetGroup.Android), Is.True, "the APK starts in VR");
            Assert.That(XRPackageMetadataStore.IsLoaderAssigned(QuestProjectSettings.OculusLoaderType, BuildTargetGroup.Standalone), Is.True, "Play over Link has a loader");
            Assert.That(OVRProjectConfig.CachedProjectConfig.handTrackingSupport, Is.EqualTo(OVRProjectConfig.HandTrackingSupport.ControllersAndHands));
        }

        [Test]
        public void OpeningAnOptedInProjectSetsWhatIsMissingAndSaysWhat()
        {
            OptIn();
            LogAssert.Expect(LogType.Log, new Regex("Kosmos Pseudo-Haptic: set for Quest 2 and Play over Link .*colour space Linear \\(was Gamma\\).*IL2CPP.*ARM64.*Android: the Oculus XR loader.*Standalone: the Oculus XR loader.*hand tracking"));
            string line = QuestSettingsOnOpen.Apply(_project);
            Assert.That(line, Is.Not.Null);
            AssertQuestSettings();
            Assert.That(QuestSettingsOnOpen.Apply(_project), Is.Null, "the second open has nothing to set, and logs nothing");
        }

        [Test]
        public void TheEditorAppliesThemOnceItHasLoadedTheScripts()
        {
            Assert.That(typeof(QuestSettingsOnOpen).IsDefined(typeof(InitializeOnLoadAttribute), false), Is.True, "its static constructor runs when scripts load");
            EditorApplication.delayCall = null;
            QuestSettingsOnOpen.ScheduleApply(); // what that constructor does
            Assert.That(EditorApplication.delayCall, Is.Not.Null, "deferred until the editor has loaded");
            UnityDouble.Editor.RunDelayCalls(); // the test's working folder has no opt-in: nothing changes
            Assert.That(PlayerSettings.colorSpace, Is.EqualTo(ColorSpace.Gamma));
        }

        [Test]
        public void AProjectThatDidNotOptInIsLeftAsItIs()
        {
            Assert.That(QuestSettingsOnOpen.Apply(_project), Is.Null);
            Assert.That(PlayerSettings.colorSpace, Is.EqualTo(ColorSpace.Gamma));
            Assert.That(XRPackageMetadataStore.IsLoaderAssigned(QuestProjectSettings.OculusLoaderType, BuildTargetGroup.Android), Is.False);
        }

        [Test]
        public void TheHeadlessQuestBuildSetsEverythingBuildsTheSampleScenesAndExitsWithZero()
        {
            UnityDouble.Editor.IsBatchMode = true;
            QuestBuild.Build();
            Assert.That(UnityDouble.Editor.ExitCode, Is.EqualTo(0));
            AssertQuestSettings();
            Assert.That(UnityDouble.Editor.Builds, Has.Count.EqualTo(1));
            BuildPlayerOptions build = UnityDouble.Editor.Builds[0];
            Assert.That(build.target, Is.EqualTo(BuildTarget.Android));
            Assert.That(build.locationPathName, Is.EqualTo(QuestBuild.DefaultApkPath));
            Assert.That(build.scenes.Select(Path.GetFileNameWithoutExtension), Is.EquivalentTo(new[] { "Calibration", "Experiment1", "Experiment2", "Playground", "Discrimination" }));
        }

        [Test]
        public void ABuildForAnotherTargetStopsSayingHowAndExitsWithOne()
        {
            UnityDouble.Editor.IsBatchMode = true;
            UnityDouble.Editor.ActiveBuildTarget = BuildTarget.StandaloneWindows64;
            LogAssert.Expect(LogType.Exception, new Regex("not Android.*-buildTarget Android"));
            QuestBuild.Build();
            Assert.That(UnityDouble.Editor.ExitCode, Is.EqualTo(1));
            Assert.That(UnityDouble.Editor.Builds, Is.Empty);
        }
    }
}
