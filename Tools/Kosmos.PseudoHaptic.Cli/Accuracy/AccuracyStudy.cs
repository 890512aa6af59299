using Kosmos.PseudoHaptic.Simulation;

namespace Kosmos.PseudoHaptic.Cli.Accuracy;

/// <summary>
/// Runs the study: every configuration on every source's seeded degraded renders against its reference, the
/// still-hand renders for creep, and the long runs for precision and integration drift. Deterministic: the
/// renders are seeded by their hand, results are kept in render order, nothing depends on the clock.
/// </summary>
public static class AccuracyStudy
{
    /// <summary>What to run; <paramref name="Configs"/> null: <see cref="AccuracyConfig.All"/>.</summary>
    public sealed record Settings(WeightModel Model, double StandardSpeed, IReadOnlyList<AccuracySource> Sources, double LongRunMinutes,
        IReadOnlyList<string> Notes, IReadOnlyList<AccuracyConfig>? Configs = null);

    public static AccuracyReport Run(Settings s, TextWriter progress)
    {
        var configs = s.Configs ?? AccuracyConfig.All(s.Model, s.StandardSpeed);
        var perSource = new List<SourceResult>();
        foreach (var source in s.Sources)
        {
            progress.WriteLine($"accuracy: {source.Name} ({source.Description}), {Degradation.RenderCount} seeded renders");
            var renders = Degradation.Renders(source.Hand);
            var referenceFrames = Degradation.Reference(source.Hand);
            var references = new Dictionary<WeightProfile, double[]>();
            foreach (var config in configs)
            {
                if (!references.TryGetValue(config.Reference, out var reference))
                {
                    var y = TraceReplay.Run(new WeightSolver(s.Model, config.Reference, s.StandardSpeed), referenceFrames);
                    reference = MillisecondGrid.Hold(referenceFrames, y, MillisecondGrid.Length(referenceFrames));
                    references.Add(config.Reference, reference);
                }
                // Renders are independent: measured on both cores, kept in render order (the result does not depend on the scheduling).
                var runs = new (string, RunMetrics)[renders.Count];
                Parallel.For(0, renders.Count, new ParallelOptions { MaxDegreeOfParallelism = 2 }, k =>
                {
                    var render = renders[k];
                    var y = config.Run(render.Frames);
                    var grid = MillisecondGrid.Hold(render.Frames, y, Math.Min(reference.Length, MillisecondGrid.Length(render.Frames)));
                    runs[k] = (render.Label, RunMetrics.Measure(grid, reference, Degradation.Latency));
                });
                perSource.Add(new SourceResult(config.Key, source.Name, runs));
            }
        }

        progress.WriteLine("accuracy: still hand with jitter (creep)");
        var rest = new List<RestResult>();
        var restRenders = Degradation.Renders(RestMetrics.Hand());
        foreach (var config in configs)
        {
            var runs = new (string, RestMetrics)[restRenders.Count];
            Parallel.For(0, restRenders.Count, new ParallelOptions { MaxDegreeOfParallelism = 2 },
                k => runs[k] = (restRenders[k].Label, RestMetrics.Measure(restRenders[k].Frames, config.Run(restRenders[k].Frames))));
            rest.Add(new RestResult(config.Key, runs));
        }

        var summary = new List<SummaryRow>();
        foreach (var config in configs)
        {
            var mine = perSource.Where(r => r.Config == config.Key).ToList();
            var r = rest.First(x => x.Config == config.Key);
            // Render k's figure is the mean over the sources of their render k; the interval is over the renders.
            Interval Across(Func<RunMetrics, double> figure) => mine.Count == 0
                ? Interval.Of(Array.Empty<double>())
                : Interval.Of(Enumerable.Range(0, Degradation.RenderCount).Select(k => mine.Select(m => figure(m.Runs[k].Metrics)).Where(double.IsFinite).DefaultIfEmpty(double.NaN).Average()));
            summary.Add(new SummaryRow(config.Key, config.Group,
                Across(m => m.RmsMm), Across(m => m.RawRmsMm),
                mine.Count > 0 ? mine.Max(m => m.MaxMm) : double.NaN,
                Across(m => m.LagMs),
                mine.Any(m => m.LagWidened),
                r.Creep, r.CreepMaxMm, r.Rest));
        }

        string? longDescription = null;
        var longRun = new List<LongRunRow>();
        if (s.LongRunMinutes > 0)
        {
            progress.WriteLine($"accuracy: long run, {s.LongRunMinutes:0.##} min");
            (longDescription, longRun) = LongRunStudy.Run(s.Model, s.StandardSpeed, s.LongRunMinutes, progress);
        }

        double gain = new WeightSolver(s.Model, NamedProfiles.Paper, s.StandardSpeed).Gain;
        return new AccuracyReport(s.Model.MassKg, gain, s.StandardSpeed, s.Sources, configs, perSource, rest, summary, longDescription, longRun, s.Notes);
    }
}
