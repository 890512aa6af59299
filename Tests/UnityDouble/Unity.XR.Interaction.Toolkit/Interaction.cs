// Test double of XR Interaction Toolkit 2.5.4 (needle-mirror/com.unity.xr.interaction.toolkit, tag 2.5.4):
// Runtime/Interaction/XRInteractionManager.cs, Interactables/XRBaseInteractable.cs, Interactors/XRBaseInteractor.cs,
// XRBaseControllerInteractor.cs, XRDirectInteractor.cs, Controllers/XRBaseController.cs, XRController.cs,
// ActionBasedController.cs, XRControllerState.cs. Bodies written here after those sources (no code copied):
// - XRInteractionManager (execution order -105) runs, per frame, the Dynamic phase in Update, Late in LateUpdate, Fixed
//   in FixedUpdate and OnBeforeRender in Application.onBeforeRender, each calling ProcessInteractable on every registered
//   interactable. SelectEnter/SelectExit/SelectCancel call OnSelectEntering, OnSelectEntered (interactor, then
//   interactable) or the exiting pair, as the real manager does; SelectEnter on an interactable already selected first
//   resolves it by its selectMode (ResolveExistingSelect: Single, the default, makes the current selectors exit). What the double does not run: choosing targets from
//   input (valid targets, hover, select actions): a test selects through SelectEnter/SelectExit, as XRI's own tests do.
// - Interactors and interactables register with the scene's manager in OnEnable (one is created when none exists, as
//   XRI's FindCreateInteractionManager does) and unregister in OnDisable.
// - XRBaseController (order -29990) writes its state's position/rotation into its local pose in Update and before
//   rendering when the state's inputTrackingState has Position/Rotation (ApplyControllerState): a lost hand's transform
//   stays where it was. Its state is what the test sets (the real XRController/ActionBasedController read devices or
//   input actions into it each frame).
// With XRI_3 (see Interfaces.cs), XRI 3.0.8's shape (tag 3.0.8, same files): XRBaseInteractable in ...Toolkit.Interactables,
// XRBaseInteractor, XRBaseInputInteractor (Interactors/XRBaseInputInteractor.cs, the 2.x XRBaseControllerInteractor
// renamed) and XRDirectInteractor (now derived from XRBaseInputInteractor) in ...Toolkit.Interactors; the manager stays
// in ...Toolkit with the same SelectEnter/SelectExit/SelectCancel. XRBaseController, ActionBasedController,
// XRControllerState and XRBaseControllerInteractor are left out there: 3.0.8 still ships them, each marked [Obsolete]
// ("deprecated in version 3.0.0"), and the package does not call them under XRI 3 (an XRI 3 rig poses its controllers and
// hands with the Input System's TrackedPoseDriver: ../Unity.InputSystem).
using System.Collections.Generic;
using UnityEngine.XR;
#if XRI_3
using UnityEngine.XR.Interaction.Toolkit.Interactables;
using UnityEngine.XR.Interaction.Toolkit.Interactors;
#endif

namespace UnityEngine.XR.Interaction.Toolkit
{
    [DefaultExecutionOrder(XRInteractionUpdateOrder.k_InteractionManager)]
    [DisallowMultipleComponent]
    public partial class XRInteractionManager : MonoBehaviour
    {
        readonly List<XRBaseInteractable> m_Interactables = new List<XRBaseInteractable>();
        readonly List<XRBaseInteractor> m_Interactors = new List<XRBaseInteractor>();

        internal static XRInteractionManager FindOrCreate()
        {
            XRInteractionManager found = FindFirstObjectByType<XRInteractionManager>();
            return found != null ? found : new GameObject("XR Interaction Manager").AddComponent<XRInteractionManager>();
        }

        internal void Register(XRBaseInteractable interactable) { if (!m_Interactables.Contains(interactable)) m_Interactables.Add(interactable); }
        internal void Unregister(XRBaseInteractable interactable) => m_Interactables.Remove(interactable);
        internal void Register(XRBaseInteractor interactor) { if (!m_Interactors.Contains(interactor)) m_Interactors.Add(interactor); }
        internal void Unregister(XRBaseInteractor interactor) => m_Interactors.Remove(interactor);

        protected virtual void OnEnable() => Application.onBeforeRender += OnBeforeRender;
        protected virtual void OnDisable() => Application.onBeforeRender -= OnBeforeRender;
        protected virtual void Update() => ProcessInteractables(XRInteractionUpdateOrder.UpdatePhase.Dynamic);
        protected virtual void LateUpdate() => ProcessInteractables(XRInteractionUpdateOrder.UpdatePhase.Late);
        protected virtual void FixedUpdate() => ProcessInteractables(XRInteractionUpdateOrder.UpdatePhase.Fixed);
        [BeforeRenderOrder(XRInteractionUpdateOrder.k_BeforeRenderOrder)]
        protected virtual void OnBeforeRender() => ProcessInteractables(XRInteractionUpdateOrder.UpdatePhase.OnBeforeRender);

