namespace Kosmos.PseudoHaptic.Cli.Accuracy;

/// <summary>One configuration on one source: its six degraded renders, pooled.</summary>
public sealed record SourceResult(string Config, string Source, IReadOnlyList<(string Render, RunMetrics Metrics)> Runs)
{
    public double RmsMm => 1000 * Math.Sqrt(Runs.Sum(r => r.Metrics.SumSquares) / Math.Max(1, Runs.Sum(r => r.Metrics.Count)));
    public double RawRmsMm => 1000 * Math.Sqrt(Runs.Sum(r => r.Metrics.RawSumSquares) / Math.Max(1, Runs.Sum(r => r.Metrics.Count)));
    public double MaxMm => 1000 * Runs.Max(r => r.Metrics.MaxAbs);

    /// <summary>Mean over the renders whose lag could be measured (NaN when none could: a hand that never moves).</summary>
    public double LagMs
    {
        get
        {
            var lags = Runs.Select(r => r.Metrics.LagMs).Where(double.IsFinite).ToList();
            return lags.Count > 0 ? lags.Average() : double.NaN;
        }
    }

    public bool LagWidened => Runs.Any(r => r.Metrics.LagWidened);
}

/// <summary>One configuration with a still hand and jitter: its six renders.</summary>
public sealed record RestResult(string Config, IReadOnlyList<(string Render, RestMetrics Metrics)> Runs)
{
    /// <summary>The worst render's creep, mm per 10 s.</summary>
    public double CreepMm => 1000 * Runs.Max(r => r.Metrics.CreepM);

    /// <summary>RMS of the object about its mean at rest, pooled over the renders, mm.</summary>
    public double RestMm => 1000 * Math.Sqrt(Runs.Sum(r => r.Metrics.RestSumSquares) / Math.Max(1, Runs.Sum(r => r.Metrics.RestCount)));
}

/// <summary>A configuration's line of the summary: per-source figures averaged over the sources (max: the largest).</summary>
public sealed record SummaryRow(string Config, string Group, double RmsMm, double RawRmsMm, double MaxMm, double LagMs, bool LagWidened, double CreepMm, double RestMm)
{
    /// <summary>Lag beyond the headset's own latency, ms.</summary>
    public double AddedLagMs => LagMs - Degradation.Latency * 1000;
}

/// <summary>A scheme's line of the long-run table.</summary>
public sealed record LongRunRow(string Scheme, string Description, double EndErrorMm, double MaxErrorMm);

/// <summary>Everything the accuracy command measured, in the order it prints it.</summary>
public sealed record AccuracyReport(
    double MassKg,
    double Gain,
    double StandardSpeed,
    IReadOnlyList<AccuracySource> Sources,
    IReadOnlyList<AccuracyConfig> Configs,
    IReadOnlyList<SourceResult> PerSource,
    IReadOnlyList<RestResult> Rest,
    IReadOnlyList<SummaryRow> Summary,
    string? LongRunDescription,
    IReadOnlyList<LongRunRow> LongRun,
    IReadOnlyList<string> Notes);
