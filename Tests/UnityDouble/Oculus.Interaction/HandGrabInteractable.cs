// Test double (the alignment is a plain property). Transcribed from the Meta XR Interaction SDK (com.meta.xr.sdk.interaction) 68.0.0, as mirrored in
// darktable-mirror/com.meta.xr.sdk.interaction, tag v68.0.0: Runtime/Scripts/Interaction/Models/HandGrab/IHandGrabState.cs
// (HandAlignType) and Runtime/Scripts/Interaction/Models/HandGrab/HandGrabInteractable.cs (HandAlignment). Assembly
// Oculus.Interaction. Simplification: HandGrabInteractable derives here from MonoBehaviour; the real base chain is
// PointerInteractable<HandGrabInteractor, HandGrabInteractable> → Interactable<,> → MonoBehaviour.
using UnityEngine;

namespace Oculus.Interaction.HandGrab
{
    public enum HandAlignType
    {
        None,
        AlignOnGrab,
        AttractOnHover,
        AlignFingersOnHover,
    }

    public partial class HandGrabInteractable : MonoBehaviour
    {
        public HandAlignType HandAlignment { get; set; } = HandAlignType.AlignOnGrab;
    }
}
