namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// Headset hygiene, not in the paper: poses the headset is unsure of are followed but not remembered
    /// (<see cref="MotionFrame.Settling"/>): a low-confidence pose (Quest drops confidence routinely in fast motion), and
    /// every pose for <see cref="SettleTime"/> after tracking was lost or unsure (the first poses after reacquiring a hand
    /// are often centimetres off). The object stays with the hand the user sees, since the weight is a function of where
    /// the hand is and a wrong pose leaves nothing once it is gone; but such poses never move what the hold remembers (the
    /// base the lift is measured from, the lift's pace). While tracking is lost the object stays where it is; when a
    /// usable pose comes back the object is where the weight puts it for the hand's new place (the estimator bridges the
    /// gap: the hand's motion across it is real motion).
    /// </summary>
    public sealed class TrackingLossHold : WeightEffect
    {
        /// <summary>This effect's name, stage, summary and settings (<see cref="EffectRegistry"/>).</summary>
        public static readonly EffectDescriptor Descriptor = new EffectDescriptor("tracking-loss-hold", EffectStage.Input, typeof(TrackingLossHold),
            "headset hygiene (not in the paper)",
            "a low-confidence pose, and every pose for the settle time after a loss, is followed but never moves what the hold remembers (the base, the pace)",
            s => new TrackingLossHold(s[0], s.Flag(1)),
            SettingDescriptor.Number<TrackingLossHold>("settleTime", "s", DefaultSettleTime, 0, 5, "steady tracking required after a loss before poses count toward what the hold remembers", e => e.SettleTime),
            SettingDescriptor.Boolean<TrackingLossHold>("requireHighConfidence", true, "a tracked but low-confidence pose is kept from what the hold remembers", e => e.RequireHighConfidence));

        public override string Name => Descriptor.Name;
        public override EffectStage Stage => Descriptor.Stage;

        /// <summary>
        /// The default settle time, s: a re-acquisition snap as the simulated Quest renders it (the poses sampled in the 0.1 s
        /// after tracking comes back are centimetres off, and each is shown 45 ms late) is on screen until about 0.16 s after
        /// the first pose back; a shorter settle time let two of its three poses into the steady hand, which the base follows
        /// down. Over 20,000 generated single lifts and 19,905 paths of several moves (ArtifactCensus, FsCheck) the holds
        /// beyond issue 22's rule 1 went from 19 and 143 at 0.11 s (119 of the latter snaps) to 13 and 39.
        /// </summary>
        public const double DefaultSettleTime = 0.16;

        /// <summary>Steady tracking required after a loss before poses count toward what the hold remembers, s.</summary>
        public double SettleTime { get; }

        /// <summary>Whether a tracked but low-confidence pose is kept from what the hold remembers.</summary>
        public bool RequireHighConfidence { get; }

        public TrackingLossHold(double settleTime = DefaultSettleTime, bool requireHighConfidence = true)
        {
            SettleTime = Descriptor.Settings[0].Check(settleTime);
            RequireHighConfidence = requireHighConfidence;
        }

        protected internal override void Apply(ref MotionFrame frame, ref HoldState state, in SolverConstants constants)
        {
            if (!frame.Usable)
            {
                state.LostFor += frame.Dt;
                state.SettleElapsed = 0; // settling starts over when the hand comes back
                return;
            }
            if (RequireHighConfidence && !frame.IsHighConfidence)
            {
                frame.Settling = true;
                state.SettleElapsed = 0;
                return;
            }
            state.LostFor = 0;
            if (state.SettleElapsed < 0) return; // settled
            state.SettleElapsed += frame.Dt;
            if (state.SettleElapsed < SettleTime) frame.Settling = true;
            else state.SettleElapsed = -1;
        }

        /// <summary>Settled (which a usable frame leaves not lost): the same sample again changes nothing. While settling,
        /// each frame counts toward it.</summary>
        protected internal override bool IsStill(in HoldState state, in SolverConstants constants) => state.SettleElapsed < 0;

        protected internal override void Reset(ref HoldState state, double handY)
        {
            state.SettleElapsed = -1;
            state.LostFor = 0;
        }
    }
}
