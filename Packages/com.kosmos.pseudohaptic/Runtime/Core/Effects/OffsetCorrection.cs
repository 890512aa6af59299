using System;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// Son et al. 2022, §3.1: past a hand–object distance of 0.2 m the object's speed is corrected "in a gradual
    /// deceleration manner", "+0.02 (m) faster if lighter, −0.02 slower if heavier". Adopted reading (design note, open
    /// question 3): past the threshold T the offset stops growing, smoothly. The weight's offset u becomes
    /// <code>C(u) = u for |u| ≤ T,   ±(T + B·(1 − e^(−(|u| − T)/B))) beyond,</code>
    /// with B = <see cref="Band"/> (the paper's 0.02 m): C is continuous with its slope, strictly increasing (heavier still
    /// hangs lower, P14) and never reaches T + B, the ceiling of the offset the user sees. Since C is a function of the
    /// offset, not of the path, a motion that comes back gives back exactly what it took (P13: no ratchet at the band).
    /// The threshold depends on the mass, so the correction keeps weights apart instead of holding every heavy object at
    /// the same offset: T(m) = <see cref="Threshold"/> × clamp(1 + <see cref="PerDoubling"/> · log2(m / 1 kg),
    /// <see cref="MinScale"/>, <see cref="MaxScale"/>) (<see cref="ThresholdFor"/>). Offsets are measured from the one at
    /// the grab.
    /// </summary>
    public sealed class OffsetCorrection : WeightEffect
    {
        public override string Name => "offset-correction";
        public override EffectStage Stage => EffectStage.ObjectMotion;
        /// <summary>C is a function of the offset.</summary>
        protected internal override bool IsFunctionOfHand => true;

        /// <summary>The threshold for a 1 kg object, m.</summary>
        public double Threshold { get; }

        /// <summary>How far past its threshold the offset may ever grow, m.</summary>
        public double Band { get; }

        /// <summary>Relative change of the threshold per doubling of the mass.</summary>
        public double PerDoubling { get; }

        /// <summary>Bounds of the threshold relative to <see cref="Threshold"/>.</summary>
        public double MinScale { get; }
        public double MaxScale { get; }

        public OffsetCorrection(double threshold = 0.2, double band = 0.02, double perDoubling = 0.1, double minScale = 0.75, double maxScale = 1.3)
        {
            Threshold = ConfigurationGuard.InRange(threshold, 0.001, 10, nameof(threshold));
            Band = ConfigurationGuard.InRange(band, 0.001, 10, nameof(band));
            PerDoubling = ConfigurationGuard.InRange(perDoubling, 0, 1, nameof(perDoubling));
            MinScale = ConfigurationGuard.InRange(minScale, 0.01, 1, nameof(minScale));
            MaxScale = ConfigurationGuard.InRange(maxScale, 1, 10, nameof(maxScale));
        }

        /// <summary>The largest offset any object can show under this correction, m: Threshold × MaxScale + Band.</summary>
        public double Ceiling => Threshold * MaxScale + Band;

        /// <summary>
        /// The threshold for an object of <paramref name="massKg"/>, m: Threshold × clamp(1 + PerDoubling · log2(m / 1 kg),
        /// MinScale, MaxScale). Defaults: 0.18 m at 0.5 kg, 0.20 at 1 kg, 0.22 at 2 kg, 0.246 at 5 kg, at most 0.26 (from
        /// about 8 kg), at least 0.15.
        /// </summary>
        public double ThresholdFor(double massKg)
        {
            double scale = 1 + PerDoubling * Math.Log(massKg) / Math.Log(2); // m ≤ 0: −∞ or NaN, the least
            if (!(scale > MinScale)) scale = MinScale;
            if (scale > MaxScale) scale = MaxScale;
            return Threshold * scale;
        }

        /// <summary>C: the offset shown for the weight's offset <paramref name="offset"/> under threshold <paramref name="threshold"/>, m.</summary>
        public double Bound(double offset, double threshold)
        {
            double a = Math.Abs(offset);
            if (!(a > threshold)) return offset;
            double bounded = threshold + Band * (1 - Math.Exp(-(a - threshold) / Band));
            return offset > 0 ? bounded : -bounded;
        }

        protected internal override void Apply(ref MotionFrame frame, ref HoldState state, in SolverConstants constants)
        {
            double threshold = constants.OffsetThreshold; // ThresholdFor(the model's mass), set by the solver
            frame.Offset = Bound(frame.Offset, threshold);
            double ceiling = threshold + Band;
            if (ceiling < frame.OffsetCeiling) frame.OffsetCeiling = ceiling;
        }
    }
}
