namespace Kosmos.PseudoHaptic.Benchmarks;

/// <summary>
/// <c>--steps CASE ROUNDS</c>: steps one held object (profile CASE, <c>every:</c> and a profile for a new pose every frame, <c>literal</c> for the paper-literal baseline, or
/// <c>3d:</c> and a <see cref="ThreeDimensionBenchmarks"/> case)
/// through <see cref="HandFrames"/> ROUNDS × 8192 times and prints the last height (and the wall time per update, a rough figure). For a deterministic instruction
/// count, run it under callgrind at two round counts: (difference of totals) / (difference of updates) is the
/// instructions per update, free of the start-up and JIT that both runs share.
/// </summary>
public static class StepCount
{
    public static void Run(string name, int rounds, TextWriter output)
    {
        double y = 0;
        var clock = new System.Diagnostics.Stopwatch();
        if (name.StartsWith("3d:", StringComparison.Ordinal))
        {
            // A ThreeDimensionBenchmarks case (3d:xyz, 3d:paper-3d, …): Frames updates per call.
            var bench = new ThreeDimensionBenchmarks { Case = name.Substring(3) };
            bench.Setup();
            int calls = HandFrames.Count / ThreeDimensionBenchmarks.Frames;
            clock.Start();
            for (int r = 0; r < rounds; r++)
                for (int c = 0; c < calls; c++) y = bench.Update();
        }
        else if (name == "literal")
        {
            var literal = new PaperLiteralSolver(HandFrames.MassKg);
            literal.BeginHold(HandFrames.Samples[0].Y, HandFrames.Samples[0].Y);
            clock.Start();
            for (int r = 0; r < rounds; r++) y = Round(literal);
        }
        else if (name.StartsWith("every:", StringComparison.Ordinal))
        {
            // A profile with a new pose every frame (HandFrames.EveryFramePoses, 90 Hz poses): no frame is still.
            var profile = NamedProfiles.Get(name.Substring(6));
            var solver = HandFrames.Holding(profile);
            clock.Start();
            for (int r = 0; r < rounds; r++) y = Round(solver, HandFrames.EveryFramePoses, HandFrames.EveryFrameDt);
        }
        else
        {
            var profile = name == "empty" ? new WeightProfile("empty", Array.Empty<WeightEffect>()) : NamedProfiles.Get(name);
            var solver = HandFrames.Holding(profile);
            clock.Start();
            for (int r = 0; r < rounds; r++) y = Round(solver);
        }
        double ns = clock.Elapsed.TotalMilliseconds * 1e6 / ((double)rounds * HandFrames.Count);
        output.WriteLine($"{name} {rounds} × {HandFrames.Count} updates: y = {y:R}, {ns:F1} ns/update (wall time, the JIT included)");
    }

    // One pass over the frames per call, so that the tiered JIT optimises the loop as it would a benchmark's.
    static double Round(WeightSolver solver) => Round(solver, HandFrames.Samples, HandFrames.Dt);

    static double Round(WeightSolver solver, HandSample[] samples, double[] dt)
    {
        double y = 0;
        for (int f = 0; f < samples.Length; f++) y = solver.Step(samples[f], dt[f]);
        return y;
    }

    static double Round(PaperLiteralSolver literal)
    {
        double y = 0;
        var samples = HandFrames.Samples;
        var dt = HandFrames.Dt;
        for (int f = 0; f < samples.Length; f++) y = literal.Step(samples[f].Y, samples[f].IsTracked, dt[f]);
        return y;
    }
}
