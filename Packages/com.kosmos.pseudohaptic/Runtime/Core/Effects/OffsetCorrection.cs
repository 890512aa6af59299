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
        /// <summary>This effect's name, stage, summary and settings (<see cref="EffectRegistry"/>).</summary>
        public static readonly EffectDescriptor Descriptor = new EffectDescriptor("offset-correction", EffectStage.ObjectMotion, typeof(OffsetCorrection),
            "§3.1 (> 0.2 m)",
            "past a mass-dependent threshold the offset stops growing, smoothly, never past the threshold plus the band",
            s => new OffsetCorrection(s[0], s[1], s[2], s[3], s[4]),
            SettingDescriptor.Number<OffsetCorrection>("threshold", "m", 0.2, 0.001, 10, "the threshold for a 1 kg object", e => e.Threshold),
            SettingDescriptor.Number<OffsetCorrection>("band", "m", 0.02, 0.001, 10, "how far past its threshold the offset may ever grow", e => e.Band),
            SettingDescriptor.Number<OffsetCorrection>("perDoubling", "", 0.1, 0, 1, "relative change of the threshold per doubling of the mass", e => e.PerDoubling),
            SettingDescriptor.Number<OffsetCorrection>("minScale", "", 0.75, 0.01, 1, "lowest threshold relative to the 1 kg one", e => e.MinScale),
            SettingDescriptor.Number<OffsetCorrection>("maxScale", "", 1.3, 1, 10, "highest threshold relative to the 1 kg one", e => e.MaxScale));

        public override string Name => Descriptor.Name;
        public override EffectStage Stage => Descriptor.Stage;
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
            Threshold = Descriptor.Settings[0].Check(threshold);
            Band = Descriptor.Settings[1].Check(band);
            PerDoubling = Descriptor.Settings[2].Check(perDoubling);
            MinScale = Descriptor.Settings[3].Check(minScale);
            MaxScale = Descriptor.Settings[4].Check(maxScale);
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
