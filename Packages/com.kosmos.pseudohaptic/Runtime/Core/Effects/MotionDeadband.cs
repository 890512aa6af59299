namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// A motion deadband (backlash) on the hand: the followed hand height moves only when the tracked hand
    /// leaves a band of ±width around it, so millimetre tracking jitter at rest moves nothing (P4) while
    /// real motion passes with a constant, small lead-in. The width is tied to the user's speed
    /// (design note, open question 2): width = v_std × <see cref="LagTime"/>, i.e. the deadband never costs
    /// more than <see cref="LagTime"/> of lag to a hand moving at the user's standard speed.
    /// </summary>
    public sealed class MotionDeadband : WeightEffect
    {
        public override string Name => "motion-deadband";
        public override EffectStage Stage => EffectStage.HandMotion;

        /// <summary>Lag the deadband may cost at the user's standard speed, s.</summary>
        public double LagTime { get; }

        public MotionDeadband(double lagTime = 0.006)
        {
            LagTime = ConfigurationGuard.InRange(lagTime, 0, 0.1, nameof(lagTime));
        }

        /// <summary>The band's half-width for a user, m.</summary>
        public double WidthFor(double standardSpeed) => LagTime * standardSpeed;

        protected internal override void Apply(ref MotionFrame frame, ref HoldState state, in SolverConstants constants)
        {
            double w = constants.DeadbandWidth, h = frame.HandAfter, r = state.DeadbandReference;
            double next = r < h - w ? h - w : (r > h + w ? h + w : r);
            frame.HandDelta = next - r;
            state.DeadbandReference = next;
        }

        protected internal override void Reset(ref HoldState state, double handY) => state.DeadbandReference = handY;
    }
}
