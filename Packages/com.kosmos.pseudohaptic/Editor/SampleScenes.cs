using System.Collections.Generic;
using Kosmos.PseudoHaptic.Samples;
using UnityEditor;
using UnityEditor.SceneManagement;
using UnityEngine;
using UnityEngine.SceneManagement;

namespace Kosmos.PseudoHaptic.Editor
{
    /// <summary>
    /// Menu items that build the sample scenes from code into <see cref="Folder"/>, the same way every time:
    /// a rig (Meta's OVRCameraRig with OVRHand prefabs when the Meta XR Core SDK is installed; Unity XR Hands sources
    /// with "Build All (Unity XR Hands)" when com.unity.xr.hands is installed; simulated hands otherwise), each hand
    /// with a <see cref="PinchGrab"/> (and, for OVRHand, a visual root it draws on the object under a hand-on-object
    /// profile), the content of <see cref="SampleContent"/>, the profile assets, and the build settings.
    /// </summary>
    public static class SampleScenes
    {
        public const string Folder = "Assets/Samples/PseudoHaptic";
        public const string ProfileFolder = Folder + "/Profiles";
        const string Menu = "Tools/Kosmos Pseudo-Haptic/Sample Scenes/";

        public const string OvrCameraRigPrefab = "Packages/com.meta.xr.sdk.core/Prefabs/OVRCameraRig.prefab";
        public const string OvrHandPrefab = "Packages/com.meta.xr.sdk.core/Prefabs/OVRHandPrefab.prefab";

        [MenuItem(Menu + "Build All", priority = 0)]
        public static void BuildAll()
        {
            Calibration();
            Experiment1();
            Experiment2();
            Playground();
            Discrimination();
        }

#if KOSMOS_XR_HANDS
        /// <summary>Builds every sample with Unity XR Hands sources instead of OVRHand (OpenXR projects).</summary>
        [MenuItem(Menu + "Build All (Unity XR Hands)", priority = 1)]
        public static void BuildAllWithXRHands()
        {
            UseXRHands = true;
            try { BuildAll(); }
            finally { UseXRHands = false; }
        }
#endif

        /// <summary>Whether the rigs use Unity XR Hands sources (set by "Build All (Unity XR Hands)").</summary>
        public static bool UseXRHands { get; set; }

        [MenuItem(Menu + "Calibration", priority = 20)]
        public static void Calibration()
        {
            if (!NewScene(out Scene scene, out Transform root, out List<IPinchHandPoseSource> hands)) return;
            // The ball is held in one hand: the right one, or the only one there is.
            SampleContent.CalibrationStation(root, hands[hands.Count - 1]);
            Save(scene, "Calibration");
        }

        [MenuItem(Menu + "Experiment 1 (boxes A, B, C)", priority = 21)]
        public static void Experiment1()
        {
            if (!NewScene(out Scene scene, out Transform root, out _)) return;
            SampleContent.Experiment1(root, Profile(PaperExperiment1.ProfileName, PaperExperiment1.ProfileName)); // the experiment's profile, Two Hands included
            Save(scene, "Experiment1");
        }

        [MenuItem(Menu + "Experiment 2 (water bottles)", priority = 22)]
        public static void Experiment2()
        {
            if (!NewScene(out Scene scene, out Transform root, out _)) return;
            SampleContent.Experiment2(root, TwoHandedExperimentProfile());
            Save(scene, "Experiment2");
        }

        [MenuItem(Menu + "Playground", priority = 23)]
        public static void Playground()
        {
            if (!NewScene(out Scene scene, out Transform root, out List<IPinchHandPoseSource> hands)) return;
            var sources = new List<IHandPoseSource>(hands);
            PseudoHapticProfile handOnObject = Profile("Playground-HandOnObject", NamedProfiles.PaperName);
            handOnObject.HandDrawing = HandDrawingMode.HandOnObject; // the same effects, the hand drawn at the object
            EditorUtility.SetDirty(handOnObject);
            AssetDatabase.SaveAssets();
            SampleContent.Playground(root, Profile("Playground", NamedProfiles.PaperName), sources, handOnObject, Profile("Playground-xyz", NamedProfiles.XyzName));
            Save(scene, "Playground");
        }

