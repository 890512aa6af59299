using System.Numerics;

namespace Kosmos.PseudoHaptic.Cli.Accuracy;

/// <summary>
/// Lag of one 1 ms series behind another by cross-correlation of their velocities (first differences):
/// c(k) = Σ v_late[j] · v_ref[j − k], maximised over k in ±<see cref="SearchMs"/> ms at 1 ms resolution.
/// Velocity, not position, so that a constant offset between the two paths (a heavy object's hang, a
/// deadband's band) does not pull the peak. When the best k lies on the edge of the search the true peak is
/// further out: the search is widened to ±<see cref="WideSearchMs"/> ms and the result flagged.
/// </summary>
public static class LagEstimator
{
    public const int SearchMs = 200;
    public const int WideSearchMs = 1000;

    /// <summary>Lag in ms (positive: <paramref name="late"/> follows <paramref name="reference"/>); NaN when either does not move.</summary>
    public static double LagMs(double[] late, double[] reference, out bool widened)
    {
        widened = false;
        int n = Math.Min(late.Length, reference.Length);
        if (n < 3) return double.NaN;
        var vl = new double[n - 1];
        var vr = new double[n - 1];
        double el = 0, er = 0;
        for (int j = 1; j < n; j++)
        {
            vl[j - 1] = late[j] - late[j - 1];
            vr[j - 1] = reference[j] - reference[j - 1];
            el += vl[j - 1] * vl[j - 1];
            er += vr[j - 1] * vr[j - 1];
        }
        if (!(el > 1e-18) || !(er > 1e-18)) return double.NaN;
        int best = Search(vl, vr, SearchMs);
        if (Math.Abs(best) == SearchMs)
        {
            widened = true;
            best = Search(vl, vr, WideSearchMs);
        }
        return best;
    }

    static int Search(double[] vl, double[] vr, int range)
    {
        int n = vl.Length, best = 0;
        double bestC = double.NegativeInfinity;
        range = Math.Min(range, n - 1);
        for (int k = -range; k <= range; k++)
        {
            // Σ vl[j] · vr[j − k] over the overlap.
            int from = Math.Max(0, k), to = Math.Min(n, n + k);
            double c = Dot(vl.AsSpan(from, to - from), vr.AsSpan(from - k, to - from));
            if (c > bestC) { bestC = c; best = k; }
        }
        return best;
    }

    static double Dot(ReadOnlySpan<double> a, ReadOnlySpan<double> b)
    {
        var sum = Vector<double>.Zero;
        int i = 0, w = Vector<double>.Count;
        for (; i + w <= a.Length; i += w) sum += new Vector<double>(a.Slice(i, w)) * new Vector<double>(b.Slice(i, w));
        double s = Vector.Sum(sum);
        for (; i < a.Length; i++) s += a[i] * b[i];
        return s;
    }
}
