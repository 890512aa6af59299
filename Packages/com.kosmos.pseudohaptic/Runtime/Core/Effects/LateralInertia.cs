using System;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// The paper's named next step (§9, Conclusions): "speed deceleration according to the movement in the xyz direction".
    /// In <see cref="WeightSolver3D"/>, an object heavier than the standard trails the hand's horizontal (x/z)
    /// motion: its horizontal lag e (a vector, from where it was grabbed) takes each frame's displacement Δ of the steady
    /// hand (the median of its last three poses) and relaxes as e ← (e + Δ) · τ/(τ + dt·(1 + |e + Δ|/M)), with
    /// τ(m) = <see cref="TimeConstant"/> · w(m), w(m) = 1 − min(G(m), 1) (0 for the standard weight and lighter, which
    /// follow exactly) and M = <see cref="MaxOffset"/>; the object shows the lag M·tanh(|e|/M) in e's direction. The
    /// factor lies in [0, 1): no overshoot past the hand, no oscillation. The decay is faster the further e is past M, so
    /// the lag a fast swing builds is gone within a second of the hand stopping, and the shown lag approaches M smoothly,
    /// strictly increasing in e: heavier always trails more, at every speed, and never more than M. Frame time counts for
    /// at most <see cref="MaxDecayStep"/> per frame, so a hitch is not a jump.
    /// </summary>
    public sealed class LateralInertia : WeightEffect
    {
        /// <summary>A frame counts for at most this long in the decay, s (one 30 Hz frame: a hitch gives back no more of the lag than the slowest frame clock would).</summary>
        public const double MaxDecayStep = 1.0 / 30;

        /// <summary>This effect's name, stage, summary and settings (<see cref="EffectRegistry"/>).</summary>
        public static readonly EffectDescriptor Descriptor = new EffectDescriptor("lateral-inertia", EffectStage.Hold, typeof(LateralInertia),
            "§9 (\"the xyz direction\"), issue 10",
            "in WeightSolver3D, an object heavier than the standard trails the hand's x/z motion, never more than the bound",
            s => new LateralInertia(s[0], s[1]),
            SettingDescriptor.Number<LateralInertia>("timeConstant", "s", 0.3, 0, 10, "the trailing's time constant for a very heavy object (scaled by 1 − G)", e => e.TimeConstant),
            SettingDescriptor.Number<LateralInertia>("maxOffset", "m", 0.10, 0.001, 10, "the largest horizontal lag", e => e.MaxOffset));

        public override string Name => Descriptor.Name;
        public override EffectStage Stage => Descriptor.Stage;

        /// <summary>τ of a very heavy object (w → 1), s.</summary>
        public double TimeConstant { get; }

        /// <summary>Largest horizontal distance between the object and where the hand holds it, m.</summary>
        public double MaxOffset { get; }

        public LateralInertia(double timeConstant = 0.3, double maxOffset = 0.10)
        {
            TimeConstant = Descriptor.Settings[0].Check(timeConstant);
            MaxOffset = Descriptor.Settings[1].Check(maxOffset);
        }

        /// <summary>τ for an object of gain <paramref name="gain"/>, s: 0 at G ≥ 1.</summary>
        public double TimeConstantFor(double gain) => TimeConstant * Math.Max(0, 1 - gain);

        /// <summary>The share of a lag the object shows, tanh(x)/x for a lag of x bounds (x ≥ 0; 1 at 0): the shown lag is
        /// M·tanh(|e|/M) = |e|·ShownShare(|e|/M). From one exponential: glibc's tanh costs an expm1 and a division more, on
        /// the chain each frame of a held object waits for.</summary>
        [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
        public static double ShownShare(double x)
        {
            // Below 10⁻³ the series (its next term, 17x⁶/315, is under 10⁻¹⁹); above, 1 − e^(−2x) loses at most 10⁻¹³ of it.
            if (x < 1e-3) { double x2 = x * x; return 1 - x2 / 3 + 2 * x2 * x2 / 15; }
            double t = Math.Exp(-2 * x);
            return (1 - t) / ((1 + t) * x);
        }

        protected internal override void Apply(ref MotionFrame frame, ref HoldState state, in SolverConstants constants) { }
    }
}
