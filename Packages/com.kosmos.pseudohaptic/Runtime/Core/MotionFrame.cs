namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// What one step knows, passed by reference through the stages: input → estimator → effects → object.
    /// Lives on the stack; nothing here is kept between frames (that is <see cref="HoldState"/>).
    /// </summary>
    public struct MotionFrame
    {
        /// <summary>Frame time, s, sanitised: finite and ≥ 0.</summary>
        public double Dt;

        /// <summary>The pose's height, m; meaningful only when <see cref="Usable"/>.</summary>
        public double PoseY;
        /// <summary>The pose's timestamp, s; NaN when the source gave none or an infinite one (never infinite).</summary>
        public double PoseTime;
        public bool IsHighConfidence;

        /// <summary>The pose can be followed this frame (tracked, finite; input effects may clear it).</summary>
        public bool Usable;

        /// <summary>Set by input effects to make the estimator re-anchor on this pose instead of following it.</summary>
        public bool ForceReanchor;

        /// <summary>Set by the estimator when it re-anchored this frame (the hand moved, the object did not).</summary>
        public bool Reanchored;

        /// <summary>The hand's height as followed, before and after this frame, m.</summary>
        public double HandBefore;
        public double HandAfter;

        /// <summary>The followed hand before and after this frame as the estimator (and filter) gave it, m, before
        /// any hand-motion effect: the hand the user sees, against which the visible offset is measured.</summary>
        public double PoseHandBefore;
        public double PoseHandAfter;

        /// <summary>Hand displacement to follow this frame, m (after the hand-motion effects).</summary>
        public double HandDelta;

        /// <summary>Hand speed measured against the pose's own timestamps, m/s (0 when no new pose).</summary>
        public double HandSpeed;

        /// <summary>The time the displacement took, s (one pose interval, or the gap it bridges); 0 when none.</summary>
        public double MotionInterval;

        /// <summary>A hand filter smooths the followed hand: it spreads a pose's motion over the frames after it, so
        /// the hand may move on frames without a new pose, and a pose's frame carries only part of its motion.</summary>
        public bool HandFiltered;

        /// <summary>The object's height before this frame, m.</summary>
        public double ObjectY;

        /// <summary>The object's proposed displacement this frame, m: G × the hand's (then shaped by effects).</summary>
        public double ObjectDelta;

        /// <summary>Displacement the speed limit carried over from earlier frames, m; it joins
        /// <see cref="ObjectDelta"/> at the speed limit. A cap on this frame's speed ignores it; a constraint on
        /// where the object may go (<see cref="TotalDelta"/>) includes it.</summary>
        public double Carry;

        /// <summary>Where the object is headed this frame: its own displacement plus the carried one, m.</summary>
        public double TotalDelta
        {
            get => ObjectDelta + Carry;
            set => ObjectDelta = value - Carry;
        }

        /// <summary>The object's height after the speed limit, m: what position effects constrain.</summary>
        public double NewObjectY;

        /// <summary>Shaped hand − object before this frame's motion, m: positive when the object is below the hand.</summary>
        public double OffsetBefore => HandBefore - ObjectY;

        /// <summary>Visible hand − object before this frame's motion, m (the hand before hand-motion effects).</summary>
        public double VisibleOffsetBefore => PoseHandBefore - ObjectY;
    }
}
