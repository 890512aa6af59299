// Test double: only the member the package reads. Written from the Meta XR Interaction SDK (com.meta.xr.sdk.interaction)
// 68.0.0, as mirrored in darktable-mirror/com.meta.xr.sdk.interaction, tag v68.0.0:
// Runtime/Scripts/Interaction/Pointable/PointableElement.cs (assembly Oculus.Interaction). There the Grabbable derives from
// it, and with AddNewPointsToFront a Select inserts its point at the front of the selecting points instead of the end.
// Simplification: the base here implements no interface; the real one implements IPointableElement (a derived double does).
using UnityEngine;

namespace Oculus.Interaction
{
    public class PointableElement : MonoBehaviour
    {
        public bool AddNewPointsToFront { get; set; }
    }
}
