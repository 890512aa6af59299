namespace Kosmos.PseudoHaptic.Cli.Plotting;

/// <summary>
/// A line/scatter chart rendered to PNG without external libraries: white background, light-grey grid at "nice"
/// ticks, dark-grey axes, 2-px lines, legend at the top left inside the plot. Axis ranges come from the data
/// unless <see cref="XMin"/> etc. are set; <see cref="LogX"/> gives a base-10 logarithmic x axis.
/// Non-finite points (and x ≤ 0 on a log axis) are skipped and break a line.
/// </summary>
/// <example><code>
/// var chart = new LineChart(900, 500) { Title = "Drop", XLabel = "time (s)", YLabel = "height (m)" };
/// chart.AddLine(ts, hs, Palette.Get(0), "solver");
/// chart.Save("drop.png");
/// </code></example>
public sealed class LineChart
{
    private const int Pad = 12;
    private const int TickLength = 5;
    private const double LineThickness = 2;
    private const double MarkerRadius = 4;
    private const double DashOn = 8;
    private const double DashOff = 6;

    private static readonly Rgb AxisColour = new(0x40, 0x40, 0x40);
    private static readonly Rgb TextColour = new(0x20, 0x20, 0x20);
    private static readonly Rgb GridColour = new(0xDC, 0xDC, 0xDC);
    private static readonly Rgb MinorGridColour = new(0xF0, 0xF0, 0xF0);
    private static readonly Rgb LegendBorderColour = new(0xB4, 0xB4, 0xB4);

    private readonly List<ChartSeries> _series = new();
    private PlotFrame? _lastFrame;
    private int _textScale;

    public LineChart(int width = 900, int height = 500)
    {
        if (width <= 0 || width > Raster.MaxSide) throw new ArgumentOutOfRangeException(nameof(width), width, $"Width must be 1..{Raster.MaxSide}.");
        if (height <= 0 || height > Raster.MaxSide) throw new ArgumentOutOfRangeException(nameof(height), height, $"Height must be 1..{Raster.MaxSide}.");
        Width = width;
        Height = height;
        _textScale = width >= 480 && height >= 280 ? 2 : 1;
    }

    public int Width { get; }

    public int Height { get; }

    /// <summary>Drawn centred above the plot; null or blank for none.</summary>
    public string? Title { get; set; }

    /// <summary>Drawn centred below the x axis; null or blank for none.</summary>
    public string? XLabel { get; set; }

    /// <summary>Drawn vertically (reading upwards) left of the y axis; null or blank for none.</summary>
    public string? YLabel { get; set; }

    /// <summary>Base-10 logarithmic x axis; points with x ≤ 0 are then skipped.</summary>
    public bool LogX { get; set; }

    /// <summary>Fixes the left end of the x axis instead of taking it from the data.</summary>
    public double? XMin { get; set; }

    /// <summary>Fixes the right end of the x axis instead of taking it from the data.</summary>
    public double? XMax { get; set; }

    /// <summary>Fixes the bottom of the y axis instead of taking it from the data.</summary>
    public double? YMin { get; set; }

    /// <summary>Fixes the top of the y axis instead of taking it from the data.</summary>
    public double? YMax { get; set; }

    /// <summary>Whether labelled series are listed in a legend (inside the plot).</summary>
    public bool ShowLegend { get; set; } = true;

    /// <summary>
    /// Corner of the legend. <see cref="Plotting.LegendPosition.Best"/> (the default) keeps it top left unless another
    /// corner hides less data.
    /// </summary>
    public LegendPosition LegendPosition { get; set; } = LegendPosition.Best;

    /// <summary>Integer font scale of the text (5x7 font pixels); 2 by default, 1 for small charts.</summary>
    public int TextScale
    {
        get => _textScale;
        set => _textScale = Math.Clamp(value, 1, 8);
    }

    /// <summary>Number of series added so far.</summary>
    public int SeriesCount => _series.Count;

    /// <summary>Adds a polyline through (xs[i], ys[i]) in order. The arrays are copied.</summary>
    public void AddLine(IReadOnlyList<double> xs, IReadOnlyList<double> ys, Rgb colour, string label, bool dashed = false) =>
        Add(xs, ys, colour, label, SeriesKind.Line, dashed, null);

    /// <summary>Adds scatter markers at (xs[i], ys[i]). The arrays are copied.</summary>
    public void AddPoints(IReadOnlyList<double> xs, IReadOnlyList<double> ys, Rgb colour, string label) =>
        Add(xs, ys, colour, label, SeriesKind.Points, false, null);

