// Compile-only. Transcribed from the Meta XR Interaction SDK (com.meta.xr.sdk.interaction 68.0.0), as mirrored in
// darktable-mirror/com.meta.xr.sdk.interaction at tag v68.0.0: Runtime/Scripts/Interaction/Grabbable/ITransformer.cs,
// Runtime/Scripts/Interaction/Grabbable/IGrabbable.cs, Runtime/Scripts/Interaction/Pointable/IPointable.cs
// (PointerEventType, PointerEvent, IPointable), Runtime/Scripts/Interaction/Core/IEvent.cs,
// Runtime/Scripts/Input/Hands/IHand.cs (IHand), Runtime/Scripts/Interaction/Models/HandGrab/IHandGrabState.cs,
// IHandGrabInteractor.cs and HandGrabInteraction.cs (assembly Oculus.Interaction). Interfaces list only the members
// the package calls (the real ones have more); nothing here implements them.
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

    public interface IPointableElement : IPointable
    {
        void ProcessPointerEvent(PointerEvent evt);
    }
}

namespace Oculus.Interaction.Input
{
    public interface IHand
    {
        bool IsHighConfidence { get; }
        bool IsTrackedDataValid { get; }
    }
}

namespace Oculus.Interaction.HandGrab
{
    using Oculus.Interaction.Input;

    public interface IHandGrabState
    {
        Pose WristToGrabPoseOffset { get; }
    }

    public interface IHandGrabInteractor : IHandGrabState
    {
        IHand Hand { get; }
    }

    public static class HandGrabInteraction
    {
        public static Pose GetHandGrabPose(this IHandGrabInteractor handGrabInteractor) => throw null;
    }
}