        [MenuItem(Menu + "Discrimination (2AFC weight task)", priority = 24)]
        public static void Discrimination()
        {
            if (!NewScene(out Scene scene, out Transform root, out List<IPinchHandPoseSource> hands)) return;
            DiscriminationStation.Build(root, Profile(NamedProfiles.PaperName, NamedProfiles.PaperName), "P1", hands);
            Save(scene, "Discrimination");
        }

        /// <summary>"paper-experiment" (its Two Hands on: each hand carries half), saved as paper-experiment, the profile Experiment 1 uses too.</summary>
        internal static PseudoHapticProfile TwoHandedExperimentProfile()
        {
            PseudoHapticProfile profile = Profile(NamedProfiles.PaperExperimentName, NamedProfiles.PaperExperimentName);
            SampleContent.LiftWithBothHands(profile);
            EditorUtility.SetDirty(profile);
            AssetDatabase.SaveAssets();
            return profile;
        }

        /// <summary>The profile asset of that name, created or reset to <paramref name="preset"/>.</summary>
        static PseudoHapticProfile Profile(string fileName, string preset)
        {
            EnsureFolder(ProfileFolder);
            string path = ProfileFolder + "/" + fileName + ".asset";
            var profile = AssetDatabase.LoadAssetAtPath<PseudoHapticProfile>(path);
            if (profile == null)
            {
                profile = PseudoHapticProfile.CreatePreset(preset);
                AssetDatabase.CreateAsset(profile, path);
            }
            else
            {
                profile.ApplyPreset(preset);
                EditorUtility.SetDirty(profile);
            }
            AssetDatabase.SaveAssets();
            return profile;
        }

        /// <summary>A new scene with a rig; false when the user chose not to leave the open, modified scene.</summary>
        static bool NewScene(out Scene scene, out Transform root, out List<IPinchHandPoseSource> hands)
        {
            scene = default;
            root = null;
            hands = null;
            // The open scene is replaced: offer to save it first (each built scene is saved, so Build All asks once).
            if (!Application.isBatchMode && !EditorSceneManager.SaveCurrentModifiedScenesIfUserWantsTo()) return false;
            scene = EditorSceneManager.NewScene(NewSceneSetup.DefaultGameObjects, NewSceneMode.Single);
            root = new GameObject("Pseudo-Haptic Sample").transform;
            hands = CreateRig();
            return true;
        }

        internal static void Save(Scene scene, string name)
        {
            EnsureFolder(Folder);
            string path = Folder + "/" + name + ".unity";
            EditorSceneManager.SaveScene(scene, path);
            AddToBuild(path);
            Debug.Log("Pseudo-haptic sample scene built: " + path);
        }

        static List<IPinchHandPoseSource> CreateRig()
        {
            var hands = new List<IPinchHandPoseSource>(2);
#if KOSMOS_XR_HANDS
            if (UseXRHands)
            {
                // Put both under the XR Origin's Camera Offset and set their Tracking Space to it (joint poses are in that space).
                hands.Add(XRHand("Left Hand (XR Hands)", UnityEngine.XR.Hands.Handedness.Left));
                hands.Add(XRHand("Right Hand (XR Hands)", UnityEngine.XR.Hands.Handedness.Right));
                return hands;
            }
#endif
#if KOSMOS_META_XR_CORE
            var rigPrefab = AssetDatabase.LoadAssetAtPath<GameObject>(OvrCameraRigPrefab);
            var handPrefab = AssetDatabase.LoadAssetAtPath<GameObject>(OvrHandPrefab);
            if (rigPrefab != null && handPrefab != null)
            {
                Camera main = Camera.main;
                if (main != null) Object.DestroyImmediate(main.gameObject);
                var rig = (GameObject)PrefabUtility.InstantiatePrefab(rigPrefab);
                SetInt(rig, "_trackingOriginType", 1); // OVRManager.TrackingOrigin.FloorLevel: y = 0 is the floor
                AddOvrHand(rig.transform.Find("TrackingSpace/LeftHandAnchor"), handPrefab, 0, hands);
                AddOvrHand(rig.transform.Find("TrackingSpace/RightHandAnchor"), handPrefab, 1, hands);
                if (hands.Count == 2) return hands;
                Debug.LogWarning("OVRCameraRig has no TrackingSpace/Left|RightHandAnchor: simulated hands added instead.");
                hands.Clear();
            }
            else
            {
                Debug.LogWarning("Meta XR Core SDK prefabs not found (" + OvrCameraRigPrefab + "): simulated hands added instead.");
            }
#endif
            // Without Meta's SDK: hands to move in the Scene view (tick Is Pinching to grab).
            hands.Add(SimulatedHand("Left Hand (simulated)", new Vector3(-0.2f, 1.0f, 0.3f)));
            hands.Add(SimulatedHand("Right Hand (simulated)", new Vector3(0.2f, 1.0f, 0.3f)));
            return hands;
        }

