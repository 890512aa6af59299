using System.Globalization;

namespace Kosmos.PseudoHaptic.Cli.Plotting;

/// <summary>Tick positions at "nice" steps (1, 2 or 5 times a power of ten) and their labels.</summary>
public static class AxisTicks
{
    private const int MaxTicks = 1000;

    /// <summary>
    /// The smallest step of the form {1, 2, 5} x 10^k that splits <paramref name="span"/> into at most about
    /// <paramref name="targetCount"/> intervals. Non-positive or non-finite spans give 1.
    /// </summary>
    public static double NiceStep(double span, int targetCount)
    {
        if (!(span > 0) || !double.IsFinite(span)) return 1;
        double raw = span / Math.Max(1, targetCount);
        double magnitude = Math.Pow(10, Math.Floor(Math.Log10(raw)));
        double normalised = raw / magnitude;
        double nice = normalised <= 1 + 1e-9 ? 1 : normalised <= 2 + 1e-9 ? 2 : normalised <= 5 + 1e-9 ? 5 : 10;
        double step = nice * magnitude;
        return double.IsFinite(step) && step > 0 ? step : 1;
    }

    /// <summary>Multiples of <paramref name="step"/> within [min, max] (ends included up to rounding).</summary>
    public static IReadOnlyList<double> Linear(double min, double max, double step)
    {
        var ticks = new List<double>();
        if (!double.IsFinite(min) || !double.IsFinite(max) || !(step > 0) || !double.IsFinite(step) || max < min) return ticks;
        double first = Math.Ceiling(min / step - 1e-9);
        double last = Math.Floor(max / step + 1e-9);
        if (!double.IsFinite(first) || !double.IsFinite(last) || last - first > MaxTicks) return ticks;
        for (double k = first; k <= last; k++)
        {
            double v = k * step;
            ticks.Add(Math.Abs(v) < step * 1e-9 ? 0 : v); // no "-0"
        }

        return ticks;
    }

    /// <summary>
    /// Powers of ten within [min, max] (both positive), every n-th decade when there are more than
    /// <paramref name="targetCount"/>.
    /// </summary>
    public static IReadOnlyList<double> Decades(double min, double max, int targetCount)
    {
        var ticks = new List<double>();
        if (!(min > 0) || !(max >= min) || !double.IsFinite(max)) return ticks;
        int lo = (int)Math.Ceiling(Math.Log10(min) - 1e-9);
        int hi = (int)Math.Floor(Math.Log10(max) + 1e-9);
        int count = hi - lo + 1;
        if (count <= 0) return ticks;
        int stride = Math.Max(1, (int)Math.Ceiling(count / (double)Math.Max(1, targetCount)));
        for (int k = lo; k <= hi; k += stride)
        {
            ticks.Add(Math.Pow(10, k));
        }

        return ticks;
    }

    /// <summary>A label for a tick on a linear axis whose ticks are <paramref name="step"/> apart.</summary>
    public static string FormatLinear(double value, double step)
    {
        if (Math.Abs(value) < Math.Abs(step) * 1e-9) value = 0;
        if (!double.IsFinite(value)) return value.ToString(CultureInfo.InvariantCulture);
        if (step >= 1e6 || (step > 0 && step < 1e-4))
        {
            return value.ToString("0.###e+0", CultureInfo.InvariantCulture);
        }

        int decimals = step > 0 ? Math.Clamp(-(int)Math.Floor(Math.Log10(step) + 1e-9), 0, 10) : 3;
        return value.ToString("F" + decimals.ToString(CultureInfo.InvariantCulture), CultureInfo.InvariantCulture);
    }

    /// <summary>A label for a tick on a log axis: plain digits for 0.001..100000, else "1e-9" style.</summary>
    public static string FormatLog(double value)
    {
        if (!(value > 0) || !double.IsFinite(value)) return value.ToString(CultureInfo.InvariantCulture);
        double exponent = Math.Log10(value);
        double rounded = Math.Round(exponent);
        if (Math.Abs(exponent - rounded) < 1e-9)
        {
            int k = (int)rounded;
            if (k >= 0 && k <= 5) return Math.Pow(10, k).ToString("0", CultureInfo.InvariantCulture);
            if (k < 0 && k >= -3) return Math.Pow(10, k).ToString("0.###", CultureInfo.InvariantCulture);
            return "1e" + k.ToString(CultureInfo.InvariantCulture);
        }

        return value.ToString("0.###e+0", CultureInfo.InvariantCulture);
    }
}
