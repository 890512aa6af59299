using System;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// The paper's named next step (§5): "speed deceleration according to the movement in the xyz direction".
    /// In <see cref="WeightSolver3D"/>, an object heavier than the standard trails the hand's horizontal (x/z)
    /// motion: its horizontal lag e (a vector, from where it was grabbed) takes each frame's hand displacement
    /// Δ and relaxes as e ← (e + Δ) · τ/(τ + dt), with τ(m) = <see cref="TimeConstant"/> · w(m) and
    /// w(m) = 1 − min(G(m), 1) (0 for the standard weight and lighter, which follow exactly). |e| never exceeds
    /// <see cref="MaxOffset"/>. The factor lies in [0, 1): no overshoot past the hand, no oscillation; once the
    /// hand stops e decays (from 0.10 m to under 1 cm within 1 s at the defaults). Frame time counts for at most
    /// <see cref="MaxDecayStep"/> per frame, so a hitch is not a jump.
    /// </summary>
    public sealed class LateralInertia : WeightEffect
    {
        /// <summary>A frame counts for at most this long in the decay, s.</summary>
        public const double MaxDecayStep = 0.1;

        public override string Name => "lateral-inertia";
        public override EffectStage Stage => EffectStage.Hold;

        /// <summary>τ of a very heavy object (w → 1), s.</summary>
        public double TimeConstant { get; }

        /// <summary>Largest horizontal distance between the object and where the hand holds it, m.</summary>
        public double MaxOffset { get; }

        public LateralInertia(double timeConstant = 0.3, double maxOffset = 0.10)
        {
            TimeConstant = ConfigurationGuard.InRange(timeConstant, 0, 10, nameof(timeConstant));
            MaxOffset = ConfigurationGuard.InRange(maxOffset, 0.001, 10, nameof(maxOffset));
        }

        /// <summary>τ for an object of gain <paramref name="gain"/>, s: 0 at G ≥ 1.</summary>
        public double TimeConstantFor(double gain) => TimeConstant * Math.Max(0, 1 - gain);

        protected internal override void Apply(ref MotionFrame frame, ref HoldState state, in SolverConstants constants) { }
    }
}
