using BenchmarkDotNet.Attributes;
using Kosmos.PseudoHaptic.Simulation;

namespace Kosmos.PseudoHaptic.Benchmarks;

/// <summary>
/// Issue 10's costs, side by side with <c>paper</c> in one run: ns and bytes per update for each new effect and the
/// <c>xyz</c> profile. Input: the benchmark hand (<see cref="HandFrames"/>: 0.3 m lifts at 90 Hz frames, 30 Hz poses,
/// 45 ms late, 1.5 mm jitter) carrying 0.3 m sideways with each lift, and a second hand 0.3 m to its side.
/// Rows: <c>paper</c> and <c>height-deceleration</c> (paper + HeightDeceleration) on the y solver
/// (<see cref="WeightSolver"/>); the rest on <see cref="WeightSolver3D"/>: <c>paper-3d</c> (paper, one hand: the 3D
/// layer alone), <c>lateral-inertia</c>, <c>two-hands</c> (two hands), <c>break-away</c> (1 m, never reached),
/// <c>xyz</c> (two hands) and <c>xyz-one-hand</c>.
/// </summary>
[MemoryDiagnoser]
[SimpleJob(launchCount: 1, warmupCount: 3, iterationCount: 5)]
public class ThreeDimensionBenchmarks
{
    public const int Frames = 1024;

    [Params("paper", "height-deceleration", "paper-3d", "lateral-inertia", "two-hands", "break-away", "xyz", "xyz-one-hand")]
    public string Case { get; set; } = "paper";

    static readonly HandPose[] First = new HandPose[HandFrames.Count], Second = new HandPose[HandFrames.Count];

    static ThreeDimensionBenchmarks()
    {
        for (int i = 0; i < HandFrames.Count; i++)
        {
            var s = HandFrames.Samples[i];
            double x = double.IsFinite(s.Y) ? s.Y - 0.9 : double.NaN; // sideways with the lift: 0 to 0.3 m
            First[i] = new HandPose(x, s.Y, 0.3, s.IsTracked, s.IsHighConfidence, s.PoseTime);
            Second[i] = new HandPose(x + 0.3, s.Y, 0.3, s.IsTracked, s.IsHighConfidence, s.PoseTime);
        }
    }

    WeightSolver? _y;
    WeightSolver3D? _xyz;
    bool _twoHands;
    int _frame;

    [GlobalSetup]
    public void Setup()
    {
        var model = WeightModel.FromMass(HandFrames.MassKg);
        var paper = NamedProfiles.Paper;
        switch (Case)
        {
            case "paper": _y = new WeightSolver(model, paper); break;
            case "height-deceleration": _y = new WeightSolver(model, paper.With(new HeightDeceleration())); break;
            case "paper-3d": _xyz = new WeightSolver3D(model, paper); break;
            case "lateral-inertia": _xyz = new WeightSolver3D(model, paper.With(new LateralInertia())); break;
            case "two-hands": _xyz = new WeightSolver3D(model, paper.With(new TwoHands())); _twoHands = true; break;
            case "break-away": _xyz = new WeightSolver3D(model, paper.With(new BreakAway(1.0))); break;
            case "xyz": _xyz = new WeightSolver3D(model, NamedProfiles.Xyz); _twoHands = true; break;
            case "xyz-one-hand": _xyz = new WeightSolver3D(model, NamedProfiles.Xyz); break;
            default: throw new ArgumentException("unknown case " + Case);
        }
        _y?.BeginHold(HandFrames.Samples[0].Y, HandFrames.Samples[0].Y, HandFrames.Samples[0].PoseTime);
        _xyz?.BeginHold(First[0], _twoHands ? Second[0] : HandPose.Lost, First[0].X, First[0].Y, First[0].Z);
        for (int i = 0; i < HandFrames.Count; i++) StepOne(); // warm: every code path once
    }

    [Benchmark(OperationsPerInvoke = Frames)]
    public double Update()
    {
        double y = 0;
        for (int i = 0; i < Frames; i++) y = StepOne();
        return y;
    }

    /// <summary>Every case set up (for <see cref="InterleavedTiming"/>), <c>paper</c> first.</summary>
    public List<(string Name, ThreeDimensionBenchmarks Bench)> Cases()
    {
        var list = new List<(string, ThreeDimensionBenchmarks)>();
        foreach (var name in new[] { "paper", "height-deceleration", "paper-3d", "lateral-inertia", "two-hands", "break-away", "xyz", "xyz-one-hand" })
        {
            var b = new ThreeDimensionBenchmarks { Case = name };
            b.Setup();
            list.Add((name, b));
        }
        return list;
    }

    double StepOne()
    {
        int f = _frame;
        _frame = (f + 1) & HandFrames.Mask;
        if (_y != null) return _y.Step(HandFrames.Samples[f], HandFrames.Dt[f]);
        var solver = _xyz!;
        if (_twoHands) solver.Step(First[f], Second[f], HandFrames.Dt[f]);
        else solver.Step(First[f], HandFrames.Dt[f]);
        return solver.ObjectY + solver.ObjectX;
    }
}
