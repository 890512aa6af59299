using Kosmos.PseudoHaptic.Simulation;

namespace Kosmos.PseudoHaptic.Cli.Accuracy;

/// <summary>
/// Runs the study: every configuration on every source's six degraded renders against its reference, the
/// still-hand renders for creep, and the long run for precision and integration drift. Deterministic: the
/// renders are seeded, the work is sequential, nothing depends on the clock.
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
        for (int si = 0; si < s.Sources.Count; si++)
        {
            var source = s.Sources[si];
            progress.WriteLine($"accuracy: {source.Name} ({source.Description})");
            var renders = Degradation.Renders(source.Hand, 1000 * (si + 1));
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
                var runs = new List<(string, RunMetrics)>();
                foreach (var render in renders)
                {
                    var y = config.Run(render.Frames);
                    var grid = MillisecondGrid.Hold(render.Frames, y, Math.Min(reference.Length, MillisecondGrid.Length(render.Frames)));
                    runs.Add((render.Label, RunMetrics.Measure(grid, reference, Degradation.Latency)));
                }
                perSource.Add(new SourceResult(config.Key, source.Name, runs));
            }
        }

        progress.WriteLine("accuracy: still hand with jitter (creep)");
        var rest = new List<RestResult>();
        var restRenders = Degradation.Renders(RestMetrics.Hand(), 99_000);
        foreach (var config in configs)
        {
            var runs = new List<(string, RestMetrics)>();
            foreach (var render in restRenders) runs.Add((render.Label, RestMetrics.Measure(render.Frames, config.Run(render.Frames))));
            rest.Add(new RestResult(config.Key, runs));
        }

        var summary = new List<SummaryRow>();
        foreach (var config in configs)
        {
            var mine = perSource.Where(r => r.Config == config.Key).ToList();
            var r = rest.First(x => x.Config == config.Key);
            var lags = mine.Select(m => m.LagMs).Where(double.IsFinite).ToList();
            summary.Add(new SummaryRow(config.Key, config.Group,
                mine.Count > 0 ? mine.Average(m => m.RmsMm) : double.NaN,
                mine.Count > 0 ? mine.Average(m => m.RawRmsMm) : double.NaN,
                mine.Count > 0 ? mine.Max(m => m.MaxMm) : double.NaN,
                lags.Count > 0 ? lags.Average() : double.NaN,
                mine.Any(m => m.LagWidened),
                r.CreepMm, r.RestMm));
        }

        string? longDescription = null;
        var longRun = new List<LongRunRow>();
        if (s.LongRunMinutes > 0)
        {
            progress.WriteLine($"accuracy: long run, {s.LongRunMinutes:0.##} min");
            (longDescription, longRun) = LongRunStudy.Run(s.Model, s.StandardSpeed, s.LongRunMinutes);
        }

        double gain = new WeightSolver(s.Model, NamedProfiles.Paper, s.StandardSpeed).Gain;
        return new AccuracyReport(s.Model.MassKg, gain, s.StandardSpeed, s.Sources, configs, perSource, rest, summary, longDescription, longRun, s.Notes);
    }
}