    /// <summary>
    /// Adds scatter markers, each with a small text label beside it (<paramref name="pointLabels"/>[i], null or empty
    /// for none; may be null altogether, else as long as <paramref name="xs"/>).
    /// </summary>
    public void AddPoints(IReadOnlyList<double> xs, IReadOnlyList<double> ys, Rgb colour, string label,
        IReadOnlyList<string?>? pointLabels) =>
        Add(xs, ys, colour, label, SeriesKind.Points, false, pointLabels);

    /// <summary>Encodes the chart as PNG bytes.</summary>
    public byte[] ToPng() => Render().ToPng();

    /// <summary>Writes the chart as a PNG file, creating its directory if needed.</summary>
    public void Save(string path)
    {
        ArgumentException.ThrowIfNullOrEmpty(path);
        byte[] png = ToPng();
        string? directory = Path.GetDirectoryName(Path.GetFullPath(path));
        if (!string.IsNullOrEmpty(directory)) Directory.CreateDirectory(directory);
        File.WriteAllBytes(path, png);
    }

    /// <summary>
    /// The pixel position (continuous coordinates) of a data point in the layout of the most recent
    /// <see cref="Render"/> (also done by <see cref="ToPng"/> and <see cref="Save"/>).
    /// </summary>
    public (double X, double Y) DataToPixel(double x, double y)
    {
        if (_lastFrame is not { } frame) throw new InvalidOperationException("Render the chart before mapping data to pixels.");
        return (frame.MapX(x), frame.MapY(y));
    }

    /// <summary>Draws the chart into a new raster.</summary>
    public Raster Render()
    {
        var raster = new Raster(Width, Height, Rgb.White);
        int s = TextScale;
        int textHeight = BitmapFont.MeasureHeight(s);
        bool hasTitle = !string.IsNullOrWhiteSpace(Title);
        bool hasXLabel = !string.IsNullOrWhiteSpace(XLabel);
        bool hasYLabel = !string.IsNullOrWhiteSpace(YLabel);
        int titleScale = hasTitle && BitmapFont.MeasureWidth(Title!, s) > Width - 2 * Pad ? 1 : s;

        // Vertical layout first: the y ticks depend only on the plot height.
        int top = hasTitle ? Pad + BitmapFont.MeasureHeight(titleScale) + Pad : Pad + textHeight / 2;
        int bottom = TickLength + 6 + textHeight + (hasXLabel ? 10 + textHeight : 0) + Pad;
        int plotHeight = Math.Max(1, Height - top - bottom);

        (AxisRange xRange, AxisRange yRange) = ComputeRanges();

        double yStep = AxisTicks.NiceStep(yRange.Span, Math.Max(2, plotHeight / (3 * textHeight + 8)));
        IReadOnlyList<double> yTicks = AxisTicks.Linear(yRange.Min, yRange.Max, yStep);
        var yTickLabels = yTicks.Select(v => AxisTicks.FormatLinear(v, yStep)).ToList();
        int yTickLabelWidth = yTickLabels.Count == 0 ? 0 : yTickLabels.Max(l => BitmapFont.MeasureWidth(l, s));

        int left = Pad + (hasYLabel ? textHeight + 10 : 0) + yTickLabelWidth + 6 + TickLength;
        int right = 2 * Pad;
        int plotWidth = Math.Max(1, Width - left - right);

        (IReadOnlyList<double> xTicks, List<string> xTickLabels) = XTicks(xRange, plotWidth, s);

        var frame = new PlotFrame(left, top, plotWidth, plotHeight, xRange.Min, xRange.Max, yRange.Min, yRange.Max, LogX);
        _lastFrame = frame;

        DrawGrid(raster, frame, xTicks, yTicks);

        raster.SetClip(frame.Left, frame.Top, frame.Width, frame.Height);
        // Lines first, so markers stay visible on top of them.
        foreach (ChartSeries series in _series.Where(e => e.Kind == SeriesKind.Line)) DrawPolyline(raster, frame, series);
        foreach (ChartSeries series in _series.Where(e => e.Kind == SeriesKind.Points)) DrawMarkers(raster, frame, series);

        foreach (ChartSeries series in _series)
        {
            if (series.PointLabels is not null) DrawPointLabels(raster, frame, series, Math.Max(1, s - 1));
        }

        if (ShowLegend) DrawLegend(raster, frame, s);
        raster.ResetClip();

        DrawAxes(raster, frame, xTicks, xTickLabels, yTicks, yTickLabels, s);

        if (hasXLabel)
        {
            int w = BitmapFont.MeasureWidth(XLabel!, s);
            int x = Math.Max(0, frame.Left + (frame.Width - w) / 2);
            int y = frame.Bottom + 1 + TickLength + 6 + textHeight + 10;
            BitmapFont.DrawText(raster, x, y, XLabel!, TextColour, s);
        }

        if (hasYLabel)
        {
            int length = BitmapFont.MeasureWidth(YLabel!, s);
            int y = Math.Max(0, frame.Top + (frame.Height - length) / 2);
            BitmapFont.DrawTextVertical(raster, Pad, y, YLabel!, TextColour, s);
        }

        if (hasTitle)
        {
            int w = BitmapFont.MeasureWidth(Title!, titleScale) + 1;
            int x = Math.Clamp(frame.Left + (frame.Width - w) / 2, 0, Math.Max(0, Width - w));
            // Bold: the same text twice, one pixel apart.
            BitmapFont.DrawText(raster, x, Pad, Title!, TextColour, titleScale);
            BitmapFont.DrawText(raster, x + 1, Pad, Title!, TextColour, titleScale);
        }

        return raster;
    }

