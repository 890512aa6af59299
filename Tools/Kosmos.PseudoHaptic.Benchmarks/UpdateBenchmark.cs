using BenchmarkDotNet.Attributes;
using Kosmos.PseudoHaptic.Cli.Accuracy;

namespace Kosmos.PseudoHaptic.Benchmarks;

/// <summary>
/// One held object stepped through <see cref="Frames"/> frames per invocation: Mean is ns per update and
/// Allocated bytes per update. Subclasses choose the profile.
/// </summary>
[MemoryDiagnoser]
[SimpleJob(launchCount: 1, warmupCount: 3, iterationCount: 5)]
public abstract class UpdateBenchmark
{
    public const int Frames = 1024;

    WeightSolver _solver = null!;
    int _frame;

    protected abstract WeightProfile Profile();

    [GlobalSetup]
    public virtual void Setup()
    {
        _solver = HandFrames.Holding(Profile());
        for (int i = 0; i < HandFrames.Count; i++) StepOne(); // warm: every code path once, filters full
    }

    [Benchmark(OperationsPerInvoke = Frames)]
    public double Update()
    {
        double y = 0;
        for (int i = 0; i < Frames; i++) y = StepOne();
        return y;
    }

    double StepOne()
    {
        int f = _frame;
        _frame = (f + 1) & HandFrames.Mask;
        return _solver.Step(HandFrames.Samples[f], HandFrames.Dt[f]);
    }
}
