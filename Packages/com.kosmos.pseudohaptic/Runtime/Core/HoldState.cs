namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// Everything a hold remembers between frames, as plain values: copying it snapshots the hold.
    /// Effects keep their few numbers here, so the effect objects stay immutable and shareable.
    /// What the weight remembers of the hand is only where the lift started (<see cref="Base"/>) and the pace of
    /// the lift (<see cref="Pace"/>): the offset is a function of them and of where the hand is now, so a motion
    /// that comes back leaves no trace, and neither does anything tracking does.
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

        /// <summary>The hand's height when the hold began (or when the first pose of a hold begun untracked came), m.</summary>
        public double StartY;

        /// <summary>Frame time since the hold began, s (double: it never loses the millisecond in hours).</summary>
        public double Time;

        /// <summary>The rounding error <see cref="Time"/> still owes (compensated summation).</summary>
        public double TimeCompensation;

        /// <summary>The estimator's memory: the last followed pose and when.</summary>
        public PoseDeltaEstimator Estimator;

        /// <summary>The hand height the object follows, m: the last accepted pose, or its filtered value.</summary>
        public double HandY;

        /// <summary>Where the lift is measured from, m: the hand's height at the grab, moved down by
        /// <see cref="LoweringGuard"/> and up by <see cref="OffsetRelaxation"/>.</summary>
        public double Base;

        /// <summary>The last accepted poses (newest first) and how many have come since the hold began or tracking
        /// came back, counted up to three (all the median needs): <see cref="SteadyY"/> is their median.</summary>
        public double Pose1, Pose2;
        public int PoseCount;

        /// <summary>The grab's pose has not yet been checked against the next two (a hold begun on a glitched pose).</summary>
        public bool AnchorPending;

        /// <summary>The hand as the hold remembers it (<see cref="MotionFrame.SteadyHand"/>), m.</summary>
        public double SteadyY;

        /// <summary>Frame time the followed pose has been shown unchanged since it last entered the window of
        /// <see cref="SteadyY"/>, s: at <see cref="SolverLimits.RepeatTime"/> it enters again (a repeated pose advances with time).</summary>
        public double HeldFor;

        /// <summary>The centre of the plausibility gate's workspace, m: the hand where the hold began (its first pose, for a
        /// hold begun untracked); <see cref="HasWorkspace"/> once known. A pose farther than
        /// <see cref="SolverLimits.WorkspaceRadius"/> from it is not tracked.</summary>
        public double WorkspaceY;
        public bool HasWorkspace;

        /// <summary>The offset the object shows beyond the weight's, m, gliding back to 0 at
        /// <see cref="SolverLimits.GlideSpeed"/>: what a change of mass or profile during the hold left.</summary>
        public double Glide;

        /// <summary>The weight's offset and the hand it read, last frame, m: a change of the offset the hand's motion does not
        /// explain glides.</summary>
        public double LastOffset, LastHand;

        /// <summary><see cref="MotionDeadband"/>: the hand height the deadband follows (the hand the weight reads), m.</summary>
        public double DeadbandReference;

        /// <summary><see cref="MotionDeadband"/>: the band's half-width now, m: closed by sustained motion, regrown at rest
        /// (at most the width for the object's gain; +∞ at the grab: full width; −∞ while the gain is at most 1: no band).</summary>
        public double DeadbandHalfWidth;

        /// <summary><see cref="MotionDeadband"/>: how many steady poses the reference averages at rest (capped; until the hand
        /// has shown it moved, the rest rule's reference run alongside the grab's backlash).</summary>
        public int DeadbandRestCount;

        /// <summary><see cref="MotionDeadband"/>: the hold's clock when the band last saw a steady pose, s.</summary>
        public double DeadbandSteadyTime;

        /// <summary><see cref="MotionDeadband"/>: the hand where the hold began, m (the reference until the hand first moves); for a
        /// band that opened during the hold near that pose, the steady hand's mean where it opened.</summary>
        public double DeadbandAnchor;

        /// <summary><see cref="MotionDeadband"/>, from the grab until the hand has moved: the band's backlash reference (the grab's
        /// pose, dragged by pushes), m.</summary>
        public double DeadbandGrabReference;

        /// <summary><see cref="MotionDeadband"/>, from the grab until the hand has moved: the reference the rest rule would give
        /// (the steady hand's mean since the last push), m.</summary>
        public double DeadbandRestMean;

        /// <summary><see cref="MotionDeadband"/>: the mean of the steady hand since the grab (while the gain is at most 1: since
        /// the band went), fading over 30 poses, m; the mean of the hold's first steady poses, m; and how many steady poses the
        /// mean has taken (capped at 30).</summary>
        public double DeadbandGrabMean, DeadbandEarlyMean;
        public int DeadbandGrabCount;

        /// <summary><see cref="MotionDeadband"/>: how far the hand has shown it moved since the grab, 0–1 (never decreasing, but
        /// for 0 again when the gain rises above 1 during the hold with the hand within the band of the grab's pose): the share
        /// of the way from the grab's backlash reference to the steady hand's mean.</summary>
        public double DeadbandMoved;

        /// <summary><see cref="MotionDeadband"/>: whether the lift is measured from the mean of the hold's first steady poses:
        /// not (a band opened during the hold, or the hand moved before they were taken), becoming so, or so.</summary>
        public int DeadbandSettle;

        /// <summary><see cref="MotionDeadband"/>: the hold's clock at the grab (or where the band began), s.</summary>
        public double DeadbandGrabTime;

        /// <summary><see cref="LoweringGuard"/>: the base after each of the last five steady poses, newest first, m (where the hold
        /// began, or the base at the last gap or where it was last measured anew, until five have been seen since).</summary>
        public double GuardBase1, GuardBase2, GuardBase3, GuardBase4, GuardBase5;

        /// <summary><see cref="TrackingLossHold"/>: how long tracking has been steady since it came back, s; negative while settled.</summary>
        public double SettleElapsed;

        /// <summary><see cref="TrackingLossHold"/>: how long the current loss has lasted, s (0 while tracked).</summary>
        public double LostFor;

        /// <summary><see cref="FasterMovesFurther"/>: the lift's pace, m/s (the mean speed of its rise from where it began to its highest point so far),
        /// 0 while the hand rests at the base.</summary>
        public double Pace;

        /// <summary><see cref="FasterMovesFurther"/>: the gain at <see cref="Pace"/> (recomputed only when the pace changes).</summary>
        public double PaceGain;

        /// <summary><see cref="FasterMovesFurther"/>: ln G that <see cref="PaceGain"/> was computed for (NaN: not yet).</summary>
        public double PaceGainOf;

        /// <summary><see cref="FasterMovesFurther"/>: where and when the current rise left the base, its highest point so
        /// far and when it got there, and whether the pace is settled (the rise paused).</summary>
        public double RiseStartLift, RiseStartTime, RiseTop, RiseTopTime;

        /// <summary><see cref="FasterMovesFurther"/>: where and when the hand last left the rest band (a rise started over after
        /// a pause keeps them): a very slow lift's pace is its mean speed since then.</summary>
        public double RiseBandLift, RiseBandTime;

        /// <summary><see cref="FasterMovesFurther"/>: the steady lift last seen and when.</summary>
        public double PaceSeenLift, PaceSeenTime;

        /// <summary><see cref="FasterMovesFurther"/>: time that gaps in tracking hid from a rise, s: the rise's clock runs that much
        /// behind the hold's.</summary>
        public double PaceClockSkip;
        public bool PaceSettled;

        /// <summary><see cref="FasterMovesFurther"/>: since the hand last left the rest band, a rise paused before it climbed
        /// <see cref="FasterMovesFurther.MinPacedRise"/> with the climb since the band that much or more (a very slow lift): a new
        /// top of a rise still under MinPacedRise reads the mean speed since the band, the pace a pause there keeps.</summary>
        public bool PaceSlowSinceBand;

        /// <summary><see cref="FasterMovesFurther"/>, with a pause time longer than <see cref="FasterMovesFurther.HeftTime"/>: the
        /// rise's top when it first stood still that long, when it got there, and the pace then (NaN top: none). A hand that
        /// rises on and comes back down to it was hefting: the pace is this one again.</summary>
        public double PaceCheckTop, PaceCheckTopTime, PaceCheckPace;

        /// <summary><see cref="OffsetRelaxation"/>: the steady hand at the start of the window its stillness is judged over and
        /// at the window's middle, m, with their times, s, and the steady hand's mean speed over the window, m/s.</summary>
        public double RelaxFromY, RelaxFromTime, RelaxMidY, RelaxMidTime, RelaxSpeed;

        /// <summary><see cref="SpeedCap"/>: where the object may be at its capped speed (held height, m), the motion it
        /// may still make this pose (m), and whether it has begun.</summary>
        public double CappedY, CapBudget;
        public bool CapStarted;

        /// <summary><see cref="SpeedCap"/>: the weight's target height of the last frame, m.</summary>
        public double CapTarget;

        /// <summary>How far the hand has pulled beyond what the weight allows, m (the speed cap's lag; 0 without it).</summary>
        public double Strain;

        /// <summary>hand − object, m: positive when the object is below the hand.</summary>
        public double Offset => HandY - ObjectY;

        /// <summary>hand − object less the grab offset, m: the offset the effects act on.</summary>
        public double RelativeOffset => HandY - HeldY;
    }
}
