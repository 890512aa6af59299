using System;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// Off in the paper's experiments (design note, open question 4): while the hand is still, the lift relaxes toward
    /// zero with time constant <see cref="TimeConstant"/> (the base rises toward the hand, dt/(τ+dt) of the way per frame:
    /// no exponential, never overshoots), so a held offset fades. Where the offset correction holds the offset at its
    /// ceiling, the visible offset starts to fade once the lift has relaxed below the ceiling's reach. "Still" is
    /// relative to the user: hand speed below <see cref="StillFraction"/> × v_std.
    /// </summary>
    public sealed class OffsetRelaxation : WeightEffect
    {
        public override string Name => "offset-relaxation";
        public override EffectStage Stage => EffectStage.Base;

        public double TimeConstant { get; }
        public double StillFraction { get; }

        public OffsetRelaxation(double timeConstant = 1.5, double stillFraction = 0.1)
        {
            TimeConstant = ConfigurationGuard.InRange(timeConstant, 0.01, 1000, nameof(timeConstant));
            StillFraction = ConfigurationGuard.InRange(stillFraction, 0, 10, nameof(stillFraction));
        }

        protected internal override void Apply(ref MotionFrame frame, ref HoldState state, in SolverConstants constants)
        {
            if (Math.Abs(state.Estimator.Speed) >= StillFraction * constants.StandardSpeed) return;
            double dt = Math.Min(frame.Dt, constants.Limits.MaxFrameTime);
            double relax = frame.Lift * dt / (TimeConstant + dt);
            state.Base += relax;
            frame.Lift -= relax;
        }
    }
}
