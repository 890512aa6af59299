using System;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// A person does not lift 5 kg as fast as a golf ball (design note, open question 2): an object heavier than
    /// the standard moves no faster than the experimental speed of its mass rescaled to this user,
    /// v_cap = headroom · v_std · v_exp(m)/v_exp(m_std). The standard weight and lighter objects are not capped (the
    /// golf ball is rigid in the hand, P1). The default headroom 2.5 clears the peak of a smooth lift at the
    /// user's standard speed (1.875 × its mean speed) with room for jittery poses.
    /// Capped motion is deferred, not lost: the object keeps rising at v_cap after the hand stops until it has
    /// made up what the cap held back (at most <see cref="SolverLimits.MaxCarry"/>), so a faster lift never ends
    /// lower than a slower one (the cap never reverses <see cref="FasterMovesFurther"/>). Motion of the hand in
    /// the other direction cancels what is owed; the lowering guard and the floor drop it when they bind. The cap is a budget refilled at v_cap × frame time and saved for at most
    /// 50 ms, so a 30 Hz pose under 120 Hz frames spends the budget of the frames that showed no new pose and
    /// the object's mean speed never exceeds v_cap on any frame clock.
    /// </summary>
    public sealed class SpeedCap : WeightEffect
    {
        public override string Name => "speed-cap";
        public override EffectStage Stage => EffectStage.ObjectMotion;

        /// <summary>Multiple of the user's rescaled experimental speed allowed, ≥ 1.</summary>
        public double Headroom { get; }

        public SpeedCap(double headroom = 2.5)
        {
            Headroom = ConfigurationGuard.InRange(headroom, 1, 100, nameof(headroom));
        }

        /// <summary>The cap for an object and a user, m/s: infinite for the standard weight and lighter objects.</summary>
        public double CapFor(WeightModel model, double standardSpeed)
            => model.MassKg > PhysicalConstants.StandardMassKg ? Headroom * standardSpeed * model.ExperimentalRatio : double.PositiveInfinity;

        protected internal override void Apply(ref MotionFrame frame, ref HoldState state, in SolverConstants constants)
        {
            double cap = constants.CapSpeed;
            if (!(cap < double.PositiveInfinity)) return;
            double budget = state.CapBudget + cap * frame.Dt, most = cap * SolverLimits.JumpWindow;
            if (budget > most) budget = most;

            double deferred = state.CapDeferred;
            double wanted = frame.ObjectDelta + deferred; // a hand that turns back cancels what it is owed
            double step = wanted > budget ? budget : (wanted < -budget ? -budget : wanted);
            frame.ObjectDelta = step;
            budget -= step < 0 ? -step : step;
            deferred = wanted - step;
            double limit = constants.Limits.MaxCarry;
            state.CapDeferred = deferred > limit ? limit : (deferred < -limit ? -limit : deferred);
            state.CapBudget = budget;
        }

        protected internal override void Reset(ref HoldState state, double handY)
        {
            state.CapDeferred = 0;
            state.CapBudget = 0;
        }
    }
}
