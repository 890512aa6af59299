using UnityEngine;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// A pinch grab for scenes without the Interaction SDK: one per hand. When the hand starts an index pinch
    /// within reach of an enabled <see cref="PseudoHapticWeight"/> (nearest first), it holds that object: x and z
    /// follow the hand, y comes from the weight's solver. Opening the hand releases it; while tracking is lost
    /// the object is held still, and released after <see cref="_releaseAfterLost"/> seconds.
    /// Runs in LateUpdate, after the hand SDK has updated its pose; nothing is allocated per frame.
    /// </summary>
    [AddComponentMenu("Kosmos/Pseudo-Haptic/Pinch Grab")]
    public sealed class PinchGrab : MonoBehaviour
    {
        [Tooltip("An IPinchHandPoseSource (e.g. OvrHandPoseSource, TransformHandPoseSource).")]
        [SerializeField] MonoBehaviour _hand;
        [Tooltip("How near the hand must be to an object's collider to grab it, m.")]
        [SerializeField] float _reach = 0.06f;
        [Tooltip("Release after tracking has been lost this long, s.")]
        [SerializeField] float _releaseAfterLost = 1f;
        [Tooltip("x and z follow the hand while held (the paper moves y only by the solver; x/z by the grab).")]
        [SerializeField] bool _followHorizontal = true;

        IPinchHandPoseSource _source;
        PseudoHapticWeight _held;
        Vector3 _grabOffset;
        bool _wasPinching;
        float _lostFor;

        public PseudoHapticWeight Held => _held;
        public IPinchHandPoseSource Hand => _source ?? (_source = HandSourceField.Resolve<IPinchHandPoseSource>(_hand));

        public float Reach
        {
            get => _reach;
            set => _reach = value;
        }

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
            if (_hand != null && Hand == null)
                Debug.LogError("Pinch Grab on '" + name + "': '" + _hand.name + "' has no IPinchHandPoseSource.", this);
        }

        void OnDisable() => Release();

        void LateUpdate() => Tick(Time.deltaTime);

        /// <summary>One frame of the grab; LateUpdate calls it, tests may too.</summary>
        public void Tick(float dt)
        {
            IPinchHandPoseSource hand = Hand;
            if (hand == null) return;
            bool tracked = hand.IsTracked;
            bool pinching = tracked && hand.IsPinching;
            Vector3 position = hand.Position;

            if (_held != null && !_held.IsHeld) _held = null; // destroyed, disabled or released elsewhere
            if (_held != null)
            {
                if (tracked && !pinching) Release();
                else if (!tracked && (_lostFor += dt) >= _releaseAfterLost) Release();
                else
                {
                    if (tracked)
                    {
                        _lostFor = 0;
                        if (_followHorizontal) FollowHorizontal(position);
                    }
                    _held.Step(position, tracked, hand.IsHighConfidence, hand.PoseTime, dt);
                }
            }
            else if (pinching && !_wasPinching)
            {
                TryGrab(hand, position);
            }
            _wasPinching = pinching;
        }

        /// <summary>Lets go of the held object, if any.</summary>
        public void Release()
        {
            if (_held != null) _held.EndHold();
            _held = null;
        }

        void TryGrab(IPinchHandPoseSource hand, Vector3 position)
        {
            PseudoHapticWeight best = null;
            float bestSq = _reach * _reach;
            var all = PseudoHapticWeight.Enabled;
            for (int i = 0; i < all.Count; i++)
            {
                PseudoHapticWeight w = all[i];
                if (w.IsHeld) continue;
                float d = (NearestPoint(w, position) - position).sqrMagnitude;
                if (d <= bestSq)
                {
                    best = w;
                    bestSq = d;
                }
            }
            if (best == null || !best.BeginHold(position, hand.PoseTime)) return;
            _held = best;
            _grabOffset = best.transform.position - position;
            _lostFor = 0;
        }

        static Vector3 NearestPoint(PseudoHapticWeight w, Vector3 position)
        {
            Collider c = w.Collider;
            if (c == null || !c.enabled) return w.transform.position;
            // PhysX answers ClosestPoint only for convex shapes.
            if (c is MeshCollider mesh && !mesh.convex) return c.bounds.ClosestPoint(position);
            return c.ClosestPoint(position);
        }

        void FollowHorizontal(Vector3 hand)
        {
            Transform t = _held.transform;
            Vector3 target = hand + _grabOffset;
            Vector3 p = t.position;
            p.x = target.x;
            p.z = target.z;
            if (IsFinite(p.x) && IsFinite(p.z)) t.position = p;
        }

        static bool IsFinite(float v) => !float.IsNaN(v) && !float.IsInfinity(v);
    }
}
