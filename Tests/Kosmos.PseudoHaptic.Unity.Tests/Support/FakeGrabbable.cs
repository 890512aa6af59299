using System;
using System.Collections.Generic;
using Oculus.Interaction;
using Oculus.Interaction.HandGrab;
using Oculus.Interaction.Input;
using UnityEngine;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>
    /// The Interaction SDK 68.0.0's Grabbable as the transformer meets it, written from its documented behaviour and
    /// sources (Grabbable.cs, PointableElement.cs): Hover adds a point; Select ends the active transformer, adds a
    /// selecting point (at the front with AddNewPointsToFront), raises the event, then begins the transformer for the new count (one-grab or two-grab); Unselect
    /// first moves the point to the release pose and updates the active transformer (the SDK's ForceMove), then ends,
    /// removes, raises, begins again; Cancel ends the transformer and removes the point (raising the event only when
    /// the pointer was hovering) and begins nothing; Move updates the point and the active transformer.
    /// </summary>
    public sealed class FakeGrabbable : PointableElement, IGrabbable, IPointableElement
    {
        readonly List<int> _pointIds = new List<int>(), _selectingIds = new List<int>();
        readonly List<Pose> _points = new List<Pose>(), _selecting = new List<Pose>();
        ITransformer _one, _two, _active;

        public event Action<PointerEvent> WhenPointerEventRaised = delegate { };
        public List<Pose> GrabPoints => _selecting;
        public Transform Transform => transform;
        public int Selecting => _selecting.Count;

        public void Use(ITransformer oneGrab, ITransformer twoGrab)
        {
            _one = oneGrab;
            _two = twoGrab;
            _one?.Initialize(this);
            if (_two != null && !ReferenceEquals(_two, _one)) _two.Initialize(this);
            else _two?.Initialize(this);
        }

        public void ProcessPointerEvent(PointerEvent evt)
        {
            // Real (ForceMove): an Unselect first moves the point to the release pose and updates the active transformer.
            if (evt.Type == PointerEventType.Unselect)
                ProcessPointerEvent(new PointerEvent(evt.Identifier, PointerEventType.Move, evt.Pose, evt.Data));
            if (evt.Type == PointerEventType.Select || evt.Type == PointerEventType.Unselect || evt.Type == PointerEventType.Cancel) End();
            switch (evt.Type)
            {
                case PointerEventType.Hover:
                    _pointIds.Add(evt.Identifier);
                    _points.Add(evt.Pose);
                    Raise(evt);
                    break;
                case PointerEventType.Unhover:
                    if (Remove(_pointIds, _points, evt.Identifier)) Raise(evt);
                    break;
                case PointerEventType.Select:
                    // AddNewPointsToFront: the new selecting point goes first (PointableElement.Select).
                    _selectingIds.Insert(AddNewPointsToFront ? 0 : _selectingIds.Count, evt.Identifier);
                    _selecting.Insert(AddNewPointsToFront ? 0 : _selecting.Count, evt.Pose);
                    Raise(evt);
                    Begin();
                    break;
                case PointerEventType.Unselect:
                    if (Remove(_selectingIds, _selecting, evt.Identifier)) Raise(evt);
                    Begin();
                    break;
                case PointerEventType.Cancel:
                    Remove(_selectingIds, _selecting, evt.Identifier);
                    if (Remove(_pointIds, _points, evt.Identifier)) Raise(evt);
                    break;
                case PointerEventType.Move:
                    int i = _selectingIds.IndexOf(evt.Identifier);
                    if (i >= 0) _selecting[i] = evt.Pose;
                    _active?.UpdateTransform();
                    break;
            }
        }

        void Raise(PointerEvent evt) => WhenPointerEventRaised(evt);

        static bool Remove(List<int> ids, List<Pose> poses, int id)
        {
            int i = ids.IndexOf(id);
            if (i < 0) return false;
            ids.RemoveAt(i);
            poses.RemoveAt(i);
            return true;
        }

        void Begin()
        {
            End();
            _active = _selecting.Count == 1 ? _one : _selecting.Count == 2 ? _two : null;
            _active?.BeginTransform();
        }

        void End()
        {
            _active?.EndTransform();
            _active = null;
        }
    }

    /// <summary>A hand the SDK tracks: its wrist pose, tracking and confidence, as the test sets them.</summary>
    public sealed class FakeHand : IHand
    {
        public Vector3 Wrist;
        public bool IsTrackedDataValid { get; set; } = true;
        public bool IsHighConfidence { get; set; } = true;

        public bool GetRootPose(out Pose pose)
        {
            pose = new Pose(Wrist, Quaternion.identity);
            return IsTrackedDataValid;
        }
    }

    /// <summary>
    /// A hand grab interactor as the Grabbable sees it (PointerInteractor.cs): it hovers then selects, sends Move each
    /// frame, and, when the Grabbable raises a Cancel of its own pointer, lets go (Unselect, then Unhover).
    /// </summary>
    public sealed class FakeHandGrabInteractor : IHandGrabInteractor
    {
        readonly FakeGrabbable _grabbable;
        public readonly int Identifier;
        public IHand Hand { get; set; }
        public Pose WristToGrabPoseOffset { get; set; } = Pose.identity;

        public FakeHandGrabInteractor(FakeGrabbable grabbable, int id, IHand hand)
        {
            _grabbable = grabbable;
            Identifier = id;
            Hand = hand;
        }

        Pose Point => Hand != null && Hand.GetRootPose(out Pose p) ? p : Pose.identity;

        public void Grab()
        {
            _grabbable.WhenPointerEventRaised += OnEvent;
            _grabbable.ProcessPointerEvent(new PointerEvent(Identifier, PointerEventType.Hover, Point, this));
            _grabbable.ProcessPointerEvent(new PointerEvent(Identifier, PointerEventType.Select, Point, this));
        }

        public void Move() => _grabbable.ProcessPointerEvent(new PointerEvent(Identifier, PointerEventType.Move, Point, this));

        void OnEvent(PointerEvent evt)
        {
            if (evt.Identifier != Identifier || evt.Type != PointerEventType.Cancel) return;
            _grabbable.WhenPointerEventRaised -= OnEvent;
            _grabbable.ProcessPointerEvent(new PointerEvent(Identifier, PointerEventType.Unselect, Point, this));
            _grabbable.ProcessPointerEvent(new PointerEvent(Identifier, PointerEventType.Unhover, Point, this));
        }
    }
}
