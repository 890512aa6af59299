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

    /// <summary>
    /// The sans-serif font of every chart. SkiaSharp's Linux assets here come without fontconfig, so a family
    /// name alone falls back to whatever typeface comes first (a serif one on Debian); the usual sans-serif
    /// files are therefore registered by path when present. Elsewhere (Windows, macOS) the system finds it.
    /// </summary>
    private static readonly Lazy<string> FontName = new(() =>
    {
        const string name = "PseudoHaptic Sans";
        string[] folders = { "/usr/share/fonts/truetype/dejavu", "/usr/share/fonts/dejavu", "/usr/share/fonts/TTF", "/usr/share/fonts/truetype/liberation" };
        (string Regular, string Bold)[] files = { ("DejaVuSans.ttf", "DejaVuSans-Bold.ttf"), ("LiberationSans-Regular.ttf", "LiberationSans-Bold.ttf") };
        foreach (string folder in folders)
        {
            foreach (var (regular, bold) in files)
            {
                string r = Path.Combine(folder, regular), b = Path.Combine(folder, bold);
                if (!File.Exists(r)) continue;
                Fonts.AddFontFile(name, File.Exists(b) ? b : r, bold: true, italic: false);
                Fonts.AddFontFile(name, r, bold: false, italic: false);
                return name;
            }
        }

        return Fonts.Sans;
    });

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
        plot.Font.Set(FontName.Value);

        plot.Title(title ?? "", TitleSize);
        plot.Axes.Title.Label.ForeColor = TextColour;
        plot.Axes.Title.Label.Bold = true;
        plot.XLabel(xLabel ?? "", LabelSize);
        plot.YLabel(yLabel ?? "", LabelSize);
        foreach (IAxis axis in new IAxis[] { plot.Axes.Bottom, plot.Axes.Left })
        {
            // Ticks about 90 px apart, every label with the same number of decimals (0.80, 0.85, ... not 0.8, 0.85).
            axis.TickGenerator = new ScottPlot.TickGenerators.NumericAutomatic { MinimumTickSpacing = 40, TickDensity = axis == plot.Axes.Bottom ? 0.5 : 0.6 };
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
        plot.Legend.ShadowColor = Colors.Transparent;
        plot.Legend.SymbolWidth = 32;
        plot.Legend.Alignment = Alignment.UpperLeft;
        plot.Axes.Margins(horizontal: 0.01, vertical: 0.05);
        plot.Legend.IsVisible = true;
        return plot;
    }

    /// <summary>A line through (xs[i], ys[i]) in order; a non-finite point breaks the line.</summary>
    public static void Line(Plot plot, IReadOnlyList<double> xs, IReadOnlyList<double> ys, string label, Color colour, bool dashed = false)
        => Line(plot, xs, ys, label, colour, dashed ? LinePattern.Dashed : LinePattern.Solid, LineWidth);

    /// <summary>Line patterns that stay apart in grey print: series i takes pattern i (solid, dotted, densely dashed, dashed).</summary>
    static readonly LinePattern[] Patterns = { LinePattern.Solid, LinePattern.Dotted, LinePattern.DenselyDashed, LinePattern.Dashed };

    public static LinePattern Pattern(int i) => Patterns[((i % Patterns.Length) + Patterns.Length) % Patterns.Length];

    /// <summary>
    /// The i-th object of a chart: colour i, line pattern i and a width that grows a little with i, so every line
    /// stays visible (and apart in grey print) where objects move together.
    /// </summary>
    public static void Series(Plot plot, IReadOnlyList<double> xs, IReadOnlyList<double> ys, string label, int i)
        => Line(plot, xs, ys, label, Colour(i), Pattern(i), LineWidth + 0.5f * (i % Patterns.Length));

    /// <summary>
    /// The hand, drawn last so it lies over the objects: black, dashed, thin. An object that follows the hand exactly
    /// (gain 1) shows between its dashes, in colour and in grey print.
    /// </summary>
    public static void Hand(Plot plot, IReadOnlyList<double> xs, IReadOnlyList<double> ys, string label)
        => Line(plot, xs, ys, label, Black, LinePattern.Dashed, 1.5f);

    /// <summary>The legend outside the data, in rows under the plot: it never covers a line.</summary>
    public static void LegendBelow(Plot plot)
    {
        plot.ShowLegend(Edge.Bottom);
        plot.Legend.Orientation = Orientation.Horizontal;
    }

    /// <summary>A horizontal reference line (a threshold) with its name in the legend; grey unless a colour is given (the object's).</summary>
    public static void Threshold(Plot plot, double y, string label, Color? colour = null)
    {
        var line = plot.Add.HorizontalLine(y);
        line.Color = colour ?? Color.FromHex("#505050");
        line.LineWidth = 1.5f;
        line.LinePattern = LinePattern.Dashed;
        line.LegendText = label;
    }

    /// <summary>
    /// The i-th object's alternative path (what it does without an effect) as a light, wide band in its colour: drawn
    /// before the objects' lines, it shows around them where they coincide and alone where they part.
    /// </summary>
    public static void Band(Plot plot, IReadOnlyList<double> xs, IReadOnlyList<double> ys, string label, int i)
        => Line(plot, xs, ys, label, Colour(i).WithAlpha(0.35), LinePattern.Solid, 7);

    /// <summary>
    /// The i-th object as markers (its colour and shape i) every <paramref name="every"/> of x (seconds), no line: for an
    /// object that moves with the hand, so it shows beside the hand's line rather than under it.
    /// </summary>
    public static void Markers(Plot plot, IReadOnlyList<double> xs, IReadOnlyList<double> ys, string label, int i, double every)
    {
        CheckLengths(xs, ys);
        var mx = new List<double>();
        var my = new List<double>();
        double next = double.NegativeInfinity;
        for (int k = 0; k < xs.Count; k++)
        {
            if (!double.IsFinite(xs[k]) || !double.IsFinite(ys[k]) || xs[k] < next) continue;
            mx.Add(xs[k]);
            my.Add(ys[k]);
            next = xs[k] + every;
        }
        var scatter = plot.Add.ScatterPoints(mx.ToArray(), my.ToArray(), Colour(i));
        scatter.MarkerSize = MarkerSize;
        scatter.MarkerShape = Shape(i);
        scatter.LegendText = label;
    }

    /// <summary>A chart with nothing to draw: its title and one sentence saying why, instead of empty axes.</summary>
    public static Plot Empty(string title, string sentence)
    {
        var plot = Create(title, "", "");
        plot.Axes.Frameless();
        plot.HideGrid();
        plot.Axes.SetLimits(0, 1, 0, 1);
        var text = plot.Add.Text(Wrap(sentence, 80), 0.5, 0.5);
        text.LabelFontSize = LabelSize;
        text.LabelFontName = FontName.Value;
        text.LabelFontColor = TextColour;
        text.LabelAlignment = Alignment.MiddleCenter;
        return plot;
    }

    /// <summary>
    /// Lines of text as a panel under a chart (the tests behind its p values), each wrapped to the width; returns the
    /// plot and the height it needs.
    /// </summary>
    public static (Plot Plot, int Height) TextPanel(IReadOnlyList<string> lines, int width)
    {
        int chars = Math.Max(40, (int)(width / (NoteSize * 0.62)) - 4);
        var wrapped = lines.Select(l => Wrap(l, chars)).ToList();
        int count = wrapped.Sum(l => l.Split('\n').Length);
        int height = 30 + (int)Math.Ceiling(count * (NoteSize + 2) * 1.35);
        var plot = Create("", "", "");
        plot.Axes.Frameless();
        plot.HideGrid();
        plot.Axes.SetLimits(0, 1, 0, 1);
        var text = plot.Add.Text(string.Join("\n", wrapped), 0.01, 0.98);
        text.LabelFontSize = NoteSize + 2;
        text.LabelFontName = FontName.Value;
        text.LabelFontColor = TextColour;
        text.LabelAlignment = Alignment.UpperLeft;
        text.LabelLineSpacing = (NoteSize + 2) * 1.3f;
        return (plot, height);
    }

    /// <summary>Text broken into lines of at most <paramref name="width"/> characters at spaces (a long word stays whole).</summary>
    public static string Wrap(string text, int width) => Kosmos.PseudoHaptic.Evaluation.TextWrap.Wrap(text ?? "", width);

    /// <summary>
    /// Panels stacked top to bottom into one PNG of <paramref name="width"/> pixels: one quantity per panel (x, y, z
    /// apart), each laid out by ScottPlot on its own (<see cref="SavePanels"/> first aligns their data areas).
    /// </summary>
    public static byte[] PanelsPng(IReadOnlyList<Plot> panels, int width, IReadOnlyList<int> heights)
    {
        using var surface = SkiaSharp.SKSurface.Create(new SkiaSharp.SKImageInfo(width, heights.Sum()));
        var canvas = surface.Canvas;
        canvas.Clear(SkiaSharp.SKColors.White);
        int top = 0;
        for (int i = 0; i < panels.Count; i++)
        {
            using var bitmap = SkiaSharp.SKBitmap.Decode(Png(panels[i], width, heights[i]));
            canvas.DrawBitmap(bitmap, 0, top);
            top += heights[i];
        }
        using var image = surface.Snapshot();
        using var data = image.Encode(SkiaSharp.SKEncodedImageFormat.Png, 100);
        return data.ToArray();
    }

    /// <summary>
    /// Gives stacked panels the same data-area left and right edges (issue 32: z's wider tick labels moved its time
    /// axis 19 px right of the others'): each panel's left and right axes are widened to the widest's.
    /// </summary>
    public static void Align(IReadOnlyList<Plot> panels, int width, IReadOnlyList<int> heights)
    {
        // The data area starts after the figure's padding and the left axis (ticks, labels, title); widening every
        // left axis to at least the largest start seen makes them all the same size, hence the same start.
        var rects = panels.Select((p, i) => { Prepare(p, width, heights[i]); return p.RenderManager.LastRender.DataRect; }).ToList();
        float left = (float)Math.Ceiling(rects.Max(r => r.Left)), right = (float)Math.Ceiling(rects.Max(r => width - r.Right));
        foreach (var p in panels)
        {
            p.Axes.Left.MinimumSize = left;
            p.Axes.Right.MinimumSize = right;
        }
    }

    /// <summary>The panels of <see cref="PanelsPng"/> as one SVG document (each panel's SVG nested at its offset).</summary>
    public static string PanelsSvg(IReadOnlyList<Plot> panels, int width, IReadOnlyList<int> heights)
    {
        var sb = new System.Text.StringBuilder($"<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{width}\" height=\"{heights.Sum()}\" viewBox=\"0 0 {width} {heights.Sum()}\">\n");
        int top = 0;
        for (int i = 0; i < panels.Count; i++)
        {
            string inner = Svg(panels[i], width, heights[i]);
            int start = inner.IndexOf("<svg", StringComparison.Ordinal);
            sb.Append($"<g transform=\"translate(0,{top})\">").Append(start >= 0 ? inner[start..] : inner).Append("</g>\n");
            top += heights[i];
        }
        return sb.Append("</svg>\n").ToString();
    }

    /// <summary><see cref="Save"/> for stacked panels.</summary>
    public static void SavePanels(IReadOnlyList<Plot> panels, string pngPath, int width, IReadOnlyList<int> heights, bool svg)
    {
        Align(panels, width, heights);
        byte[] png = PanelsPng(panels, width, heights);
        string? svgText = svg ? PanelsSvg(panels, width, heights) : null;
        Kosmos.PseudoHaptic.Evaluation.AtomicFile.WriteWith(pngPath, temp => File.WriteAllBytes(temp, png));
        if (svgText != null) Kosmos.PseudoHaptic.Evaluation.AtomicFile.WriteAllText(Path.ChangeExtension(pngPath, ".svg"), svgText);
    }

    static void Line(Plot plot, IReadOnlyList<double> xs, IReadOnlyList<double> ys, string label, Color colour, LinePattern pattern, float width)
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
                scatter.LineWidth = width;
                scatter.LinePattern = pattern;
                if (!labelled) scatter.LegendText = label;
                labelled = true;
            }

            start = i + 1;
        }
    }

    /// <summary>Markers at (xs[i], ys[i]); non-finite points are left out.</summary>
    /// <summary>Marker shapes that stay apart in grey print: series i takes shape i.</summary>
    static readonly MarkerShape[] Shapes = { MarkerShape.FilledCircle, MarkerShape.FilledSquare, MarkerShape.FilledTriangleUp, MarkerShape.FilledDiamond, MarkerShape.OpenCircle, MarkerShape.FilledTriangleDown };

    public static MarkerShape Shape(int i) => Shapes[((i % Shapes.Length) + Shapes.Length) % Shapes.Length];

    /// <summary>Vertical error bars (a 95 % interval: <paramref name="low"/> to <paramref name="high"/>) in <paramref name="colour"/>.</summary>
    public static void ErrorBars(Plot plot, IReadOnlyList<double> xs, IReadOnlyList<double> low, IReadOnlyList<double> high, Color colour)
    {
        for (int i = 0; i < xs.Count; i++)
        {
            if (!double.IsFinite(xs[i]) || !double.IsFinite(low[i]) || !double.IsFinite(high[i])) continue;
            var bar = plot.Add.Line(xs[i], low[i], xs[i], high[i]);
            bar.Color = colour;
            bar.LineWidth = 1.5f;
            bar.MarkerSize = 0;
        }
    }

    public static ScottPlot.Plottables.Scatter Points(Plot plot, IReadOnlyList<double> xs, IReadOnlyList<double> ys, string label, Color colour, int shape = 0)
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
        scatter.MarkerShape = Shape(shape);
        scatter.LegendText = label;
        return scatter;
    }

    /// <summary>Font size of a <see cref="Note"/> (pixels).</summary>
    public const float NoteSize = 12;

    /// <summary>Height of a <see cref="Note"/>'s box (pixels), for placing notes apart.</summary>
    public const double NoteHeight = NoteSize + 4;

    /// <summary>Width of a <see cref="Note"/>'s box (pixels), for placing notes apart.</summary>
    public static double NoteWidth(string text)
    {
        var style = new LabelStyle { FontSize = NoteSize, FontName = FontName.Value, Text = text ?? "" };
        using var paint = Paint.NewDisposablePaint();
        return style.Measure(text ?? "", paint).Width;
    }

    /// <summary>A small text whose top-left corner is at data point (x, y): a point's name.</summary>
    public static void Note(Plot plot, double x, double y, string text)
    {
        if (!double.IsFinite(x) || !double.IsFinite(y) || string.IsNullOrEmpty(text)) return;
        var note = plot.Add.Text(text, x, y);
        note.LabelFontSize = NoteSize;
        note.LabelFontName = FontName.Value;
        note.LabelFontColor = TextColour;
        note.LabelAlignment = Alignment.UpperLeft;
    }

    /// <summary>
    /// Ticks for a base-10 logarithmic axis whose data are plotted as log10(value) between log10(min) and
    /// log10(max): labelled at 1, 2 and 5 of each decade (in the values' own units), minor lines between.
    /// </summary>
    public static ITickGenerator LogTicks(double min, double max)
    {
        var ticks = new ScottPlot.TickGenerators.NumericManual();
        for (int decade = (int)Math.Floor(Math.Log10(min)); decade <= (int)Math.Ceiling(Math.Log10(max)); decade++)
        {
            for (int m = 1; m <= 9; m++)
            {
                double value = m * Math.Pow(10, decade);
                if (value < min * (1 - 1e-9) || value > max * (1 + 1e-9)) continue;
                if (m == 1 || m == 2 || m == 5) ticks.AddMajor(Math.Log10(value), value.ToString("G6", System.Globalization.CultureInfo.InvariantCulture));
                else ticks.AddMinor(Math.Log10(value));
            }
        }

        return ticks;
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
        byte[] png = Png(plot, width, height);
        string? svgText = svg ? Svg(plot, width, height) : null;

        string? directory = Path.GetDirectoryName(Path.GetFullPath(pngPath));
        if (!string.IsNullOrEmpty(directory)) Directory.CreateDirectory(directory);
        Kosmos.PseudoHaptic.Evaluation.AtomicFile.WriteWith(pngPath, temp => File.WriteAllBytes(temp, png));
        if (svgText != null) Kosmos.PseudoHaptic.Evaluation.AtomicFile.WriteAllText(Path.ChangeExtension(pngPath, ".svg"), svgText);
    }


    /// <summary>
    /// For tests (this thread only): called with every plot <see cref="Png"/> draws, laid out at its size, so a test can
    /// inspect each chart's series (ChartInk in the tests: every series' ink visible against the others).
    /// </summary>
    [ThreadStatic] public static Action<Plot, int, int>? Drawing;

    /// <summary>The plot as PNG bytes of exactly <paramref name="width"/> x <paramref name="height"/> pixels.</summary>
    public static byte[] Png(Plot plot, int width, int height)
    {
        Prepare(plot, width, height);
        byte[] png = plot.GetImageBytes(width, height, ImageFormat.Png);
        Drawing?.Invoke(plot, width, height);
        return png;
    }

    /// <summary>The plot as an SVG document of <paramref name="width"/> x <paramref name="height"/> pixels.</summary>
    public static string Svg(Plot plot, int width, int height)
    {
        Prepare(plot, width, height);
        return plot.GetSvgXml(width, height);
    }

    private static void Prepare(Plot plot, int width, int height)
    {
        ArgumentNullException.ThrowIfNull(plot);
        if (width <= 0 || width > MaxSide) throw new ArgumentOutOfRangeException(nameof(width), width, $"Width must be 1..{MaxSide}.");
        if (height <= 0 || height > MaxSide) throw new ArgumentOutOfRangeException(nameof(height), height, $"Height must be 1..{MaxSide}.");
        // A legend only when a series has a name.
        if (!plot.GetPlottables().Any(p => p.LegendItems.Any(item => !string.IsNullOrEmpty(item.LabelText)))) plot.HideLegend();

        // Lay the plot out once to learn the tick steps, then label every tick of an axis with the decimals its
        // step needs (0.80, 0.85, 0.90 rather than 0.8, 0.85, 0.9).
        plot.RenderInMemory(width, height);
        foreach (IAxis axis in new IAxis[] { plot.Axes.Bottom, plot.Axes.Left })
        {
            if (axis.TickGenerator is not ScottPlot.TickGenerators.NumericAutomatic numeric) continue;
            double step = double.PositiveInfinity;
            double previous = double.NaN;
            foreach (Tick tick in numeric.Ticks.Where(t => t.IsMajor).OrderBy(t => t.Position))
            {
                if (double.IsFinite(previous) && tick.Position - previous > 0) step = Math.Min(step, tick.Position - previous);
                previous = tick.Position;
            }

            if (!double.IsFinite(step)) continue;
            int decimals = 0;
            while (decimals < 10 && Math.Abs(step * Math.Pow(10, decimals) - Math.Round(step * Math.Pow(10, decimals))) > 1e-6 * step * Math.Pow(10, decimals)) decimals++;
            string format = "F" + decimals.ToString(System.Globalization.CultureInfo.InvariantCulture);
            numeric.LabelFormatter = value => value.ToString(format, System.Globalization.CultureInfo.InvariantCulture);
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