    private void Add(IReadOnlyList<double> xs, IReadOnlyList<double> ys, Rgb colour, string label, SeriesKind kind,
        bool dashed, IReadOnlyList<string?>? pointLabels)
    {
        ArgumentNullException.ThrowIfNull(xs);
        ArgumentNullException.ThrowIfNull(ys);
        if (xs.Count != ys.Count)
        {
            throw new ArgumentException($"xs has {xs.Count} values but ys has {ys.Count}.", nameof(ys));
        }

        if (pointLabels is not null && pointLabels.Count != xs.Count)
        {
            throw new ArgumentException($"pointLabels has {pointLabels.Count} entries for {xs.Count} points.", nameof(pointLabels));
        }

        _series.Add(new ChartSeries(xs.ToArray(), ys.ToArray(), colour, label ?? string.Empty, kind, dashed,
            pointLabels?.ToArray()));
    }

    private bool IsDrawable(double x, double y) => double.IsFinite(x) && double.IsFinite(y) && (!LogX || x > 0);

    /// <summary>The axis ranges, from the drawable data and the fixed ends.</summary>
    private (AxisRange X, AxisRange Y) ComputeRanges()
    {
        double xLo = double.PositiveInfinity, xHi = double.NegativeInfinity;
        double yLo = double.PositiveInfinity, yHi = double.NegativeInfinity;
        bool anyPoints = false;
        foreach (ChartSeries series in _series)
        {
            for (int i = 0; i < series.Xs.Length; i++)
            {
                double x = series.Xs[i], y = series.Ys[i];
                if (!IsDrawable(x, y)) continue;
                xLo = Math.Min(xLo, x);
                xHi = Math.Max(xHi, x);
                yLo = Math.Min(yLo, y);
                yHi = Math.Max(yHi, y);
                anyPoints |= series.Kind == SeriesKind.Points;
            }
        }

        bool hasData = xLo <= xHi;
        AxisRange xRange = LogX
            ? LogRange(xLo, xHi, hasData, XMin, XMax)
            : LinearRange(xLo, xHi, hasData, anyPoints ? 0.04 : 0, XMin, XMax);
        return (xRange, LinearRange(yLo, yHi, hasData, 0.05, YMin, YMax));
    }

    private static AxisRange LinearRange(double dataMin, double dataMax, bool hasData, double margin, double? fixedMin, double? fixedMax)
    {
        const double Limit = 1e300; // keeps max - min finite
        double lo = hasData ? Math.Max(dataMin, -Limit) : 0;
        double hi = hasData ? Math.Min(dataMax, Limit) : 1;
        if (hi <= lo) (lo, hi) = Widen(lo);
        double span = hi - lo;
        bool fixLo = fixedMin is { } fMin && double.IsFinite(fMin);
        bool fixHi = fixedMax is { } fMax && double.IsFinite(fMax);
        lo = fixLo ? Math.Clamp(fixedMin!.Value, -Limit, Limit) : lo - margin * span;
        hi = fixHi ? Math.Clamp(fixedMax!.Value, -Limit, Limit) : hi + margin * span;
        if (hi < lo) (lo, hi) = (hi, lo);
        if (hi <= lo) (lo, hi) = Widen(lo);
        return new AxisRange(lo, hi);

        static (double, double) Widen(double v)
        {
            double d = v == 0 ? 1 : Math.Abs(v) * 0.1;
            return (v - d, v + d);
        }
    }

