#if KOSMOS_XRI
using System.Collections.Generic;
using Kosmos.PseudoHaptic.Samples;
using Kosmos.PseudoHaptic.XRI;
using Unity.XR.CoreUtils;
using UnityEditor;
using UnityEditor.SceneManagement;
using UnityEngine;
using UnityEngine.SceneManagement;
using UnityEngine.XR.Interaction.Toolkit;
#if KOSMOS_XRI_3
using UnityEngine.InputSystem.XR;
using UnityEngine.XR.Interaction.Toolkit.Interactables;
using UnityEngine.XR.Interaction.Toolkit.Interactors;
#endif

namespace Kosmos.PseudoHaptic.Editor
{
    /// <summary>
    /// Issue 34: the Experiment 1 boxes grabbed through Unity's XR Interaction Toolkit (2.x or 3.x), built into
    /// <see cref="ScenePath"/>: an XRI rig (the "XR Origin Hands (XR Rig)" prefab of XRI's Hands Interaction Demo sample,
    /// else the "XR Origin (XR Rig)" of its Starter Assets sample, whichever is imported; else a bare XR Origin with a
    /// direct interactor per controller, whose input actions are left for you to bind, with a warning: under XRI 2.x on an
    /// ActionBasedController, under XRI 3.x on an Input System TrackedPoseDriver, as each version's rigs pose controllers),
    /// an XR Interaction Manager, and a <see cref="PseudoHapticGrabTransformer"/> on every box (which brings its XR Grab
    /// Interactable, its Select Mode Multiple: both hands hold a box). Kept apart from <see cref="SampleScenes"/> (its own menu item); compiled only when XRI 2.5 or a later
    /// 2.x or 3.x is installed.
    /// </summary>
    public static class XriSampleScene
    {
        public const string SceneName = "Experiment1-XRI";
        public const string ScenePath = SampleScenes.Folder + "/" + SceneName + ".unity";

        /// <summary>The rig prefabs looked for, in order: bare hands first (XR Hands through OpenXR), then controllers and hands.</summary>
        public static readonly string[] RigPrefabNames = { "XR Origin Hands (XR Rig)", "XR Origin (XR Rig)" };

        [MenuItem("Tools/Kosmos Pseudo-Haptic/Sample Scenes/Experiment 1 with XR Interaction Toolkit", priority = 40)]
        public static void Build()
        {
            if (!Application.isBatchMode && !EditorSceneManager.SaveCurrentModifiedScenesIfUserWantsTo()) return;
            Scene scene = EditorSceneManager.NewScene(NewSceneSetup.DefaultGameObjects, NewSceneMode.Single);
            CreateRig();
            if (Object.FindFirstObjectByType<XRInteractionManager>() == null) new GameObject("XR Interaction Manager").AddComponent<XRInteractionManager>();
            var root = new GameObject("Pseudo-Haptic Sample (XRI)").transform;
            List<PseudoHapticWeight> boxes = SampleContent.Experiment1(root, SampleScenes.TwoHandedExperimentProfile());
            foreach (PseudoHapticWeight box in boxes)
            {
                if (box.GetComponent<PseudoHapticGrabTransformer>() == null) box.gameObject.AddComponent<PseudoHapticGrabTransformer>();
                // What the transformer sets when it links, saved in the scene so that the inspector shows it: two hands.
                box.GetComponent<XRGrabInteractable>().selectMode = InteractableSelectMode.Multiple;
            }
            SampleScenes.Save(scene, SceneName);
        }

        /// <summary>The path of the first imported rig prefab of <see cref="RigPrefabNames"/>, or null.</summary>
        public static string FindRigPrefab()
        {
            foreach (string name in RigPrefabNames)
                foreach (string guid in AssetDatabase.FindAssets(name + " t:Prefab"))
                {
                    string path = AssetDatabase.GUIDToAssetPath(guid);
                    if (System.IO.Path.GetFileNameWithoutExtension(path) == name) return path;
                }
            return null;
        }

        static void CreateRig()
        {
            string path = FindRigPrefab();
            GameObject prefab = path != null ? AssetDatabase.LoadAssetAtPath<GameObject>(path) : null;
            if (prefab != null && PrefabUtility.InstantiatePrefab(prefab) is GameObject)
            {
                Camera scenes = Camera.main;
                if (scenes != null && scenes.GetComponentInParent<XROrigin>() == null) Object.DestroyImmediate(scenes.gameObject); // the rig brings its own
                return;
            }
            Debug.LogWarning("Kosmos Pseudo-Haptic: no XR Interaction Toolkit rig prefab (" + string.Join(", ", RigPrefabNames) + ") found; built a bare XR Origin " +
                             "with a direct interactor per controller whose input actions are not bound, so nothing moves. Import the XR Interaction Toolkit's " +
                             "'Hands Interaction Demo' (bare hands, needs XR Hands) or 'Starter Assets' sample (Package Manager ▸ XR Interaction Toolkit ▸ Samples) and build again.");
            var origin = new GameObject("XR Origin (XR Rig)");
            var xrOrigin = origin.AddComponent<XROrigin>();
            var offset = new GameObject("Camera Offset");
            offset.transform.SetParent(origin.transform, false);
            xrOrigin.Origin = origin;
            xrOrigin.CameraFloorOffsetObject = offset;
            Camera camera = Camera.main;
            if (camera != null)
            {
                camera.transform.SetParent(offset.transform, false);
                camera.transform.localPosition = new Vector3(0, 1.6f, 0);
                xrOrigin.Camera = camera;
            }
            Controller("Left Controller", offset.transform, new Vector3(-0.2f, 1.0f, 0.3f));
            Controller("Right Controller", offset.transform, new Vector3(0.2f, 1.0f, 0.3f));
        }

        static void Controller(string name, Transform offset, Vector3 at)
        {
            var go = new GameObject(name);
            go.transform.SetParent(offset, false);
            go.transform.localPosition = at;
#if KOSMOS_XRI_3
            go.AddComponent<TrackedPoseDriver>(); // XRI 3 rigs pose each controller and hand with one; its actions are yours to bind
#else
            go.AddComponent<ActionBasedController>();
#endif
            var reach = go.AddComponent<SphereCollider>(); // a direct interactor selects what its trigger touches
            reach.isTrigger = true;
            reach.radius = 0.1f;
            go.AddComponent<XRDirectInteractor>();
        }
    }
}
#endif
