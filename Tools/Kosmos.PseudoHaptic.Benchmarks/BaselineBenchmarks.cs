using System.Runtime.CompilerServices;
using BenchmarkDotNet.Attributes;
using Kosmos.PseudoHaptic.Cli.Accuracy;

namespace Kosmos.PseudoHaptic.Benchmarks;

/// <summary>
/// The speed-up as a ratio measured side by side: the paper-literal baseline (<see cref="PaperLiteralSolver"/>:
/// exp recomputed every frame, a List&lt;double&gt; of the last second of samples averaged every frame) against
/// the default pipeline (the paper profile), on Quest-like input (30 Hz poses over 90 Hz frames) and with a new pose every
/// frame. Ratio &lt; 1 for the default means faster.
/// </summary>
[MemoryDiagnoser]
[SimpleJob(launchCount: 1, warmupCount: 3, iterationCount: 5)]
public class BaselineBenchmarks
{
    public const int Frames = UpdateBenchmark.Frames;

    PaperLiteralSolver _literal = null!;
    WeightSolver _solver = null!, _everyFrame = null!;
    int _literalFrame, _solverFrame, _everyFrameFrame;

    [GlobalSetup]
    public void Setup()
    {
        _literal = new PaperLiteralSolver(HandFrames.MassKg);
        _literal.BeginHold(HandFrames.Samples[0].Y, HandFrames.Samples[0].Y);
        _solver = HandFrames.Holding(NamedProfiles.Paper);
        _everyFrame = HandFrames.Holding(NamedProfiles.Paper);
        for (int i = 0; i < HandFrames.Count / Frames; i++) { PaperLiteral(); DefaultPipeline(); DefaultPipelineNewPoseEveryFrame(); }
    }

    [Benchmark(Baseline = true, OperationsPerInvoke = Frames)]
    public double PaperLiteral()
    {
        double y = 0;
        for (int i = 0; i < Frames; i++)
        {
            int f = _literalFrame;
            _literalFrame = (f + 1) & HandFrames.Mask;
            y = _literal.Step(HandFrames.Samples[f].Y, HandFrames.Samples[f].IsTracked, HandFrames.Dt[f]);
        }
        return y;
    }

    [Benchmark(OperationsPerInvoke = Frames)]
    public double DefaultPipeline() => Steps(_solver, HandFrames.Samples, HandFrames.Dt, ref _solverFrame);

    /// <summary>The default pipeline when every frame brings a new pose (no still frame): what a frame costs at most.</summary>
    [Benchmark(OperationsPerInvoke = Frames)]
    public double DefaultPipelineNewPoseEveryFrame() => Steps(_everyFrame, HandFrames.EveryFramePoses, HandFrames.EveryFrameDt, ref _everyFrameFrame);

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    static double Steps(WeightSolver solver, HandSample[] samples, double[] dts, ref int frame)
    {
        double y = 0;
        for (int i = 0; i < Frames; i++)
        {
            int f = frame;
            frame = (f + 1) & HandFrames.Mask;
            y = solver.Step(samples[f], dts[f]);
        }
        return y;
    }
}