    private static AxisRange LogRange(double dataMin, double dataMax, bool hasData, double? fixedMin, double? fixedMax)
    {
        double lo = hasData ? Math.Pow(10, Math.Floor(Math.Log10(dataMin))) : 1;
        double hi = hasData ? Math.Pow(10, Math.Ceiling(Math.Log10(dataMax))) : 10;
        if (!(lo > 0)) lo = hasData ? dataMin : 1;
        if (!double.IsFinite(hi)) hi = hasData ? dataMax : 10;
        if (fixedMin is { } fMin && fMin > 0 && double.IsFinite(fMin)) lo = fMin;
        if (fixedMax is { } fMax && fMax > 0 && double.IsFinite(fMax)) hi = fMax;
        if (hi < lo) (lo, hi) = (hi, lo);
        if (hi <= lo)
        {
            lo /= 10;
            hi *= 10;
        }

        return new AxisRange(lo, hi);
    }

    private (IReadOnlyList<double> Ticks, List<string> Labels) XTicks(AxisRange range, int plotWidth, int s)
    {
        int charWidth = BitmapFont.Advance * s;
        if (LogX)
        {
            int target = Math.Max(2, plotWidth / (6 * charWidth));
            IReadOnlyList<double> decades = AxisTicks.Decades(range.Min, range.Max, target);
            return (decades, decades.Select(AxisTicks.FormatLog).ToList());
        }

        // Ask for fewer ticks until the labels have room (at least two characters between neighbours).
        IReadOnlyList<double> ticks = Array.Empty<double>();
        List<string> labels = new();
        for (int target = Math.Max(2, plotWidth / (8 * charWidth)); target >= 1; target--)
        {
            double step = AxisTicks.NiceStep(range.Span, target);
            ticks = AxisTicks.Linear(range.Min, range.Max, step);
            labels = ticks.Select(v => AxisTicks.FormatLinear(v, step)).ToList();
            int widest = labels.Count == 0 ? 0 : labels.Max(l => BitmapFont.MeasureWidth(l, s));
            if (widest + 2 * charWidth <= step / range.Span * plotWidth) break;
        }

        return (ticks, labels);
    }

    private static void DrawGrid(Raster raster, PlotFrame frame, IReadOnlyList<double> xTicks, IReadOnlyList<double> yTicks)
    {
        if (frame.LogX && xTicks.Count > 0)
        {
            double decades = Math.Log10(frame.XMax) - Math.Log10(frame.XMin);
            if (decades * 40 <= frame.Width)
            {
                int first = (int)Math.Floor(Math.Log10(frame.XMin)), last = (int)Math.Ceiling(Math.Log10(frame.XMax));
                for (int k = first; k <= last; k++)
                {
                    for (int m = 2; m <= 9; m++)
                    {
                        double v = m * Math.Pow(10, k);
                        if (v > frame.XMin && v < frame.XMax) VerticalGridLine(raster, frame, frame.MapX(v), MinorGridColour);
                    }
                }
            }
        }

        foreach (double v in xTicks) VerticalGridLine(raster, frame, frame.MapX(v), GridColour);
        foreach (double v in yTicks)
        {
            int row = PixelIndex(frame.MapY(v), frame.Top, frame.Bottom);
            if (row >= 0) raster.FillRect(frame.Left, row, frame.Width, 1, GridColour);
        }
    }

    private static void VerticalGridLine(Raster raster, PlotFrame frame, double px, Rgb colour)
    {
        int col = PixelIndex(px, frame.Left, frame.Right);
        if (col >= 0) raster.FillRect(col, frame.Top, 1, frame.Height, colour);
    }

    /// <summary>The pixel row/column holding continuous coordinate <paramref name="p"/>, kept in [from, to); -1 if far outside.</summary>
    private static int PixelIndex(double p, int from, int to)
    {
        if (!double.IsFinite(p) || p < from - 1 || p > to + 1) return -1;
        return Math.Clamp((int)Math.Floor(p), from, to - 1);
    }

