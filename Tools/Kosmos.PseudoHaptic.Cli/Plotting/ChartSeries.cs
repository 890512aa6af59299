namespace Kosmos.PseudoHaptic.Cli.Plotting;

/// <summary>How a series is drawn.</summary>
internal enum SeriesKind
{
    Line,
    Points,
}

/// <summary>One data series of a <see cref="LineChart"/>, copied at the time it was added.</summary>
internal sealed record ChartSeries(
    double[] Xs,
    double[] Ys,
    Rgb Colour,
    string Label,
    SeriesKind Kind,
    bool Dashed,
    string?[]? PointLabels);
