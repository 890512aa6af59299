// Test double of XR Interaction Toolkit 2.5.4's XRGrabInteractable and XRBaseGrabTransformer (needle-mirror/
// com.unity.xr.interaction.toolkit, tag 2.5.4: Runtime/Interaction/Interactables/XRGrabInteractable.cs,
// Runtime/Interaction/Transformers/XRBaseGrabTransformer.cs). Bodies written here after those sources (no code copied),
// calling the grab transformers in XRI's order:
// - Add{Single,Multiple}GrabTransformer: OnLink at once; if the object is already grabbed, OnGrab at once and
//   OnGrabCountChanged right before its next Process. Remove…/OnDestroy: OnUnlink. Awake adds the starting lists.
// - The first select (OnSelectEntering, count 0 -> 1): Grab() (unparents the object, makes the Rigidbody kinematic for
//   Kinematic and Instantaneous movement, gravity off, target pose = the object's pose), then OnGrab on every transformer.
//   Every select and deselect marks the grab count changed.
// - Per phase (ProcessInteractable): Dynamic and OnBeforeRender, while selected: OnGrabCountChanged on every transformer
//   (single list, then multiple) if the count changed, then Process: the multiple-grab list first when two or more
//   interactors select (or no single transformer can process) and, if none of those processed, the single list; only
//   transformers whose canProcess is true. Then the attach ease-in and smoothing (XRGrabInteractable.StepSmoothing) and,
//   for Instantaneous movement, the transform set to the target pose. Fixed, for Kinematic movement: the target pose applied.
// - The last deselect (count -> 0): Drop() (the parent restored when retainTransformParent, the Rigidbody's kinematic
//   and gravity flags restored), then OnDrop on every IXRDropTransformer.
// What the double leaves out: the default XRGeneralGrabTransformer (added by the real one when no single transformer is
// registered), rotation easing and smoothing (position only here), dynamic attach transforms, throwing (detach velocity), Velocity Tracking movement (logged), character
// collision handling, teleport handling, and registration lists' deferred flushing (here a change takes effect at the
// next phase, as a flush would make it).
// With XRI_3 (see Interfaces.cs): XRI 3.0.8's shape (tag 3.0.8, same files): XRGrabInteractable in
// ...Toolkit.Interactables with the same grab-transformer members and call order (the two files differ, in the grab
// transformer code, only by 2.5.4's legacy-transformer branch, which the double leaves out anyway; 3.0.11's file is 3.0.8's),
// XRBaseGrabTransformer's Start and OnDestroy now `protected virtual`.
using System.Collections.Generic;
using UnityEngine.XR.Interaction.Toolkit.Transformers;
#if XRI_3
using UnityEngine.XR.Interaction.Toolkit.Interactors;

namespace UnityEngine.XR.Interaction.Toolkit.Interactables
#else