    private void DrawPolyline(Raster raster, PlotFrame frame, ChartSeries series)
    {
        int n = series.Xs.Length;
        double phase = 0;
        bool havePrevious = false;
        double px0 = 0, py0 = 0;
        for (int i = 0; i < n; i++)
        {
            double x = series.Xs[i], y = series.Ys[i];
            double px = frame.MapX(x), py = frame.MapY(y);
            if (!IsDrawable(x, y) || !double.IsFinite(px) || !double.IsFinite(py))
            {
                havePrevious = false;
                continue;
            }

            if (havePrevious)
            {
                if (series.Dashed) raster.DrawDashedLine(px0, py0, px, py, series.Colour, LineThickness, DashOn, DashOff, ref phase);
                else raster.DrawLine(px0, py0, px, py, series.Colour, LineThickness);
            }
            else
            {
                phase = 0;
                bool nextDrawable = i + 1 < n && IsDrawable(series.Xs[i + 1], series.Ys[i + 1]);
                if (!nextDrawable) raster.FillCircle(px, py, LineThickness / 2 + 0.5, series.Colour); // lone point
            }

            px0 = px;
            py0 = py;
            havePrevious = true;
        }
    }

    private void DrawMarkers(Raster raster, PlotFrame frame, ChartSeries series)
    {
        for (int i = 0; i < series.Xs.Length; i++)
        {
            if (!IsDrawable(series.Xs[i], series.Ys[i])) continue;
            double px = frame.MapX(series.Xs[i]), py = frame.MapY(series.Ys[i]);
            DrawMarker(raster, px, py, series.Colour);
        }
    }

    private static void DrawMarker(Raster raster, double px, double py, Rgb colour)
    {
        raster.FillCircle(px, py, MarkerRadius + 1, Rgb.White);
        raster.FillCircle(px, py, MarkerRadius, colour);
    }

    private void DrawPointLabels(Raster raster, PlotFrame frame, ChartSeries series, int scale)
    {
        int height = BitmapFont.MeasureHeight(scale);
        for (int i = 0; i < series.Xs.Length; i++)
        {
            string? text = series.PointLabels![i];
            if (string.IsNullOrEmpty(text) || !IsDrawable(series.Xs[i], series.Ys[i])) continue;
            double px = frame.MapX(series.Xs[i]), py = frame.MapY(series.Ys[i]);
            if (!double.IsFinite(px) || !double.IsFinite(py)) continue;
            int w = BitmapFont.MeasureWidth(text, scale);
            int gap = (int)MarkerRadius + 3;
            int x = (int)Math.Round(px) + gap;
            if (x + w > frame.Right) x = (int)Math.Round(px) - gap - w;
            int y = (int)Math.Round(py) - gap - height + 2;
            if (y < frame.Top) y = (int)Math.Round(py) + gap - 2;
            BitmapFont.DrawText(raster, x, y, text, TextColour, scale);
        }
    }

    private void DrawLegend(Raster raster, PlotFrame frame, int s)
    {
        var entries = _series.Where(e => !string.IsNullOrWhiteSpace(e.Label)).ToList();
        if (entries.Count == 0) return;
        int textHeight = BitmapFont.MeasureHeight(s);
        int inner = 4 * s;
        int rowGap = 2 * s;
        int sample = 14 * s;
        int labelWidth = entries.Max(e => BitmapFont.MeasureWidth(e.Label, s));
        int width = inner + sample + 2 * inner + labelWidth + inner;
        int height = 2 * inner + entries.Count * textHeight + (entries.Count - 1) * rowGap;
        (int x0, int y0) = LegendCorner(frame, width, height);
        raster.FillRect(x0, y0, width, height, Rgb.White);
        raster.DrawRect(x0, y0, width, height, LegendBorderColour);
        for (int k = 0; k < entries.Count; k++)
        {
            ChartSeries e = entries[k];
            int rowTop = y0 + inner + k * (textHeight + rowGap);
            double cy = rowTop + BitmapFont.MeasureCapHeight(s) / 2; // level with the middle of the capitals
            double sx0 = x0 + inner, sx1 = x0 + inner + sample;
            if (e.Kind == SeriesKind.Points)
            {
                DrawMarker(raster, (sx0 + sx1) / 2, cy, e.Colour);
            }
            else if (e.Dashed)
            {
                double phase = 0;
                raster.DrawDashedLine(sx0 + 1, cy, sx1 - 1, cy, e.Colour, LineThickness, DashOn, DashOff, ref phase);
            }
            else
            {
                raster.DrawLine(sx0 + 1, cy, sx1 - 1, cy, e.Colour, LineThickness);
            }

            BitmapFont.DrawText(raster, (int)sx1 + 2 * inner, rowTop, e.Label, TextColour, s);
        }
    }

