using Kosmos.PseudoHaptic.Simulation;

namespace Kosmos.PseudoHaptic.Cli.Accuracy;

/// <summary>
/// How the study degrades a true hand the way a Quest 2 delivers it, and how it renders the reference:
/// 30 Hz poses, 45 ms late, Gaussian jitter of 1 and 2 mm, each held over 72, 90 and 120 Hz frames: six conditions,
/// each rendered <see cref="Replicates"/> times with its own seed (24 seeded renders per source, so every figure is a
/// mean over 24 seeds with its 95 % interval). The seeds come from the hand itself (<see cref="ContentSeed"/>), so the
/// same hand gets the same renders whatever its name or its place among the sources. The reference is the
/// noise-free hand with a pose every 1 ms and no latency, at 1 kHz frames.
/// </summary>
public static class Degradation
{
    public const double PoseRate = 30;
    public const double Latency = 0.045;
    public static readonly double[] FrameRates = { 72, 90, 120 };
    public static readonly double[] JitterMm = { 1, 2 };
    public const double ReferenceRate = 1000;

    /// <summary>Seeded renders of each condition (frame rate × jitter).</summary>
    public const int Replicates = 4;

    /// <summary>Renders per source: every condition, <see cref="Replicates"/> times.</summary>
    public static int RenderCount => Replicates * FrameRates.Length * JitterMm.Length;

    public sealed record Render(string Label, double FrameRate, double JitterMm, TraceFrame[] Frames);

    /// <summary>The seeded degraded renders of <paramref name="hand"/>, replicate by replicate, each replicate every
    /// condition in the same order.</summary>
    public static List<Render> Renders(HandPath hand)
    {
        int seedBase = ContentSeed(hand);
        var list = new List<Render>();
        for (int k = 0; k < Replicates; k++)
            for (int r = 0; r < FrameRates.Length; r++)
                for (int j = 0; j < JitterMm.Length; j++)
                {
                    var headset = new HeadsetSimulator
                    {
                        FrameRate = FrameRates[r], PoseRate = PoseRate, Latency = Latency,
                        JitterSd = JitterMm[j] / 1000, Seed = seedBase + 100 * k + 10 * r + j,
                    };
                    list.Add(new Render($"{FrameRates[r]:0} Hz {JitterMm[j]:0} mm #{k + 1}", FrameRates[r], JitterMm[j], headset.Render(hand)));
                }
        return list;
    }

    /// <summary>A seed drawn from the hand's heights every 10 ms (FNV-1a over their bits), below 2^30 so the
    /// renders' offsets cannot overflow: a hand's renders depend on the hand alone.</summary>
    public static int ContentSeed(HandPath hand)
    {
        ulong h = 14695981039346656037UL;
        void Add(ulong v)
        {
            for (int b = 0; b < 8; b++) { h ^= (v >> (8 * b)) & 0xFF; h *= 1099511628211UL; }
        }
        Add((ulong)BitConverter.DoubleToInt64Bits(hand.Duration));
        for (double t = 0; t <= hand.Duration; t += 0.01) Add((ulong)BitConverter.DoubleToInt64Bits(hand.HeightAt(t)));
        return (int)(h % (1 << 30));
    }

    /// <summary>The noise-free hand, a pose every 1 ms, no latency, 1 kHz frames.</summary>
    public static TraceFrame[] Reference(HandPath hand)
        => new HeadsetSimulator { FrameRate = ReferenceRate, PoseRate = ReferenceRate, Latency = 0, JitterSd = 0 }.Render(hand);
}
