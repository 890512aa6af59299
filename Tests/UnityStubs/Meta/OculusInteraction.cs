// Compile-only. Transcribed from the Meta XR Interaction SDK (com.meta.xr.sdk.interaction 85.0.0), as mirrored in
// darktable-mirror/com.meta.xr.sdk.interaction: Runtime/Scripts/Interaction/Grabbable/ITransformer.cs and
// Runtime/Scripts/Interaction/Grabbable/IGrabbable.cs (assembly Oculus.Interaction).
using System.Collections.Generic;
using UnityEngine;

namespace Oculus.Interaction
{
    public interface IGrabbable
    {
        List<Pose> GrabPoints { get; }
        Transform Transform { get; }
    }

    public interface ITransformer
    {
        void Initialize(IGrabbable grabbable);
        void BeginTransform();
        void UpdateTransform();
        void EndTransform();
    }
}
