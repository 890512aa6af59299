using ScottPlot;

namespace Kosmos.PseudoHaptic.Cli.Plotting;

/// <summary>
/// The one place that knows the project's chart style. Every chart the tools write is a ScottPlot
/// <see cref="Plot"/> made by <see cref="Create"/> and written by <see cref="Save"/>: white background, light
/// grid, the "tab10" colours in order (<see cref="Colour"/>), a title, axis labels with their units, a legend
/// inside the plot.
/// </summary>
/// <example><code>
/// Plot plot = Charts.Create("Drop", "time (s)", "height (m)");
/// Charts.Line(plot, ts, hs, "solver", Charts.Colour(0));
/// Charts.Save(plot, "drop.png", 1000, 560, svg: false);
/// </code></example>
public static class Charts
{
    /// <summary>Largest width or height accepted by <see cref="Save"/> (pixels).</summary>
    public const int MaxSide = 8000;

    private const float TitleSize = 22;
    private const float LabelSize = 18;
    private const float TickSize = 15;
    private const float LegendSize = 15;
    private const float LineWidth = 2;
    private const float MarkerSize = 8;

    private static readonly Color TextColour = Color.FromHex("#202020");
    private static readonly Color AxisColour = Color.FromHex("#404040");
    private static readonly Color GridColour = Color.FromHex("#DCDCDC");

    private static readonly Color[] Tab10 =
    {
        Color.FromHex("#1f77b4"), // blue
        Color.FromHex("#ff7f0e"), // orange
        Color.FromHex("#2ca02c"), // green
        Color.FromHex("#d62728"), // red
        Color.FromHex("#9467bd"), // purple
        Color.FromHex("#8c564b"), // brown
        Color.FromHex("#e377c2"), // pink
        Color.FromHex("#7f7f7f"), // grey
        Color.FromHex("#bcbd22"), // olive
        Color.FromHex("#17becf"), // cyan
    };

    /// <summary>Black, for a reference series (the hand, a mean).</summary>
    public static Color Black => Colors.Black;

    /// <summary>Number of distinct series colours before <see cref="Colour"/> repeats.</summary>
    public static int ColourCount => Tab10.Length;

    /// <summary>The i-th series colour ("tab10"); wraps around, any int is valid.</summary>
    public static Color Colour(int i) => Tab10[((i % Tab10.Length) + Tab10.Length) % Tab10.Length];

    /// <summary>A new plot in the project's style with its title and axis labels (give the units in the labels).</summary>
    public static Plot Create(string title, string xLabel, string yLabel)
    {
        var plot = new Plot();
        plot.FigureBackground.Color = Colors.White;
        plot.DataBackground.Color = Colors.White;
        plot.Add.Palette = new ScottPlot.Palettes.Category10();

        plot.Title(title ?? "", TitleSize);
        plot.Axes.Title.Label.ForeColor = TextColour;
        plot.Axes.Title.Label.Bold = true;
        plot.XLabel(xLabel ?? "", LabelSize);
        plot.YLabel(yLabel ?? "", LabelSize);
        foreach (IAxis axis in new IAxis[] { plot.Axes.Bottom, plot.Axes.Left })
        {
            axis.Label.ForeColor = TextColour;
            axis.Label.Bold = false;
            axis.TickLabelStyle.FontSize = TickSize;
            axis.TickLabelStyle.ForeColor = TextColour;
            axis.MajorTickStyle.Color = AxisColour;
            axis.MinorTickStyle.Color = AxisColour;
            axis.FrameLineStyle.Color = AxisColour;
        }

        plot.Grid.MajorLineColor = GridColour;
        plot.Grid.MinorLineColor = Colors.Transparent;

        plot.Legend.FontSize = LegendSize;
        plot.Legend.FontColor = TextColour;
        plot.Legend.OutlineColor = Color.FromHex("#B4B4B4");
        plot.Legend.BackgroundColor = Colors.White.WithAlpha(0.9);
        plot.Legend.Alignment = Alignment.UpperLeft;
        plot.Legend.IsVisible = true;
        return plot;
    }

