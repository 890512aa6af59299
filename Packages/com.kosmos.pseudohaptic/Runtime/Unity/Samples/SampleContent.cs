using System.Collections.Generic;
using UnityEngine;

namespace Kosmos.PseudoHaptic.Samples
{
    /// <summary>
    /// Builds the content of the sample scenes (tables, boxes, bottles, calibration station, effect
    /// switches) from code, so the editor menu and the package's Samples~ setup scripts build the very same
    /// scenes. Objects rest on a "surface" anchor at the table top (upright, unit scale, pivot at the object's
    /// bottom), so the floor effect's local y ≥ 0 means "never through the table". Not for per-frame use.
    /// </summary>
    public static class SampleContent
    {
        public const float TableHeight = 0.75f;

        /// <summary>Densities of Experiment 1's boxes, kg/m³: same size, B heaviest (<see cref="PaperExperiment1"/>, the one definition).</summary>
        public const float BoxADensity = (float)PaperExperiment1.BoxADensity, BoxBDensity = (float)PaperExperiment1.BoxBDensity, BoxCDensity = (float)PaperExperiment1.BoxCDensity;

        /// <summary>Edge of Experiment 1's boxes, m (<see cref="PaperExperiment1.BoxEdge"/>).</summary>
        public const float BoxSize = (float)PaperExperiment1.BoxEdge;

        /// <summary>Experiment 2's water bottles, litres.</summary>
        public static readonly float[] BottleLitres = { 0.33f, 0.5f, 1.0f, 1.5f, 2.0f };

        /// <summary>A golf ball: 42.7 mm across, 45 g (the paper's standard weight).</summary>
        public const float GolfBallRadius = 0.02135f;

        public const float WaterDensity = 1000f;

        /// <summary>A table whose top centre is at <paramref name="position"/>; returns the anchor objects go under.</summary>
        public static Transform Table(Transform root, string name, Vector3 position, Vector2 size)
        {
            var table = new GameObject(name).transform;
            table.SetParent(root, false);
            table.localPosition = position;

            var top = GameObject.CreatePrimitive(PrimitiveType.Cube).transform;
            top.name = "Top";
            top.SetParent(table, false);
            top.localScale = new Vector3(size.x, 0.04f, size.y);
            top.localPosition = new Vector3(0, -0.02f, 0);

            var legs = GameObject.CreatePrimitive(PrimitiveType.Cube).transform;
            legs.name = "Base";
            legs.SetParent(table, false);
            legs.localScale = new Vector3(size.x * 0.8f, position.y - 0.04f, size.y * 0.8f);
            legs.localPosition = new Vector3(0, -0.04f - (position.y - 0.04f) / 2, 0);

            var surface = new GameObject("Surface").transform;
            surface.SetParent(table, false);
            return surface;
        }

        /// <summary>A box of density ρ resting on <paramref name="surface"/>: mass = ρ × the box collider's volume.</summary>
        public static PseudoHapticWeight Box(Transform surface, string name, Vector3 localPosition, Vector3 size, float density, PseudoHapticProfile profile)
        {
            var go = new GameObject(name);
            go.transform.SetParent(surface, false);
            go.transform.localPosition = localPosition;
            var box = go.AddComponent<BoxCollider>();
            box.size = size;
            box.center = new Vector3(0, size.y / 2, 0);
            go.AddComponent<Rigidbody>();

            var visual = Visual(PrimitiveType.Cube, go.transform);
            visual.localScale = size;
            visual.localPosition = new Vector3(0, size.y / 2, 0);

            Label(go.transform, name, new Vector3(0, size.y + 0.05f, 0));
            return Weight(go, MassSource.DensityTimesVolume, density, 0, profile);
        }

