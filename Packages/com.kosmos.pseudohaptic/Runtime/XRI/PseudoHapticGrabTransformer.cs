using Unity.XR.CoreUtils;
using UnityEngine;
using UnityEngine.XR.Interaction.Toolkit;
using UnityEngine.XR.Interaction.Toolkit.Transformers;
#if KOSMOS_XRI_3
using System.Collections.Generic;
using UnityEngine.InputSystem.XR;
using UnityEngine.XR.Interaction.Toolkit.Interactables;
using UnityEngine.XR.Interaction.Toolkit.Interactors;
#else
using UnityEngine.XR;
#endif

namespace Kosmos.PseudoHaptic.XRI
{
    /// <summary>
    /// The pseudo-haptic weight as a grab transformer of Unity's XR Interaction Toolkit 2.x and 3.x (2.5.0 up to, not including, 4.0):
    /// add it to an object with an <see cref="XRGrabInteractable"/> (it brings one, with the Rigidbody, and a
    /// <see cref="PseudoHapticWeight"/>), and it registers itself as the interactable's single- and multiple-grab
    /// transformer in its Start (XRI's own <see cref="XRBaseGrabTransformer"/> registration). Each interactor selecting the
    /// object (direct, ray, poke-free, controller or hand: any <see cref="IXRSelectInteractor"/>) is a hand of one hold on the
    /// weight, placed at that interactor's attach transform; a second one joins the hold (the solver's two-hand case), one
    /// that lets go leaves it, as the Interaction SDK transformer does, through the same engine-free hold
    /// (<see cref="HeldObject"/>) and the same bookkeeping (<see cref="GrabbingHands{T}"/>). Hands join and leave in
    /// <see cref="OnGrabCountChanged"/>, which XRI calls right before <see cref="Process"/> whenever the number of
    /// selections changed; the last one leaves in <see cref="OnDrop"/>. In XRI's Dynamic phase the solver steps once and the
    /// target pose becomes the weight's answer (x/z follow the mean of the hands unless the profile has lateral inertia, y is
    /// the solver's, the rotation is kept and turns with the rig); in its OnBeforeRender phase the target is the object's
    /// pose as the weight last placed it through the rig. A break-away cancels every selection through the interaction
    /// manager (<see cref="XRInteractionManager.SelectCancel"/>); the interactable then restores its Rigidbody and the
    /// object falls. Tracking, under XRI 2.x: an interactor under an <c>XRBaseController</c> whose state has no tracked
    /// position is a lost hand (its attach transform stays where it was; the solver holds the object); other interactors are
    /// tracked. Under XRI 3.x (which deprecated the controller components; its rigs pose controllers and hands with the Input
    /// System's <c>TrackedPoseDriver</c>): the nearest <c>TrackedPoseDriver</c> at or above the interactor (looked up when it
    /// joins), read by the driver's own rule (<see cref="PoseDriverTracking"/>); without one, or with a disabled one, the
    /// interactor is tracked.
    /// The rig: the XR Origin's Camera Offset above the first hand (or <see cref="Rig"/>), so locomotion, snap turns and
    /// teleports carry the object rigidly. XRI owns the Rigidbody (kinematic while grabbed, restored and thrown on release).
    /// On link it sets the interactable's Select Mode to Multiple (XRI's default, Single, makes a second interactor take the
    /// object from the first rather than join it) and turns its attach ease-in and position/rotation smoothing off: they
    /// would add a lag the solver does not know about. Use Instantaneous or Kinematic movement (Velocity Tracking is warned about).
    /// Compiled only when com.unity.xr.interaction.toolkit 2.5.0 or a later 2.x or 3.x is installed (KOSMOS_XRI; KOSMOS_XRI_3
    /// from 3.0.0 selects XRI 3's namespaces and the pose-driver reading). Process allocates nothing.
    /// </summary>
    [AddComponentMenu("Kosmos/Pseudo-Haptic/Pseudo-Haptic Grab Transformer (XR Interaction Toolkit)")]
    [RequireComponent(typeof(XRGrabInteractable))]
    [RequireComponent(typeof(PseudoHapticWeight))]
    public sealed class PseudoHapticGrabTransformer : XRBaseGrabTransformer, IXRDropTransformer
    {
        [Tooltip("The weight to drive; this object's when empty.")]
        [SerializeField] PseudoHapticWeight _weight;
        [Tooltip("The tracking space the hands are tracked in (XR Origin ▸ Camera Offset): its motion (locomotion, snap turns, teleports) carries the object rigidly. Found above the first grabbing interactor when empty.")]
        [SerializeField] Transform _rig;

