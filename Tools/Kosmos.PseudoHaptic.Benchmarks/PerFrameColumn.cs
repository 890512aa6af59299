using BenchmarkDotNet.Columns;
using BenchmarkDotNet.Reports;
using BenchmarkDotNet.Running;

namespace Kosmos.PseudoHaptic.Benchmarks;

/// <summary>
/// For the batch benchmarks, whose Mean is per held object: the time of one whole frame, Mean × Objects, in µs
/// (the issue's target: 10 000 held objects under 250 µs per frame). Empty for the other benchmarks.
/// </summary>
public sealed class PerFrameColumn : IColumn
{
    public string Id => nameof(PerFrameColumn);
    public string ColumnName => "Per frame [us]";
    public bool AlwaysShow => false;
    public ColumnCategory Category => ColumnCategory.Custom;
    public int PriorityInCategory => 0;
    public bool IsNumeric => true;
    public UnitType UnitType => UnitType.Dimensionless;
    public string Legend => "Mean × Objects: one frame of every held object, µs";

    public bool IsDefault(Summary summary, BenchmarkCase benchmarkCase) => false;
    public bool IsAvailable(Summary summary) => summary.BenchmarksCases.Any(c => Objects(c) > 0);

    public string GetValue(Summary summary, BenchmarkCase benchmarkCase) => GetValue(summary, benchmarkCase, SummaryStyle.Default);

    public string GetValue(Summary summary, BenchmarkCase benchmarkCase, SummaryStyle style)
    {
        int objects = Objects(benchmarkCase);
        var stats = summary[benchmarkCase]?.ResultStatistics;
        if (objects <= 0 || stats == null) return "-";
        return (stats.Mean * objects / 1000).ToString("0.###", System.Globalization.CultureInfo.InvariantCulture);
    }

    static int Objects(BenchmarkCase c)
    {
        foreach (var p in c.Parameters.Items)
            if (p.Name == nameof(BatchBenchmarks.Objects) && p.Value is int n) return n;
        return 0;
    }
}
