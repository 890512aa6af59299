using System;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// Son et al. 2022, §3.1: "even if we moved our hands at the same height when lifting two virtual objects with
    /// the same weight, ... the movement of the two fast-moving virtual objects was greater". A gain that is
    /// constant in speed cannot keep that rule, and in it the user's standard speed v_std would cancel. For an
    /// object heavier than the standard (G &lt; 1) the gain on each pose's displacement is
    /// <code>G_v = G^r,  r = clamp(1/√x, <see cref="FastExponent"/>, <see cref="SlowExponent"/>),  x = v / v_std</code>
    /// where v is the hand's speed over the pose: at the user's standard speed r = 1 (the gain of Eq. 4–6);
    /// faster, r &lt; 1 and the gain moves toward 1 (the object moves further); slower, r &gt; 1 and it moves away
    /// from 1. Bounded both ways (G^SlowExponent ≤ G_v ≤ G^FastExponent &lt; 1: never a jitter amplifier),
    /// continuous in v, and monotone in G at every speed (heavier still lags more, P2). The standard weight
    /// (G = 1) and lighter objects are untouched. v is judged on a hand that follows the pose only once it leaves a
    /// ±<see cref="RestBand"/> band, so tracking jitter at rest reads as speed 0 (the slow end, a constant gain):
    /// jitter back and forth then cancels exactly instead of walking the object away.
    /// </summary>
    public sealed class FasterMovesFurther : WeightEffect
    {
        public override string Name => "faster-moves-further";
        public override EffectStage Stage => EffectStage.ObjectMotion;

        /// <summary>The exponent r for a hand much faster than v_std (r ≤ 1): G^r is the largest gain.</summary>
        public double FastExponent { get; }

        /// <summary>The exponent r for a hand much slower than v_std, and at rest (r ≥ 1).</summary>
        public double SlowExponent { get; }

        /// <summary>Half-width of the band that keeps jitter at rest from reading as speed, m.</summary>
        public double RestBand { get; }

        /// <summary>Time constant over which the hand's pace is smoothed, s.</summary>
        public double SmoothingTime { get; }

        /// <summary>
        /// Hand travel over which <see cref="HoldState.HeldPace"/> forgets a faster pace, m. The held pace rises at once to
        /// the smoothed pace and falls toward it in proportion to the distance the (band-followed) hand travels, never with
        /// time: a resting hand keeps the pace of its latest motion.
        /// </summary>
        public double ReleaseDistance { get; }

        public FasterMovesFurther(double fastExponent = 0.5, double slowExponent = 1.5, double restBand = 0.005, double smoothingTime = 0.1,
            double releaseDistance = 0.2)
        {
            ReleaseDistance = ConfigurationGuard.InRange(releaseDistance, 0.001, 10, nameof(releaseDistance));
            SmoothingTime = ConfigurationGuard.InRange(smoothingTime, 0, 1, nameof(smoothingTime));
            FastExponent = ConfigurationGuard.InRange(fastExponent, 0.01, 1, nameof(fastExponent));
            SlowExponent = ConfigurationGuard.InRange(slowExponent, 1, 10, nameof(slowExponent));
            RestBand = ConfigurationGuard.InRange(restBand, 0, 0.05, nameof(restBand));
        }

        /// <summary>The exponent r at hand speed <paramref name="speed"/> for a user of standard speed <paramref name="standardSpeed"/>.</summary>
        public double ExponentAt(double speed, double standardSpeed)
        {
            double x = Math.Abs(speed) / standardSpeed;
            // r = 1/√x, clamped: x ≤ 1/SlowExponent² reads as slow, x ≥ 1/FastExponent² as fast.
            if (!(x * SlowExponent * SlowExponent > 1)) return SlowExponent;
            double r = 1 / Math.Sqrt(x);
            return Math.Max(r, FastExponent);
        }

        /// <summary>The gain G_v for an object of gain <paramref name="gain"/> at hand speed <paramref name="speed"/>.</summary>
        public double GainAt(double gain, double speed, double standardSpeed)
            => gain < 1 ? Math.Exp(ExponentAt(speed, standardSpeed) * Math.Log(gain)) : gain; // gain 0: e^(−∞) = 0

        protected internal override void Apply(ref MotionFrame frame, ref HoldState state, in SolverConstants constants)
        {
            double h = frame.HandAfter, r = state.PaceReference, w = RestBand;
            double next = Math.Min(Math.Max(r, h - w), h + w);
            state.PaceReference = next;
            if (!(constants.Gain < 1)) return;
            // The hand's pace: the band-follower's speed over each new pose, smoothed over about SmoothingTime
            // (exponentially, per pose, so every frame clock sees the same pace), so one pose's jitter barely moves
            // the gain and lifts repeated for hours do not random-walk.
            double interval = frame.MotionInterval;
            if (interval > 0)
            {
                double a = interval / (SmoothingTime + interval);
                state.Pace += a * ((next - r) / interval - state.Pace);
                double pace = Math.Abs(state.Pace);
                bool faster = pace >= state.HeldPace;
                double share = Math.Min(Math.Abs(next - r) / ReleaseDistance, 1);
                state.HeldPace = faster ? pace : state.HeldPace + share * (pace - state.HeldPace);
            }
            double exponent = ExponentAt(state.Pace, constants.StandardSpeed);
            double g = Math.Exp(exponent * constants.LogGain); // G = 0: log G = −∞, g = 0
            frame.ObjectDelta += (g - constants.Gain) * frame.HandDelta;
        }

        protected internal override void Reset(ref HoldState state, double handY)
        {
            state.PaceReference = handY;
            state.Pace = 0;
            state.HeldPace = 0;
        }
    }
}
