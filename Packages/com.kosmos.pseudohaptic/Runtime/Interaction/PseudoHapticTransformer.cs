using System;
using Oculus.Interaction;
using Oculus.Interaction.HandGrab;
using UnityEngine;

namespace Kosmos.PseudoHaptic.Interaction
{
    /// <summary>
    /// The pseudo-haptic weight as a transformer of Meta's Interaction SDK: put it on a <c>Grabbable</c> that
    /// also has a <see cref="PseudoHapticWeight"/> and make it the Grabbable's one-grab transformer (and its
    /// two-grab one, for lifting with both hands). Each grab (pointer id) is a hand of one hold on the weight: two
    /// grabs are the solver's two-hand case (each hand's share of the mass, re-anchoring when one joins or leaves;
    /// the Grabbable ends and begins its transformer whenever the count changes, so hands join and leave through its
    /// Select and Unselect events, not through Begin/EndTransform). x and z follow the mean of the grabbing hands,
    /// keeping the offset they had when the count last changed, unless the profile has lateral inertia (then they
    /// are the solver's); the object's rotation is left as it is; y comes from the solver. A break-away cancels
    /// every grab point through the Grabbable (<see cref="IPointableElement.ProcessPointerEvent"/>), which then
    /// unlocks its Rigidbody, and the object falls.
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
        [Tooltip("The tracking space the hands are tracked in (OVRCameraRig ▸ TrackingSpace): its motion (locomotion, snap turns, teleports) carries the object rigidly. Found from the scene's OVRCameraRig when empty.")]
        [SerializeField] Transform _rig;

        IGrabbable _grabbable;
        IPointable _pointable;
        // The grabs selecting the object, by pointer id (from the Grabbable's Select events), and the hand grab
        // interactor of each (null for other interactors): the same bookkeeping as the XR Interaction Toolkit transformer's.
        readonly GrabbingHands<IHandGrabInteractor> _grabs = new GrabbingHands<IHandGrabInteractor>();
        FrameClock _clock;
        bool _holding, _cancelling;
        int[] _cancelIds = new int[4];

        public PseudoHapticWeight Weight => _weight;

        public void InjectWeight(PseudoHapticWeight weight) => _weight = weight;

        /// <summary>The tracking space the hands are tracked in; null: the world.</summary>
        public Transform Rig { get => _rig; set => _rig = value; }

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
#if KOSMOS_META_XR_CORE
            if (_rig == null)
            {
                OVRCameraRig rig = FindFirstObjectByType<OVRCameraRig>();
                if (rig != null) _rig = rig.trackingSpace;
            }
#endif
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
            // While this transformer cancels the grabs (a break-away), the SDK's interactors unselect, and the Grabbable
            // begins its one-grab transformer again for the hand not yet cancelled: nothing is to begin then.
            if (_cancelling) return;
            _holding = false;
            if (_grabbable == null || _weight == null || _grabs.Count == 0) return;
            if (_rig != null && _weight.Hold.HandCount == 0) _weight.Rig = _rig; // the hold is solved in the rig's frame
            _clock.Start(Time.unscaledTimeAsDouble);
            for (int i = 0; i < _grabs.Count; i++) _weight.BeginHold(_grabs.IdAt(i), HandPose(i, out _, out _), double.NaN, RigidbodyControl.External);
            _holding = _weight.IsHeld;
        }

        public void UpdateTransform()
        {
            if (!_holding || _grabs.Count == 0 || _weight == null) return; // a destroyed weight compares equal to null
            if (!_weight.IsHeld)
            {
                // The weight's hold ended while the Grabbable kept its grabs (the weight switched off, or its hold ended from
                // code): once it is on, the grabs hold it again from where the hands are, as the Grabbable still selects it.
                if (!_weight.isActiveAndEnabled) return;
                BeginTransform();
                if (!_holding) return;
            }
            float dt = _clock.Delta(Time.unscaledTimeAsDouble); // 0 when called twice in a frame: the solver moves nothing
            // x/z: the mean of the grabbing hands and the offset taken when they changed (HeldObject.GrabTarget), or the solver's.
            for (int i = 0; i < _grabs.Count; i++)
            {
                Vector3 hand = HandPose(i, out bool handTracked, out bool highConfidence);
                _weight.Step(_grabs.IdAt(i), hand, handTracked, highConfidence, double.NaN, dt, grabMovesHorizontal: true);
            }
            if (_weight.Hold.BrokeAway) CancelGrabs();
        }

        // Hands leave the hold through Unselect and Cancel (the Grabbable also ends its transformer when a second hand joins).
        public void EndTransform() => _holding = false;

        /// <summary>Break-away: every grab point is cancelled through the Grabbable, which unlocks its Rigidbody.</summary>
        void CancelGrabs()
        {
            var element = _grabbable as IPointableElement;
            int n = _grabs.CopyIds(ref _cancelIds); // the Cancel events change _grabs while this loops
            _cancelling = true;
            try
            {
                for (int i = n - 1; i >= 0 && element != null; i--)
                    element.ProcessPointerEvent(new PointerEvent(_cancelIds[i], PointerEventType.Cancel, default(Pose)));
            }
            finally
            {
                _cancelling = false;
            }
            _holding = false;
            if (_weight != null) _weight.EndHold(); // whatever the Grabbable did not report
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
                _grabs.Add(evt.Identifier, evt.Data as IHandGrabInteractor);
            }
            else if (evt.Type == PointerEventType.Unselect || evt.Type == PointerEventType.Cancel)
            {
                _grabs.Remove(evt.Identifier);
                if (_weight != null) _weight.EndHold(evt.Identifier);
            }
        }

        /// <summary>
        /// Grab <paramref name="i"/>'s point: the tracked hand's for a hand grab interactor, else the Grabbable's grab point
        /// of that grab: the same index, as its grab points are kept in the order of the Select events as these lists are,
        /// or counted from the end when the Grabbable adds new points to the front (<c>PointableElement.AddNewPointsToFront</c>).
        /// </summary>
        Vector3 HandPose(int i, out bool tracked, out bool highConfidence)
        {
            IHandGrabInteractor hand = _grabs.SourceAt(i);
            var points = _grabbable.GrabPoints;
            // A hand grab interactor without its hand (not wired, or its hand destroyed) reads as lost, never as an exception.
            Oculus.Interaction.Input.IHand tracking = hand != null ? hand.Hand : null;
            bool noHand = hand != null && tracking == null;
            tracked = hand == null || (!noHand && tracking.IsTrackedDataValid);
            highConfidence = hand == null || (!noHand && tracking.IsHighConfidence);
            if (hand != null && !noHand) return hand.GetHandGrabPose().position;
            if (points == null || i >= points.Count) return _weight.transform.position;
            bool toFront = _grabbable is PointableElement element && element.AddNewPointsToFront;
            return points[toFront ? points.Count - 1 - i : i].position;
        }
    }
}