        /// <summary>
        /// A water bottle of <paramref name="litres"/>: a cylinder mesh collider, mass = 1000 kg/m³ × the mesh's
        /// volume (signed tetrahedra), its height set so the mesh holds that volume. The volume is stored with the
        /// weight here, at edit time when the editor builds the scene, so a player build never reads the mesh. Where
        /// the mesh cannot be read (a setup script running in a player that stripped it), the height stays the
        /// circle's and the mass is computed from the mesh at configuration if it can be, else it is reported.
        /// </summary>
        public static PseudoHapticWeight Bottle(Transform surface, string name, Vector3 localPosition, float litres, float radius, PseudoHapticProfile profile)
        {
            var go = new GameObject(name);
            go.transform.SetParent(surface, false);
            go.transform.localPosition = localPosition;
            go.AddComponent<Rigidbody>();

            // Unity's cylinder is 2 units tall and 1 across; scale it, then correct the height for the polygon.
            var body = GameObject.CreatePrimitive(PrimitiveType.Cylinder);
            body.name = "Body";
            Object.DestroyImmediate(body.GetComponent<Collider>());
            body.transform.SetParent(go.transform, false);
            float volume = litres / 1000f;
            float height = volume / (Mathf.PI * radius * radius);
            body.transform.localScale = new Vector3(2 * radius, height / 2, 2 * radius);
            var mesh = body.AddComponent<MeshCollider>();
            mesh.sharedMesh = body.GetComponent<MeshFilter>().sharedMesh;
            mesh.convex = true;
            if (ColliderVolume.TryGet(mesh, out double actual, out _))
            {
                height *= (float)(volume / actual);
                body.transform.localScale = new Vector3(2 * radius, height / 2, 2 * radius);
            }
            body.transform.localPosition = new Vector3(0, height / 2, 0);

            Label(go.transform, name, new Vector3(0, height + 0.05f, 0));
            var weight = Weight(go, MassSource.DensityTimesVolume, WaterDensity, 0, profile);
            weight.VolumeCollider = mesh;
            weight.StoreMeshVolume();
            return weight;
        }

        /// <summary>A sphere of a given mass (explicit), e.g. a golf-ball-weight ball or a heavy shot.</summary>
        public static PseudoHapticWeight Ball(Transform surface, string name, Vector3 localPosition, float radius, float massKg, PseudoHapticProfile profile)
        {
            var go = new GameObject(name);
            go.transform.SetParent(surface, false);
            go.transform.localPosition = localPosition;
            var sphere = go.AddComponent<SphereCollider>();
            sphere.radius = radius;
            sphere.center = new Vector3(0, radius, 0);
            go.AddComponent<Rigidbody>();
            var visual = Visual(PrimitiveType.Sphere, go.transform);
            visual.localScale = Vector3.one * (2 * radius);
            visual.localPosition = new Vector3(0, radius, 0);
            Label(go.transform, name, new Vector3(0, 2 * radius + 0.05f, 0));
            return Weight(go, MassSource.Explicit, 0, massKg, profile);
        }

        /// <summary>The calibration station: a table, a marker where the golf ball rests, instructions, the calibrator.</summary>
        public static StandardSpeedCalibrator CalibrationStation(Transform root, IHandPoseSource hand)
        {
            Transform surface = Table(root, "Calibration Table", new Vector3(0, TableHeight, 0.45f), new Vector2(0.8f, 0.5f));
            var marker = Visual(PrimitiveType.Sphere, surface);
            marker.name = "Golf Ball Marker";
            marker.localScale = Vector3.one * (2 * GolfBallRadius);
            marker.localPosition = new Vector3(0, GolfBallRadius, 0);

            TextMesh display = Label(surface, "Hold a real golf ball in your hand, resting on the table.", new Vector3(0, 0.55f, 0.2f));
            display.characterSize = 0.012f;

            var go = new GameObject("Standard Speed Calibrator");
            go.transform.SetParent(root, false);
            var calibrator = go.AddComponent<StandardSpeedCalibrator>();
            calibrator.InjectHand(hand);
            calibrator.InjectDisplay(display);
            CueStrengthStation(root, calibrator, hand);
            return calibrator;
        }

