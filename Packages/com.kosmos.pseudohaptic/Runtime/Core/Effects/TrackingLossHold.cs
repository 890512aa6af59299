namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// Headset hygiene, not in the paper: a low-confidence pose counts as lost (Quest drops confidence routinely in
    /// fast motion). A short loss, up to <see cref="SolverLimits.MaxCatchUpGap"/>, is bridged: the object holds, and
    /// when a usable pose comes back it catches up G × the hand's displacement across the loss through the speed
    /// limit (only a pose no hand could have reached is rejected, by the estimator). After a longer loss the
    /// object stays where it is until tracking has been steady for <see cref="SettleTime"/>, then follows the
    /// hand from where it is (re-anchors): the first poses after reacquiring a hand are often off by centimetres.
    /// </summary>
    public sealed class TrackingLossHold : WeightEffect
    {
        public override string Name => "tracking-loss-hold";
        public override EffectStage Stage => EffectStage.Input;

        /// <summary>Steady tracking required after a long loss before the object follows again, s.</summary>
        public double SettleTime { get; }

        /// <summary>Whether a tracked but low-confidence pose counts as lost.</summary>
        public bool RequireHighConfidence { get; }

        public TrackingLossHold(double settleTime = 0.1, bool requireHighConfidence = true)
        {
            SettleTime = ConfigurationGuard.InRange(settleTime, 0, 5, nameof(settleTime));
            RequireHighConfidence = requireHighConfidence;
        }

        protected internal override void Apply(ref MotionFrame frame, ref HoldState state, in SolverConstants constants)
        {
            if (!frame.Usable || (RequireHighConfidence && !frame.IsHighConfidence))
            {
                frame.Usable = false;
                state.LostFor += frame.Dt;
                // A long loss: settling starts over when the hand comes back. A short one is bridged.
                if (state.LostFor > constants.Limits.MaxCatchUpGap) state.SettleElapsed = 0;
                return;
            }
            state.LostFor = 0;
            if (state.SettleElapsed < 0) return; // settled: a short loss is caught up by the estimator
            state.SettleElapsed += frame.Dt;
            if (state.SettleElapsed < SettleTime)
            {
                frame.Usable = false;
                return;
            }
            // Stryker disable once Unary : the re-anchoring forced below resets every effect, this one to −1 too
            state.SettleElapsed = -1;
            // Stryker disable once Boolean : withheld past the catch-up gap, the estimator would re-anchor by itself too; said here, not relied on
            frame.ForceReanchor = true;
        }

        protected internal override void Reset(ref HoldState state, double handY)
        {
            state.SettleElapsed = -1;
            state.LostFor = 0;
        }
    }
}
