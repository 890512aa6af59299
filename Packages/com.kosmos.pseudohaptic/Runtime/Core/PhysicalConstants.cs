namespace Kosmos.PseudoHaptic
{
    /// <summary>Constants of the paper's weight model (Son et al. 2022, Eq. 1–2).</summary>
    public static class PhysicalConstants
    {
        /// <summary>Standard gravity g, m/s² (Eq. 1–2).</summary>
        public const double Gravity = 9.80665;

        /// <summary>Mass of the standard object, a golf ball, kg (Eq. 2).</summary>
        public const double StandardMassKg = 0.045;

        /// <summary>W_std = 0.045 kg · g ≈ 0.4413 N (Eq. 2).</summary>
        public const double StandardWeightNewtons = StandardMassKg * Gravity;
    }
}
