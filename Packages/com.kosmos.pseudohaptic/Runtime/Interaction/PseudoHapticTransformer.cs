using System.Collections.Generic;
using Oculus.Interaction;
using Oculus.Interaction.HandGrab;
using UnityEngine;

namespace Kosmos.PseudoHaptic.Interaction
{
    /// <summary>
    /// The pseudo-haptic weight as a transformer of Meta's Interaction SDK: put it on a <c>Grabbable</c> that
    /// also has a <see cref="PseudoHapticWeight"/> and make it the Grabbable's one-grab transformer (and its
    /// two-grab one, for lifting with both hands). x and z follow the hand (the mean of the grabbing hands),
    /// keeping the offset they had at the grab; the object's rotation is left as it is; y comes from the solver.
    /// The hand is the tracked one: a hand grab interactor's grab point is not the hand at the start of a grab
    /// (its movement provider, <c>MoveTowardsTargetProvider</c> by default, slides it from the object toward the
    /// hand), so for every grab by an <see cref="IHandGrabInteractor"/> (the pointer event's data) the solver
    /// gets <see cref="HandGrabInteraction.GetHandGrabPose"/>: the tracked wrist times the offset from the wrist to
    /// the hand's pinch or palm point taken at the grab (a point fixed to the hand), the pose that movement slides
    /// toward. Grabs by other interactors (controllers) use the Grabbable's grab points, as they have no such slide.
    /// The Grabbable keeps owning the Rigidbody (Kinematic While Selected, Throw When Unselected), so the
    /// weight's release setting does not apply here. Compiled only when com.meta.xr.sdk.interaction is installed.
    /// </summary>
    [AddComponentMenu("Kosmos/Pseudo-Haptic/Pseudo-Haptic Transformer (Interaction SDK)")]
    public sealed class PseudoHapticTransformer : MonoBehaviour, ITransformer
    {
        [Tooltip("The weight to drive; found on the Grabbable's target transform when empty.")]
        [SerializeField] PseudoHapticWeight _weight;

        IGrabbable _grabbable;
        IPointable _pointable;
        // The hand grab interactors selecting the object, by pointer id (from the Grabbable's Select events).
        readonly List<int> _handIds = new List<int>(4);
        readonly List<IHandGrabInteractor> _hands = new List<IHandGrabInteractor>(4);
        Vector3 _grabOffset;
        double _lastTime;
        bool _holding;

        public PseudoHapticWeight Weight => _weight;

        public void InjectWeight(PseudoHapticWeight weight) => _weight = weight;

        public void Initialize(IGrabbable grabbable)
        {
            // Called once per role: the same transformer may be the Grabbable's one-grab and two-grab transformer.
            if (_pointable != null) _pointable.WhenPointerEventRaised -= OnPointerEvent;
            _grabbable = grabbable;
            _pointable = grabbable as IPointable; // Grabbable is a PointableElement
            if (_pointable != null) _pointable.WhenPointerEventRaised += OnPointerEvent;
            if (_weight == null && grabbable.Transform != null) _weight = grabbable.Transform.GetComponent<PseudoHapticWeight>();
            if (_weight == null) _weight = GetComponent<PseudoHapticWeight>();
            if (_weight == null) Debug.LogError("Pseudo-Haptic Transformer on '" + name + "' found no PseudoHapticWeight on the grabbed object.", this);
            ApplyHandDrawing();
        }

        /// <summary>
        /// Where the hand is drawn (issue 14 item 4), through the Interaction SDK's wrist lock: while a hand grab selects, its
        /// HandGrabStateVisual locks the synthetic hand's wrist to the grabbed object unless the interactable's HandAlignment
        /// is None. The weight's profile chooses: hand on object → AlignOnGrab (the SDK's default), hand true → None. The
        /// return to the tracked hand after the release is the SyntheticHand's wrist unlock curve. Initialize calls it; call
        /// it again after changing the profile. Allocates (finds the interactables): not per frame.
        /// </summary>
        public void ApplyHandDrawing()
        {
            if (_grabbable == null || _grabbable.Transform == null || _weight == null) return;
            HandAlignType align = _weight.HandDrawing == HandDrawingMode.HandOnObject ? HandAlignType.AlignOnGrab : HandAlignType.None;
            foreach (HandGrabInteractable interactable in _grabbable.Transform.GetComponentsInChildren<HandGrabInteractable>())
                interactable.HandAlignment = align;
        }

        public void BeginTransform()
        {
            _holding = false;
            if (_grabbable == null || _weight == null || !TryHandCentre(out Vector3 grab, out _, out _)) return;
            _grabOffset = _weight.transform.position - grab;
            _lastTime = Time.timeAsDouble;
            _holding = _weight.BeginHold(grab, double.NaN, RigidbodyControl.External);
        }

        public void UpdateTransform()
        {
            if (!_holding || !TryHandCentre(out Vector3 grab, out bool tracked, out bool highConfidence)) return;
            double now = Time.timeAsDouble;
            float dt = (float)(now - _lastTime); // 0 when called twice in a frame: the solver moves nothing
            _lastTime = now;
            Transform target = _weight.transform;
            target.position = GrabFollow.Horizontal(target.position.ToDouble(), grab.ToDouble(), _grabOffset.ToDouble(), tracked, true).ToUnity();
            _weight.Step(grab, tracked, highConfidence, double.NaN, dt);
        }

        public void EndTransform()
        {
            if (_holding && _weight != null) _weight.EndHold();
            _holding = false;
        }

        void OnDestroy()
        {
            if (_pointable != null) _pointable.WhenPointerEventRaised -= OnPointerEvent;
        }

        // The Grabbable raises Select after adding the grab point and before BeginTransform, Unselect and Cancel
        // after removing it.
        void OnPointerEvent(PointerEvent evt)
        {
            if (evt.Type == PointerEventType.Select)
            {
                if (evt.Data is IHandGrabInteractor hand && !_handIds.Contains(evt.Identifier))
                {
                    _handIds.Add(evt.Identifier);
                    _hands.Add(hand);
                }
            }
            else if (evt.Type == PointerEventType.Unselect || evt.Type == PointerEventType.Cancel)
            {
                int i = _handIds.IndexOf(evt.Identifier);
                if (i >= 0)
                {
                    _handIds.RemoveAt(i);
                    _hands.RemoveAt(i);
                }
            }
        }

        /// <summary>
        /// The mean of the grabbing hands (<see cref="GrabCentre"/>): the tracked hands when every grab comes from a hand grab
        /// interactor, else the Grabbable's grab points. Tracked (and high confidence) only when every hand is.
        /// </summary>
        bool TryHandCentre(out Vector3 centre, out bool tracked, out bool highConfidence)
        {
            var points = _grabbable.GrabPoints;
            int n = points != null ? points.Count : 0;
            var mean = new GrabCentre();
            for (int i = 0; i < n && _hands.Count == n; i++)
                mean.Add(_hands[i].GetHandGrabPose().position.ToDouble(), _hands[i].Hand.IsTrackedDataValid, _hands[i].Hand.IsHighConfidence);
            for (int i = 0; i < n && _hands.Count != n; i++)
                mean.Add(points[i].position.ToDouble());
            centre = mean.Point.ToUnity();
            tracked = mean.IsTracked;
            highConfidence = mean.IsHighConfidence;
            return mean.Count > 0;
        }
    }
}