        /// <summary>
        /// The calibration's second step (issue 31), beside the golf-ball table: two balls and two "heavier" buttons run by a
        /// <see cref="DiscriminationTask"/> at the default cue strength, and a <see cref="CueStrengthCalibrator"/> that begins its
        /// short 1-up-2-down staircase on mass once the golf-ball lifts are accepted and stores the tuned strength.
        /// </summary>
        public static CueStrengthCalibrator CueStrengthStation(Transform root, StandardSpeedCalibrator after, IHandPoseSource hand)
        {
            var station = new GameObject("Cue Strength Station");
            station.transform.SetParent(root, false);
            var profile = PseudoHapticProfile.CreatePreset(NamedProfiles.PaperExperimentName);
            DiscriminationTask task = DiscriminationStation.Build(station.transform, profile, "", hand != null ? new[] { hand } : null,
                new Vector3(1.0f, TableHeight, 0.45f), userCueStrength: false);
            var go = new GameObject("Cue Strength Calibrator");
            go.transform.SetParent(station.transform, false);
            var cue = go.AddComponent<CueStrengthCalibrator>();
            cue.Inject(task, after, null);
            return cue;
        }

        /// <summary>Height of the Playground's high shelf top, m (above a standing user's shoulder: height deceleration).</summary>
        public const float HighShelfHeight = 1.6f;

        /// <summary>
        /// The paper's participants lifted with both hands: switches on the profile's Two Hands effect (each hand carries
        /// its share, half by default), so two PinchGrabs on one object are one two-handed hold. Null: nothing to switch
        /// (the weight then uses "paper", where a second hand is followed and each carries the whole mass).
        /// </summary>
        public static void LiftWithBothHands(PseudoHapticProfile profile)
        {
            if (profile != null) profile.SetEnabled<TwoHands>(true);
        }

        /// <summary>
        /// Experiment 1 (paper §6, <see cref="PaperExperiment1"/>): boxes A, B, C of one size and different densities, B
        /// heaviest, mass = density × the box collider's volume, under <paramref name="profile"/> (the samples give it the
        /// experiment's, "paper-experiment", whose Two Hands shares the weight when both hands lift).
        /// </summary>
        public static List<PseudoHapticWeight> Experiment1(Transform root, PseudoHapticProfile profile)
        {
            Transform surface = Table(root, "Table", new Vector3(0, TableHeight, 0.45f), new Vector2(1.0f, 0.5f));
            var size = Vector3.one * BoxSize;
            return new List<PseudoHapticWeight>
            {
                Box(surface, "Box A", new Vector3(-0.3f, 0, 0), size, BoxADensity, profile),
                Box(surface, "Box B", new Vector3(0, 0, 0), size, BoxBDensity, profile),
                Box(surface, "Box C", new Vector3(0.3f, 0, 0), size, BoxCDensity, profile),
            };
        }

        /// <summary>Experiment 2 (paper §7): water bottles of several sizes, lifted with both hands (a profile with Two Hands,
        /// <see cref="LiftWithBothHands"/>; the profile is used as given).</summary>
        public static List<PseudoHapticWeight> Experiment2(Transform root, PseudoHapticProfile profile)
        {
            Transform surface = Table(root, "Table", new Vector3(0, TableHeight, 0.45f), new Vector2(1.2f, 0.5f));
            var bottles = new List<PseudoHapticWeight>();
            float x = -0.45f;
            foreach (float litres in BottleLitres)
            {
                float radius = litres <= 0.5f ? 0.033f : 0.045f;
                string label = litres.ToString("0.##", System.Globalization.CultureInfo.InvariantCulture) + " L";
                bottles.Add(Bottle(surface, label, new Vector3(x, 0, 0), litres, radius, profile));
                x += 0.225f;
            }
            return bottles;
        }

