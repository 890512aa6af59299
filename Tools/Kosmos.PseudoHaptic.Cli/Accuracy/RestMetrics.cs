using Kosmos.PseudoHaptic.Simulation;

namespace Kosmos.PseudoHaptic.Cli.Accuracy;

/// <summary>
/// A still hand with tracking jitter: the object should not move. Creep is how far the object's mean height
/// moved between the second after warm-up ([1, 2) s) and the second ten seconds later ([11, 12) s), so the
/// figure is mm per 10 s; rest is the RMS of the object's height about its mean over [1, 12) s (the jitter
/// that reaches the object).
/// </summary>
public readonly record struct RestMetrics(double CreepM, double RestSumSquares, int RestCount)
{
    public const double Height = 1.0, Warmup = 1.0, Span = 10.0, Seconds = Warmup + Span + 1.0;

    public static HandPath Hand() => HandPath.StartAt(Height).Hold(Seconds);

    public static RestMetrics Measure(IReadOnlyList<TraceFrame> frames, double[] objectY)
    {
        double first = Mean(frames, objectY, Warmup, Warmup + 1), last = Mean(frames, objectY, Warmup + Span, Warmup + Span + 1);
        double all = Mean(frames, objectY, Warmup, Seconds + 1);
        double ss = 0;
        int n = 0;
        for (int i = 0; i < frames.Count; i++)
            if (frames[i].Time >= Warmup)
            {
                double d = objectY[i] - all;
                ss += d * d;
                n++;
            }
        return new RestMetrics(Math.Abs(last - first), ss, n);
    }

    static double Mean(IReadOnlyList<TraceFrame> frames, double[] y, double from, double to)
    {
        double s = 0;
        int n = 0;
        for (int i = 0; i < frames.Count; i++)
            if (frames[i].Time >= from && frames[i].Time < to) { s += y[i]; n++; }
        return n > 0 ? s / n : double.NaN;
    }
}