    /// <summary>Top-left pixel of a legend box of the given size, per <see cref="LegendPosition"/>.</summary>
    private (int X, int Y) LegendCorner(PlotFrame frame, int width, int height)
    {
        const int Margin = 10;
        (int X, int Y) At(LegendPosition p) => p switch
        {
            LegendPosition.TopRight => (frame.Right - Margin - width, frame.Top + Margin),
            LegendPosition.BottomLeft => (frame.Left + Margin, frame.Bottom - Margin - height),
            LegendPosition.BottomRight => (frame.Right - Margin - width, frame.Bottom - Margin - height),
            _ => (frame.Left + Margin, frame.Top + Margin),
        };

        if (LegendPosition != LegendPosition.Best) return At(LegendPosition);

        LegendPosition best = LegendPosition.TopLeft;
        int fewest = int.MaxValue;
        foreach (LegendPosition p in new[] { LegendPosition.TopLeft, LegendPosition.TopRight, LegendPosition.BottomLeft, LegendPosition.BottomRight })
        {
            (int x, int y) = At(p);
            int covered = CountCovered(frame, x - 4, y - 4, x + width + 4, y + height + 4);
            if (covered < fewest)
            {
                fewest = covered;
                best = p;
            }

            if (covered == 0) break;
        }

        return At(best);
    }

    /// <summary>How many markers, line segments and point labels of the data touch the box.</summary>
    private int CountCovered(PlotFrame frame, double left, double top, double right, double bottom)
    {
        int count = 0;
        foreach (ChartSeries series in _series)
        {
            bool havePrevious = false;
            double px0 = 0, py0 = 0;
            for (int i = 0; i < series.Xs.Length; i++)
            {
                double px = frame.MapX(series.Xs[i]), py = frame.MapY(series.Ys[i]);
                if (!IsDrawable(series.Xs[i], series.Ys[i]) || !double.IsFinite(px) || !double.IsFinite(py))
                {
                    havePrevious = false;
                    continue;
                }

                if (series.Kind == SeriesKind.Points)
                {
                    double reach = MarkerRadius + (string.IsNullOrEmpty(series.PointLabels?[i]) ? 0 : 20);
                    if (px + reach >= left && px - reach <= right && py + reach >= top && py - reach <= bottom) count++;
                }
                else if (havePrevious)
                {
                    double ax = px0, ay = py0, bx = px, by = py;
                    if (Raster.ClipSegment(ref ax, ref ay, ref bx, ref by, left, top, right, bottom)) count++;
                }

                px0 = px;
                py0 = py;
                havePrevious = true;
            }
        }

        return count;
    }

    private static void DrawAxes(Raster raster, PlotFrame frame, IReadOnlyList<double> xTicks, List<string> xTickLabels,
        IReadOnlyList<double> yTicks, List<string> yTickLabels, int s)
    {
        int capHeight = BitmapFont.MeasureCapHeight(s);
        raster.DrawRect(frame.Left - 1, frame.Top - 1, frame.Width + 2, frame.Height + 2, AxisColour);

        for (int i = 0; i < xTicks.Count; i++)
        {
            int col = PixelIndex(frame.MapX(xTicks[i]), frame.Left, frame.Right);
            if (col < 0) continue;
            raster.FillRect(col, frame.Bottom + 1, 1, TickLength, AxisColour);
            int w = BitmapFont.MeasureWidth(xTickLabels[i], s);
            int x = Math.Clamp(col - w / 2, 0, Math.Max(0, raster.Width - w));
            BitmapFont.DrawText(raster, x, frame.Bottom + 1 + TickLength + 6, xTickLabels[i], TextColour, s);
        }

        for (int i = 0; i < yTicks.Count; i++)
        {
            int row = PixelIndex(frame.MapY(yTicks[i]), frame.Top, frame.Bottom);
            if (row < 0) continue;
            raster.FillRect(frame.Left - 1 - TickLength, row, TickLength, 1, AxisColour);
            int w = BitmapFont.MeasureWidth(yTickLabels[i], s);
            int y = Math.Clamp(row - capHeight / 2, 0, Math.Max(0, raster.Height - capHeight));
            BitmapFont.DrawText(raster, frame.Left - 1 - TickLength - 6 - w, y, yTickLabels[i], TextColour, s);
        }
    }

    /// <summary>A closed interval [Min, Max] of one axis.</summary>
    private readonly record struct AxisRange(double Min, double Max)
    {
        public double Span => Max - Min;
    }
}
