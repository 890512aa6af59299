namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// What one step knows, passed by reference through the stages: input → estimator → hand → base → lift →
    /// offset → object. Lives on the stack; nothing here is kept between frames (that is <see cref="HoldState"/>).
    /// Heights are held heights (the object's plus the grab offset, <see cref="HoldState.HeldY"/>), in the held
    /// object's parent space, so every offset here is relative to the one at the grab.
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

        /// <summary>The pose can be followed this frame (tracked, finite; input effects may clear it, the estimator
        /// clears it for a pose no hand could have reached).</summary>
        public bool Usable;

        /// <summary>Set by an input effect: this frame's pose is followed, but it does not count toward what the hold
        /// remembers of the hand (<see cref="SteadyHand"/>): the first poses after a loss are often centimetres off.</summary>
        public bool Settling;

        /// <summary>A new pose arrived this frame (not a repeat of the last one).</summary>
        public bool NewPose;

        /// <summary>The new pose is the first after tracking was lost (or a pose was rejected): the hand's motion across
        /// the gap is followed in full, as real motion.</summary>
        public bool Bridged;

        /// <summary>The new pose ends a gap: it is <see cref="Bridged"/>, or more than <see cref="SolverLimits.GapTime"/> of frame
        /// time passed since the last accepted pose (a hitch). The hand's motion across it is followed as far as the hand went,
        /// never further: a light object's lead on it glides.</summary>
        public bool AcrossGap;

        /// <summary>The first usable pose of a hold begun before the hand was tracked: it anchors the hold (the grab
        /// offset is taken here) instead of being followed.</summary>
        public bool Reanchored;

        /// <summary>The followed hand before and after this frame, m: the last accepted pose (or its filtered value).</summary>
        public double HandBefore;
        public double HandAfter;

        /// <summary>HandAfter − HandBefore, m.</summary>
        public double HandDelta;

        /// <summary>Hand speed measured against the pose's own timestamps, m/s (0 when no new pose).</summary>
        public double HandSpeed;

        /// <summary>The time the displacement took, s (one pose interval, or the gap it bridges); 0 when none.</summary>
        public double MotionInterval;

        /// <summary>A hand filter smooths the followed hand: it may move on frames without a new pose.</summary>
        public bool HandFiltered;

        /// <summary>The hand the weight reads, m: <see cref="HandAfter"/>, or less its jitter (<see cref="MotionDeadband"/>).</summary>
        public double WeightHand;

        /// <summary>The median of the last three accepted poses, m, held while tracking settles after a loss: the
        /// hand as the hold remembers it (the base and the lift's pace read it), blind to a one-pose glitch.</summary>
        public double SteadyHand;

        /// <summary><see cref="SteadyHand"/> was taken anew this frame (a new pose, three since the last gap), moved or not.</summary>
        public bool SteadyTaken;

        /// <summary>The lift's base was measured anew this frame from where the hand rests (the solver from a glitched grab pose,
        /// <see cref="MotionDeadband"/> from the hold's first poses): where the base was before says nothing of a glitch
        /// (<see cref="LoweringGuard"/>).</summary>
        public bool BaseMeasured;

        /// <summary>How far the hand has lifted the object: <see cref="WeightHand"/> − <see cref="HoldState.Base"/>, m
        /// (base effects may shape it).</summary>
        public double Lift;

        /// <summary>The gain on the lift this frame: G, or as an effect of the lift's pace reshapes it.</summary>
        public double Gain;

        /// <summary>The lift the gain carries, m: <see cref="Lift"/>, or less as the object slows with height.</summary>
        public double CarriedLift;

        /// <summary>The weight's offset, m: hand − object, positive when the object hangs below the hand. The solver
        /// sets it to Lift − Gain × CarriedLift; object-motion effects shape it.</summary>
        public double Offset;

        /// <summary>The largest offset the user may see, m (an effect that bounds the offset sets it; +∞ otherwise).</summary>
        public double OffsetCeiling;

        /// <summary>The object's height before this frame, m.</summary>
        public double ObjectY;

        /// <summary>The object's new height, m: the hand less the offset, then constrained by position effects.</summary>
        public double NewObjectY;
    }
}
