using BenchmarkDotNet.Attributes;

namespace Kosmos.PseudoHaptic.Benchmarks;

/// <summary>
/// Many held objects per frame, each its own solver under the default (paper) profile, stepped in a loop as a
/// scene would: every invocation makes 10 000 updates (10 000 frames of 1 object, 100 frames of 100, one frame
/// of 10 000), so Mean is ns per held object per update and "Per frame" is one frame of them all. Each object
/// reads the hand at its own phase of the input, so their branches differ as different holds' would.
/// </summary>
[MemoryDiagnoser]
[SimpleJob(launchCount: 1, warmupCount: 3, iterationCount: 5)]
public class BatchBenchmarks
{
    public const int UpdatesPerInvoke = 10_000;

    [Params(1, 100, 10_000)]
    public int Objects { get; set; }

    WeightSolver[] _solvers = Array.Empty<WeightSolver>();
    int _frame;

    [GlobalSetup]
    public void Setup()
    {
        _solvers = new WeightSolver[Objects];
        for (int k = 0; k < Objects; k++) _solvers[k] = HandFrames.Holding(NamedProfiles.Paper);
        for (int i = 0; i < 3; i++) Frame();
    }

    [Benchmark(OperationsPerInvoke = UpdatesPerInvoke)]
    public double Update()
    {
        double y = 0;
        for (int f = 0; f < UpdatesPerInvoke / Objects; f++) y = Frame();
        return y;
    }

    double Frame()
    {
        var samples = HandFrames.Samples;
        var dts = HandFrames.Dt;
        int frame = _frame;
        _frame = (frame + 1) & HandFrames.Mask;
        double y = 0;
        var solvers = _solvers;
        for (int k = 0; k < solvers.Length; k++)
        {
            int i = (frame + 37 * k) & HandFrames.Mask;
            y += solvers[k].Step(samples[i], dts[i]);
        }
        return y;
    }
}
