using BenchmarkDotNet.Columns;
using BenchmarkDotNet.Configs;
using BenchmarkDotNet.Exporters;
using BenchmarkDotNet.Exporters.Csv;
using BenchmarkDotNet.Reports;
using System.Globalization;
using Perfolizer.Horology;
using Perfolizer.Metrology;

namespace Kosmos.PseudoHaptic.Benchmarks;

/// <summary>
/// Times in ns and sizes in bytes everywhere, CSV without units in the cells (the accuracy command reads it for
/// the Pareto chart: <c>pseudohaptic accuracy --costs BenchmarkDotNet.Artifacts/results</c>), GitHub markdown.
/// </summary>
public sealed class BenchmarkConfig : ManualConfig
{
    public BenchmarkConfig()
    {
        // The default configuration less its exporters, which are replaced by the two below.
        var defaults = DefaultConfig.Instance;
        AddLogger(defaults.GetLoggers().ToArray());
        AddColumnProvider(defaults.GetColumnProviders().ToArray());
        AddAnalyser(defaults.GetAnalysers().ToArray());
        AddValidator(defaults.GetValidators().ToArray());
        SummaryStyle = SummaryStyle.Default.WithTimeUnit(TimeUnit.Nanosecond).WithSizeUnit(SizeUnit.B)
            .WithCultureInfo(CultureInfo.InvariantCulture).WithMaxParameterColumnWidth(30);
        var csv = new SummaryStyle(CultureInfo.InvariantCulture, printUnitsInHeader: true, SizeUnit.B, TimeUnit.Nanosecond,
            printUnitsInContent: false, printZeroValuesInContent: true, maxParameterColumnWidth: 30, RatioStyle.Value);
        AddExporter(new CsvExporter(CsvSeparator.Comma, csv));
        AddExporter(MarkdownExporter.GitHub);
        AddColumn(new PerFrameColumn());
    }
}
