using UnityEngine;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// A pinch grab for scenes without the Interaction SDK: one per hand. Glue over the engine-free
    /// <see cref="HandGrab"/> (pinch with hysteresis, release on an opened hand, a long tracking loss or a
    /// break-away), <see cref="GrabSelection"/> (the nearest enabled <see cref="PseudoHapticWeight"/> in reach; two
    /// hands may share one) and <see cref="HandDrawing"/> (where the hand's visual root is drawn, per the held
    /// object's profile). Two of these (one per hand) on one weight are one two-handed hold. x and z follow the hand,
    /// unless the weight's profile has lateral inertia (then they are its solver's); y comes from the weight's
    /// solver. A break-away reported by the solver releases the grab, and the Rigidbody falls. Runs in LateUpdate, after the
    /// hand SDK has updated its pose; the hand visual is placed again in <c>Application.onBeforeRender</c> after the rigs'
    /// own before-render updates (<see cref="BeforeRenderOrder"/>), from the hand as the rig re-posed it, so a hand drawn
    /// on the object stays on it. Nothing is allocated per frame.
    /// </summary>
    [AddComponentMenu("Kosmos/Pseudo-Haptic/Pinch Grab")]
    public sealed class PinchGrab : MonoBehaviour, IGrabDriver, IGrabCandidates
    {
        [Tooltip("An IPinchHandPoseSource (OvrHandPoseSource, XRHandPoseSource, TransformHandPoseSource).")]
        [SerializeField] MonoBehaviour _hand;
        [Tooltip("How near the hand must be to an object's collider to grab it, m.")]
        [SerializeField] float _reach = 0.06f;
        [Tooltip("Release after tracking has been lost this long, s.")]
        [SerializeField] float _releaseAfterLost = (float)HandGrab.DefaultReleaseAfterLost;
        [Tooltip("x and z follow the hand while held (the paper moves y only by the solver; x/z by the grab).")]
        [SerializeField] bool _followHorizontal = true;
        [Tooltip("Optional: the hand's visual root (a transform the hand SDK does not drive, above the hand mesh), offset to the object when the held object's profile draws the hand on the object.")]
        [SerializeField] Transform _handVisual;

        /// <summary>
        /// Where the hand visual is placed in <c>Application.onBeforeRender</c> (Unity's <c>[BeforeRenderOrder]</c>, lower
        /// first): after OVRCameraRig's late anchor update (its <c>OnBeforeRenderCallback</c> has no order: 0), after
        /// XR Interaction Toolkit's interaction manager (100), and after the weights re-place their objects (0).
        /// </summary>
        public const int BeforeRenderOrder = 200;

        static int s_nextId;
        int _id;
        IPinchHandPoseSource _source;
        readonly HandGrab _grab = new HandGrab();
        readonly HandDrawing _drawing = new HandDrawing();
        PseudoHapticWeight _held;
        Vector3 _position, _grabOffset, _visualRest;
        float _dt;

        public PseudoHapticWeight Held => _held;
        public HandGrab Grab => _grab;
        public HandDrawing Drawing => _drawing;
        public IPinchHandPoseSource Hand => _source ?? (_source = HandSourceField.Resolve<IPinchHandPoseSource>(_hand));
        /// <summary>How near the hand must be to an object's collider to grab it, m (finite, ≥ 0).</summary>
        public float Reach
        {
            get => _reach;
            set
            {
                FieldRules.Require(FieldRules.NonNegative(nameof(Reach), value), nameof(Reach), value);
                _reach = value;
            }
        }
        public float ReleaseAfterLost { get => _releaseAfterLost; set => _grab.ReleaseAfterLost = _releaseAfterLost = value; }
        public Transform HandVisual { get => _handVisual; set { _handVisual = value; _visualRest = value != null ? value.localPosition : default; } }
        int Id => _id != 0 ? _id : (_id = ++s_nextId);

        /// <summary>Sets the hand in code (tests, scene builders).</summary>
        public void InjectHand(IPinchHandPoseSource hand)
        {
            _source = hand;
            _hand = hand as MonoBehaviour;
        }

        void OnValidate()
        {
            MonoBehaviour source = HandSourceField.Normalize<IPinchHandPoseSource>(_hand);
            if (source != null) _hand = source;
            _source = null;
        }

        void Awake()
        {
            HandVisual = _handVisual;
            _grab.ReleaseAfterLost = _releaseAfterLost; // throws on an invalid setting, naming it
            string reach = FieldRules.NonNegative("Reach", _reach);
            if (reach != null)
            {
                Debug.LogError("Pinch Grab on '" + name + "': " + reach, this);
                enabled = false; // grabbing nothing beats grabbing with a NaN reach every frame
            }
            if (_hand != null && Hand == null) Debug.LogError("Pinch Grab on '" + name + "': '" + _hand.name + "' has no IPinchHandPoseSource.", this);
        }

        UnityEngine.Events.UnityAction _beforeRender;

        void OnEnable() => Application.onBeforeRender += _beforeRender ?? (_beforeRender = PlaceVisualBeforeRender);

        void OnDisable()
        {
            Application.onBeforeRender -= _beforeRender;
            Release();
            // Nothing draws the visual while this is off: it goes back on the tracked hand now, not where the last lag put it.
            _drawing.Reset();
            if (_handVisual != null) _handVisual.localPosition = _visualRest;
        }

        void LateUpdate() => Tick(Time.unscaledDeltaTime);

        /// <summary>One frame of the grab; LateUpdate calls it, tests may too.</summary>
        public void Tick(float dt)
        {
            IPinchHandPoseSource hand = Hand;
            if (hand == null) return;
            _position = hand.Position;
            _dt = dt;
            _grab.Tick(hand.IsTracked, PinchSources.Strength(hand), dt, this);
            // The lag in the hold's frame (the rig at the grab), turned back into the world with the rig.
            Vector3d lag = HeldLag(_position);
            Vector3d offset = _drawing.Update(_held != null ? _held.HandDrawing : HandDrawingMode.HandTrue, _held != null, lag, dt);
            DrawVisual(offset);
        }

        Vector3d HeldLag(Vector3 hand) => _held != null
            ? _held.OutOfHoldFrame(GrabFollow.Lag(_held.InHoldFrame(_held.transform.position).ToDouble(), _held.InHoldFrame(hand).ToDouble(), _grabOffset.ToDouble()).ToUnity()).ToDouble()
            : Vector3d.Zero;

        void DrawVisual(Vector3d offset)
        {
            if (_handVisual == null) return;
            _handVisual.localPosition = _visualRest;
            _handVisual.position += offset.ToUnity();
        }

        /// <summary>
        /// Before the frame renders, after the rig re-posed its hand anchors (and the weights their objects): the visual
        /// from the hand where it is now, the same frame's drawing (<see cref="HandDrawing.Remeasure"/>).
        /// </summary>
        [BeforeRenderOrder(BeforeRenderOrder)]
        void PlaceVisualBeforeRender()
        {
            if (_handVisual == null || !isActiveAndEnabled) return;
            IPinchHandPoseSource hand = Hand;
            if (hand == null) return;
            Vector3 now = hand.Position;
            DrawVisual(_drawing.Remeasure(_held != null ? HeldLag(now) : Vector3d.Zero));
        }

        /// <summary>Lets go of the held object, if any.</summary>
        public void Release() => _grab.Release(this);

        bool IGrabDriver.TryGrab()
        {
            int i = GrabSelection.Nearest(_position.ToDouble(), _reach, HeldObject.MaxHands, this);
            PseudoHapticWeight w = i >= 0 ? PseudoHapticWeight.Enabled[i] : null;
            if (w == null) return false;
            if (Hand is IRigHandPoseSource rigged && rigged.Rig != null && w.Hold.HandCount == 0) w.Rig = rigged.Rig; // the hold is solved in the hand's rig
            if (!w.BeginHold(Id, _position, Hand.PoseTime)) return false;
            _held = w;
            _grabOffset = w.InHoldFrame(w.transform.position) - w.InHoldFrame(_position);
            return true;
        }

        bool IGrabDriver.IsStillHeld => _held != null && _held.Hold.Holds(Id);
        bool IGrabDriver.BrokeAway => _held != null && _held.Hold.BrokeAway;

        // x/z: the hold's, from every hand on the object (HeldObject.GrabTarget), so two hands agree whichever ticks last.
        void IGrabDriver.Follow(bool tracked)
        {
            IPinchHandPoseSource hand = Hand;
            _held.Step(Id, _position, tracked, hand.IsHighConfidence, hand.PoseTime, _dt, GrabFollow.GrabMovesHorizontal(_followHorizontal, _held.Hold));
        }

        void IGrabDriver.Release()
        {
            if (_held != null) _held.EndHold(Id);
            _held = null;
        }

        int IGrabCandidates.Count => PseudoHapticWeight.Enabled.Count;
        int IGrabCandidates.HandsOn(int index) => PseudoHapticWeight.Enabled[index].Hold.HandCount;

        Vector3d IGrabCandidates.ClosestPoint(int index, Vector3d hand)
        {
            PseudoHapticWeight w = PseudoHapticWeight.Enabled[index];
            Collider c = w.Collider;
            Vector3 p = hand.ToUnity();
            // PhysX answers ClosestPoint only for convex shapes.
            if (c == null || !c.enabled) return w.transform.position.ToDouble();
            return (c is MeshCollider mesh && !mesh.convex ? c.bounds.ClosestPoint(p) : c.ClosestPoint(p)).ToDouble();
        }
    }
}
