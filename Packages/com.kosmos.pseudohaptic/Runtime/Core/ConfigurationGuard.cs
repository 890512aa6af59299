using System;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// Validation of configuration values. Bad configuration fails loudly when it is set, with the
    /// field's name; it is never checked per frame.
    /// </summary>
    internal static class ConfigurationGuard
    {
        public static double Positive(double value, string field)
        {
            if (double.IsNaN(value) || double.IsInfinity(value) || value <= 0)
                throw new ArgumentOutOfRangeException(field, value, field + " must be a finite number greater than 0, got " + Describe(value) + ".");
            return value;
        }

        public static double NonNegative(double value, string field)
        {
            if (double.IsNaN(value) || double.IsInfinity(value) || value < 0)
                throw new ArgumentOutOfRangeException(field, value, field + " must be a finite number of at least 0, got " + Describe(value) + ".");
            return value;
        }

        public static double Finite(double value, string field)
        {
            if (double.IsNaN(value) || double.IsInfinity(value))
                throw new ArgumentOutOfRangeException(field, value, field + " must be a finite number, got " + Describe(value) + ".");
            return value;
        }

        public static double InRange(double value, double min, double max, string field)
        {
            if (double.IsNaN(value) || value < min || value > max)
                throw new ArgumentOutOfRangeException(field, value, field + " must lie in [" + min.ToString("R", System.Globalization.CultureInfo.InvariantCulture) + ", " + max.ToString("R", System.Globalization.CultureInfo.InvariantCulture) + "], got " + Describe(value) + ".");
            return value;
        }

        static string Describe(double value) => value.ToString("R", System.Globalization.CultureInfo.InvariantCulture);
    }
}
