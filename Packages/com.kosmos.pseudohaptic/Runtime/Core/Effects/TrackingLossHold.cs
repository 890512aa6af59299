namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// Headset hygiene, not in the paper: a low-confidence pose counts as lost, and after a loss the object
    /// stays where it is until tracking has been steady for <see cref="SettleTime"/>, then follows the hand
    /// from where it is (re-anchors). Quest's first poses after reacquiring a hand are often off by
    /// centimetres; following them would shake the object. Without this effect the solver still holds the
    /// object during a loss and re-anchors after a long one; it just trusts every tracked pose at once.
    /// </summary>
    public sealed class TrackingLossHold : WeightEffect
    {
        public override string Name => "tracking-loss-hold";
        public override EffectStage Stage => EffectStage.Input;

        /// <summary>Steady tracking required after a loss before the object follows again, s.</summary>
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
                state.SettleElapsed = 0; // settling starts over when the hand comes back
                return;
            }
            if (state.SettleElapsed < 0) return; // settled
            state.SettleElapsed += frame.Dt;
            if (state.SettleElapsed < SettleTime)
            {
                frame.Usable = false;
                return;
            }
            state.SettleElapsed = -1;
            frame.ForceReanchor = true;
        }

        protected internal override void Reset(ref HoldState state, double handY) => state.SettleElapsed = -1;
    }
}
