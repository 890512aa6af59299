using System;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// A person does not lift 5 kg as fast as a golf ball (design note, open question 2): an object heavier than the
    /// standard can be moved no faster than the experimental speed of its mass rescaled to this user,
    /// v_cap = headroom · v_std · v_exp(m)/v_exp(m_std). The standard weight and lighter objects are not capped. The default
    /// headroom 2.5 clears the peak of a smooth lift at the user's standard speed (1.875 × its mean speed) with room for
    /// jittery poses. What the hand pulls beyond that is the hold's <see cref="HoldState.Strain"/>: the distance between
    /// where the weight puts the object and where an object following it at no more than v_cap would be (a follower with
    /// an allowance of one pose's worth of motion, <see cref="BurstTime"/>, so every frame clock gives the same strain). The
    /// object the user sees is not held back: one held back would have to catch up after the hand stopped, moving while
    /// the hand does not (issue 22); the strain is what a yank does, and <see cref="BreakAway"/> measures it under the
    /// offset correction. What tracking hid (the hand's motion across a loss) is not strain.
    /// </summary>
    public sealed class SpeedCap : WeightEffect
    {
        /// <summary>This effect's name, stage, summary and settings (<see cref="EffectRegistry"/>).</summary>
        public static readonly EffectDescriptor Descriptor = new EffectDescriptor("speed-cap", EffectStage.Position, typeof(SpeedCap),
            "design note, open question 2",
            "measures the strain: how far the hand pulls beyond a follower moving at most the user's rescaled experimental speed; never moves the object",
            s => new SpeedCap(s[0]),
            SettingDescriptor.Number<SpeedCap>("headroom", "× v_exp", 2.5, 1, 100, "multiple of the user's rescaled experimental speed allowed", e => e.Headroom));

        public override string Name => Descriptor.Name;
        public override EffectStage Stage => Descriptor.Stage;

        /// <summary>The motion allowed in one go: this much time at v_cap, s (a 30 Hz pose's interval and a half).</summary>
        public const double BurstTime = 0.05;

        /// <summary>Multiple of the user's rescaled experimental speed allowed, ≥ 1.</summary>
        public double Headroom { get; }

        public SpeedCap(double headroom = 2.5)
        {
            Headroom = Descriptor.Settings[0].Check(headroom);
        }

        /// <summary>The cap for an object and a user, m/s: infinite for the standard weight and lighter objects.</summary>
        public double CapFor(WeightModel model, double standardSpeed)
            => model.MassKg > PhysicalConstants.StandardMassKg ? Headroom * standardSpeed * model.ExperimentalRatio : double.PositiveInfinity;

        protected internal override void Apply(ref MotionFrame frame, ref HoldState state, in SolverConstants constants)
        {
            double cap = constants.CapSpeed, target = frame.NewObjectY;
            if (!(cap < double.PositiveInfinity) || !state.CapStarted)
            {
                // Uncapped (the standard weight and lighter), or the first frame: no strain.
                state.CappedY = state.CapTarget = target;
                state.CapBudget = 0;
                state.Strain = 0;
                state.CapStarted = cap < double.PositiveInfinity;
                return;
            }
            double burst = cap * BurstTime;
            if (target == state.CappedY && state.CapBudget == burst && !frame.Bridged)
            {
                // Caught up with the budget full (most frames): exactly what the lines below would leave, the move being
                // the ±0 the follower wants (added as they add it: a −0 becomes +0).
                state.CappedY += target - state.CappedY;
                state.CapTarget = target;
                state.Strain = 0;
                return;
            }
            // What tracking hid moves the follower as it moves the object: the strain stays as it was.
            if (frame.Bridged) state.CappedY += target - state.CapTarget;
            state.CapTarget = target;
            double budget = Refilled(state.CapBudget, cap, frame.Dt, constants);
            double want = target - state.CappedY;
            double move = want > budget ? budget : (want < -budget ? -budget : want);
            state.CappedY += move;
            state.CapBudget = budget - Math.Abs(move);
            state.Strain = Math.Abs(target - state.CappedY);
        }

        /// <summary>Caught up (an uncapped follower always is): the same target again wants a move of 0, and only the
        /// budget refills (<see cref="AdvanceStill"/>; a follower at −0 would turn +0 there, which nothing reads).</summary>
        protected internal override bool IsStill(in HoldState state, in SolverConstants constants) => state.CappedY == state.CapTarget;

        protected internal override bool AdvancesWhenStill => true;

        /// <summary>Caught up, the budget refills as <see cref="Apply"/> refills it (a full one stays full).</summary>
        protected internal override void AdvanceStill(ref HoldState state, in SolverConstants constants, double dt)
        {
            double cap = constants.CapSpeed;
            if (cap < double.PositiveInfinity)
                state.CapBudget = Refilled(state.CapBudget, cap, dt, constants);
        }

        /// <summary>The follower's budget after <paramref name="dt"/> s at v_cap: at most one burst.</summary>
        static double Refilled(double budget, double cap, double dt, in SolverConstants constants)
            => Math.Min(budget + cap * Math.Min(dt, constants.Limits.MaxFrameTime), cap * BurstTime);

        protected internal override void Reset(ref HoldState state, double handY)
        {
            state.CapStarted = false;
            state.Strain = 0;
        }
    }
}
