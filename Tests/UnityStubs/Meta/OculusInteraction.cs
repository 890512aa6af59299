// Compile-only. Transcribed from the Meta XR Interaction SDK (com.meta.xr.sdk.interaction 85.0.0), as mirrored in
// darktable-mirror/com.meta.xr.sdk.interaction: Runtime/Scripts/Interaction/Grabbable/ITransformer.cs,
// Runtime/Scripts/Interaction/Grabbable/IGrabbable.cs, Runtime/Scripts/Interaction/Pointable/IPointable.cs
// (PointerEventType, PointerEvent, IPointable) and Runtime/Scripts/Interaction/Core/IEvent.cs (assembly Oculus.Interaction).
using System;
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

    public interface IEvent
    {
        object Data { get; }
    }

    public enum PointerEventType
    {
        Hover,
        Unhover,
        Select,
        Unselect,
        Move,
        Cancel
    }

    public struct PointerEvent : IEvent
    {
        public int Identifier => throw null;
        public PointerEventType Type => throw null;
        public Pose Pose => throw null;
        public object Data => throw null;
        public PointerEvent(int identifier, PointerEventType type, Pose pose, object data = null) => throw null;
    }

    public interface IPointable
    {
        event Action<PointerEvent> WhenPointerEventRaised;
    }
}