        static IPinchHandPoseSource SimulatedHand(string name, Vector3 position)
        {
            var go = new GameObject(name);
            go.transform.position = position;
            var source = go.AddComponent<TransformHandPoseSource>();
            go.AddComponent<PinchGrab>().InjectHand(source);
            return source;
        }

#if KOSMOS_XR_HANDS
        static IPinchHandPoseSource XRHand(string name, UnityEngine.XR.Hands.Handedness side)
        {
            var go = new GameObject(name);
            var source = go.AddComponent<XRHands.XRHandPoseSource>();
            source.HandSide = side;
            go.AddComponent<PinchGrab>().InjectHand(source);
            return source;
        }
#endif

#if KOSMOS_META_XR_CORE
        static void AddOvrHand(Transform anchor, GameObject handPrefab, int handType, List<IPinchHandPoseSource> hands)
        {
            if (anchor == null) return;
            // anchor (tracked) → Hand Visual (offset by the Pinch Grab when the hand is drawn on the object) → OVRHandPrefab.
            var visual = new GameObject("Hand Visual").transform;
            visual.SetParent(anchor, false);
            var go = (GameObject)PrefabUtility.InstantiatePrefab(handPrefab, visual);
            // OVRHand.HandType, OVRSkeleton._skeletonType, OVRMesh._meshType: 0 = left, 1 = right.
            SetInt(go, "HandType", handType);
            SetInt(go, "_skeletonType", handType);
            SetInt(go, "_meshType", handType);
            var source = go.AddComponent<Meta.OvrHandPoseSource>();
            source.InjectHand(go.GetComponent<OVRHand>());
            source.Tracked = anchor; // the solver follows the anchor, never the offset visual
            source.Source = Meta.OvrHandPoseSource.PositionSource.PinchPoint; // the skeleton's pinch point, placed from the anchor
            var grab = go.AddComponent<PinchGrab>();
            grab.InjectHand(source);
            grab.HandVisual = visual;
            hands.Add(source);
        }

        /// <summary>Sets a serialized int/enum field, by name, on every component of the object that has it.</summary>
        static void SetInt(GameObject go, string property, int value)
        {
            foreach (Component c in go.GetComponents<Component>())
            {
                if (c == null) continue;
                var so = new SerializedObject(c);
                SerializedProperty p = so.FindProperty(property);
                if (p == null) continue;
                p.intValue = value;
                so.ApplyModifiedPropertiesWithoutUndo();
            }
        }
#endif

        static void EnsureFolder(string path)
        {
            if (AssetDatabase.IsValidFolder(path)) return;
            int slash = path.LastIndexOf('/');
            EnsureFolder(path.Substring(0, slash));
            AssetDatabase.CreateFolder(path.Substring(0, slash), path.Substring(slash + 1));
        }

        static void AddToBuild(string path)
        {
            var scenes = new List<EditorBuildSettingsScene>(EditorBuildSettings.scenes);
            foreach (EditorBuildSettingsScene s in scenes)
                if (s.path == path) return;
            scenes.Add(new EditorBuildSettingsScene(path, true));
            EditorBuildSettings.scenes = scenes.ToArray();
        }
    }
}
