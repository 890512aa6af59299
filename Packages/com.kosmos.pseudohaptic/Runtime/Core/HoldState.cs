namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// Everything a hold remembers between frames, as plain values: copying it snapshots the hold.
    /// Effects keep their few numbers here, so the effect objects stay immutable and shareable.
    /// </summary>
    public struct HoldState
    {
        public bool IsHolding;

        /// <summary>The object's height (its pivot), m: <see cref="HeldY"/> − <see cref="GrabOffset"/>.</summary>
        public double ObjectY;

        /// <summary>hand − object when the hold began, m (0 when the hand was not tracked then). Every effect acts on
        /// the offset relative to this one: a hold that starts with hand and object apart behaves exactly as one that
        /// starts together, shifted.</summary>
        public double GrabOffset;

        /// <summary>The object's height plus <see cref="GrabOffset"/>, m: where it would be had it been grabbed with
        /// hand and object together. The solver and its effects move this; <see cref="ObjectY"/> follows it.</summary>
        public double HeldY;

        /// <summary><see cref="HeldY"/> when the hold began, m (<see cref="HeightDeceleration"/> measures from it).</summary>
        public double StartY;

        /// <summary>Frame time since the hold began, s (double: it never loses the millisecond in hours).</summary>
        public double Time;

        /// <summary>The rounding error <see cref="Time"/> still owes (compensated summation).</summary>
        public double TimeCompensation;

        /// <summary>The estimator's memory: the last followed pose and when.</summary>
        public PoseDeltaEstimator Estimator;

        /// <summary>The hand height the object follows, m: the last pose, or its filtered value when the profile has a filter.</summary>
        public double HandY;

        /// <summary>Displacement the speed limit has not yet applied, m.</summary>
        public double Carry;

        /// <summary><see cref="MotionDeadband"/>: the hand height the deadband follows.</summary>
        public double DeadbandReference;

        /// <summary><see cref="TrackingLossHold"/>: how long tracking has been steady since it came back, s; negative while settled.</summary>
        public double SettleElapsed;

        /// <summary><see cref="TrackingLossHold"/>: how long the current loss has lasted, s (0 while tracked).</summary>
        public double LostFor;

        /// <summary><see cref="SpeedCap"/>: motion the cap has deferred, m.</summary>
        public double CapDeferred;

        /// <summary><see cref="LoweringGuard"/>: what it added to the object's motion and may give back, m, and how long ago it acted, s.</summary>
        public double GuardDebt;
        public double GuardAge;

        /// <summary><see cref="FasterMovesFurther"/>: the hand height its speed judgement follows, m.</summary>
        public double PaceReference;

        /// <summary><see cref="FasterMovesFurther"/>: the hand's smoothed speed, m/s.</summary>
        public double Pace;

        /// <summary><see cref="FasterMovesFurther"/>: the pace of the latest motion, m/s, held (not decayed) while the hand
        /// rests; <see cref="OffsetCorrection"/> scales its threshold by it.</summary>
        public double HeldPace;

        /// <summary>hand − object, m: positive when the object is below the hand.</summary>
        public double Offset => HandY - ObjectY;

        /// <summary>hand − object less the grab offset, m: the offset the effects act on.</summary>
        public double RelativeOffset => HandY - HeldY;
    }
}
