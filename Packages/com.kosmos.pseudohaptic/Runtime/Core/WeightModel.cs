using System;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// The virtual object's weight (Eq. 1, W = m·g) and what the paper derives from it: the ratio of the
    /// standard weight W_std/W (Eq. 4) and the experimental speed ratio v_exp(m)/v_exp(m_std) (Eq. 5).
    /// Immutable; invalid values throw here, naming the field.
    /// </summary>
    public sealed class WeightModel
    {
        public double MassKg { get; }

        /// <summary>W = m·g, N (Eq. 1).</summary>
        public double WeightNewtons => MassKg * PhysicalConstants.Gravity;

        public ExperimentalSpeedCurve Curve { get; }

        /// <summary>W_std / W: the gain of Eq. 4 alone.</summary>
        public double StandardWeightRatio => PhysicalConstants.StandardMassKg / MassKg;

        /// <summary>v_exp(m) / v_exp(m_std): the experimental curve relative to the golf ball.</summary>
        public double ExperimentalRatio => Curve.RatioToStandard(MassKg);

        WeightModel(double massKg, ExperimentalSpeedCurve curve)
        {
            MassKg = massKg;
            Curve = curve ?? ExperimentalSpeedCurve.Paper;
        }

        public static WeightModel FromMass(double massKg, ExperimentalSpeedCurve curve = null)
            => new WeightModel(ConfigurationGuard.Positive(massKg, nameof(massKg)), curve);

        /// <summary>m = ρ·V (paper 3.1), ρ in kg/m³, V in m³.</summary>
        public static WeightModel FromDensity(double densityKgPerCubicMetre, double volumeCubicMetres, ExperimentalSpeedCurve curve = null)
        {
            ConfigurationGuard.Positive(densityKgPerCubicMetre, nameof(densityKgPerCubicMetre));
            ConfigurationGuard.Positive(volumeCubicMetres, nameof(volumeCubicMetres));
            double mass = densityKgPerCubicMetre * volumeCubicMetres;
            return new WeightModel(ConfigurationGuard.Positive(mass, "massKg (density × volume)"), curve);
        }

        /// <summary>
        /// The gain G on the hand's displacement under the adopted reading of Eq. 4–6:
        /// with both terms G = ½(W_std/W + v_exp(m)/v_exp(m_std)); with one, that term; with none, 1;
        /// never above <paramref name="maxGain"/>. G(m_std) = 1 exactly in every combination.
        /// </summary>
        public double Gain(bool weightRatio, bool experimentalBlend, double maxGain)
        {
            double g;
            if (weightRatio && experimentalBlend) g = 0.5 * (StandardWeightRatio + ExperimentalRatio);
            else if (weightRatio) g = StandardWeightRatio;
            else if (experimentalBlend) g = ExperimentalRatio;
            else g = 1.0;
            return Math.Min(g, maxGain);
        }
    }
}
