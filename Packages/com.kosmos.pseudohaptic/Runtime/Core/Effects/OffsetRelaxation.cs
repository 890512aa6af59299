using System;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// Off in the paper's experiments (design note, open question 4): while the hand is still, a held
    /// offset relaxes toward zero with time constant <see cref="TimeConstant"/>. "Still" is relative to the
    /// user: hand speed below <see cref="StillFraction"/> × v_std.
    /// </summary>
    public sealed class OffsetRelaxation : WeightEffect
    {
        public override string Name => "offset-relaxation";
        public override EffectStage Stage => EffectStage.ObjectMotion;

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
            double after = frame.HandAfter - frame.ObjectY - frame.TotalDelta;
            // dt/(τ+dt) ≈ 1 − e^(−dt/τ) without an exponential per frame; never overshoots.
            double relax = after * dt / (TimeConstant + dt);
            frame.ObjectDelta += relax;
            SpeedCap.Settle(ref state, relax);
        }
    }
}
