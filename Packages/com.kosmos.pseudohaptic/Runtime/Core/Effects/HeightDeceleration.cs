using System;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// The paper's named next step (§5): "speed deceleration according to ... the height". On the way up, an
    /// object heavier than the standard rises more slowly the higher it already is above where the hold began,
    /// and the more the heavier it is. The object's upward displacement is multiplied by
    /// f(h, m) = φ + (1 − φ) / (1 + w(m) · h / <see cref="Height"/>), with h ≥ 0 the object's height above its
    /// height when the hold began, φ = <see cref="MinFraction"/>, and w(m) = 1 − min(G(m), 1) the object's
    /// weight cue (0 for the standard weight and anything lighter, rising toward 1 with mass; G the profile's
    /// gain). f(0) = 1, f is strictly decreasing in h and in m from the first millimetre, continuous, and never
    /// below φ, so nothing stalls. Lowering and holding still are untouched. One division per rising frame.
    /// ALGORITHM.md §6 says why this shape.
    /// </summary>
    public sealed class HeightDeceleration : WeightEffect
    {
        public override string Name => "height-deceleration";
        public override EffectStage Stage => EffectStage.ObjectMotion;

        /// <summary>Height scale, m: at h = Height a very heavy object (w → 1) rises at the midpoint between full
        /// speed and the floor fraction.</summary>
        public double Height { get; }

        /// <summary>The gain is never multiplied by less than this (the floor φ), in (0, 1].</summary>
        public double MinFraction { get; }

        public HeightDeceleration(double height = 0.5, double minFraction = 0.5)
        {
            Height = ConfigurationGuard.InRange(height, 0.01, 100, nameof(height));
            MinFraction = ConfigurationGuard.InRange(minFraction, 0.01, 1, nameof(minFraction));
        }

        /// <summary>The factor on the upward displacement at height <paramref name="height"/> above the hold's
        /// start for an object of gain <paramref name="gain"/>.</summary>
        public double Factor(double height, double gain)
        {
            double w = Math.Max(0, 1 - gain), h = Math.Max(0, height);
            return MinFraction + (1 - MinFraction) / (1 + w * h / Height);
        }

        protected internal override void Apply(ref MotionFrame frame, ref HoldState state, in SolverConstants constants)
        {
            // Only motion up is slowed (Factor is 1 at or below the start height, and for the standard weight and lighter).
            frame.ObjectDelta += Math.Max(0, frame.ObjectDelta) * (Factor(frame.ObjectY - state.StartY, constants.Gain) - 1);
        }
    }
}
