using System;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// Son et al. 2022, §3.1: "even if we moved our hands at the same height when lifting two virtual objects with
    /// the same weight, ... the movement of the two fast-moving virtual objects was greater". A gain that is constant
    /// in speed cannot keep that rule, and in it the user's standard speed v_std would cancel. For an object heavier
    /// than the standard (G &lt; 1) the gain on the lift is
    /// <code>G_p = G^r,  r = clamp(x^(−s), <see cref="FastExponent"/>, <see cref="SlowExponent"/>),  x = κ · p / v_std</code>
    /// (s = <see cref="Sensitivity"/>, 0.06 by default)
    /// where p is the lift's pace: the mean speed of its rise from the base to its highest point so far, which settles
    /// once the rise pauses for <see cref="PauseTime"/> and starts over when the hand is back at the base. It changes only
    /// when the steady hand reaches a new top or the base, never while the hand rests: a pause decides only where the next
    /// rise starts and how it reads its pace (<see cref="MinPacedRise"/>), so nothing moves while the hand is still. κ =
    /// <see cref="StandardLiftRatio"/> makes a lift at the user's standard speed read x = 1, where G_p = G (Eq. 4–6);
    /// faster, r &lt; 1 and the gain moves toward 1 (the object rises further); slower, r &gt; 1 and it moves away from 1.
    /// Bounded both ways (G^SlowExponent ≤ G_p ≤ G^FastExponent &lt; 1), continuous, monotone in G at every pace (heavier
    /// still lags more, P2). The pace is a mean over the whole rise, read on the steady hand (the median of three
    /// poses), so a glitch, a loss or a snap barely changes it; and it never changes once the rise has paused, so a heft
    /// after a lift, however fast, leaves the gain as it was: the weight stays a function of where the hand is.
    /// The standard weight (G = 1) and lighter objects are untouched (their pace is followed all the same, so that a gain that
    /// falls below 1 during the hold reads the rise's own pace).
    /// </summary>
    public sealed class FasterMovesFurther : WeightEffect
    {
        /// <summary>This effect's name, stage, summary and settings (<see cref="EffectRegistry"/>).</summary>
        public static readonly EffectDescriptor Descriptor = new EffectDescriptor("faster-moves-further", EffectStage.Lift, typeof(FasterMovesFurther),
            "§3.1",
            "a heavy object's gain G^r follows the lift's pace relative to the user's standard speed: a faster lift moves it further",
            s => new FasterMovesFurther(s[0], s[1], s[2], s[3], s[4]),
            SettingDescriptor.Number<FasterMovesFurther>("fastExponent", "", 0.5, 0.01, 1, "the exponent r for a hand much faster than v_std", e => e.FastExponent),
            SettingDescriptor.Number<FasterMovesFurther>("slowExponent", "", 1.5, 1, 10, "the exponent r for a hand much slower than v_std, and at a lift's start", e => e.SlowExponent),
            SettingDescriptor.Number<FasterMovesFurther>("restBand", "m", 0.005, 0, 0.05, "how far above the base the steady hand is still at rest", e => e.RestBand),
            SettingDescriptor.Number<FasterMovesFurther>("pauseTime", "s", 0.16, 0.01, 5, "a rise that has not gone higher for this long has paused: its pace is settled", e => e.PauseTime),
            SettingDescriptor.Number<FasterMovesFurther>("sensitivity", "", 0.06, 0, 2, "how strongly the exponent follows the pace: r = x^(−sensitivity)", e => e.Sensitivity));

        public override string Name => Descriptor.Name;
        public override EffectStage Stage => Descriptor.Stage;
        /// <summary>The pace changes only on a new steady pose, and the gain is a function of the pace.</summary>
        protected internal override bool IsFunctionOfHand => true;

        /// <summary>
        /// Mean speed of a standard lift's 10–90 % span (how <see cref="StandardSpeedCalibration"/> measures v_std) over
        /// its pace as this effect measures it (the mean speed from leaving a 5 mm band at the base to the top), for a
        /// minimum-jerk lift: a lift at the user's standard speed reads x = 1 (`FasterMovesFurtherTests`).
        /// </summary>
        public const double StandardLiftRatio = 1.29;

        /// <summary>The exponent r for a hand much faster than v_std (r ≤ 1): G^r is the largest gain.</summary>
        public double FastExponent { get; }

        /// <summary>The exponent r for a hand much slower than v_std, and at the start of a lift (r ≥ 1).</summary>
        public double SlowExponent { get; }

        /// <summary>How far above the base the steady hand is still at rest, m: a rise starts when it leaves this band.</summary>
        public double RestBand { get; }

        /// <summary>A rise that has not gone higher for this long has paused: its pace is settled until the hand is back at
        /// the base, s.</summary>
        public double PauseTime { get; }

        /// <summary>How strongly the exponent follows the pace: r = x^(−Sensitivity) (0: not at all).</summary>
        public double Sensitivity { get; }

        public FasterMovesFurther(double fastExponent = 0.5, double slowExponent = 1.5, double restBand = 0.005, double pauseTime = 0.16,
            double sensitivity = 0.06)
        {
            Sensitivity = Descriptor.Settings[4].Check(sensitivity);
            FastExponent = Descriptor.Settings[0].Check(fastExponent);
            SlowExponent = Descriptor.Settings[1].Check(slowExponent);
            RestBand = Descriptor.Settings[2].Check(restBand);
            PauseTime = Descriptor.Settings[3].Check(pauseTime);
        }

        /// <summary>The exponent r at lift pace <paramref name="pace"/> for a user of standard speed <paramref name="standardSpeed"/>;
        /// 1 (the gain of Eq. 4–6) while no rise has a pace yet.</summary>
        public double ExponentAt(double pace, double standardSpeed)
        {
            double x = StandardLiftRatio * Math.Abs(pace) / standardSpeed;
            if (!(x > 0)) return 1;
            double r = Math.Exp(-Sensitivity * Math.Log(x));
            return r > SlowExponent ? SlowExponent : (r < FastExponent ? FastExponent : r);
        }

        /// <summary>The gain G_p for an object of gain <paramref name="gain"/> at lift pace <paramref name="pace"/>.</summary>
        public double GainAt(double gain, double pace, double standardSpeed)
            => gain < 1 ? Math.Exp(ExponentAt(pace, standardSpeed) * Math.Log(gain)) : gain; // gain 0: e^(−∞) = 0

        protected internal override void Apply(ref MotionFrame frame, ref HoldState state, in SolverConstants constants)
        {
            // The pace is followed at every gain and applied only below 1: when the gain falls below 1 during a hold (a hand
            // lets go of a light object two carried, a change of mass), the rise made so far reads its own pace.
            bool changed = frame.SteadyTaken && UpdatePace(ref state, frame.SteadyHand - state.Base, state.Time, constants.StandardSpeed);
            if (!(constants.Gain < 1)) return;
            // Recomputed only when the pace or the object changed (PaceGainOf is NaN after a reset).
            if (changed || state.PaceGainOf != constants.LogGain)
            {
                state.PaceGain = Math.Exp(ExponentAt(state.Pace, constants.StandardSpeed) * constants.LogGain);
                state.PaceGainOf = constants.LogGain;
            }
            frame.Gain = state.PaceGain;
        }

        /// <summary>A rise reaches a new top when the steady hand passes the last one by this much, m: tracking jitter at
        /// the end of a lift does not keep the rise going.</summary>
        public const double TopStep = 0.002;

        /// <summary>A rise that pauses before it has climbed this far, m, was a hand at rest a little above the rest band, not a
        /// lift: its pace does not settle, and the next rise starts where it paused and reads its own pace from its first new
        /// top (a creep of a centimetre and a pause would otherwise give a lift of half a metre after it the creep's pace, the
        /// heaviest gain). While the hand rests the pace stays the creep's: changing it there moved the object with the hand
        /// still. Once the climb since the rest band is this much too, it is a very slow lift, and the next rise reads the mean
        /// speed since the band until it has itself climbed this far.</summary>
        public const double MinPacedRise = 0.03;

        /// <summary>With a <see cref="PauseTime"/> longer than this, s (the default pause time), a rise that stands still this long
        /// is remembered, and a hand that rises on from there and comes back down to it gets the pace it had there again: a
        /// heft within the pause time leaves the weight as it was (P13). At 2–5 s without it, a heft 0.6–3 s after a lift read
        /// as the lift going on, slower, and left up to 22 mm of offset (PauseTimeHeftTests).</summary>
        public const double HeftTime = 0.16;

        /// <summary>Steady poses further apart than this, s, had a gap between them (a loss, and the settling after it). Not a
        /// whole number of frames at 30, 60, 72, 90 or 120 Hz, so no common frame clock sits on the boundary.</summary>
        public const double GapTime = 0.11;

        /// <summary>Follows the rise on the steady hand; true when the pace changed.</summary>
        bool UpdatePace(ref HoldState state, double lift, double time, double standardSpeed)
        {
            time -= state.PaceClockSkip; // the rise's clock: the hold's, less the time gaps hid from a rise
            double seenTime = state.PaceSeenTime, seenLift = state.PaceSeenLift;
            state.PaceSeenTime = time;
            state.PaceSeenLift = lift;
            if (lift <= RestBand)
            {
                // At the base: the next rise starts from here.
                state.RiseStartLift = state.RiseTop = state.RiseBandLift = lift;
                state.RiseStartTime = state.RiseTopTime = state.RiseBandTime = time;
                state.PaceSettled = false;
                state.PaceSlowSinceBand = false;
                state.PaceCheckTop = double.NaN;
                return AtRest(ref state);
            }
            if (state.PaceSettled) return false;
            // A rise that stood still for HeftTime (its top remembered) goes on only by MinPacedRise more: jitter at rest over
            // seconds reaches 2 mm above the top, and a top it made would count the whole rest in a slower pace.
            double step = state.RiseTop == state.PaceCheckTop ? MinPacedRise : TopStep;
            if (lift < state.RiseTop + step)
            {
                if (PauseTime > HeftTime)
                {
                    // Back down to where the rise stood still for HeftTime (within the MinPacedRise it takes to go on from there),
                    // after rising on: that was a heft (P13), not the lift going on. The pace, the top and its time are what they
                    // were there.
                    if (state.RiseTop > state.PaceCheckTop && lift < state.PaceCheckTop + MinPacedRise)
                    {
                        state.RiseTop = state.PaceCheckTop;
                        state.RiseTopTime = state.PaceCheckTopTime;
                        if (state.Pace == state.PaceCheckPace) return false;
                        state.Pace = state.PaceCheckPace;
                        return true;
                    }
                    if (double.IsNaN(state.PaceCheckTop) && time - state.RiseTopTime > HeftTime && state.RiseTop - state.RiseStartLift >= MinPacedRise)
                    {
                        state.PaceCheckTop = state.RiseTop;
                        state.PaceCheckTopTime = state.RiseTopTime;
                        state.PaceCheckPace = state.Pace;
                    }
                }
                if (!(time - state.RiseTopTime > PauseTime)) return false;
                if (state.RiseTop - state.RiseStartLift >= MinPacedRise)
                {
                    state.PaceSettled = true;
                    return false;
                }
                // Paused before it rose MinPacedRise: not a lift but a hand at rest a little above the rest band (a creep, a
                // hand resting where jitter no longer reaches the band), or a very slow lift. The next rise starts from here, as
                // from the base, and reads its own pace from its first new top (a fast lift after a few creeps is not given
                // theirs). The pace is not changed here: the hand is at rest, and the object with it (the offset is a function
                // of where the hand is for a given pace; changing it now moved a heavy object at the glide's speed while the
                // hand was still, up to 16 mm over a lift in eight stages: HandAtRestObjectAtRestTests).
                state.RiseStartLift = lift;
                state.RiseStartTime = time;
                // Rises each too slow to climb MinPacedRise before a pause, MinPacedRise in all since the band: a very slow lift,
                // whose pace is its mean speed since the band. From the next new top on, a rise still under MinPacedRise reads
                // that mean, which is what the pace stays at when it pauses. (Started over with no pace, it got the standard's
                // gain: a heavy object lifted 0.2 m in 20 s ended 11 mm above one lifted in 10 s.)
                if (state.RiseTop - state.RiseBandLift >= MinPacedRise) state.PaceSlowSinceBand = true;
                return false;
            }
            if (time - seenTime > GapTime && lift > seenLift)
            {
                // The hand rose while unseen: it got here no later than now; at the rise's pace so far (or, if it had not
                // started, at the user's standard pace) it got here earlier. A gap in tracking must not read as a slow lift.
                double pace = state.Pace > 0 ? state.Pace : standardSpeed / StandardLiftRatio;
                double reached = seenTime + (lift - seenLift) / pace;
                if (reached < time)
                {
                    state.PaceClockSkip += time - reached;
                    state.PaceSeenTime = time = reached;
                }
            }
            state.RiseTop = lift;
            state.RiseTopTime = time;
            // The mean speed from where the rise left the base to its top: a function of the two ends. At least one 60 Hz
            // pose period of time.
            // A very slow lift (PaceSlowSinceBand) whose current rise is still under MinPacedRise: the mean since the band.
            double mean = state.PaceSlowSinceBand && lift - state.RiseStartLift < MinPacedRise
                ? MeanSpeed(lift - state.RiseBandLift, time - state.RiseBandTime)
                : MeanSpeed(lift - state.RiseStartLift, time - state.RiseStartTime);
            if (mean == state.Pace) return false;
            state.Pace = mean;
            return true;
        }

        /// <summary>A rise's mean speed, m/s, over at least one 60 Hz pose period of time (the span is never NaN: clock times;
        /// a comparison, not Math.Max's call).</summary>
        static double MeanSpeed(double rise, double span) => rise / (span > 1.0 / 60 ? span : 1.0 / 60);

        /// <summary>The hand is at rest: no rise, no pace. True when the pace changed.</summary>
        static bool AtRest(ref HoldState state)
        {
            if (state.Pace == 0) return false;
            state.Pace = 0;
            return true;
        }

        protected internal override void Reset(ref HoldState state, double handY)
        {
            state.Pace = 0;
            state.PaceGain = 0;
            state.PaceGainOf = double.NaN;
            state.RiseStartLift = state.RiseTop = 0;
            state.PaceClockSkip = 0;
            state.RiseBandLift = 0;
            state.RiseStartTime = state.RiseTopTime = state.RiseBandTime = state.PaceSeenTime = state.Time;
            state.PaceSeenLift = 0;
            state.PaceSettled = false;
            state.PaceSlowSinceBand = false;
            state.PaceCheckTop = double.NaN;
            state.PaceCheckTopTime = state.PaceCheckPace = 0;
        }
    }
}
