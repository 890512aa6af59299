using System;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// Off in the paper's experiments (design note, open question 4): while the hand is still, the lift relaxes toward
    /// zero with time constant <see cref="TimeConstant"/> (the base rises toward the hand, dt/(τ+dt) of the way per frame:
    /// no exponential, never overshoots), so a held offset fades. Where the offset correction holds the offset at its
    /// ceiling, the visible offset starts to fade once the lift has relaxed below the ceiling's reach. "Still" is
    /// relative to the user: hand speed below <see cref="StillFraction"/> × v_std, the speed being the steady hand's mean
    /// over the last <see cref="StillWindow"/> to twice that (not the pose-to-pose speed: Quest's 1–3 mm of jitter at 30 Hz
    /// reads 0.06–0.13 m/s from one pose to the next, above 0.1 × v_std, and slowed the relaxation to a time constant of
    /// 2–3 τ; OffsetRelaxationJitterTests).
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

        /// <summary>The shortest span the hand's stillness is judged over, s (the span runs from this to twice this): over it,
        /// millimetres of jitter read a few mm/s, while a pose-to-pose speed reads them ×30. Not a whole number of pose periods
        /// at 30 or 60 Hz, so no common pose clock sits on the boundary.</summary>
        public const double StillWindow = 0.21;

        protected internal override void Apply(ref MotionFrame frame, ref HoldState state, in SolverConstants constants)
        {
            if (frame.SteadyTaken) FollowSteadyHand(ref state, frame.SteadyHand, state.Time);
            if (Math.Abs(state.RelaxSpeed) >= StillFraction * constants.StandardSpeed) return;
            double dt = Math.Min(frame.Dt, constants.Limits.MaxFrameTime);
            double relax = frame.Lift * dt / (TimeConstant + dt);
            state.Base += relax;
            frame.Lift -= relax;
        }

        /// <summary>The steady hand's mean speed from the window's start (<see cref="StillWindow"/> to twice that ago) to now;
        /// the window moves on every <see cref="StillWindow"/>. The steady hand is the median of three poses: a one-pose glitch
        /// never reaches it.</summary>
        static void FollowSteadyHand(ref HoldState state, double y, double time)
        {
            if (time - state.RelaxMidTime >= StillWindow)
            {
                state.RelaxFromY = state.RelaxMidY;
                state.RelaxFromTime = state.RelaxMidTime;
                state.RelaxMidY = y;
                state.RelaxMidTime = time;
            }
            double span = time - state.RelaxFromTime;
            state.RelaxSpeed = span > 0 ? (y - state.RelaxFromY) / span : 0;
        }

        protected internal override void Reset(ref HoldState state, double handY)
        {
            state.RelaxFromY = state.RelaxMidY = handY;
            state.RelaxFromTime = state.RelaxMidTime = state.Time;
            state.RelaxSpeed = 0;
        }
    }
}
