namespace Kosmos.PseudoHaptic.Cli.Accuracy;

/// <summary>
/// How one degraded run's object path differs from the reference's, both on the 1 ms grid. The error is taken
/// against the reference delayed by the headset's latency (what the pipeline adds: pose hold, frame hold,
/// jitter, filter lag, lost motion) and, as "raw", against the undelayed reference (what the user sees).
/// Sums are kept so that runs pool into one RMS.
/// </summary>
public readonly record struct RunMetrics(double SumSquares, double RawSumSquares, int Count, double MaxAbs, double LagMs, bool LagWidened)
{
    /// <summary>This run's RMS error against the delayed reference, mm.</summary>
    public double RmsMm => 1000 * Math.Sqrt(SumSquares / Math.Max(1, Count));

    /// <summary>This run's RMS error against the undelayed reference, mm.</summary>
    public double RawRmsMm => 1000 * Math.Sqrt(RawSumSquares / Math.Max(1, Count));

    public static RunMetrics Measure(double[] degraded, double[] reference, double latencySeconds)
    {
        int n = Math.Min(degraded.Length, reference.Length);
        int shift = (int)Math.Round(latencySeconds / MillisecondGrid.Step);
        double sum = 0, raw = 0, max = 0;
        int count = 0;
        for (int j = shift; j < n; j++)
        {
            double e = degraded[j] - reference[j - shift];
            double r = degraded[j] - reference[j];
            sum += e * e;
            raw += r * r;
            if (Math.Abs(e) > max) max = Math.Abs(e);
            count++;
        }
        double lag = LagEstimator.LagMs(degraded[..n], reference[..n], out bool widened);
        return new RunMetrics(sum, raw, count, max, lag, widened);
    }
}