namespace UnityEngine.XR.Interaction.Toolkit
#endif
{
    [DisallowMultipleComponent]
    [RequireComponent(typeof(Rigidbody))]
    public partial class XRGrabInteractable : XRBaseInteractable
    {
        [SerializeField] MovementType m_MovementType = MovementType.Instantaneous;
        [SerializeField] float m_AttachEaseInTime = 0.15f;
        [SerializeField] bool m_SmoothPosition, m_SmoothRotation;
        [SerializeField] float m_SmoothPositionAmount = 8f, m_TightenPosition = 0.1f;
        [SerializeField] bool m_RetainTransformParent = true;
        [SerializeField] bool m_AddDefaultGrabTransformers = true;
        [SerializeField] List<XRBaseGrabTransformer> m_StartingSingleGrabTransformers = new List<XRBaseGrabTransformer>();
        [SerializeField] List<XRBaseGrabTransformer> m_StartingMultipleGrabTransformers = new List<XRBaseGrabTransformer>();

        readonly List<IXRGrabTransformer> m_Single = new List<IXRGrabTransformer>(), m_Multiple = new List<IXRGrabTransformer>();
        readonly List<IXRGrabTransformer> m_SingleSnapshot = new List<IXRGrabTransformer>(), m_MultipleSnapshot = new List<IXRGrabTransformer>();
        readonly List<IXRGrabTransformer> m_AddedWhenGrabbed = new List<IXRGrabTransformer>();
        int m_DropTransformersCount;
        bool m_GrabCountChanged, m_WasKinematic, m_UsedGravity, m_WarnedVelocityTracking;
        Transform m_OriginalSceneParent;
        Pose m_TargetPose;
        Vector3 m_TargetLocalScale;
        float m_CurrentAttachEaseTime;

        public MovementType movementType { get => m_MovementType; set => m_MovementType = value; }
        public float attachEaseInTime { get => m_AttachEaseInTime; set => m_AttachEaseInTime = value; }
        public bool smoothPosition { get => m_SmoothPosition; set => m_SmoothPosition = value; }
        public bool smoothRotation { get => m_SmoothRotation; set => m_SmoothRotation = value; }
        public bool retainTransformParent { get => m_RetainTransformParent; set => m_RetainTransformParent = value; }
        public bool addDefaultGrabTransformers { get => m_AddDefaultGrabTransformers; set => m_AddDefaultGrabTransformers = value; }
        public List<XRBaseGrabTransformer> startingSingleGrabTransformers { get => m_StartingSingleGrabTransformers; set => m_StartingSingleGrabTransformers = value; }
        public List<XRBaseGrabTransformer> startingMultipleGrabTransformers { get => m_StartingMultipleGrabTransformers; set => m_StartingMultipleGrabTransformers = value; }
        public int singleGrabTransformersCount => m_Single.Count;
        public int multipleGrabTransformersCount => m_Multiple.Count;

        public IXRGrabTransformer GetSingleGrabTransformerAt(int index) => m_Single[index];
        public IXRGrabTransformer GetMultipleGrabTransformerAt(int index) => m_Multiple[index];
        public void AddSingleGrabTransformer(IXRGrabTransformer transformer) => Add(transformer, m_Single);
        public void AddMultipleGrabTransformer(IXRGrabTransformer transformer) => Add(transformer, m_Multiple);
        public bool RemoveSingleGrabTransformer(IXRGrabTransformer transformer) => Remove(transformer, m_Single);
        public bool RemoveMultipleGrabTransformer(IXRGrabTransformer transformer) => Remove(transformer, m_Multiple);
        public Pose GetTargetPose() => m_TargetPose;

        protected override void Awake()
        {
            base.Awake();
            m_TargetPose = new Pose(transform.position, transform.rotation);
            m_TargetLocalScale = transform.localScale;
            foreach (XRBaseGrabTransformer t in m_StartingSingleGrabTransformers) if (t != null) AddSingleGrabTransformer(t);
            foreach (XRBaseGrabTransformer t in m_StartingMultipleGrabTransformers) if (t != null) AddMultipleGrabTransformer(t);
        }

        protected override void OnDestroy()
        {
            for (int i = m_Single.Count - 1; i >= 0; i--) Remove(m_Single[i], m_Single);
            for (int i = m_Multiple.Count - 1; i >= 0; i--) Remove(m_Multiple[i], m_Multiple);
            base.OnDestroy();
        }

        void Add(IXRGrabTransformer transformer, List<IXRGrabTransformer> list)
        {
            if (transformer == null || list.Contains(transformer)) return;
            list.Add(transformer);
            if (transformer is IXRDropTransformer) m_DropTransformersCount++;
            transformer.OnLink(this);
            if (interactorsSelecting.Count == 0) return;
            transformer.OnGrab(this);
            m_AddedWhenGrabbed.Add(transformer);
        }

        bool Remove(IXRGrabTransformer transformer, List<IXRGrabTransformer> list)
        {
            if (!list.Remove(transformer)) return false;
            if (transformer is IXRDropTransformer) m_DropTransformersCount--;
            transformer.OnUnlink(this);
            m_AddedWhenGrabbed.Remove(transformer);
            return true;
        }

        public override void ProcessInteractable(XRInteractionUpdateOrder.UpdatePhase updatePhase)
        {
            base.ProcessInteractable(updatePhase);
            m_SingleSnapshot.Clear();
            m_SingleSnapshot.AddRange(m_Single);
            m_MultipleSnapshot.Clear();
            m_MultipleSnapshot.AddRange(m_Multiple);
            switch (updatePhase)
            {
                case XRInteractionUpdateOrder.UpdatePhase.Fixed:
                    if (isSelected && m_MovementType == MovementType.Kinematic) Apply();
                    break;
                case XRInteractionUpdateOrder.UpdatePhase.Dynamic:
                case XRInteractionUpdateOrder.UpdatePhase.OnBeforeRender:
                    if (isSelected || (m_GrabCountChanged && m_DropTransformersCount > 0))
                    {
                        UpdateTarget(updatePhase, Time.deltaTime);
                        if (m_MovementType == MovementType.Instantaneous) Apply();
                        else if (m_MovementType == MovementType.VelocityTracking && !m_WarnedVelocityTracking)
                        {
                            m_WarnedVelocityTracking = true;
                            Debug.LogWarning("UnityDouble: XRGrabInteractable's Velocity Tracking movement is not modelled.", this);
                        }
                    }
                    break;
            }
        }

        void Apply()
        {
            transform.position = m_TargetPose.position;
            transform.rotation = m_TargetPose.rotation;
            transform.localScale = m_TargetLocalScale;
        }

        void UpdateTarget(XRInteractionUpdateOrder.UpdatePhase updatePhase, float deltaTime)
        {
            Pose raw = m_TargetPose;
            Vector3 rawScale = m_TargetLocalScale;
            InvokeProcess(updatePhase, ref raw, ref rawScale);
            if (!isSelected)
            {
                m_TargetPose = raw;
                m_TargetLocalScale = rawScale;
                return;
            }
            if (m_AttachEaseInTime > 0f && m_CurrentAttachEaseTime <= m_AttachEaseInTime)
            {
                float t = m_CurrentAttachEaseTime / m_AttachEaseInTime;
                m_TargetPose = new Pose(Vector3.Lerp(m_TargetPose.position, raw.position, t), raw.rotation); // rotation: not eased here
                m_TargetLocalScale = Vector3.Lerp(m_TargetLocalScale, rawScale, t);
                m_CurrentAttachEaseTime += deltaTime;
                return;
            }
            Vector3 p = raw.position;
            Quaternion r = raw.rotation;
            if (m_SmoothPosition)
            {
                p = Vector3.Lerp(m_TargetPose.position, raw.position, m_SmoothPositionAmount * deltaTime);
                p = Vector3.Lerp(p, raw.position, m_TightenPosition);
            }
            m_TargetPose = new Pose(p, r);
            m_TargetLocalScale = rawScale;
        }

        void InvokeProcess(XRInteractionUpdateOrder.UpdatePhase updatePhase, ref Pose targetPose, ref Vector3 localScale)
        {
            bool grabbed = isSelected;
            if (m_GrabCountChanged)
            {
                if (grabbed)
                {
                    foreach (IXRGrabTransformer t in m_SingleSnapshot) if (m_Single.Contains(t)) t.OnGrabCountChanged(this, targetPose, localScale);
                    foreach (IXRGrabTransformer t in m_MultipleSnapshot) if (m_Multiple.Contains(t)) t.OnGrabCountChanged(this, targetPose, localScale);
                }
                m_GrabCountChanged = false;
                m_AddedWhenGrabbed.Clear();
            }
            else if (m_AddedWhenGrabbed.Count > 0)
            {
                if (grabbed) foreach (IXRGrabTransformer t in m_AddedWhenGrabbed) t.OnGrabCountChanged(this, targetPose, localScale);
                m_AddedWhenGrabbed.Clear();
            }
            if (grabbed)
            {
                bool processed = false;
                if (m_MultipleSnapshot.Count > 0 && (interactorsSelecting.Count > 1 || !CanProcessAnySingle()))
                    foreach (IXRGrabTransformer t in m_MultipleSnapshot)
                        if (m_Multiple.Contains(t) && t.canProcess)
                        {
                            t.Process(this, updatePhase, ref targetPose, ref localScale);
                            processed = true;
                        }
                if (!processed)
                    foreach (IXRGrabTransformer t in m_SingleSnapshot)
                        if (m_Single.Contains(t) && t.canProcess) t.Process(this, updatePhase, ref targetPose, ref localScale);
            }
            else
            {
                foreach (IXRGrabTransformer t in m_MultipleSnapshot)
                    if (t is IXRDropTransformer d && m_Multiple.Contains(t) && d.canProcessOnDrop && t.canProcess) t.Process(this, updatePhase, ref targetPose, ref localScale);
                foreach (IXRGrabTransformer t in m_SingleSnapshot)
                    if (t is IXRDropTransformer d && m_Single.Contains(t) && d.canProcessOnDrop && t.canProcess) t.Process(this, updatePhase, ref targetPose, ref localScale);
            }
        }

        bool CanProcessAnySingle()
        {
            foreach (IXRGrabTransformer t in m_SingleSnapshot) if (m_Single.Contains(t) && t.canProcess) return true;
            return false;
        }

        protected override void OnSelectEntering(SelectEnterEventArgs args)
        {
            base.OnSelectEntering(args);
            m_GrabCountChanged = true;
            m_CurrentAttachEaseTime = 0f;
            if (interactorsSelecting.Count == 1)
            {
                Grab();
                foreach (IXRGrabTransformer t in m_Single.ToArray()) if (m_Single.Contains(t)) t.OnGrab(this);
                foreach (IXRGrabTransformer t in m_Multiple.ToArray()) if (m_Multiple.Contains(t)) t.OnGrab(this);
            }
        }

        protected override void OnSelectExiting(SelectExitEventArgs args)
        {
            base.OnSelectExiting(args);
            m_GrabCountChanged = true;
            m_CurrentAttachEaseTime = 0f;
            if (interactorsSelecting.Count == 0)
            {
                Drop();
                if (m_DropTransformersCount > 0)
                {
                    var drop = new DropEventArgs { selectExitEventArgs = args };
                    foreach (IXRGrabTransformer t in m_Single.ToArray()) if (t is IXRDropTransformer d && m_Single.Contains(t)) d.OnDrop(this, drop);
                    foreach (IXRGrabTransformer t in m_Multiple.ToArray()) if (t is IXRDropTransformer d && m_Multiple.Contains(t)) d.OnDrop(this, drop);
                }
            }
        }

        protected virtual void Grab()
        {
            m_OriginalSceneParent = transform.parent;
            transform.SetParent(null);
            Rigidbody body = GetComponent<Rigidbody>();
            if (body != null)
            {
                m_WasKinematic = body.isKinematic;
                m_UsedGravity = body.useGravity;
                body.isKinematic = m_MovementType == MovementType.Kinematic || m_MovementType == MovementType.Instantaneous;
                body.useGravity = false;
            }
            m_TargetPose = new Pose(transform.position, transform.rotation);
            m_TargetLocalScale = transform.localScale;
        }

        protected virtual void Drop()
        {
            if (m_RetainTransformParent && m_OriginalSceneParent != null && m_OriginalSceneParent.gameObject.activeInHierarchy && gameObject.activeInHierarchy)
                transform.SetParent(m_OriginalSceneParent);
            Rigidbody body = GetComponent<Rigidbody>();
            if (body != null)
            {
                body.isKinematic = m_WasKinematic;
                body.useGravity = m_UsedGravity;
            }
        }
    }
}

