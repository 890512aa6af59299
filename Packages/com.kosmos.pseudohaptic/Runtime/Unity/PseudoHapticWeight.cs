using System;
using System.Collections.Generic;
using UnityEngine;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// Makes a grabbable object feel heavy (Son et al. 2022): while held, its local y is the core solver's answer
    /// to the hands (<see cref="WeightSolver3D"/>), and so are x/z when the profile has lateral inertia. Glue only:
    /// the decisions (mass, hands, per-hand share, break-away, release velocity) are the engine-free
    /// <see cref="HeldObject"/> and <see cref="WeightSettings"/>; this reads the transform, the Rigidbody and the
    /// collider, and writes the answer. A grab driver calls BeginHold, Step once per frame, then EndHold, each with
    /// its hand's id (two hands may hold one object); it moves x and z itself unless <see cref="HeldObject.MovesHorizontal"/>,
    /// and releases when <see cref="HeldObject.BrokeAway"/> (the Rigidbody then falls). Overloads without a hand id:
    /// <see cref="PseudoHapticWeightCalls"/>. Give held objects an upright parent of unit scale. Steps allocate nothing and never write NaN.
    /// From the settings to the solver's configuration: PseudoHapticWeight.Configuration.cs; where the held object is
    /// written (the hold's frame, the parent's space): PseudoHapticWeight.Placement.cs.
    /// </summary>
    [DisallowMultipleComponent]
    [AddComponentMenu("Kosmos/Pseudo-Haptic/Pseudo-Haptic Weight")]
    public sealed partial class PseudoHapticWeight : MonoBehaviour, IParentSpace
    {
        [Header("Mass")]
        [SerializeField] MassSource _massSource = MassSource.Rigidbody;
        [Tooltip("kg, when Mass Source is Explicit.")]
        [SerializeField] float _explicitMassKg = 0.5f;
        [Tooltip("kg/m³, when Mass Source is Density Times Volume (water 1000, oak ~700, pine ~450).")]
        [SerializeField] float _densityKgPerCubicMetre = 1000f;
        [Tooltip("The collider whose volume counts and that a hand reaches for; this object's first collider when empty.")]
        [SerializeField] Collider _volumeCollider;
        // A mesh collider's volume (mesh units³) computed in the editor, and the mesh it is of: a player build strips
        // meshes that are not Read/Write, so it uses this instead of reading the mesh (ColliderVolume, MeshVolume.Choose).
        [SerializeField, HideInInspector] double _storedMeshVolume;
        [SerializeField, HideInInspector] Mesh _storedVolumeMesh;

        [Header("Effects")]
        [Tooltip("The scene's effects and where the hand is drawn; the 'paper' preset when empty.")]
        [SerializeField] PseudoHapticProfile _profile;
        [Header("User")]
        [SerializeField] StandardSpeedSource _standardSpeedSource = StandardSpeedSource.UserCalibration;
        [Tooltip("v_std, m/s, when Standard Speed Source is Explicit.")]
        [SerializeField] float _explicitStandardSpeed = (float)WeightSolver.DefaultStandardSpeed;
        [Tooltip("Apply the user's cue strength from their calibration (issue 31: tuned from their own weight threshold; 1 when none is stored). Off: the paper's cue, strength 1.")]
        [SerializeField] bool _userCueStrength = true;
        [Header("Release")]
        [SerializeField] ReleaseVelocity _releaseVelocity = ReleaseVelocity.Object;
        [Header("Rig")]
        [Tooltip("The tracking space the hands are tracked in (OVRCameraRig ▸ TrackingSpace, the XR Origin's Camera Offset): its motion carries a held object rigidly and is never weighed. Grab drivers set it from their hand source; empty: the world.")]
        [SerializeField] Transform _rig;

        static readonly List<PseudoHapticWeight> s_enabled = new List<PseudoHapticWeight>();
        HeldObject _hold;
        HeldBody _body;
        RigidbodyControl _rigidbodyControl;

        /// <summary>Raised after a hold began (first hand), after each solver step, and after it ended (last hand); a throwing handler is logged.</summary>
        public static event Action<PseudoHapticWeight> HoldBegan, HoldStepped, HoldEnded;

        /// <summary>The enabled weights, for grab drivers that look for the nearest one. Index it; do not keep it.</summary>
        public static IReadOnlyList<PseudoHapticWeight> Enabled => s_enabled;
        public HeldObject Hold => _hold ?? (_hold = CreateHold());
        public WeightSolver Solver => Hold.Solver;
        public bool IsHeld => Hold.IsHeld;
        public double MassKg => Hold.MassKg;
        public double Gain => Solver != null ? Solver.Gain : double.NaN;
        public double StandardSpeed => Solver != null ? Solver.StandardSpeed : double.NaN;
        /// <summary>The cue strength the solver runs at (NaN until configured).</summary>
        public double CueStrength => Solver != null ? Solver.CueStrength : double.NaN;
        /// <summary>hand − object in the parent's space, m (its value at the grab is Solver.GrabOffset); 0 when not held.</summary>
        public double Offset => IsHeld ? Hold.Offset : 0;
        public HandSample LastHand => Hold.LastHand;
        public float LastDeltaTime => (float)Hold.LastDeltaTime;

        /// <summary>The tracking space the hands are tracked in (null: the world); a new value applies from the next hold.</summary>
        public Transform Rig { get => _rig; set => _rig = value; }

        public HandDrawingMode HandDrawing => _profile != null ? _profile.HandDrawing : HandDrawingMode.HandTrue;
        public Collider Collider => _volumeCollider != null ? _volumeCollider : GetComponent<Collider>();
        public ReleaseVelocity Release { get => _releaseVelocity; set => _releaseVelocity = value; }
        Rigidbody Body => GetComponent<Rigidbody>();

        HeldObject CreateHold()
        {
            var hold = new HeldObject(this);
            hold.Began += () => { _body = new HeldBody(_rigidbodyControl == RigidbodyControl.ByThisComponent ? Body : null); _body.Take(); Raise(HoldBegan); };
            hold.Stepped += () => Raise(HoldStepped);
            hold.Ended += () => { _body.Restore(_frame.OutDirection(Hold.ReleaseVelocity(_releaseVelocity).ToUnity())); Raise(HoldEnded); };
            return hold;
        }

        void OnEnable() { s_enabled.Add(this); UserCalibrationStore.Changed += MarkDirty; Application.onBeforeRender += FollowRig; }
        void OnDisable() { Hold.EndAll(); s_enabled.Remove(this); UserCalibrationStore.Changed -= MarkDirty; Application.onBeforeRender -= FollowRig; }

        /// <summary>Hand <paramref name="hand"/> takes the object at <paramref name="handWorld"/> (a second hand joins). False when it cannot.</summary>
        public bool BeginHold(int hand, Vector3 handWorld, double poseTime = double.NaN, RigidbodyControl rigidbody = RigidbodyControl.ByThisComponent)
        {
            if (NeedsConfiguration) Configure();
            Collider c = Collider;
            Hold.BottomBelowPivot = c != null ? Math.Max(0, transform.position.y - c.bounds.min.y) : 0; // the floor keeps the bottom up
            _rigidbodyControl = rigidbody; // the first hand's Began takes the Rigidbody
            if (Hold.HandCount == 0)
            {
                _frame = HoldFrame.At(_rig);
                _heldPosition = transform.position;
                _heldRotation = transform.rotation;
            }
            bool began = Hold.Begin(hand, _frame.In(handWorld).ToDouble(), poseTime, _heldPosition.ToDouble(), transform.localPosition.y);
            if (began && Hold.HandCount == 1) SetHeld(_heldPosition, Hold.ObjectY); // the floor may have lifted the start
            return began;
        }

        /// <summary>
        /// One frame of hand <paramref name="hand"/>; writes the object's local y (and x/z: the solver's with lateral inertia,
        /// else, when <paramref name="grabMovesHorizontal"/>, the mean of the hands on it plus the offset it had from them:
        /// <see cref="HeldObject.GrabTarget"/>) and returns y. Never throws, never allocates.
        /// </summary>
        public float Step(int hand, Vector3 handWorld, bool isTracked, bool isHighConfidence, double poseTime, float dt, bool grabMovesHorizontal = false)
        {
            if (IsHeld && NeedsConfiguration) Configure(); // only after a setting changed
            if (!Hold.Holds(hand)) return transform.localPosition.y;
            double y = Hold.Step(hand, _frame.In(handWorld).ToDouble(), isTracked, isHighConfidence, poseTime, dt);
            SetHeld(Hold.Horizontal(_heldPosition.ToDouble(), grabMovesHorizontal).ToUnity(), y);
            Hold.TrackObject(_heldPosition.ToDouble());
            return (float)ParentY(_heldPosition);
        }

        /// <summary>Hand <paramref name="hand"/> lets go; the last hand ends the hold and the Rigidbody gets its state and release velocity back.</summary>
        public void EndHold(int hand) => Hold.End(hand);

        /// <summary>Every hand lets go.</summary>
        public void EndHold() => Hold.EndAll();

        void Raise(Action<PseudoHapticWeight> handlers)
        {
            try { handlers?.Invoke(this); }
            catch (Exception e) { Debug.LogException(e, this); }
        }

        [RuntimeInitializeOnLoadMethod(RuntimeInitializeLoadType.SubsystemRegistration)]
        static void ResetStatics()
        {
            // With domain reload off, statics survive play sessions: start each one clean.
            s_enabled.Clear();
            HoldBegan = HoldStepped = HoldEnded = null;
        }
    }
}