        /// <summary>
        /// The playground: objects from 10 g to 5 kg sharing one profile, and a switch for every effect (two rows); a
        /// sideways carry (a 2 kg box to carry to the side table: lateral inertia) and a high shelf (a 1 kg box to lift
        /// onto it: height deceleration), both under the "xyz" profile <paramref name="threeD"/> (an in-memory preset when null).
        /// </summary>
        /// <remarks>With <paramref name="handOnObject"/> (a profile drawing the hand on the object), a 2 kg box under it too.</remarks>
        public static List<PseudoHapticWeight> Playground(Transform root, PseudoHapticProfile profile, IReadOnlyList<IHandPoseSource> hands, PseudoHapticProfile handOnObject = null, PseudoHapticProfile threeD = null)
        {
            Transform surface = Table(root, "Table", new Vector3(0, TableHeight, 0.45f), new Vector2(1.4f, 0.6f));
            var objects = new List<PseudoHapticWeight>
            {
                Ball(surface, "10 g", new Vector3(-0.55f, 0, 0.05f), 0.02f, 0.01f, profile),
                Ball(surface, "Golf ball 45 g", new Vector3(-0.4f, 0, 0.05f), GolfBallRadius, 0.045f, profile),
                Box(surface, "0.5 kg", new Vector3(-0.2f, 0, 0.05f), Vector3.one * 0.08f, 0.5f / (0.08f * 0.08f * 0.08f), profile),
                Box(surface, "1 kg", new Vector3(0f, 0, 0.05f), Vector3.one * 0.1f, 1000f, profile),
                Bottle(surface, "2 L water", new Vector3(0.2f, 0, 0.05f), 2f, 0.045f, profile),
                Ball(surface, "5 kg", new Vector3(0.45f, 0, 0.05f), 0.06f, 5f, profile),
            };
            if (handOnObject != null)
                objects.Add(Box(surface, "2 kg (hand on object)", new Vector3(0.6f, 0, 0.05f), Vector3.one * 0.1f, 2000f, handOnObject));

            IReadOnlyList<string> effects = PseudoHapticProfile.EffectNames;
            int perRow = (effects.Count + 1) / 2;
            for (int i = 0; i < effects.Count; i++)
                EffectSwitch.Create(surface, effects[i], new Vector3(-0.6f + 0.18f * (i % perRow), 0, -0.14f - 0.12f * (i / perRow)), profile, hands);

            threeD = threeD != null ? threeD : PseudoHapticProfile.CreatePreset(NamedProfiles.XyzName);
            Transform carryFrom = Table(root, "Carry Table", new Vector3(-1.1f, TableHeight, 0.2f), new Vector2(0.5f, 0.5f));
            objects.Add(Box(carryFrom, "2 kg sideways carry (xyz)", Vector3.zero, Vector3.one * 0.12f, 2f / (0.12f * 0.12f * 0.12f), threeD));
            Transform carryTo = Table(root, "Carry Target Table", new Vector3(-1.1f, TableHeight, -0.6f), new Vector2(0.5f, 0.5f));
            Label(carryTo, "Carry the 2 kg box here", new Vector3(0, 0.1f, 0));
            Transform low = Table(root, "Shelf Table", new Vector3(1.1f, TableHeight, 0.2f), new Vector2(0.5f, 0.5f));
            objects.Add(Box(low, "1 kg to the high shelf (xyz)", Vector3.zero, Vector3.one * 0.1f, 1000f, threeD));
            Transform shelf = Table(root, "High Shelf", new Vector3(1.1f, HighShelfHeight, 0.55f), new Vector2(0.6f, 0.3f));
            Label(shelf, "Lift the 1 kg box up here", new Vector3(0, 0.12f, 0));
            return objects;
        }

        static System.Func<int> s_ovrHands;

        /// <summary>
        /// Called by the Meta assembly (<c>Kosmos.PseudoHaptic.Meta.OvrRigHands</c>, when the Meta XR Core SDK is installed)
        /// as play mode starts: <paramref name="addPoseSources"/> gives every enabled <c>OVRHand</c> that no pose source reads
        /// an <c>OvrHandPoseSource</c> and returns how many <c>OVRHand</c>s it found. Null: none (Meta's hands are not looked for).
        /// </summary>
        public static void RegisterOvrHands(System.Func<int> addPoseSources) => s_ovrHands = addPoseSources;

        static System.Func<bool> s_ovrFloorLevel;

        /// <summary>
        /// Called by the Meta assembly as play mode starts: <paramref name="useFloorLevel"/> sets Meta's rig to track from the
        /// floor when it tracks from the eyes, and says whether it did (the samples' tables stand on y = 0).
        /// </summary>
        public static void RegisterOvrFloorLevel(System.Func<bool> useFloorLevel) => s_ovrFloorLevel = useFloorLevel;

