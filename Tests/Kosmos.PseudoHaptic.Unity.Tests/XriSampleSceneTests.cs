using System.Linq;
using Kosmos.PseudoHaptic.Editor;
using Kosmos.PseudoHaptic.XRI;
using NUnit.Framework;
using Unity.XR.CoreUtils;
using UnityDouble;
using UnityEditor;
using UnityEngine;
using UnityEngine.TestTools;
using UnityEngine.XR.Interaction.Toolkit;
#if KOSMOS_XRI_3
using UnityEngine.InputSystem;
using UnityEngine.InputSystem.XR;
using UnityEngine.XR.Interaction.Toolkit.Interactables;
using UnityEngine.XR.Interaction.Toolkit.Interactors;
#else
using UnityEngine.XR;
#endif

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>Issue 34 item 1: the sample-scene menu's XR Interaction Toolkit scene, built and then lifted through its own rig.</summary>
    public sealed class XriSampleSceneTests
    {
        [Test]
        public void WithoutAnXriRigPrefabTheSceneGetsABareXrOriginAndSaysWhatToImport()
        {
            LogAssert.Expect(LogType.Warning, new System.Text.RegularExpressions.Regex("no XR Interaction Toolkit rig prefab .* found"));
            XriSampleScene.Build();
            Assert.That(UnityDouble.Editor.SavedScenes, Does.Contain(XriSampleScene.ScenePath));
            Assert.That(EditorBuildSettings.scenes.Select(s => s.path), Does.Contain(XriSampleScene.ScenePath));
            XROrigin origin = Object.FindFirstObjectByType<XROrigin>();
            Assert.That(origin, Is.Not.Null);
            XRDirectInteractor[] hands = Object.FindObjectsByType<XRDirectInteractor>(FindObjectsSortMode.InstanceID);
            Assert.That(hands, Has.Length.EqualTo(2));
            Assert.That(hands.Select(h => h.transform.parent), Is.All.SameAs(origin.CameraFloorOffsetObject.transform), "hands are tracked in the Camera Offset");
            Assert.That(Camera.main.GetComponentInParent<XROrigin>(), Is.SameAs(origin), "the scene's camera is the rig's");
            PseudoHapticGrabTransformer[] transformers = Object.FindObjectsByType<PseudoHapticGrabTransformer>(FindObjectsSortMode.InstanceID);
            Assert.That(transformers.Select(t => t.name), Is.EquivalentTo(new[] { "Box A", "Box B", "Box C" }));
            Assert.That(transformers.Select(t => t.GetComponent<XRGrabInteractable>().selectMode), Is.All.EqualTo(InteractableSelectMode.Multiple),
                "saved for two hands: XRI's default Single lets the second hand take a box from the first");
            Assert.That(Object.FindObjectsByType<XRInteractionManager>(FindObjectsSortMode.None), Has.Length.EqualTo(1));
        }

        [Test]
        public void TheBuiltSceneLiftsBoxBThroughItsOwnRig()
        {
            LogAssert.Expect(LogType.Warning, new System.Text.RegularExpressions.Regex("no XR Interaction Toolkit rig prefab"));
            XriSampleScene.Build();
            Frames.Run(1); // the transformers register in Start
            XROrigin origin = Object.FindFirstObjectByType<XROrigin>();
            Transform offset = origin.CameraFloorOffsetObject.transform;
            XRDirectInteractor right = Object.FindObjectsByType<XRDirectInteractor>(FindObjectsSortMode.InstanceID).First(h => h.name == "Right Controller");
            PseudoHapticGrabTransformer boxB = Object.FindObjectsByType<PseudoHapticGrabTransformer>(FindObjectsSortMode.None).First(t => t.name == "Box B");
            var grab = boxB.GetComponent<XRGrabInteractable>();
#if KOSMOS_XRI_3
            // The bare rig's controllers carry an unbound TrackedPoseDriver (XRI 3's rigs pose them so): bind it as the Starter Assets do.
            TrackedPoseDriver driver = right.GetComponent<TrackedPoseDriver>();
            Assert.That(driver, Is.Not.Null, "XRI 3: the bare controller is posed by a TrackedPoseDriver");
            driver.positionInput = new InputActionProperty(new InputAction("Position", expectedControlType: "Vector3"));
            driver.trackingStateInput = new InputActionProperty(new InputAction("Tracking State", expectedControlType: "Integer"));
            void Report(Vector3 p)
            {
                InputActions.Report(driver.positionInput.action, p);
                InputActions.Report(driver.trackingStateInput.action, 3); // Position | Rotation
            }
#else
            ActionBasedController controller = right.GetComponent<ActionBasedController>();
            void Report(Vector3 p)
            {
                controller.currentControllerState.position = p;
                controller.currentControllerState.inputTrackingState = InputTrackingState.Position | InputTrackingState.Rotation;
            }
#endif
            Vector3 start = offset.InverseTransformPoint(boxB.transform.position + new Vector3(0, 0.05f, 0));
            Report(start);
            Frames.Run(1);
            float y0 = boxB.transform.position.y;
            grab.interactionManager.SelectEnter(right, grab);
            for (int i = 1; i <= 90; i++)
            {
                Report(start + new Vector3(0, 0.3f * Mathf.Clamp01(i / 60f), 0));
                Frames.Run(1);
            }
            Assert.That(boxB.Weight.IsHeld, Is.True);
            Assert.That(boxB.Weight.Hold.HandCount, Is.EqualTo(1));
            float rise = boxB.transform.position.y - y0;
            Assert.That(rise, Is.GreaterThan(0.02f).And.LessThan(0.3f), "box B (the heaviest) rose, behind the 0.3 m hand");
            grab.interactionManager.SelectExit(right, grab);
            Assert.That(boxB.Weight.IsHeld, Is.False);
        }

        [Test]
        public void AnImportedHandsRigPrefabIsUsedInsteadOfTheBareOne()
        {
            const string path = "Assets/Samples/XR Interaction Toolkit/2.5.4/Hands Interaction Demo/Prefabs/XR Origin Hands (XR Rig).prefab";
            UnityDouble.Editor.Prefab(path, () =>
            {
                var rig = new GameObject("XR Origin Hands (XR Rig)");
                rig.AddComponent<XROrigin>();
                new GameObject("Main Camera") { tag = "MainCamera" }.AddComponent<Camera>().transform.SetParent(rig.transform, false);
                return rig;
            });
            Assert.That(XriSampleScene.FindRigPrefab(), Is.EqualTo(path));
            XriSampleScene.Build(); // no warning: an unexpected one fails the test
            Assert.That(Object.FindObjectsByType<XROrigin>(FindObjectsSortMode.None).Select(o => o.name), Is.EqualTo(new[] { "XR Origin Hands (XR Rig)" }));
            Assert.That(Object.FindObjectsByType<Camera>(FindObjectsSortMode.None), Has.Length.EqualTo(1), "the default camera gave way to the rig's");
        }
    }
}
