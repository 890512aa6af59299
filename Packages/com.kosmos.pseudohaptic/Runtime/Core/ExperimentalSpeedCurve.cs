using System;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// Eq. 5 as meant: the speed at which a person lifts a real object of mass m with one hand,
    /// v_exp(m) = a · e^(−b·m), m in kg. Defaults a = 1.6793 m/s, b = 0.24 /kg are the paper's fit to
    /// one participant lifting dumbbells of 1.25–5 kg; <see cref="Fit"/> refits them from a user's lifts.
    /// </summary>
    public sealed class ExperimentalSpeedCurve
    {
        public const double PaperA = 1.6793;
        public const double PaperB = 0.24;

        /// <summary>The paper's curve.</summary>
        public static readonly ExperimentalSpeedCurve Paper = new ExperimentalSpeedCurve(PaperA, PaperB);

        /// <summary>Speed at zero mass, m/s.</summary>
        public double A { get; }

        /// <summary>Decay per kilogram, 1/kg (0 means speed does not depend on mass).</summary>
        public double B { get; }

        public ExperimentalSpeedCurve(double a, double b)
        {
            A = ConfigurationGuard.Positive(a, nameof(a));
            B = ConfigurationGuard.NonNegative(b, nameof(b));
        }

        /// <summary>v_exp(m) in m/s. Underflows to 0 for huge masses, never NaN.</summary>
        public double Speed(double massKg) => A * Math.Exp(-B * massKg);

        /// <summary>v_exp(m) / v_exp(m_std) = e^(−b·(m − m_std)): the curve relative to the golf ball, so a is irrelevant.</summary>
        public double RatioToStandard(double massKg) => Math.Exp(-B * (massKg - PhysicalConstants.StandardMassKg));

        /// <summary>
        /// Least-squares fit of ln v = ln a − b·m to measured (mass, mean lift speed) pairs, as the paper
        /// derived Eq. 5. Needs at least two distinct masses and positive finite speeds.
        /// </summary>
        public static ExperimentalSpeedCurve Fit(ReadOnlySpan<double> massesKg, ReadOnlySpan<double> speeds)
        {
            if (massesKg.Length != speeds.Length)
                throw new ArgumentException("massesKg and speeds must have the same length.", nameof(speeds));
            if (massesKg.Length < 2)
                throw new ArgumentException("at least two (mass, speed) pairs are needed.", nameof(massesKg));
            double sm = 0, sl = 0;
            for (int i = 0; i < massesKg.Length; i++)
            {
                ConfigurationGuard.Positive(massesKg[i], "massesKg[" + i + "]");
                ConfigurationGuard.Positive(speeds[i], "speeds[" + i + "]");
                sm += massesKg[i];
                sl += Math.Log(speeds[i]);
            }
            int n = massesKg.Length;
            double mm = sm / n, ml = sl / n, sxx = 0, sxy = 0;
            for (int i = 0; i < n; i++)
            {
                double dx = massesKg[i] - mm;
                sxx += dx * dx;
                sxy += dx * Math.Log(speeds[i]); // the dx sum to 0: centring the logs too would change nothing
            }
            if (sxx <= 0)
                throw new ArgumentException("the masses must not all be equal.", nameof(massesKg));
            double slope = sxy / sxx;
            double b = Math.Max(0, -slope); // a curve where heavier is faster is not a weight cue
            double a = Math.Exp(ml + b * mm);
            return new ExperimentalSpeedCurve(a, b);
        }
    }
}
