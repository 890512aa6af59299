using Kosmos.PseudoHaptic.Simulation;

namespace Kosmos.PseudoHaptic.Cli.Accuracy;

/// <summary>
/// Precision and integration over a long hold: minutes of pseudo-random minimum-jerk lifts (seeded), then 2 s
/// still, degraded at 72 Hz frames (non-integer 2.4 frames per 30 Hz pose), 45 ms late, 1.5 mm jitter. Each
/// scheme moves the object with the paper profile's gain and no effect; it is judged against the exact
/// displacement follower, start + G·(latest pose − first pose), computed in double from the very same poses:
/// the end error is the drift that remains after the hand stops, the max error the worst moment. Each figure is
/// the mean over <see cref="Seeds"/> seeded runs (its own lifts and jitter each) with its 95 % interval.
/// </summary>
public static class LongRunStudy
{
    public const double FrameRate = 72, JitterMm = 1.5;

    /// <summary>Seeded long runs; each figure is their mean.</summary>
    public const int Seeds = 20;

    public static (string Description, List<LongRunRow> Rows) Run(WeightModel model, double standardSpeed, double minutes, TextWriter progress)
    {
        var runs = new List<(List<(string Scheme, string What, double End, double Max)> Rows, int Frames)>();
        for (int seed = 0; seed < Seeds; seed++)
        {
            progress.Write($"\raccuracy: long run {seed + 1}/{Seeds}");
            runs.Add(RunOne(model, standardSpeed, minutes, seed));
        }
        progress.WriteLine();
        var rows = runs[0].Rows.Select((row, i) => new LongRunRow(row.Scheme, row.What,
            Interval.Of(runs.Select(r => r.Rows[i].End)), Interval.Of(runs.Select(r => r.Rows[i].Max)))).ToList();
        string description = $"{Seeds} seeded runs of {minutes:0.##} min of lifts (0.8–1.4 m) then 2 s still; {FrameRate:0} Hz frames, {Degradation.PoseRate:0} Hz poses, {Degradation.Latency * 1000:0} ms late, {JitterMm} mm jitter; {runs.Min(r => r.Frames)}–{runs.Max(r => r.Frames)} frames each; error vs start + G·(latest pose − first pose)";
        return (description, rows);
    }

    static (List<(string, string, double, double)> Rows, int Frames) RunOne(WeightModel model, double standardSpeed, double minutes, int seed)
    {
        var hand = Hand(minutes * 60, 4 + seed);
        var frames = new HeadsetSimulator { FrameRate = FrameRate, PoseRate = Degradation.PoseRate, Latency = Degradation.Latency, JitterSd = JitterMm / 1000, Seed = 7 + seed }.Render(hand);
        var profile = EstimatorCatalog.GainOnly;
        double gain = new WeightSolver(model, profile, standardSpeed).Gain;

        var exact = new double[frames.Length];
        int first = TraceReplay.FirstUsable(frames);
        double start = frames[first].HandY, latest = start;
        for (int i = 0; i < frames.Length; i++)
        {
            if (i >= first && frames[i].Tracked && double.IsFinite(frames[i].HandY)) latest = frames[i].HandY;
            exact[i] = start + gain * (latest - start);
        }

        var rows = new List<(string, string, double, double)>();
        void Add(string scheme, string description, double[] y)
        {
            double max = 0;
            for (int i = 0; i < y.Length; i++) max = Math.Max(max, Math.Abs(y[i] - exact[i]));
            rows.Add((scheme, description, 1000 * Math.Abs(y[^1] - exact[^1]), 1000 * max));
        }
        Add("increments", "the solver (gain-only profile), double state", TraceReplay.Run(new WeightSolver(model, profile, standardSpeed), frames));
        Add("increments-double", "harness increments, double state", IntegratorReplay.Run(new IncrementIntegrator<double>(gain), frames));
        Add("increments-float", "harness increments, float state", IntegratorReplay.Run(new IncrementIntegrator<float>(gain), frames));
        Add("velocity-dt", "object += G·v_hand·dt", IntegratorReplay.Run(new VelocityIntegrator(gain), frames));
        Add("velocity-substep4", "4 sub-steps per frame, v ramped", IntegratorReplay.Run(new VelocityIntegrator(gain, 4), frames));
        Add(EstimatorCatalog.PaperLiteral, "mean speed over the last 1 s, v·dt", IntegratorReplay.Run(new IntegratorReplay.PaperLiteral(model.MassKg), frames));
        return (rows, frames.Length);
    }

    /// <summary>Seeded lifts between 0.8 and 1.4 m, 0.4–1.5 s each, with 0.1–1 s pauses, for <paramref name="seconds"/>, then 2 s still.</summary>
    public static HandPath Hand(double seconds, int seed = 4)
    {
        var rng = new Random(seed);
        var path = HandPath.StartAt(1.0).Hold(0.5);
        while (path.Duration < seconds)
        {
            path.MoveTo(0.8 + 0.6 * rng.NextDouble(), 0.4 + 1.1 * rng.NextDouble());
            path.Hold(0.1 + 0.9 * rng.NextDouble());
        }
        return path.Hold(2.0);
    }
}
