using System.Collections.Generic;
using System.Linq;
using System.Reflection;
using Kosmos.PseudoHaptic.Editor;
using Kosmos.PseudoHaptic.Interaction;
using Kosmos.PseudoHaptic.Meta;
using Kosmos.PseudoHaptic.SampleScenes;
using NUnit.Framework;
using Oculus.Interaction;
using UnityDouble;
using UnityEditor;
using UnityEngine;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>The editor tools, the samples' setup scripts and the Interaction SDK poke surface, under the doubles.</summary>
    public sealed class EditorAndSamplesTests
    {
        static TransformHandPoseSource SimulatedHand(string name, Vector3 at)
        {
            var go = new GameObject(name);
            go.transform.position = at;
            return go.AddComponent<TransformHandPoseSource>();
        }

        [Test]
        public void TheWeightsInspectorShowsTheCoresNumbersAndTheLiveHold()
        {
            var go = new GameObject("2 kg");
            go.AddComponent<BoxCollider>();
            go.AddComponent<Rigidbody>();
            var weight = go.AddComponent<PseudoHapticWeight>();
            weight.Mass = MassSource.Explicit;
            weight.ExplicitMassKg = 2f;
            weight.SpeedSource = StandardSpeedSource.Explicit;
            var inspector = ScriptableObject.CreateInstance<PseudoHapticWeightEditor>();
            inspector.target = weight;
            Assert.That(weight.BeginHold(go.transform.position), Is.True);
            inspector.OnInspectorGUI();
            var shown = UnityDouble.Editor.InspectorShown;
            Assert.That(shown, Has.Some.EqualTo("Mass: 2 kg"));
            Assert.That(shown, Has.Some.StartsWith("Gain G: 0.").And.Some.Contains("lags the hand"));
            Assert.That(shown, Has.Some.EqualTo("Held: yes"));
            Assert.That(inspector.RequiresConstantRepaint(), Is.True, "in play mode");
            typeof(PseudoHapticWeightEditor).GetMethod("DrawOffset", BindingFlags.Static | BindingFlags.NonPublic).Invoke(null, new object[] { weight, GizmoType.Selected });

            weight.ExplicitMassKg = -1f;
            weight.EndHold();
            inspector.OnInspectorGUI();
            Assert.That(shown.Last(), Does.StartWith("Error: ").And.Contains("massKg"), "an invalid mass is shown as the core's error");
        }

        [Test]
        public void TheProfileInspectorsPresetButtonAppliesThePreset()
        {
            PseudoHapticProfile profile = PseudoHapticProfile.CreatePreset(NamedProfiles.PaperName);
            var inspector = ScriptableObject.CreateInstance<PseudoHapticProfileEditor>();
            inspector.target = profile;
            GUILayoutDriver.Click(NamedProfiles.XyzName);
            // The list grew past what this event's layout measured: the event ends (Unity's GUI loop catches it) and the
            // next draws the new list.
            Assert.Throws<ExitGUIException>(() => inspector.OnInspectorGUI());
            inspector.OnInspectorGUI();
            Assert.That(profile.Build().ToString(), Is.EqualTo(NamedProfiles.Get(NamedProfiles.XyzName).ToString()));
            Assert.That(UnityDouble.Editor.InspectorShown.Last(), Does.StartWith("Info: Runs: xyz"));
        }

        [Test]
        public void TheSamplesSetupScriptsBuildTheirContentAroundTheScenesHands()
        {
            SimulatedHand("Left", new Vector3(-0.2f, 1f, 0.3f));
            SimulatedHand("Right", new Vector3(0.2f, 1f, 0.3f));
            new GameObject("Experiment 1").AddComponent<Experiment1Setup>();
            Assert.That(PseudoHapticWeight.Enabled.Select(w => w.name), Is.EquivalentTo(new[] { "Box A", "Box B", "Box C" }));
            new GameObject("Experiment 2").AddComponent<Experiment2Setup>();
            new GameObject("Playground").AddComponent<PlaygroundSetup>();
            new GameObject("Calibration").AddComponent<CalibrationSetup>();
            new GameObject("Discrimination").AddComponent<DiscriminationSetup>();
            Assert.That(Object.FindObjectsByType<PinchGrab>(FindObjectsSortMode.None), Has.Length.EqualTo(2), "one grab per hand, added once");
            Assert.That(Object.FindObjectsByType<StandardSpeedCalibrator>(FindObjectsSortMode.None), Has.Length.EqualTo(1));
            Assert.That(Object.FindObjectsByType<FingertipPoker>(FindObjectsSortMode.None), Has.Length.EqualTo(2));
            Assert.That(PseudoHapticWeight.Enabled.Count, Is.EqualTo(3 + 5 + 8 + 2 + 2), "the calibration's cue-strength staircase has two balls (issue 31)");
            Frames.Run(3);
        }

        /// <summary>The imported Discrimination sample's task exists only in play mode and begins at its Start: the setup
        /// carries the condition and the study's seed to it before then (every imported session ran condition "" and seed 1).</summary>
        [Test]
        public void TheDiscriminationSampleCarriesItsConditionAndSeedToTheTask()
        {
            SimulatedHand("Left", new Vector3(-0.2f, 1f, 0.3f));
            var go = new GameObject("Discrimination");
            go.SetActive(false); // its fields set before Awake, as a scene's are
            var setup = go.AddComponent<DiscriminationSetup>();
            var flags = System.Reflection.BindingFlags.NonPublic | System.Reflection.BindingFlags.Instance;
            typeof(DiscriminationSetup).GetField("_condition", flags)!.SetValue(setup, "with effect");
            typeof(DiscriminationSetup).GetField("_seed", flags)!.SetValue(setup, 7);
            go.SetActive(true);
            DiscriminationTask task = Object.FindObjectsByType<DiscriminationTask>(FindObjectsSortMode.None).Single();
            Assert.That((task.Condition, task.Seed), Is.EqualTo(("with effect", 7)));
        }

        /// <summary>A profile asset given to the Experiment 2 sample is used as it is: the setup switched Two Hands on in it,
        /// in play mode, where a change to an asset stays in the project.</summary>
        [Test]
        public void TheExperimentTwoSampleLeavesTheProfileAssetGivenToItAsItIs()
        {
            SimulatedHand("Left", new Vector3(-0.2f, 1f, 0.3f));
            PseudoHapticProfile asset = PseudoHapticProfile.CreatePreset(NamedProfiles.PaperName);
            Assert.That(asset.IsEnabled<TwoHands>(), Is.False);
            var warnings = new List<string>();
            void Collect(string message, string stack, LogType type) { if (type == LogType.Warning) warnings.Add(message); }
            Application.logMessageReceived += Collect;
            try
            {
                var go = new GameObject("Experiment 2");
                go.SetActive(false);
                var setup = go.AddComponent<Experiment2Setup>();
                typeof(Experiment2Setup).GetField("_profile", System.Reflection.BindingFlags.NonPublic | System.Reflection.BindingFlags.Instance)!.SetValue(setup, asset);
                go.SetActive(true);
            }
            finally { Application.logMessageReceived -= Collect; }
            Assert.That(asset.IsEnabled<TwoHands>(), Is.False, "the asset is as it was");
            Assert.That(warnings.Count(w => w.Contains("Two Hands off")), Is.EqualTo(1));
            Assert.That(PseudoHapticWeight.Enabled.Select(w => w.Profile).Distinct(), Is.EqualTo(new[] { asset }), "the bottles use it");
        }

        [Test]
        public void TheSampleScenesGetAnOvrRigWithAHandVisualPerHandWhenMetasPrefabsAreThere()
        {
            UnityDouble.Editor.Prefab(Kosmos.PseudoHaptic.Editor.SampleScenes.OvrCameraRigPrefab, () => { var rig = new GameObject("OVRCameraRig"); rig.AddComponent<OVRCameraRig>(); return rig; });
            UnityDouble.Editor.Prefab(Kosmos.PseudoHaptic.Editor.SampleScenes.OvrHandPrefab, () => { var hand = new GameObject("OVRHandPrefab"); hand.AddComponent<OVRHand>(); hand.AddComponent<OVRSkeleton>(); return hand; });
            Kosmos.PseudoHaptic.Editor.SampleScenes.BuildAll();
            Assert.That(UnityDouble.Editor.SavedScenes, Has.Count.EqualTo(5));
            Assert.That(EditorBuildSettings.scenes, Has.Length.EqualTo(5));
            OvrHandPoseSource[] sources = Object.FindObjectsByType<OvrHandPoseSource>(FindObjectsSortMode.InstanceID);
            Assert.That(sources, Has.Length.EqualTo(2), "the last scene built (Discrimination) has both hands");
            Assert.That(sources.Select(s => s.Tracked.name), Is.EquivalentTo(new[] { "LeftHandAnchor", "RightHandAnchor" }), "the solver reads the anchors, never the visual");
            Assert.That(sources.Select(s => s.GetComponent<PinchGrab>().HandVisual.name), Is.All.EqualTo("Hand Visual"));
            Assert.That(sources.Select(s => s.Source), Is.All.EqualTo(OvrHandPoseSource.PositionSource.PinchPoint), "the pinch point, placed from the anchor");
            Assert.That(sources.Select(s => s.GetComponent<OVRSkeleton>().GetSkeletonType()), Is.EquivalentTo(new[] { OVRSkeleton.SkeletonType.HandLeft, OVRSkeleton.SkeletonType.HandRight }), "each skeleton is its hand's");
            Assert.That(Camera.main, Is.Null, "the default camera gave way to the rig's");
        }

        [Test]
        public void TheSampleScenesWithUnityXRHandsGetAnXRHandsSourcePerHand()
        {
            Kosmos.PseudoHaptic.Editor.SampleScenes.BuildAllWithXRHands();
            Assert.That(Object.FindObjectsByType<XRHands.XRHandPoseSource>(FindObjectsSortMode.None), Has.Length.EqualTo(2));
            Assert.That(Kosmos.PseudoHaptic.Editor.SampleScenes.UseXRHands, Is.False, "back to OVR for the next build");
        }

        [Test]
        public void AnInteractionSdkPokeOnThePanelAnswersTheItemUnderIt()
        {
            var go = new GameObject("Questionnaire");
            var panel = go.AddComponent<QuestionnairePanel>();
            panel.ResponsesFile = System.IO.Path.Combine(Application.persistentDataPath, "poke-responses.csv");
            var catalog = new Evaluation.QuestionnaireCatalog(new[] { new Evaluation.Questionnaire("q", "Q", 1, 5, new[] { new Evaluation.QuestionnaireItem(1, "Heavy?", false) }) });
            Assert.That(panel.Begin(catalog, "P1"), Is.True, panel.Error);
            var pointable = go.AddComponent<FakePointable>();
            var surface = go.AddComponent<QuestionnairePokeSurface>();
            surface.InjectPointable(pointable);
            Frames.Run(1);
            pointable.Raise(new PointerEvent(3, PointerEventType.Hover, new Pose(panel.ScaleButtons[3].transform.position, Quaternion.identity)));
            Assert.That(panel.Session.AnsweredCount, Is.EqualTo(0), "hovering answers nothing");
            pointable.Raise(new PointerEvent(3, PointerEventType.Select, new Pose(panel.ScaleButtons[3].transform.position, Quaternion.identity)));
            Assert.That(panel.WaitForSaves(), Is.True, panel.Error); // written in the background; a later frame's Update delivers it
            Assert.That(panel.Session.AnsweredCount, Is.EqualTo(1));
            Assert.That(surface.Panel, Is.SameAs(panel), "found on its own GameObject");
        }
    }

    /// <summary>Any IPointable: what a PokeInteractable raises.</summary>
    public sealed class FakePointable : MonoBehaviour, IPointable
    {
        public event System.Action<PointerEvent> WhenPointerEventRaised;
        public void Raise(PointerEvent evt) => WhenPointerEventRaised?.Invoke(evt);
    }
}
