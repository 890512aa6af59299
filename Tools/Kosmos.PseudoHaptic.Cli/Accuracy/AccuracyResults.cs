namespace Kosmos.PseudoHaptic.Cli.Accuracy;

/// <summary>One configuration on one source: its seeded renders, in the study's render order (the same for every
/// source, so render k of each source shares its frame rate, jitter and replicate).</summary>
public sealed record SourceResult(string Config, string Source, IReadOnlyList<(string Render, RunMetrics Metrics)> Runs)
{
    public Interval Rms => Interval.Of(Runs.Select(r => r.Metrics.RmsMm));
    public Interval RawRms => Interval.Of(Runs.Select(r => r.Metrics.RawRmsMm));
    public double RmsMm => Rms.Mean;
    public double RawRmsMm => RawRms.Mean;
    public double MaxMm => 1000 * Runs.Max(r => r.Metrics.MaxAbs);

    /// <summary>Over the renders whose lag could be measured (none: NaN, a hand that never moves).</summary>
    public Interval Lag => Interval.Of(Runs.Select(r => r.Metrics.LagMs));

    public double LagMs => Lag.Mean;

    public bool LagWidened => Runs.Any(r => r.Metrics.LagWidened);
}

/// <summary>One configuration with a still hand and jitter: its seeded renders.</summary>
public sealed record RestResult(string Config, IReadOnlyList<(string Render, RestMetrics Metrics)> Runs)
{
    /// <summary>Creep, mm per 10 s, over the renders.</summary>
    public Interval Creep => Interval.Of(Runs.Select(r => 1000 * r.Metrics.CreepM));

    /// <summary>The worst render's creep, mm per 10 s.</summary>
    public double CreepMaxMm => 1000 * Runs.Max(r => r.Metrics.CreepM);

    /// <summary>RMS of the object about its mean at rest, mm, over the renders.</summary>
    public Interval Rest => Interval.Of(Runs.Select(r => 1000 * Math.Sqrt(r.Metrics.RestSumSquares / Math.Max(1, r.Metrics.RestCount))));
}

/// <summary>
/// A configuration's line of the summary. Each figure's value for render k is the mean over the sources of their
/// render k; the interval is over the renders. max: the largest of any render of any source.
/// </summary>
public sealed record SummaryRow(string Config, string Group, Interval Rms, Interval RawRms, double MaxMm, Interval Lag, bool LagWidened, Interval Creep, double CreepMaxMm, Interval Rest)
{
    public double RmsMm => Rms.Mean;
    public double RawRmsMm => RawRms.Mean;
    public double LagMs => Lag.Mean;
    public double CreepMm => Creep.Mean;
    public double RestMm => Rest.Mean;

    /// <summary>Lag beyond the headset's own latency, ms.</summary>
    public double AddedLagMs => LagMs - Degradation.Latency * 1000;

    public Interval AddedLag => new(Lag.Mean - Degradation.Latency * 1000, Lag.Low - Degradation.Latency * 1000, Lag.High - Degradation.Latency * 1000, Lag.N);
}

/// <summary>A scheme's line of the long-run table: over the seeded long runs.</summary>
public sealed record LongRunRow(string Scheme, string Description, Interval EndError, Interval MaxError)
{
    public double EndErrorMm => EndError.Mean;
    public double MaxErrorMm => MaxError.Mean;
}

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
