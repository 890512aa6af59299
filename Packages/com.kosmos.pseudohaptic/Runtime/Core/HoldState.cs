namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// Everything a hold remembers between frames, as plain values: copying it snapshots the hold.
    /// Effects keep their few numbers here, so the effect objects stay immutable and shareable.
    /// </summary>
    public struct HoldState
    {
        public bool IsHolding;

        /// <summary>The object's height, m.</summary>
        public double ObjectY;

        /// <summary>The object's height when the hold began, m (<see cref="HeightDeceleration"/> measures from it).</summary>
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

        /// <summary>hand − object, m: positive when the object is below the hand.</summary>
        public double Offset => HandY - ObjectY;
    }
}