        /// <summary>
        /// The scene's pinch hands (every enabled <see cref="IPinchHandPoseSource"/>), each given a <see cref="PinchGrab"/>
        /// if it has none, after Meta's stock rig (an <c>OVRCameraRig</c> with an <c>OVRHandPrefab</c> per hand anchor) got
        /// a pose source on each <c>OVRHand</c>. When it finds none, logs one warning naming what is missing
        /// (<see cref="RigHands.MissingHandsWarning"/>). For setup scripts dropped into a scene that already has a rig;
        /// not for per-frame use.
        /// </summary>
        public static List<IPinchHandPoseSource> HandsInScene(string sample = null, Object context = null)
        {
            int ovrHands = s_ovrHands != null ? s_ovrHands() : 0;
            var hands = new List<IPinchHandPoseSource>();
            foreach (MonoBehaviour b in Object.FindObjectsByType<MonoBehaviour>(FindObjectsSortMode.InstanceID))
            {
                if (!(b is IPinchHandPoseSource hand) || !b.enabled) continue; // enabled, not isActiveAndEnabled: a source not yet awake still counts
                hands.Add(hand);
                if (b.GetComponent<PinchGrab>() == null) b.gameObject.AddComponent<PinchGrab>().InjectHand(hand);
            }
            string warning = RigHands.MissingHandsWarning(sample, hands.Count, s_ovrHands != null, ovrHands);
            if (warning != null) Debug.LogWarning(warning, context);
            TrackFromTheFloor(sample, context);
            return hands;
        }

        /// <summary>
        /// The samples' tables stand on y = 0: when Meta's rig tracks from Eye Level (y = 0 at the user's eyes), it is set to
        /// Floor Level, saying so once (<see cref="RegisterOvrFloorLevel"/>). <see cref="HandsInScene"/> calls it; a setup that
        /// does not look for the scene's hands calls it itself. Not for per-frame use.
        /// </summary>
        public static void TrackFromTheFloor(string sample = null, Object context = null)
        {
            if (s_ovrFloorLevel != null && s_ovrFloorLevel())
                Debug.LogWarning((sample ?? "The sample") + ": the OVRCameraRig tracked from Eye Level (y = 0 at the eyes), so its table would float above them; "
                    + "set to Floor Level. Set the OVRManager's Tracking Origin Type to Floor Level to keep it so.", context);
        }

        static PseudoHapticWeight Weight(GameObject go, MassSource source, float density, float massKg, PseudoHapticProfile profile)
        {
            var weight = go.AddComponent<PseudoHapticWeight>();
            weight.Mass = source;
            if (density > 0) weight.DensityKgPerCubicMetre = density;
            if (massKg > 0) weight.ExplicitMassKg = massKg;
            weight.Profile = profile;
            return weight;
        }

        static Transform Visual(PrimitiveType type, Transform parent)
        {
            var go = GameObject.CreatePrimitive(type);
            go.name = "Visual";
            Object.DestroyImmediate(go.GetComponent<Collider>());
            go.transform.SetParent(parent, false);
            return go.transform;
        }

        /// <summary>A 3D text label (legacy TextMesh: no UI package needed).</summary>
        public static TextMesh Label(Transform parent, string text, Vector3 localPosition)
        {
            var go = new GameObject("Label");
            go.transform.SetParent(parent, false);
            go.transform.localPosition = localPosition;
            var label = go.AddComponent<TextMesh>();
            label.text = text;
            label.anchor = TextAnchor.MiddleCenter;
            label.characterSize = 0.01f;
            label.fontSize = 48;
            // Unity 2022.2+ ships its legacy font as LegacyRuntime.ttf.
            Font font = Resources.GetBuiltinResource<Font>("LegacyRuntime.ttf");
            if (font != null)
            {
                label.font = font;
                go.GetComponent<MeshRenderer>().sharedMaterial = font.material;
            }
            return label;
        }
    }
}
