using Oculus.Interaction;
using UnityEngine;

namespace Kosmos.PseudoHaptic.Interaction
{
    /// <summary>
    /// The pseudo-haptic weight as a transformer of Meta's Interaction SDK: put it on a <c>Grabbable</c> that
    /// also has a <see cref="PseudoHapticWeight"/> and make it the Grabbable's one-grab transformer (and its
    /// two-grab one, for lifting with both hands). x and z follow the grab point (the mean of the grab points),
    /// keeping the offset they had at the grab; the object's rotation is left as it is; y comes from the solver.
    /// The Grabbable keeps owning the Rigidbody (Kinematic While Selected, Throw When Unselected), so the
    /// weight's release setting does not apply here. Compiled only when com.meta.xr.sdk.interaction is installed.
    /// </summary>
    [AddComponentMenu("Kosmos/Pseudo-Haptic/Pseudo-Haptic Transformer (Interaction SDK)")]
    public sealed class PseudoHapticTransformer : MonoBehaviour, ITransformer
    {
        [Tooltip("The weight to drive; found on the Grabbable's target transform when empty.")]
        [SerializeField] PseudoHapticWeight _weight;

        IGrabbable _grabbable;
        Vector3 _grabOffset;
        double _lastTime;
        bool _holding;

        public PseudoHapticWeight Weight => _weight;

        public void InjectWeight(PseudoHapticWeight weight) => _weight = weight;

        public void Initialize(IGrabbable grabbable)
        {
            _grabbable = grabbable;
            if (_weight == null && grabbable.Transform != null) _weight = grabbable.Transform.GetComponent<PseudoHapticWeight>();
            if (_weight == null) _weight = GetComponent<PseudoHapticWeight>();
            if (_weight == null) Debug.LogError("Pseudo-Haptic Transformer on '" + name + "' found no PseudoHapticWeight on the grabbed object.", this);
        }

        public void BeginTransform()
        {
            _holding = false;
            if (_grabbable == null || _weight == null || !TryGrabCentre(out Vector3 grab)) return;
            _grabOffset = _weight.transform.position - grab;
            _lastTime = Time.timeAsDouble;
            _holding = _weight.BeginHold(grab, double.NaN, RigidbodyControl.External);
        }

        public void UpdateTransform()
        {
            if (!_holding || !TryGrabCentre(out Vector3 grab)) return;
            double now = Time.timeAsDouble;
            float dt = (float)(now - _lastTime); // 0 when called twice in a frame: the solver moves nothing
            _lastTime = now;

            Transform target = _weight.transform;
            Vector3 p = target.position;
            Vector3 follow = grab + _grabOffset;
            p.x = follow.x;
            p.z = follow.z;
            if (IsFinite(p.x) && IsFinite(p.z)) target.position = p;

            // The grab interactor stops selecting when it loses the hand: a grab point is a tracked pose.
            _weight.Step(grab, true, true, double.NaN, dt);
        }

        public void EndTransform()
        {
            if (_holding && _weight != null) _weight.EndHold();
            _holding = false;
        }

        bool TryGrabCentre(out Vector3 centre)
        {
            var points = _grabbable.GrabPoints;
            centre = Vector3.zero;
            int n = points != null ? points.Count : 0;
            if (n == 0) return false;
            for (int i = 0; i < n; i++) centre += points[i].position;
            centre /= n;
            return true;
        }

        static bool IsFinite(float v) => !float.IsNaN(v) && !float.IsInfinity(v);
    }
}
