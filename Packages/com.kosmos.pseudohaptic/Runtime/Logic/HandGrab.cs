using System;

namespace Kosmos.PseudoHaptic
{
    /// <summary>What a hand's grab asks of the scene; the Unity layer answers from its objects.</summary>
    public interface IGrabDriver
    {
        /// <summary>Takes the nearest object in reach (see <see cref="GrabSelection"/>); true when a hold began.</summary>
        bool TryGrab();

        /// <summary>The object this hand holds is still held by it (not destroyed, disabled or released elsewhere).</summary>
        bool IsStillHeld { get; }

        /// <summary>The solver reports that the object has torn loose from the hand (break-away); false when it has no such effect.</summary>
        bool BrokeAway { get; }

        /// <summary>Advances the held object by this frame; <paramref name="tracked"/> false: the hand is lost, hold it still.</summary>
        void Follow(bool tracked);

        /// <summary>Lets go of the held object.</summary>
        void Release();
    }

    /// <summary>Why the last hold of a hand ended.</summary>
    public enum GrabEnd
    {
        None,
        /// <summary>The tracked hand opened its pinch.</summary>
        Opened,
        /// <summary>Tracking stayed lost for <see cref="HandGrab.ReleaseAfterLost"/>.</summary>
        TrackingLost,
        /// <summary>The solver reported a break-away.</summary>
        BrokeAway,
        /// <summary>The object was released, disabled or destroyed elsewhere.</summary>
        Elsewhere,
        /// <summary><see cref="HandGrab.Release"/> was called (the component was disabled).</summary>
        Called,
    }

    /// <summary>
    /// One hand's grab as a state machine, engine-free: idle until the pinch closes (<see cref="PinchDetector"/>),
    /// then it asks for the nearest object in reach; while holding, each frame it follows the hand, holds the
    /// object still while tracking is lost, and releases when the tracked hand opens, when tracking has been
    /// lost for <see cref="ReleaseAfterLost"/> seconds, when the solver reports a break-away, or when the
    /// object is gone. A pinch that closed away from any object grabs nothing until it opens and closes again.
    /// Two hands on one object are two of these on one <see cref="HeldObject"/>. No allocation per frame.
    /// </summary>
    public sealed class HandGrab
    {
        public const double DefaultReleaseAfterLost = 1.0;

        double _releaseAfterLost = DefaultReleaseAfterLost;
        double _lostFor;

        public PinchDetector Pinch { get; } = new PinchDetector();

        /// <summary>This hand holds an object.</summary>
        public bool IsHolding { get; private set; }

        /// <summary>Why the last hold ended.</summary>
        public GrabEnd LastEnd { get; private set; }

        /// <summary>How long tracking has been lost during this hold, s.</summary>
        public double LostFor => _lostFor;

        /// <summary>Release after tracking has been lost this long, s (finite, ≥ 0).</summary>
        public double ReleaseAfterLost
        {
            get => _releaseAfterLost;
            set
            {
                if (!(value >= 0) || double.IsInfinity(value)) throw new ArgumentOutOfRangeException(nameof(ReleaseAfterLost), value, "ReleaseAfterLost must be finite and >= 0");
                _releaseAfterLost = value;
            }
        }

        /// <summary>One frame: the hand's tracking and pinch strength, the frame's duration, and the scene.</summary>
        public void Tick(bool tracked, double pinchStrength, double dt, IGrabDriver scene)
        {
            Pinch.Update(tracked, pinchStrength, dt);
            if (scene == null) return;
            if (!IsHolding)
            {
                if (Pinch.Began && scene.TryGrab())
                {
                    IsHolding = true;
                    LastEnd = GrabEnd.None;
                    _lostFor = 0;
                }
                return;
            }
            if (!scene.IsStillHeld) { End(GrabEnd.Elsewhere, null); return; }
            if (tracked) _lostFor = 0;
            else if (dt > 0 && !double.IsInfinity(dt)) _lostFor += Math.Min(dt, PinchDetector.LongestCountedFrame); // a hitch is one frame of loss

            if (scene.BrokeAway) End(GrabEnd.BrokeAway, scene);
            else if (tracked && !Pinch.IsPinching) End(GrabEnd.Opened, scene);
            else if (!tracked && _lostFor >= _releaseAfterLost) End(GrabEnd.TrackingLost, scene);
            else scene.Follow(tracked);
        }

        /// <summary>Ends the hold now, if any (a disabled component); the pinch must reopen before the next grab.</summary>
        public void Release(IGrabDriver scene)
        {
            if (IsHolding) End(GrabEnd.Called, scene);
        }

        void End(GrabEnd why, IGrabDriver scene)
        {
            IsHolding = false;
            LastEnd = why;
            _lostFor = 0;
            if (scene != null) scene.Release();
        }
    }
}