namespace UnityEngine.XR.Interaction.Toolkit.Transformers
{
#if XRI_3
    using UnityEngine.XR.Interaction.Toolkit.Interactables;

#endif
    public abstract class XRBaseGrabTransformer : MonoBehaviour, IXRGrabTransformer
    {
        public enum RegistrationMode
        {
            None,
            Single,
            Multiple,
            SingleAndMultiple,
        }

        public virtual bool canProcess => isActiveAndEnabled;

        protected virtual RegistrationMode registrationMode => RegistrationMode.Single;

        /// <summary>Registers with the XRGrabInteractable on this GameObject unless a starting or runtime list already holds it.</summary>
#if XRI_3
        protected virtual void Start()
#else
        protected void Start()
#endif
        {
            XRGrabInteractable grab = GetComponent<XRGrabInteractable>();
            if (grab == null) return;
            if (grab.startingSingleGrabTransformers.Contains(this) || grab.startingMultipleGrabTransformers.Contains(this)) return;
            for (int i = grab.singleGrabTransformersCount - 1; i >= 0; i--) if (ReferenceEquals(grab.GetSingleGrabTransformerAt(i), this)) return;
            for (int i = grab.multipleGrabTransformersCount - 1; i >= 0; i--) if (ReferenceEquals(grab.GetMultipleGrabTransformerAt(i), this)) return;
            RegistrationMode mode = registrationMode;
            if (mode == RegistrationMode.Single || mode == RegistrationMode.SingleAndMultiple) grab.AddSingleGrabTransformer(this);
            if (mode == RegistrationMode.Multiple || mode == RegistrationMode.SingleAndMultiple) grab.AddMultipleGrabTransformer(this);
        }

#if XRI_3
        protected virtual void OnDestroy()
#else
        protected void OnDestroy()
#endif
        {
            XRGrabInteractable grab = GetComponent<XRGrabInteractable>();
            if (grab == null) return;
            grab.RemoveSingleGrabTransformer(this);
            grab.RemoveMultipleGrabTransformer(this);
        }

        public virtual void OnLink(XRGrabInteractable grabInteractable) { }
        public virtual void OnGrab(XRGrabInteractable grabInteractable) { }
        public virtual void OnGrabCountChanged(XRGrabInteractable grabInteractable, Pose targetPose, Vector3 localScale) { }
        public abstract void Process(XRGrabInteractable grabInteractable, XRInteractionUpdateOrder.UpdatePhase updatePhase, ref Pose targetPose, ref Vector3 localScale);
        public virtual void OnUnlink(XRGrabInteractable grabInteractable) { }
    }
}
