using System.Diagnostics;

namespace Kosmos.PseudoHaptic.Benchmarks;

/// <summary>
/// <c>--interleaved</c>: the <see cref="ThreeDimensionBenchmarks"/> cases timed in alternation, each round stepping every
/// case once through the same 8192 frames, 60 rounds (the first 10 discarded), medians printed in ns per update and
/// as a multiple of <c>paper</c>. On a machine shared with other work, BenchmarkDotNet's separate runs of each case
/// see different loads; alternating puts every case under the same load, so the ratios hold even when the absolute
/// times do not.
/// </summary>
public static class InterleavedTiming
{
    public static void Run(TextWriter output)
    {
        var cases = new ThreeDimensionBenchmarks().Cases();
        var times = cases.Select(_ => new List<double>()).ToArray();
        for (int round = 0; round < 60; round++)
            for (int c = 0; c < cases.Count; c++)
            {
                var bench = cases[c].Bench;
                var sw = Stopwatch.StartNew();
                for (int k = 0; k < HandFrames.Count / ThreeDimensionBenchmarks.Frames; k++) bench.Update();
                times[c].Add(sw.Elapsed.TotalMilliseconds * 1e6 / HandFrames.Count);
            }
        static double Median(List<double> l) { var o = l.Skip(10).OrderBy(v => v).ToList(); return o[o.Count / 2]; }
        double paper = Median(times[0]);
        output.WriteLine("case                 ns/update  x paper");
        for (int c = 0; c < cases.Count; c++)
            output.WriteLine($"{cases[c].Name,-20} {Median(times[c]),9:F2}  {Median(times[c]) / paper,7:F2}");
    }
}
