using System.Globalization;

namespace Kosmos.PseudoHaptic.Cli;

/// <summary>Invariant-culture number parsing and formatting for the tool's CSV files.</summary>
public static class NumberText
{
    /// <summary>Parses a decimal number, or NaN / Infinity / inf written in any case with an optional sign.</summary>
    public static bool TryParse(ReadOnlySpan<char> text, out double value)
    {
        text = text.Trim();
        if (double.TryParse(text, NumberStyles.Float, CultureInfo.InvariantCulture, out value)) return true;
        var t = text;
        bool negative = false;
        if (t.Length > 0 && (t[0] == '+' || t[0] == '-')) { negative = t[0] == '-'; t = t[1..]; }
        if (t.Equals("nan", StringComparison.OrdinalIgnoreCase)) { value = double.NaN; return true; }
        if (t.Equals("inf", StringComparison.OrdinalIgnoreCase) || t.Equals("infinity", StringComparison.OrdinalIgnoreCase))
        {
            value = negative ? double.NegativeInfinity : double.PositiveInfinity;
            return true;
        }
        value = 0;
        return false;
    }

    /// <summary>Round-trippable, invariant; NaN and ±Infinity spelled as .NET spells them.</summary>
    public static string Format(double v) => v.ToString("R", CultureInfo.InvariantCulture);

    /// <summary><see cref="Format(double)"/> into <paramref name="destination"/> (at least 32 characters) without allocating; returns the length.</summary>
    public static int Format(double v, Span<char> destination)
    {
        if (!v.TryFormat(destination, out int written, "R", CultureInfo.InvariantCulture))
            throw new ArgumentException("the destination is too short", nameof(destination));
        return written;
    }

    /// <summary>Fixed decimals for tables.</summary>
    public static string Fixed(double v, int decimals) => v.ToString("F" + decimals, CultureInfo.InvariantCulture);

    /// <summary>
    /// A p value as a reader expects it (APA style): "p &lt; 0.001" below 0.001, else "p = " and three significant
    /// digits in plain decimals (0.00781, 0.918, 1.00), never E notation; "p = n/a" when not finite.
    /// </summary>
    public static string P(double p)
    {
        if (!double.IsFinite(p)) return "p = n/a";
        if (p < 0.001) return "p < 0.001";
        return "p = " + Plain(p, 3);
    }

    /// <summary><paramref name="v"/> to <paramref name="digits"/> significant digits in plain decimals (no E notation).</summary>
    public static string Plain(double v, int digits)
    {
        if (!double.IsFinite(v)) return "n/a";
        if (v == 0) return "0";
        int magnitude = (int)Math.Floor(Math.Log10(Math.Abs(v)));
        double rounded = Math.Round(v, Math.Clamp(digits - 1 - magnitude, 0, 15), MidpointRounding.AwayFromZero);
        magnitude = (int)Math.Floor(Math.Log10(Math.Abs(rounded))); // 0.9996 rounds up to 1.00
        int decimals = Math.Clamp(digits - 1 - magnitude, 0, 15);
        return rounded.ToString("F" + decimals.ToString(CultureInfo.InvariantCulture), CultureInfo.InvariantCulture);
    }
}
