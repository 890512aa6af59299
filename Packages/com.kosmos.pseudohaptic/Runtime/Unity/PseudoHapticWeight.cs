using System;
using System.Collections.Generic;
using UnityEngine;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// Makes a grabbable object feel heavy (Son et al. 2022): while it is held, its local y is the core
    /// <see cref="WeightSolver"/>'s answer to the hand's height, so a heavier object lags the hand and a
    /// lighter one leads it. A grab driver (<see cref="PinchGrab"/>, the Interaction SDK transformer, your own)
    /// calls <see cref="BeginHold(Vector3, double, RigidbodyControl)"/>, then <see cref="Step(Vector3, bool, bool, double, float)"/>
    /// once per frame, then <see cref="EndHold"/>; it moves x and z itself. Every number comes from the core;
    /// this component converts poses into the parent's space and writes the result.
    /// </summary>
    /// <remarks>
    /// The solver works in the parent's space, so give held objects an upright parent of unit scale
    /// (the table, the floor, or none): the floor effect keeps local y ≥ its floor (0 by default).
    /// Steps allocate nothing and never write NaN to the transform.
    /// </remarks>
    [DisallowMultipleComponent]
    [AddComponentMenu("Kosmos/Pseudo-Haptic/Pseudo-Haptic Weight")]
    public sealed class PseudoHapticWeight : MonoBehaviour
    {
        public enum MassSource
        {
            /// <summary>The Rigidbody's mass.</summary>
            Rigidbody,
            /// <summary>m = ρ·V with V the collider's volume (box, sphere, capsule or mesh); written to the Rigidbody if any.</summary>
            DensityTimesVolume,
            /// <summary>The mass given here; written to the Rigidbody if any.</summary>
            Explicit,
        }

        public enum StandardSpeedSource
        {
            /// <summary>The current user's stored calibration (<see cref="UserCalibrationStore"/>), else the solver's default.</summary>
            UserCalibration,
            /// <summary>The speed given here.</summary>
            Explicit,
        }

        /// <summary>What the Rigidbody gets back when the hold ends (paper 3.3 removes inertia while held; release is a setting).</summary>
        public enum ReleaseVelocity
        {
            Zero,
            /// <summary>The object's own velocity over its last motion.</summary>
            Object,
            /// <summary>The hand's velocity over its last motion (a throw).</summary>
            Hand,
        }

        /// <summary>Who makes the Rigidbody kinematic during a hold.</summary>
        public enum RigidbodyControl
        {
            /// <summary>This component: kinematic while held, falling velocity removed, release velocity per setting.</summary>
            ByThisComponent,
            /// <summary>The grab system (e.g. the Interaction SDK's Grabbable): this component leaves the Rigidbody alone.</summary>
            External,
        }

        [Header("Mass")]
        [SerializeField] MassSource _massSource = MassSource.Rigidbody;
        [Tooltip("kg, when Mass Source is Explicit.")]
        [SerializeField] float _explicitMassKg = 0.5f;
        [Tooltip("kg/m³, when Mass Source is Density Times Volume (water 1000, oak ~700, pine ~450).")]
        [SerializeField] float _densityKgPerCubicMetre = 1000f;
        [Tooltip("The collider whose volume counts; this object's first collider when empty.")]
        [SerializeField] Collider _volumeCollider;
        // A mesh collider's volume (mesh units³) computed in the editor, and the mesh it is of: a player build strips
        // meshes that are not Read/Write, so it uses this instead of reading the mesh (ColliderVolume, MeshVolume.Choose).
        [SerializeField, HideInInspector] double _storedMeshVolume;
        [SerializeField, HideInInspector] Mesh _storedVolumeMesh;

        [Header("Effects")]
        [Tooltip("The scene's effects; the 'paper' preset when empty.")]
        [SerializeField] PseudoHapticProfile _profile;

        [Header("User")]
        [SerializeField] StandardSpeedSource _standardSpeedSource = StandardSpeedSource.UserCalibration;
        [Tooltip("v_std, m/s, when Standard Speed Source is Explicit.")]
        [SerializeField] float _explicitStandardSpeed = (float)WeightSolver.DefaultStandardSpeed;

        [Header("Release")]
        [SerializeField] ReleaseVelocity _releaseVelocity = ReleaseVelocity.Object;

        static readonly List<PseudoHapticWeight> s_enabled = new List<PseudoHapticWeight>();

        WeightSolver _solver;
        bool _dirty = true;
        PseudoHapticProfile _configuredAsset;
        int _configuredVersion;
        string _error;

        Rigidbody _rigidbody;
        Collider _ownCollider;
        bool _controlsRigidbody;
        bool _wasKinematic;
        RigidbodyInterpolation _wasInterpolation;

        double _clock;
        Vector3 _handWorld;
        HandSample _lastHand;
        float _lastDt;
        VelocityTracker _handVelocity;
        VelocityTracker _objectVelocity;

        /// <summary>
        /// Raised with the weight after any weight's hold began (<see cref="BeginHold(Vector3, double, RigidbodyControl)"/>
        /// succeeded), after each of its steps, and after it ended: for observers such as <see cref="SessionRecorder"/>,
        /// which read <see cref="Solver"/>, <see cref="LastHand"/> and <see cref="LastDeltaTime"/>. Raising allocates
        /// nothing; a handler that throws is logged and does not stop the hold.
        /// </summary>
        public static event Action<PseudoHapticWeight> HoldBegan;
        public static event Action<PseudoHapticWeight> HoldStepped;
        public static event Action<PseudoHapticWeight> HoldEnded;

        /// <summary>The enabled weights, for grab drivers that look for the nearest one. Index it; do not keep it.</summary>
        public static IReadOnlyList<PseudoHapticWeight> Enabled => s_enabled;

        /// <summary>The core solver, null until the first successful configuration.</summary>
        public WeightSolver Solver => _solver;

        /// <summary>Why the last configuration failed; null when it succeeded.</summary>
        public string ConfigurationError => _error;

        public bool IsHeld => _solver != null && _solver.IsHolding;
        public double MassKg => _solver != null ? _solver.Model.MassKg : double.NaN;
        public double WeightNewtons => _solver != null ? _solver.Model.WeightNewtons : double.NaN;
        public double Gain => _solver != null ? _solver.Gain : double.NaN;
        public double StandardSpeed => _solver != null ? _solver.StandardSpeed : double.NaN;

        /// <summary>hand − object in the parent's space, m; positive when the object hangs below the hand; 0 when not held.</summary>
        public double Offset => IsHeld ? _solver.Offset : 0;

        /// <summary>
        /// The hand as the solver was given it on the hold's last frame (its begin or its last step): height in the
        /// parent's space (NaN while untracked), tracking, confidence, pose time.
        /// </summary>
        public HandSample LastHand => _lastHand;

        /// <summary>The frame time given to the last step, s (0 right after the hold began).</summary>
        public float LastDeltaTime => _lastDt;

        /// <summary>The hand's last tracked world position during the hold.</summary>
        public Vector3 HandWorldPosition => _handWorld;

        /// <summary>The hand's velocity over its last motion, world space (zero once it has been still for 0.1 s).</summary>
        public Vector3 HandVelocity => _handVelocity.VelocityAt(_clock);

        /// <summary>The object's velocity over its last motion, world space.</summary>
        public Vector3 ObjectVelocity => _objectVelocity.VelocityAt(_clock);

        /// <summary>The collider whose volume counts and that a hand reaches for.</summary>
        public Collider Collider
        {
            get
            {
                if (_volumeCollider != null) return _volumeCollider;
                if (_ownCollider == null) _ownCollider = GetComponent<Collider>();
                return _ownCollider;
            }
        }

        /// <summary>The collider whose volume counts; null for this object's first collider.</summary>
        public Collider VolumeCollider
        {
            get => _volumeCollider;
            set { _volumeCollider = value; _dirty = true; }
        }

        public PseudoHapticProfile Profile
        {
            get => _profile;
            set { _profile = value; _dirty = true; }
        }

        public MassSource Mass
        {
            get => _massSource;
            set { _massSource = value; _dirty = true; }
        }

        public float ExplicitMassKg
        {
            get => _explicitMassKg;
            set { _explicitMassKg = value; _dirty = true; }
        }

        public float DensityKgPerCubicMetre
        {
            get => _densityKgPerCubicMetre;
            set { _densityKgPerCubicMetre = value; _dirty = true; }
        }

        public StandardSpeedSource SpeedSource
        {
            get => _standardSpeedSource;
            set { _standardSpeedSource = value; _dirty = true; }
        }

        public float ExplicitStandardSpeed
        {
            get => _explicitStandardSpeed;
            set { _explicitStandardSpeed = value; _dirty = true; }
        }

        public ReleaseVelocity Release
        {
            get => _releaseVelocity;
            set => _releaseVelocity = value;
        }

        Rigidbody Body
        {
            get
            {
                if (_rigidbody == null) _rigidbody = GetComponent<Rigidbody>();
                return _rigidbody;
            }
        }

        bool NeedsConfiguration => _dirty || _profile != _configuredAsset || (_profile != null && _profile.Version != _configuredVersion);

        void OnEnable()
        {
            s_enabled.Add(this);
            UserCalibrationStore.Changed += MarkDirty;
        }

        void OnDisable()
        {
            if (IsHeld) EndHold();
            s_enabled.Remove(this);
            UserCalibrationStore.Changed -= MarkDirty;
        }

        void OnValidate()
        {
            _dirty = true;
#if UNITY_EDITOR
            if (_massSource == MassSource.DensityTimesVolume) StoreMeshVolume();
#endif
        }

        /// <summary>
        /// Reads the volume collider's mesh (a <see cref="MeshCollider"/> whose mesh is readable, as every mesh is in the
        /// editor) and stores its volume with this component, so that a player build, where the mesh may be stripped,
        /// needs no readable mesh. The editor calls it whenever the component is edited; the sample scene builders
        /// call it for the bottles. False when there is no readable closed mesh. Allocates: not for run time.
        /// </summary>
        public bool StoreMeshVolume()
        {
            if (!(Collider is MeshCollider meshCollider)) return false;
            Mesh mesh = meshCollider.sharedMesh;
            if (mesh == null || !mesh.isReadable) return false;
            double v = Math.Abs(ColliderVolume.Mesh(mesh.vertices, mesh.triangles));
            if (!(v > 0) || double.IsInfinity(v)) return false;
            _storedMeshVolume = v;
            _storedVolumeMesh = mesh;
            _dirty = true;
            return true;
        }

        void MarkDirty() => _dirty = true;

        /// <summary>
        /// The weight model of this object's current settings, or false with the reason (the core's message,
        /// naming the field). Configuration-time work: reading a mesh collider's volume allocates.
        /// </summary>
        public bool TryCreateModel(out WeightModel model, out string error)
        {
            model = null;
            error = null;
            try
            {
                switch (_massSource)
                {
                    case MassSource.Rigidbody:
                        if (Body == null) { error = "Mass Source is Rigidbody, but there is no Rigidbody on '" + name + "'"; return false; }
                        model = WeightModel.FromMass(Body.mass);
                        return true;
                    case MassSource.DensityTimesVolume:
                        if (!ColliderVolume.TryGet(Collider, _storedVolumeMesh, _storedMeshVolume, out double volume, out error)) return false;
                        model = WeightModel.FromDensity(_densityKgPerCubicMetre, volume);
                        return true;
                    default:
                        model = WeightModel.FromMass(_explicitMassKg);
                        return true;
                }
            }
            catch (ArgumentException e)
            {
                error = e.Message;
                return false;
            }
        }

        /// <summary>The profile this object uses: its asset's, or the "paper" preset.</summary>
        public bool TryGetProfile(out WeightProfile profile, out string error)
        {
            if (_profile == null)
            {
                profile = NamedProfiles.Paper;
                error = null;
                return true;
            }
            return _profile.TryBuild(out profile, out error);
        }

        /// <summary>The user's v_std this object uses, m/s.</summary>
        public double ResolveStandardSpeed() =>
            _standardSpeedSource == StandardSpeedSource.Explicit ? _explicitStandardSpeed : UserCalibrationStore.StandardSpeedOrDefault;

        /// <summary>
        /// Applies the current settings (mass, profile, user) to the solver; allowed during a hold. On invalid
        /// settings it logs the reason once, keeps the last valid configuration, and returns false.
        /// Called by the hold methods when a setting changed; never needed per frame.
        /// </summary>
        public bool Configure()
        {
            _dirty = false;
            _configuredAsset = _profile;
            _configuredVersion = _profile != null ? _profile.Version : 0;

            if (!TryCreateModel(out WeightModel model, out string error) || !TryGetProfile(out WeightProfile profile, out error))
                return Fail(error);
            try
            {
                double v = ResolveStandardSpeed();
                if (_solver == null) _solver = new WeightSolver(model, profile, v);
                else _solver.Configure(model, profile, v);
            }
            catch (ArgumentException e)
            {
                return Fail(e.Message);
            }
            if (_massSource != MassSource.Rigidbody && Body != null) Body.mass = (float)model.MassKg;
            _error = null;
            return true;
        }

        bool Fail(string error)
        {
            _error = error;
            Debug.LogError("Pseudo-haptic weight on '" + name + "' is not configured: " + error, this);
            return false;
        }

        /// <summary>
        /// Starts a hold with the hand at <paramref name="handWorld"/>. False when the object is already held or
        /// cannot be configured. With <see cref="RigidbodyControl.ByThisComponent"/> the Rigidbody loses its
        /// velocity and turns kinematic until <see cref="EndHold"/> (paper 3.3).
        /// </summary>
        public bool BeginHold(Vector3 handWorld, double poseTime = double.NaN, RigidbodyControl rigidbody = RigidbodyControl.ByThisComponent)
        {
            if (IsHeld) return false;
            if (NeedsConfiguration) Configure();
            if (_solver == null) return false;
            double handY = ParentY(handWorld);
            try
            {
                _solver.BeginHold(handY, transform.localPosition.y, poseTime);
            }
            catch (ArgumentException e)
            {
                Debug.LogError("Pseudo-haptic weight on '" + name + "' cannot be held: " + e.Message, this);
                return false;
            }

            _controlsRigidbody = rigidbody == RigidbodyControl.ByThisComponent && Body != null;
            if (_controlsRigidbody)
            {
                _wasKinematic = _rigidbody.isKinematic;
                _wasInterpolation = _rigidbody.interpolation;
                if (!_wasKinematic)
                {
                    _rigidbody.velocity = Vector3.zero;
                    _rigidbody.angularVelocity = Vector3.zero;
                }
                _rigidbody.isKinematic = true;
                // An interpolated body would overwrite the transform this component writes.
                _rigidbody.interpolation = RigidbodyInterpolation.None;
            }

            SetLocalY(_solver.ObjectY); // the floor may have lifted the start
            _clock = 0;
            _handWorld = handWorld;
            _handVelocity.Reset(handWorld, 0);
            _objectVelocity.Reset(transform.position, 0);
            bool usable = !double.IsNaN(handY) && !double.IsInfinity(handY);
            _lastHand = new HandSample(handY, usable, usable, poseTime);
            _lastDt = 0;
            Raise(HoldBegan);
            return true;
        }

        /// <summary>Starts a hold from a pose source's current pose.</summary>
        public bool BeginHold(IHandPoseSource hand, RigidbodyControl rigidbody = RigidbodyControl.ByThisComponent)
            => hand != null && BeginHold(hand.Position, hand.PoseTime, rigidbody);

        /// <summary>
        /// Advances the hold by one frame of <paramref name="dt"/> seconds and writes the object's local y.
        /// Returns the new local y (the current one when not held). Never throws, never allocates.
        /// </summary>
        public float Step(Vector3 handWorld, bool isTracked, bool isHighConfidence, double poseTime, float dt)
        {
            if (!IsHeld) return transform.localPosition.y;
            if (NeedsConfiguration) Configure(); // only after a setting changed

            double handY = isTracked ? ParentY(handWorld) : double.NaN;
            var sample = new HandSample(handY, isTracked, isHighConfidence, poseTime);
            double y = _solver.Step(in sample, dt);
            SetLocalY(y);
            _lastHand = sample;
            _lastDt = dt;

            if (dt > 0 && dt < float.PositiveInfinity) _clock += dt;
            if (isTracked)
            {
                _handWorld = handWorld;
                _handVelocity.Add(handWorld, _clock);
            }
            _objectVelocity.Add(transform.position, _clock);
            Raise(HoldStepped);
            return transform.localPosition.y;
        }

        /// <summary>Advances the hold from a pose source's current pose.</summary>
        public float Step(IHandPoseSource hand, float dt)
        {
            if (hand == null) return Step(default, false, false, double.NaN, dt);
            return Step(hand.Position, hand.IsTracked, hand.IsHighConfidence, hand.PoseTime, dt);
        }

        /// <summary>Ends the hold; the Rigidbody, if this component holds it, gets back its kinematic state and the release velocity.</summary>
        public void EndHold()
        {
            if (!IsHeld) return;
            _solver.EndHold();
            RestoreRigidbody();
            Raise(HoldEnded);
        }

        void RestoreRigidbody()
        {
            if (!_controlsRigidbody) return;
            _controlsRigidbody = false;
            if (_rigidbody == null) return;
            _rigidbody.isKinematic = _wasKinematic;
            _rigidbody.interpolation = _wasInterpolation;
            if (_wasKinematic) return;
            _rigidbody.velocity = _releaseVelocity == ReleaseVelocity.Hand ? HandVelocity
                : _releaseVelocity == ReleaseVelocity.Object ? ObjectVelocity
                : Vector3.zero;
            _rigidbody.angularVelocity = Vector3.zero;
        }

        void Raise(Action<PseudoHapticWeight> handlers)
        {
            if (handlers == null) return;
            try { handlers(this); }
            catch (Exception e) { Debug.LogException(e, this); }
        }

        /// <summary>A world point's height in this object's parent space, the space its local y lives in.</summary>
        public double ParentY(Vector3 world)
        {
            Transform parent = transform.parent;
            return parent == null ? world.y : parent.InverseTransformPoint(world).y;
        }

        void SetLocalY(double y)
        {
            float f = (float)y;
            if (float.IsNaN(f) || float.IsInfinity(f)) return;
            Vector3 p = transform.localPosition;
            p.y = f;
            transform.localPosition = p;
        }

        [RuntimeInitializeOnLoadMethod(RuntimeInitializeLoadType.SubsystemRegistration)]
        static void ResetStatics()
        {
            // With domain reload off, statics survive play sessions: start each one clean.
            s_enabled.Clear();
            HoldBegan = null;
            HoldStepped = null;
            HoldEnded = null;
        }
    }
}
