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
        /// <summary>This effect's name, stage, summary and settings (<see cref="EffectRegistry"/>).</summary>
        public static readonly EffectDescriptor Descriptor = new EffectDescriptor("offset-relaxation", EffectStage.Base, typeof(OffsetRelaxation),
            "design note, open question 4 (off in the paper)",
            "while the hand is still, the lift (and with it the offset) relaxes toward zero",
            s => new OffsetRelaxation(s[0], s[1]),
            SettingDescriptor.Number<OffsetRelaxation>("timeConstant", "s", 1.5, 0.01, 1000, "time constant of the relaxation", e => e.TimeConstant),
            SettingDescriptor.Number<OffsetRelaxation>("stillFraction", "× v_std", 0.1, 0, 10, "the hand is still below this fraction of the user's standard speed", e => e.StillFraction));

        public override string Name => Descriptor.Name;
        public override EffectStage Stage => Descriptor.Stage;

        public double TimeConstant { get; }
        public double StillFraction { get; }

        public OffsetRelaxation(double timeConstant = 1.5, double stillFraction = 0.1)
        {
            TimeConstant = Descriptor.Settings[0].Check(timeConstant);
            StillFraction = Descriptor.Settings[1].Check(stillFraction);
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
