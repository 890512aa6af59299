// Test double of XR Interaction Toolkit 2.5.4 (com.unity.xr.interaction.toolkit, assembly Unity.XR.Interaction.Toolkit), as
// mirrored in needle-mirror/com.unity.xr.interaction.toolkit at tag 2.5.4: Runtime/Interaction/XRInteractionUpdateOrder.cs,
// Interactors/IXRInteractor.cs, IXRSelectInteractor.cs, Interactables/IXRInteractable.cs, IXRSelectInteractable.cs,
// Transformers/IXRGrabTransformer.cs, IXRDropTransformer.cs. Declarations transcribed (namespaces, names, types); the
// interfaces list only the members the package calls or the double's machinery needs (the real ones have more).
// With XRI_3 (the compile check defines it when the manifest has com.unity.xr.interaction.toolkit [3.0.0,4.0.0); the
// XRI 3 test project always): the same members in XRI 3.0.8's namespaces (tag 3.0.8, same files): the interactor
// interfaces in ...Toolkit.Interactors, the interactable ones in ...Toolkit.Interactables; XRInteractionUpdateOrder and
// the event args stay in ...Toolkit (Runtime/Interaction/XRInteractionEvents.cs), the transformer interfaces in
// ...Toolkit.Transformers, each with the signature it had in 2.5.4.
using System.Collections.Generic;
#if XRI_3
using UnityEngine.XR.Interaction.Toolkit.Interactables;
using UnityEngine.XR.Interaction.Toolkit.Interactors;
#endif

namespace UnityEngine.XR.Interaction.Toolkit
{
    public static class XRInteractionUpdateOrder
    {
        public const int k_Controllers = -29990;
        public const int k_LocomotionProviders = -210;
        public const int k_InteractionManager = -105;
        public const int k_Interactors = -99;
        public const int k_Interactables = -98;
        public const int k_BeforeRenderOrder = 100;

        public enum UpdatePhase
        {
            Fixed,
            Dynamic,
            Late,
            OnBeforeRender,
        }
    }

#if XRI_3
}

namespace UnityEngine.XR.Interaction.Toolkit.Interactors
{
#endif
    public interface IXRInteractor
    {
        Transform transform { get; }
        Transform GetAttachTransform(IXRInteractable interactable);
    }

    public interface IXRSelectInteractor : IXRInteractor
    {
        List<IXRSelectInteractable> interactablesSelected { get; }
        bool hasSelection { get; }
    }

#if XRI_3
}

namespace UnityEngine.XR.Interaction.Toolkit.Interactables
{
#endif
    public interface IXRInteractable
    {
        Transform transform { get; }
        Transform GetAttachTransform(IXRInteractor interactor);
    }

    public interface IXRSelectInteractable : IXRInteractable
    {
        List<IXRSelectInteractor> interactorsSelecting { get; }
        bool isSelected { get; }
        InteractableSelectMode selectMode { get; }
    }

    /// <summary>Real: IXRSelectInteractable.cs. Single (XRBaseInteractable's default): a new selector takes the interactable, the others exit first.</summary>
    public enum InteractableSelectMode
    {
        Single,
        Multiple,
    }

#if XRI_3
}

namespace UnityEngine.XR.Interaction.Toolkit
{
#endif
    /// <summary>Real: Runtime/Interaction/Interaction/InteractionEventArgs.cs (3.0.8: Runtime/Interaction/XRInteractionEvents.cs) (pooled; the double allocates one per event).</summary>
    public class SelectExitEventArgs
    {
        public IXRSelectInteractor interactorObject { get; set; }
        public IXRSelectInteractable interactableObject { get; set; }
        public XRInteractionManager manager { get; set; }
        public bool isCanceled { get; set; }
    }

    public class SelectEnterEventArgs
    {
        public IXRSelectInteractor interactorObject { get; set; }
        public IXRSelectInteractable interactableObject { get; set; }
        public XRInteractionManager manager { get; set; }
    }
}

namespace UnityEngine.XR.Interaction.Toolkit.Transformers
{
#if XRI_3
    using UnityEngine.XR.Interaction.Toolkit.Interactables;

#endif
    public interface IXRGrabTransformer
    {
        bool canProcess { get; }
        void OnLink(XRGrabInteractable grabInteractable);
        void OnGrab(XRGrabInteractable grabInteractable);
        void OnGrabCountChanged(XRGrabInteractable grabInteractable, Pose targetPose, Vector3 localScale);
        void Process(XRGrabInteractable grabInteractable, XRInteractionUpdateOrder.UpdatePhase updatePhase, ref Pose targetPose, ref Vector3 localScale);
        void OnUnlink(XRGrabInteractable grabInteractable);
    }

    public sealed class DropEventArgs
    {
        public SelectExitEventArgs selectExitEventArgs { get; set; }
    }

    public interface IXRDropTransformer : IXRGrabTransformer
    {
        bool canProcessOnDrop { get; }
        void OnDrop(XRGrabInteractable grabInteractable, DropEventArgs args);
    }
}
