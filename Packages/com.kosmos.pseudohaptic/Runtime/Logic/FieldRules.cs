using System;
using System.Globalization;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// The checks of the components' numeric settings (a reach, a radius, a size), engine-free: a setting given in code
    /// that breaks one throws, naming it; a serialized one is reported by the component when it wakes.
    /// </summary>
    public static class FieldRules
    {
        /// <summary>Null when <paramref name="value"/> is finite and greater than 0; otherwise why not, naming <paramref name="field"/>.</summary>
        public static string Positive(string field, double value) =>
            value > 0 && !double.IsInfinity(value) ? null : field + " must be finite and greater than 0 (was " + Show(value) + ")";

        /// <summary>Null when <paramref name="value"/> is finite and not negative; otherwise why not.</summary>
        public static string NonNegative(string field, double value) =>
            value >= 0 && !double.IsInfinity(value) ? null : field + " must be finite and at least 0 (was " + Show(value) + ")";

        /// <summary>Throws <see cref="ArgumentOutOfRangeException"/> with <paramref name="error"/> when it is not null.</summary>
        public static void Require(string error, string field, double value)
        {
            if (error != null) throw new ArgumentOutOfRangeException(field, value, error);
        }

        /// <summary>The first of the errors that is not null, or null.</summary>
        public static string First(params string[] errors)
        {
            foreach (string e in errors)
                if (e != null) return e;
            return null;
        }

        static string Show(double v) => v.ToString("R", CultureInfo.InvariantCulture);
    }
}