        readonly GrabbingHands<IXRSelectInteractor> _hands = new GrabbingHands<IXRSelectInteractor>();
        FrameClock _clock;
        bool _cancelling;
        bool _rejoin; // the weight's hold ended while XRI kept the selection (this or the weight was switched off)
        IXRSelectInteractor[] _cancel = new IXRSelectInteractor[4];
#if KOSMOS_XRI_3
        readonly Dictionary<IXRSelectInteractor, TrackedPoseDriver> _drivers = new Dictionary<IXRSelectInteractor, TrackedPoseDriver>();
#endif

        /// <summary>Registered in both lists: XRI gives the multiple-grab list the object while two or more interactors select it.</summary>
        protected override RegistrationMode registrationMode => RegistrationMode.SingleAndMultiple;

        /// <summary>Nothing to do once dropped: the Rigidbody is XRI's.</summary>
        public bool canProcessOnDrop => false;

        public PseudoHapticWeight Weight => _weight;

        /// <summary>The tracking space the hands are tracked in; null: the XR Origin's Camera Offset above the first hand, or the world.</summary>
        public Transform Rig { get => _rig; set => _rig = value; }

        /// <summary>The interactors on the weight's hold now, by hand id (join order).</summary>
        public GrabbingHands<IXRSelectInteractor> Hands => _hands;

        public override void OnLink(XRGrabInteractable grabInteractable)
        {
            // Called once per list this transformer is in: idempotent.
            if (_weight == null) _weight = GetComponent<PseudoHapticWeight>();
            if (_weight == null) Debug.LogError("Pseudo-Haptic Grab Transformer on '" + name + "' found no PseudoHapticWeight.", this);
            // XRI's default Single lets a second interactor take the object from the first (it exits before the other
            // enters): the weight's two-hand hold needs both selecting at once.
            grabInteractable.selectMode = InteractableSelectMode.Multiple;
            grabInteractable.attachEaseInTime = 0f;
            grabInteractable.smoothPosition = false;
            grabInteractable.smoothRotation = false;
            if (grabInteractable.movementType == XRBaseInteractable.MovementType.VelocityTracking)
                Debug.LogWarning("Pseudo-Haptic Grab Transformer on '" + name + "': the XR Grab Interactable moves by Velocity Tracking, which chases the weight's pose a physics step late; use Instantaneous or Kinematic.", this);
        }

        public override void OnGrabCountChanged(XRGrabInteractable grabInteractable, Pose targetPose, Vector3 localScale)
        {
            if (!_cancelling) Resync(grabInteractable);
        }

        public override void Process(XRGrabInteractable grabInteractable, XRInteractionUpdateOrder.UpdatePhase updatePhase, ref Pose targetPose, ref Vector3 localScale)
        {
            if (_weight == null) return;
            if (updatePhase == XRInteractionUpdateOrder.UpdatePhase.Dynamic)
            {
                // Switched off and on again mid-grab, XRI calls no OnGrabCountChanged: the selecting hands join here.
                if (_hands.Count > 0 && !_weight.IsHeld) Forget(); // the weight was switched off: its hold ended
                if (_rejoin && _weight.isActiveAndEnabled && grabInteractable.isSelected)
                {
                    _rejoin = false;
                    Resync(grabInteractable);
                }
            }
            if (_hands.Count == 0 || !_weight.IsHeld) return;
            if (updatePhase == XRInteractionUpdateOrder.UpdatePhase.Dynamic)
            {
                float dt = _clock.Delta(Time.unscaledTimeAsDouble); // 0 when called twice in a frame: the solver moves nothing
                for (int i = 0; i < _hands.Count; i++)
                {
                    Vector3 hand = HandPosition(_hands.SourceAt(i), grabInteractable, out bool tracked);
                    _weight.Step(_hands.IdAt(i), hand, tracked, tracked, double.NaN, dt, grabMovesHorizontal: true);
                }
                if (_weight.Hold.BrokeAway)
                {
                    CancelGrabs(grabInteractable);
                    return; // XRI applies the last target pose; the Rigidbody it restored lets the object fall
                }
            }
            // The weight has placed the object (and re-places it through the rig before rendering): that is the target.
            Transform t = _weight.transform;
            targetPose = new Pose(t.position, t.rotation);
        }

        public void OnDrop(XRGrabInteractable grabInteractable, DropEventArgs args) => EndAll();

        public override void OnUnlink(XRGrabInteractable grabInteractable) => EndAll();

        void OnDisable()
        {
            EndAll();
            _rejoin = true;
        }

        void EndAll()
        {
            Forget();
            _rejoin = false;
            if (_weight != null) _weight.EndHold();
        }