        protected virtual void ProcessInteractables(XRInteractionUpdateOrder.UpdatePhase updatePhase)
        {
            for (int i = 0; i < m_Interactables.Count; i++)
            {
                XRBaseInteractable interactable = m_Interactables[i];
                if (interactable != null && interactable.isActiveAndEnabled) interactable.ProcessInteractable(updatePhase);
            }
        }

        public virtual void SelectEnter(IXRSelectInteractor interactor, IXRSelectInteractable interactable)
        {
            if (interactable.isSelected && !ResolveExistingSelect(interactor, interactable)) return;
            var args = new SelectEnterEventArgs { manager = this, interactorObject = interactor, interactableObject = interactable };
            var baseInteractor = interactor as XRBaseInteractor;
            var baseInteractable = interactable as XRBaseInteractable;
            baseInteractor?.SelectEntering(args);
            baseInteractable?.SelectEntering(args);
        }

        /// <summary>
        /// Real: an interactor already selecting it does not select again; under Single every current selector exits
        /// (not cancelled) before the new one enters; under Multiple they stay.
        /// </summary>
        protected virtual bool ResolveExistingSelect(IXRSelectInteractor interactor, IXRSelectInteractable interactable)
        {
            if (interactable.interactorsSelecting.Contains(interactor)) return false;
            if (interactable.selectMode == InteractableSelectMode.Single)
                for (int i = interactable.interactorsSelecting.Count - 1; i >= 0; i--) Exit(interactable.interactorsSelecting[i], interactable, false);
            return true;
        }

        public virtual void SelectExit(IXRSelectInteractor interactor, IXRSelectInteractable interactable) => Exit(interactor, interactable, false);

        public virtual void SelectCancel(IXRSelectInteractor interactor, IXRSelectInteractable interactable) => Exit(interactor, interactable, true);

        void Exit(IXRSelectInteractor interactor, IXRSelectInteractable interactable, bool canceled)
        {
            if (!interactable.interactorsSelecting.Contains(interactor)) return;
            var args = new SelectExitEventArgs { manager = this, interactorObject = interactor, interactableObject = interactable, isCanceled = canceled };
            (interactor as XRBaseInteractor)?.SelectExiting(args);
            (interactable as XRBaseInteractable)?.SelectExiting(args);
        }
    }

#if XRI_3
}

namespace UnityEngine.XR.Interaction.Toolkit.Interactables
{
#endif
    [DefaultExecutionOrder(XRInteractionUpdateOrder.k_Interactables)]
    public abstract partial class XRBaseInteractable : MonoBehaviour, IXRSelectInteractable
    {
        public enum MovementType
        {
            VelocityTracking,
            Kinematic,
            Instantaneous,
        }

        [SerializeField] XRInteractionManager m_InteractionManager;
        readonly List<IXRSelectInteractor> m_InteractorsSelecting = new List<IXRSelectInteractor>();
        XRInteractionManager m_Registered;

        public XRInteractionManager interactionManager { get => m_InteractionManager; set => m_InteractionManager = value; }
        public List<IXRSelectInteractor> interactorsSelecting => m_InteractorsSelecting;
        public bool isSelected => m_InteractorsSelecting.Count > 0;
        [SerializeField] InteractableSelectMode m_SelectMode = InteractableSelectMode.Single;
        public InteractableSelectMode selectMode { get => m_SelectMode; set => m_SelectMode = value; }

        protected virtual void Awake() { }

        protected virtual void OnEnable()
        {
            if (m_InteractionManager == null) m_InteractionManager = XRInteractionManager.FindOrCreate();
            m_Registered = m_InteractionManager;
            m_Registered.Register(this);
        }

        protected virtual void OnDisable()
        {
            // The real one cancels its selections when it unregisters (XRInteractionManager.UnregisterInteractable).
            for (int i = m_InteractorsSelecting.Count - 1; i >= 0 && m_Registered != null; i--) m_Registered.SelectCancel(m_InteractorsSelecting[i], this);
            if (m_Registered != null) m_Registered.Unregister(this);
            m_Registered = null;
        }

        protected virtual void OnDestroy() { }

        public virtual Transform GetAttachTransform(IXRInteractor interactor) => transform;

        public virtual void ProcessInteractable(XRInteractionUpdateOrder.UpdatePhase updatePhase) { }

        internal void SelectEntering(SelectEnterEventArgs args) => OnSelectEntering(args);
        internal void SelectExiting(SelectExitEventArgs args) => OnSelectExiting(args);