    /// <summary>A line through (xs[i], ys[i]) in order; a non-finite point breaks the line.</summary>
    public static void Line(Plot plot, IReadOnlyList<double> xs, IReadOnlyList<double> ys, string label, Color colour, bool dashed = false)
    {
        CheckLengths(xs, ys);
        // ScottPlot joins across NaN; split the series at every non-finite point instead, one legend entry.
        bool labelled = false;
        int start = 0;
        for (int i = 0; i <= xs.Count; i++)
        {
            if (i < xs.Count && double.IsFinite(xs[i]) && double.IsFinite(ys[i])) continue;
            if (i > start)
            {
                var scatter = plot.Add.ScatterLine(Slice(xs, start, i), Slice(ys, start, i), colour);
                scatter.LineWidth = LineWidth;
                if (dashed) scatter.LinePattern = LinePattern.Dashed;
                if (!labelled) scatter.LegendText = label;
                labelled = true;
            }

            start = i + 1;
        }
    }

    /// <summary>Markers at (xs[i], ys[i]); non-finite points are left out.</summary>
    public static ScottPlot.Plottables.Scatter Points(Plot plot, IReadOnlyList<double> xs, IReadOnlyList<double> ys, string label, Color colour)
    {
        CheckLengths(xs, ys);
        var fx = new List<double>();
        var fy = new List<double>();
        for (int i = 0; i < xs.Count; i++)
        {
            if (!double.IsFinite(xs[i]) || !double.IsFinite(ys[i])) continue;
            fx.Add(xs[i]);
            fy.Add(ys[i]);
        }

        var scatter = plot.Add.ScatterPoints(fx.ToArray(), fy.ToArray(), colour);
        scatter.MarkerSize = MarkerSize;
        scatter.LegendText = label;
        return scatter;
    }

    /// <summary>A small text beside a data point (a point's name).</summary>
    public static void Note(Plot plot, double x, double y, string text)
    {
        if (!double.IsFinite(x) || !double.IsFinite(y) || string.IsNullOrEmpty(text)) return;
        var note = plot.Add.Text(text, x, y);
        note.LabelFontSize = 12;
        note.LabelFontColor = TextColour;
        note.LabelAlignment = Alignment.LowerLeft;
        note.LabelOffsetX = 6;
        note.LabelOffsetY = -4;
    }

    /// <summary>
    /// Writes the plot as a PNG of exactly <paramref name="width"/> x <paramref name="height"/> pixels at
    /// <paramref name="pngPath"/>, and when <paramref name="svg"/> also an SVG of the same size beside it (same
    /// name, extension <c>.svg</c>). Each file is written to a temporary file in its folder and then renamed, so a
    /// failure leaves no half-written chart. The folder is created if missing.
    /// </summary>
    public static void Save(Plot plot, string pngPath, int width, int height, bool svg)
    {
        ArgumentNullException.ThrowIfNull(plot);
        ArgumentException.ThrowIfNullOrEmpty(pngPath);
        if (width <= 0 || width > MaxSide) throw new ArgumentOutOfRangeException(nameof(width), width, $"Width must be 1..{MaxSide}.");
        if (height <= 0 || height > MaxSide) throw new ArgumentOutOfRangeException(nameof(height), height, $"Height must be 1..{MaxSide}.");

        string? directory = Path.GetDirectoryName(Path.GetFullPath(pngPath));
        if (!string.IsNullOrEmpty(directory)) Directory.CreateDirectory(directory);

        bool legend = plot.GetPlottables().Any(p => p.LegendItems.Any(item => !string.IsNullOrEmpty(item.LabelText)));
        plot.Legend.IsVisible = legend;

        byte[] png = plot.GetImageBytes(width, height, ImageFormat.Png);
        Kosmos.PseudoHaptic.Evaluation.AtomicFile.WriteWith(pngPath, temp => File.WriteAllBytes(temp, png));
        if (svg)
        {
            string svgText = plot.GetSvgXml(width, height);
            Kosmos.PseudoHaptic.Evaluation.AtomicFile.WriteAllText(Path.ChangeExtension(pngPath, ".svg"), svgText);
        }
    }

    private static void CheckLengths(IReadOnlyList<double> xs, IReadOnlyList<double> ys)
    {
        ArgumentNullException.ThrowIfNull(xs);
        ArgumentNullException.ThrowIfNull(ys);
        if (xs.Count != ys.Count) throw new ArgumentException($"xs has {xs.Count} values but ys has {ys.Count}.", nameof(ys));
    }

    private static double[] Slice(IReadOnlyList<double> values, int from, int to)
    {
        var slice = new double[to - from];
        for (int i = from; i < to; i++) slice[i - from] = values[i];
        return slice;
    }
}
