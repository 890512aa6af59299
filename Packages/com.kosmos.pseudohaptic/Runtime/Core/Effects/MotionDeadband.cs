using System;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// A motion deadband (backlash) on the hand: the followed hand height moves only when the tracked hand
    /// leaves a band of ±width around it, so millimetre tracking jitter at rest moves nothing (P4) while
    /// real motion passes with a constant, small lead-in. The width is tied to the user's speed
    /// (design note, open question 2): width = v_std × <see cref="LagTime"/>, i.e. the deadband costs
    /// <see cref="LagTime"/> of lag to a hand moving at the user's standard speed, but never less than
    /// <see cref="MinWidth"/>, the jitter of a tracked hand at rest. Later effects see the deadbanded hand.
    /// </summary>
    public sealed class MotionDeadband : WeightEffect
    {
        public override string Name => "motion-deadband";
        public override EffectStage Stage => EffectStage.HandMotion;

        /// <summary>Lag the deadband may cost at the user's standard speed, s.</summary>
        public double LagTime { get; }

        /// <summary>The band is never narrower than this, m: Quest 2 hand jitter at rest is a few millimetres
        /// whoever the user is, and a light object multiplies it by up to the gain cap.</summary>
        public double MinWidth { get; }

        public MotionDeadband(double lagTime = 0.006, double minWidth = 0.004)
        {
            LagTime = ConfigurationGuard.InRange(lagTime, 0, 0.1, nameof(lagTime));
            MinWidth = ConfigurationGuard.InRange(minWidth, 0, 0.05, nameof(minWidth));
        }

        /// <summary>The band's half-width for a user, m: max(v_std × lag time, minimum width).</summary>
        public double WidthFor(double standardSpeed) => Math.Max(LagTime * standardSpeed, MinWidth);

        protected internal override void Apply(ref MotionFrame frame, ref HoldState state, in SolverConstants constants)
        {
            double w = constants.DeadbandWidth, h = frame.HandAfter, r = state.DeadbandReference;
            double next = r < h - w ? h - w : (r > h + w ? h + w : r);
            // Later effects see the deadbanded hand: jitter the band swallowed is not hand motion to them either.
            frame.HandBefore = r;
            frame.HandAfter = next;
            frame.HandDelta = next - r;
            state.DeadbandReference = next;
        }

        protected internal override void Reset(ref HoldState state, double handY) => state.DeadbandReference = handY;
    }
}
