using Kosmos.PseudoHaptic.Simulation;

namespace Kosmos.PseudoHaptic.Cli.Accuracy;

/// <summary>
/// Resamples a per-frame series onto a 1 ms grid (t = 0, 1, 2, … ms) by zero-order hold: the value a frame
/// shows stays until the next frame, which is what the user sees of a rendered object.
/// </summary>
public static class MillisecondGrid
{
    public const double Step = 0.001;

    /// <summary>Grid points covered by frames (0 ms up to the last frame's time).</summary>
    public static int Length(IReadOnlyList<TraceFrame> frames) => frames.Count == 0 ? 0 : (int)Math.Floor(frames[^1].Time / Step + 1e-6) + 1;

    public static double[] Hold(IReadOnlyList<TraceFrame> frames, double[] values, int length)
    {
        var grid = new double[length];
        int i = 0;
        for (int k = 0; k < length; k++)
        {
            double t = k * Step + 1e-9;
            while (i + 1 < frames.Count && frames[i + 1].Time <= t) i++;
            grid[k] = values[i];
        }
        return grid;
    }
}