        /// <summary>The hands let go of here, taken back from the interactable's selection on the next Dynamic phase.</summary>
        void Forget()
        {
            _hands.Clear();
#if KOSMOS_XRI_3
            _drivers.Clear();
#endif
            _rejoin = true;
        }

        /// <summary>The weight's hands made the interactable's: those no longer selecting leave, new ones join (at their attach transforms).</summary>
        void Resync(XRGrabInteractable grab)
        {
            if (_weight == null) return;
            var selecting = grab.interactorsSelecting;
            while (_hands.TakeGone(selecting, out int gone)) _weight.EndHold(gone);
            for (int i = 0; i < selecting.Count; i++)
            {
                IXRSelectInteractor interactor = selecting[i];
                if (_hands.IndexOfSource(interactor) >= 0) continue;
                bool first = _weight.Hold.HandCount == 0;
                if (first) _weight.Rig = _rig != null ? _rig : RigAbove(interactor);
#if KOSMOS_XRI_3
                _drivers[interactor] = interactor.transform != null ? interactor.transform.GetComponentInParent<TrackedPoseDriver>() : null; // looked up once per join
#endif
                int id = _hands.Add(interactor);
                if (!_weight.BeginHold(id, HandPosition(interactor, grab, out _), double.NaN, RigidbodyControl.External))
                {
                    _hands.Remove(id); // not taken (a third hand, a broken-away hold, a bad setting): tried again at the next change
                    continue;
                }
                if (first) _clock.Start(Time.unscaledTimeAsDouble);
            }
        }

        /// <summary>Break-away: every selection is cancelled through the interaction manager.</summary>
        void CancelGrabs(XRGrabInteractable grab)
        {
            var selecting = grab.interactorsSelecting;
            int n = selecting.Count;
            if (_cancel.Length < n) _cancel = new IXRSelectInteractor[n];
            selecting.CopyTo(_cancel); // each cancel removes its interactor from the list
            _cancelling = true;
            try
            {
                XRInteractionManager manager = grab.interactionManager;
                for (int i = n - 1; i >= 0 && manager != null; i--) manager.SelectCancel(_cancel[i], grab);
            }
            finally
            {
                _cancelling = false;
                for (int i = 0; i < n; i++) _cancel[i] = null;
            }
            EndAll(); // whatever the interactable did not report
        }

        /// <summary>The interactor's attach transform (the point it holds by), and whether what poses it tracks its position.</summary>
        Vector3 HandPosition(IXRSelectInteractor interactor, XRGrabInteractable grab, out bool tracked)
        {
            tracked = PositionTracked(interactor);
            Transform attach = interactor.GetAttachTransform(grab);
            if (attach == null) attach = interactor.transform;
            return attach.position;
        }

#if KOSMOS_XRI_3
        /// <summary>XRI 3: the interactor's TrackedPoseDriver (found when it joined), by the driver's own rule.</summary>
        bool PositionTracked(IXRSelectInteractor interactor)
        {
            _drivers.TryGetValue(interactor, out TrackedPoseDriver driver);
            bool hasDriver = driver != null && driver.isActiveAndEnabled; // a disabled driver moves nothing: as none
            var action = hasDriver ? driver.trackingStateInput.action : null;
            bool hasAction = action != null;
            bool enabled = hasAction && action.enabled;
            int controls = enabled ? action.controls.Count : 0;
            int state = enabled && controls > 0 ? action.ReadValue<int>() : 0;
            return PoseDriverTracking.PositionTracked(hasDriver, hasDriver && driver.ignoreTrackingState, hasAction, enabled, controls, state);
        }
#else
        /// <summary>XRI 2: the tracking state of the interactor's XRBaseController, if it has one.</summary>
        static bool PositionTracked(IXRSelectInteractor interactor)
        {
            if (!(interactor is XRBaseControllerInteractor controlled)) return true;
            XRBaseController controller = controlled.xrController;
            XRControllerState state = controller != null ? controller.currentControllerState : null;
            return state == null || (state.inputTrackingState & InputTrackingState.Position) != 0;
        }
#endif

        /// <summary>The XR Origin's Camera Offset (the tracking space) above <paramref name="interactor"/>, else its origin, else null (the world).</summary>
        static Transform RigAbove(IXRSelectInteractor interactor)
        {
            XROrigin origin = interactor.transform != null ? interactor.transform.GetComponentInParent<XROrigin>() : null;
            if (origin == null) return null;
            return origin.CameraFloorOffsetObject != null ? origin.CameraFloorOffsetObject.transform : origin.transform;
        }
    }
}
