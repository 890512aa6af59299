namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// The paper covers lifting only (design note, open question 4). The lift is measured from the lowest place the
    /// hand has rested at: when the hand goes below the base, the base follows it down (to <see cref="Slack"/> above the
    /// steady hand), and below the base the object moves with the hand. So a heavy object the hand lowers follows it
    /// down instead of hanging above it, a light one does not dive below it, and the next lift is weighed from where it
    /// starts. The base follows the steady hand (<see cref="MotionFrame.SteadyHand"/>, the median of three poses), so a
    /// one-pose glitch down never moves it; the slack keeps tracking jitter at rest from walking it down. A glitch of two to
    /// four poses passes the median, so a hand back up within the slack of where the base was five steady poses ago undoes
    /// what took the base down since: such a glitch, or a dip that came straight back, lowers nothing (a base measured anew
    /// from where the hand rests, <see cref="MotionFrame.BaseMeasured"/>, is no such dip). A motion that goes up and comes
    /// back never moves the base, so it leaves no trace.
    /// </summary>
    public sealed class LoweringGuard : WeightEffect
    {
        /// <summary>This effect's name, stage, summary and settings (<see cref="EffectRegistry"/>).</summary>
        public static readonly EffectDescriptor Descriptor = new EffectDescriptor("lowering-guard", EffectStage.Base, typeof(LoweringGuard),
            "design note, open question 4",
            "the lift's base follows the steady hand down: lowered below it, the object moves with the hand, and the next lift is weighed from where it starts",
            s => new LoweringGuard(s[0]),
            SettingDescriptor.Number<LoweringGuard>("slack", "m", 0.005, 0, 0.1, "how far below the base the steady hand may go before the base follows", e => e.Slack));

        public override string Name => Descriptor.Name;
        public override EffectStage Stage => Descriptor.Stage;
        /// <summary>The base follows the steady hand, which only a new pose moves.</summary>
        protected internal override bool IsFunctionOfHand => true;

        /// <summary>How far below the base the steady hand may go before the base follows, m (tracking jitter at rest is
        /// not lowering).</summary>
        public double Slack { get; }

        public LoweringGuard(double slack = 0.005)
        {
            Slack = Descriptor.Settings[0].Check(slack);
        }

        protected internal override void Reset(ref HoldState state, double handY)
            => state.GuardBase1 = state.GuardBase2 = state.GuardBase3 = state.GuardBase4 = state.GuardBase5 = handY;

        protected internal override void Apply(ref MotionFrame frame, ref HoldState state, in SolverConstants constants)
        {
            // After a gap, or poses not remembered (the steady hand's window starts over), where the base was before it says
            // nothing of a glitch after it: a hand found higher after a lowering did not dip, the gap hid its way back up.
            // Nor does it once the base has been measured anew from where the hand rests (a base taken down from a glitched grab
            // pose is not a dip to undo).
            if (frame.Bridged || frame.Settling || frame.BaseMeasured) Reset(ref state, state.Base);
            if (frame.SteadyTaken)
            {
                double floor = frame.SteadyHand + Slack, ago = state.GuardBase5;
                if (floor < state.Base) state.Base = floor;
                else if (state.Base < ago - Slack && floor >= ago - Slack)
                {
                    // Back up within the slack of where the base was five steady poses ago: what took it down since was a
                    // glitch of two to four poses (which the median of three passes) or a dip that came straight back, not
                    // a lowering. A base left there would keep the glitch as weight for the rest of the hold, (G − 1) × its
                    // depth.
                    state.Base = floor < ago ? floor : ago;
                }
                state.GuardBase5 = state.GuardBase4;
                state.GuardBase4 = state.GuardBase3;
                state.GuardBase3 = state.GuardBase2;
                state.GuardBase2 = state.GuardBase1;
                state.GuardBase1 = state.Base;
            }
            double lift = frame.WeightHand - state.Base;
            frame.Lift = lift > 0 ? lift : 0;
        }
    }
}