        protected virtual void OnSelectEntering(SelectEnterEventArgs args) => m_InteractorsSelecting.Add(args.interactorObject);

        protected virtual void OnSelectExiting(SelectExitEventArgs args) => m_InteractorsSelecting.Remove(args.interactorObject);
    }

#if XRI_3
}

namespace UnityEngine.XR.Interaction.Toolkit.Interactors
{
#endif
    [DefaultExecutionOrder(XRInteractionUpdateOrder.k_Interactors)]
    public abstract partial class XRBaseInteractor : MonoBehaviour, IXRSelectInteractor
    {
        [SerializeField] XRInteractionManager m_InteractionManager;
        [SerializeField] Transform m_AttachTransform;
        readonly List<IXRSelectInteractable> m_InteractablesSelected = new List<IXRSelectInteractable>();
        XRInteractionManager m_Registered;

        public XRInteractionManager interactionManager { get => m_InteractionManager; set => m_InteractionManager = value; }
        public Transform attachTransform { get => m_AttachTransform; set => m_AttachTransform = value; }
        public List<IXRSelectInteractable> interactablesSelected => m_InteractablesSelected;
        public bool hasSelection => m_InteractablesSelected.Count > 0;

        protected virtual void OnEnable()
        {
            if (m_InteractionManager == null) m_InteractionManager = XRInteractionManager.FindOrCreate();
            m_Registered = m_InteractionManager;
            m_Registered.Register(this);
        }

        protected virtual void OnDisable()
        {
            for (int i = m_InteractablesSelected.Count - 1; i >= 0 && m_Registered != null; i--) m_Registered.SelectCancel(this, m_InteractablesSelected[i]);
            if (m_Registered != null) m_Registered.Unregister(this);
            m_Registered = null;
        }

        public virtual Transform GetAttachTransform(IXRInteractable interactable) => m_AttachTransform != null ? m_AttachTransform : transform;

        internal void SelectEntering(SelectEnterEventArgs args) => m_InteractablesSelected.Add(args.interactableObject);
        internal void SelectExiting(SelectExitEventArgs args) => m_InteractablesSelected.Remove(args.interactableObject);
    }

#if XRI_3
    /// <summary>Real (3.0.8): the interactors driven by input (direct, ray, near-far…); 2.x's XRBaseControllerInteractor renamed.</summary>
    public abstract partial class XRBaseInputInteractor : XRBaseInteractor { }

    public partial class XRDirectInteractor : XRBaseInputInteractor { }
}
#else
    public abstract partial class XRBaseControllerInteractor : XRBaseInteractor
    {
        [SerializeField] XRBaseController m_Controller;

        /// <summary>The controller above this interactor (the real one finds it in Awake with GetComponentInParent).</summary>
        public XRBaseController xrController
        {
            get => m_Controller != null ? m_Controller : (m_Controller = GetComponentInParent<XRBaseController>());
            set => m_Controller = value;
        }
    }

    public partial class XRDirectInteractor : XRBaseControllerInteractor { }

    public partial class XRControllerState
    {
        public double time;
        public InputTrackingState inputTrackingState;
        public bool isTracked;
        public Vector3 position;
        public Quaternion rotation = Quaternion.identity;
    }

    [DefaultExecutionOrder(XRInteractionUpdateOrder.k_Controllers)]
    public abstract partial class XRBaseController : MonoBehaviour
    {
        XRControllerState m_ControllerState = new XRControllerState();

        public XRControllerState currentControllerState { get => m_ControllerState; set => m_ControllerState = value; }

        protected virtual void OnEnable() => Application.onBeforeRender += OnBeforeRender;
        protected virtual void OnDisable() => Application.onBeforeRender -= OnBeforeRender;
        protected void Update() => ApplyControllerState(XRInteractionUpdateOrder.UpdatePhase.Dynamic, m_ControllerState);
        protected virtual void OnBeforeRender() => ApplyControllerState(XRInteractionUpdateOrder.UpdatePhase.OnBeforeRender, m_ControllerState);

        protected virtual void ApplyControllerState(XRInteractionUpdateOrder.UpdatePhase updatePhase, XRControllerState controllerState)
        {
            if (controllerState == null) return;
            if ((controllerState.inputTrackingState & InputTrackingState.Position) != 0) transform.localPosition = controllerState.position;
            if ((controllerState.inputTrackingState & InputTrackingState.Rotation) != 0) transform.localRotation = controllerState.rotation;
        }
    }

    /// <summary>Real: an XRBaseController reading its pose and buttons from Input System actions (Starter Assets bind them).</summary>
    public partial class ActionBasedController : XRBaseController { }
}
#endif
