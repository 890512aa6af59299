using Kosmos.PseudoHaptic.Simulation;

namespace Kosmos.PseudoHaptic.Cli.Accuracy;

/// <summary>
/// How the study degrades a true hand the way a Quest 2 delivers it, and how it renders the reference:
/// 30 Hz poses, 45 ms late, Gaussian jitter of 1 and 2 mm, each held over 72, 90 and 120 Hz frames (six
/// renders per source, each with its own seed); the reference is the noise-free hand with a pose every 1 ms
/// and no latency, at 1 kHz frames.
/// </summary>
public static class Degradation
{
    public const double PoseRate = 30;
    public const double Latency = 0.045;
    public static readonly double[] FrameRates = { 72, 90, 120 };
    public static readonly double[] JitterMm = { 1, 2 };
    public const double ReferenceRate = 1000;

    public sealed record Render(string Label, double FrameRate, double JitterMm, TraceFrame[] Frames);

    /// <summary>The six degraded renders of <paramref name="hand"/>; <paramref name="seedBase"/> keeps sources apart.</summary>
    public static List<Render> Renders(HandPath hand, int seedBase)
    {
        var list = new List<Render>();
        for (int r = 0; r < FrameRates.Length; r++)
            for (int j = 0; j < JitterMm.Length; j++)
            {
                var headset = new HeadsetSimulator
                {
                    FrameRate = FrameRates[r], PoseRate = PoseRate, Latency = Latency,
                    JitterSd = JitterMm[j] / 1000, Seed = seedBase + 10 * r + j,
                };
                list.Add(new Render($"{FrameRates[r]:0} Hz {JitterMm[j]:0} mm", FrameRates[r], JitterMm[j], headset.Render(hand)));
            }
        return list;
    }

    /// <summary>The noise-free hand, a pose every 1 ms, no latency, 1 kHz frames.</summary>
    public static TraceFrame[] Reference(HandPath hand)
        => new HeadsetSimulator { FrameRate = ReferenceRate, PoseRate = ReferenceRate, Latency = 0, JitterSd = 0 }.Render(hand);
}
