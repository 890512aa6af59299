// Test double (a PointerEvent carries its values; GetHandGrabPose composes the wrist pose and the grab offset, as the
// SDK's HandGrabInteraction and PoseUtils.Multiply do). Transcribed from the Meta XR Interaction SDK (com.meta.xr.sdk.interaction 68.0.0), as mirrored in
// darktable-mirror/com.meta.xr.sdk.interaction at tag v68.0.0: Runtime/Scripts/Interaction/Grabbable/ITransformer.cs,
// Runtime/Scripts/Interaction/Grabbable/IGrabbable.cs, Runtime/Scripts/Interaction/Pointable/IPointable.cs
// (PointerEventType, PointerEvent, IPointable), Runtime/Scripts/Interaction/Core/IEvent.cs,
// Runtime/Scripts/Input/Hands/IHand.cs (IHand), Runtime/Scripts/Interaction/Models/HandGrab/IHandGrabState.cs,
// IHandGrabInteractor.cs and HandGrabInteraction.cs (assembly Oculus.Interaction). Interfaces list only the members
// the package calls and the tests' fakes implement (the real ones have more).
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
        public int Identifier { get; }
        public PointerEventType Type { get; }
        public Pose Pose { get; }
        public object Data { get; }

        public PointerEvent(int identifier, PointerEventType type, Pose pose, object data = null)
        {
            Identifier = identifier;
            Type = type;
            Pose = pose;
            Data = data;
        }
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
        bool GetRootPose(out Pose pose);
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
        /// <summary>The tracked wrist (the hand's root pose) times the wrist-to-grab offset; a null Hand throws, as in the SDK.</summary>
        public static Pose GetHandGrabPose(this IHandGrabInteractor handGrabInteractor)
        {
            handGrabInteractor.Hand.GetRootPose(out Pose wrist);
            Pose offset = handGrabInteractor.WristToGrabPoseOffset;
            return new Pose(wrist.position + wrist.rotation * offset.position, wrist.rotation * offset.rotation);
        }
    }
}
