using BenchmarkDotNet.Attributes;
using Kosmos.PseudoHaptic.Cli.Accuracy;

namespace Kosmos.PseudoHaptic.Benchmarks;

/// <summary>
/// Each estimator of the accuracy study in the full paper profile, plus the paper-literal baseline: ns and
/// bytes per update. The keys are the accuracy table's (<see cref="EstimatorCatalog"/>); the Pareto chart
/// joins the two on them.
/// </summary>
[MemoryDiagnoser]
[SimpleJob(launchCount: 1, warmupCount: 3, iterationCount: 5)]
public class EstimatorBenchmarks
{
    public const int Frames = UpdateBenchmark.Frames;

    public static IEnumerable<string> Keys => EstimatorCatalog.EstimatorKeys.Append(EstimatorCatalog.PaperLiteral);

    [ParamsSource(nameof(Keys))]
    public string Estimator { get; set; } = EstimatorCatalog.Default;

    WeightSolver? _solver;
    PaperLiteralSolver? _literal;
    int _frame;

    [GlobalSetup]
    public void Setup()
    {
        if (Estimator == EstimatorCatalog.PaperLiteral)
        {
            _literal = new PaperLiteralSolver(HandFrames.MassKg);
            _literal.BeginHold(HandFrames.Samples[0].Y, HandFrames.Samples[0].Y);
        }
        else _solver = HandFrames.Holding(EstimatorCatalog.EstimatorProfile(Estimator));
        for (int i = 0; i < HandFrames.Count; i++) Update();
    }

    [Benchmark(OperationsPerInvoke = Frames)]
    public double Update()
    {
        double y = 0;
        var samples = HandFrames.Samples;
        var dts = HandFrames.Dt;
        if (_literal != null)
        {
            for (int i = 0; i < Frames; i++)
            {
                int f = _frame;
                _frame = (f + 1) & HandFrames.Mask;
                y = _literal.Step(samples[f].Y, samples[f].IsTracked, dts[f]);
            }
            return y;
        }
        var solver = _solver!;
        for (int i = 0; i < Frames; i++)
        {
            int f = _frame;
            _frame = (f + 1) & HandFrames.Mask;
            y = solver.Step(samples[f], dts[f]);
        }
        return y;
    }
}
