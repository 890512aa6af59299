using System.Globalization;
using Kosmos.PseudoHaptic.Cli.Plotting;

namespace Kosmos.PseudoHaptic.Cli.Accuracy;

/// <summary>
/// Error against compute: one point per estimator at (ns per update from the benchmark, RMS error from the
/// summary), log x, each labelled with its key and added lag. Lower-left is better; the default is drawn in
/// its own colour, the paper-literal baseline in another. Points far above the rest (more than 3× the median
/// error) are drawn on the top edge, their labels giving the true error, so the cluster that matters is not
/// squashed. Labels are placed beside their point where they overlap no other label, point, bar or the legend.
/// Each point is its own marker; the default is a ring drawn around its point, so an estimator at the same place (the
/// default is no-filter plus a deadband that seldom acts) shows inside it. The 95 % bars stand 14 px right of their (the default's left of its)
/// point with caps, so an interval narrower than the marker still shows. The right edge keeps room for the last tick
/// label (issue 32: "1000" was cut).
/// </summary>
public static class ParetoChart
{
    const int Width = 1000, Height = 600, Gap = 7, BarOffset = 14, Cap = 4;

    sealed record Point(string Key, double Ns, double RmsMm, double Low, double High, string Label, int Group);

    public static void Save(string path, AccuracyReport report, IReadOnlyDictionary<string, double> costs, bool svg)
        => Charts.Save(Build(report, costs), path, Width, Height, svg);

    /// <summary>The chart as SVG text (accuracy --svg writes it through its own output file, beside the PNG).</summary>
    public static string Svg(AccuracyReport report, IReadOnlyDictionary<string, double> costs)
        => Charts.Svg(Build(report, costs), Width, Height);

    static ScottPlot.Plot Build(AccuracyReport report, IReadOnlyDictionary<string, double> costs)
    {
        var groups = new[]
        {
            (Label: "estimators", Colour: Charts.Colour(0)),
            (Label: "default (deadband)", Colour: Charts.Colour(1)),
            (Label: "paper-literal baseline", Colour: Charts.Colour(2)),
        };
        var points = new List<Point>();
        foreach (var key in EstimatorCatalog.EstimatorKeys.Append(EstimatorCatalog.PaperLiteral))
        {
            var row = report.Summary.FirstOrDefault(r => r.Config == key);
            if (row == null || !costs.TryGetValue(key, out double ns) || !(ns > 0) || !double.IsFinite(row.RmsMm)) continue;
            string lag = row.AddedLagMs.ToString("+0;-0;0", CultureInfo.InvariantCulture) + (row.LagWidened ? "*" : "");
            int group = key == EstimatorCatalog.Default ? 1 : key == EstimatorCatalog.PaperLiteral ? 2 : 0;
            points.Add(new Point(key, ns, row.RmsMm, row.Rms.Low, row.Rms.High, $"{key} {lag} ms", group));
        }
        if (points.Count == 0) throw new CliException("option --costs: none of the estimators has a benchmark figure; run the benchmarks first");

        var sorted = points.Select(p => p.RmsMm).OrderBy(v => v).ToList();
        double median = sorted[sorted.Count / 2];
        bool Off(Point p) => p.RmsMm > 3 * median;
        double top = Math.Max(1, 1.3 * points.Where(p => !Off(p)).Select(p => p.RmsMm).DefaultIfEmpty(1).Max());
        double Y(Point p) => Off(p) ? 0.97 * top : p.RmsMm;
        string Text(Point p) => Off(p) ? $"{p.Label}, {p.RmsMm.ToString("0.0", CultureInfo.InvariantCulture)} mm (off scale)" : p.Label;

        // Log x: the points are placed at log10(ns); the ticks name the ns (1, 2, 5 per decade, minor lines between).
        double xMin = Math.Pow(10, Math.Floor(Math.Log10(points.Min(p => p.Ns)))), xMax = Math.Pow(10, Math.Ceiling(Math.Log10(points.Max(p => p.Ns))));
        if (xMax <= xMin) xMax = xMin * 10;
        var plot = Charts.Create(
            $"RMS error vs ns per update, {report.MassKg.ToString("0.###", CultureInfo.InvariantCulture)} kg, Quest-like input (label: added lag)",
            "ns per update (BenchmarkDotNet, log scale)",
            "RMS error vs reference (mm; bars: 95 % interval)");
        plot.Axes.Bottom.TickGenerator = Charts.LogTicks(xMin, xMax);
        // One marker per point (the legend named once per group); the default's ring goes on last.
        for (int g = 0; g < groups.Length; g++)
        {
            bool named = false;
            foreach (var p in points.Where(p => p.Group == g))
            {
                var marker = Charts.Points(plot, new[] { Math.Log10(p.Ns) }, new[] { Y(p) }, named ? "" : groups[g].Label, groups[g].Colour, shape: g);
                if (g == 1)
                {
                    marker.MarkerShape = ScottPlot.MarkerShape.OpenCircle;
                    marker.MarkerSize = 17;
                    marker.MarkerLineWidth = 2.5f;
                }
                named = true;
            }
        }
        // The last tick label (centred on the right edge) needs half its width beyond the data area.
        plot.Axes.Right.MinimumSize = (float)(Charts.NoteWidth(xMax.ToString("G6", CultureInfo.InvariantCulture)) * 15 / Charts.NoteSize / 2 + 12);
        plot.Legend.Alignment = ScottPlot.Alignment.LowerRight;
        plot.Axes.SetLimits(Math.Log10(xMin), Math.Log10(xMax), 0, top);

        // Labels beside their points where they overlap no other label, point or the legend, found in pixels of
        // the laid-out chart.
        plot.RenderInMemory(Width, Height);
        var frame = plot.RenderManager.LastRender.DataRect;
        double legendW, legendH;
        using (var legendImage = plot.GetLegendImage()) { legendW = legendImage.Width; legendH = legendImage.Height; }
        var legend = (L: frame.Right - legendW - 14, T: frame.Bottom - legendH - 14, R: (double)frame.Right, B: (double)frame.Bottom);
        var taken = new List<(double L, double T, double R, double B)> { legend };
        (double X, double Y) Pixel(Point p)
        {
            var px = plot.GetPixel(new ScottPlot.Coordinates(Math.Log10(p.Ns), Y(p)));
            return (px.X, px.Y);
        }
        foreach (var p in points)
        {
            var (px, py) = Pixel(p);
            taken.Add((px - (p.Group == 1 ? 10 : 6), py - (p.Group == 1 ? 10 : 6), px + (p.Group == 1 ? 10 : 6), py + (p.Group == 1 ? 10 : 6)));
        }
        // The 95 % bars, beside their points (taken too, so no label covers them).
        bool barNamed = false;
        foreach (var p in points.Where(p => !Off(p) && double.IsFinite(p.Low) && double.IsFinite(p.High)))
        {
            var (px, _) = Pixel(p);
            double bx = p.Group == 1 ? px - BarOffset : px + BarOffset; // the default's on the left: it may share its point
            var low = plot.GetPixel(new ScottPlot.Coordinates(0, p.Low)).Y;
            var high = plot.GetPixel(new ScottPlot.Coordinates(0, p.High)).Y;
            var x = plot.GetCoordinates(new ScottPlot.Pixel((float)bx, 0)).X;
            double capLeft = plot.GetCoordinates(new ScottPlot.Pixel((float)(bx - Cap), 0)).X, capRight = plot.GetCoordinates(new ScottPlot.Pixel((float)(bx + Cap), 0)).X;
            var colour = groups[p.Group].Colour;
            // One path per bar, an I: the low cap, up the bar, the high cap.
            var bar = plot.Add.ScatterLine(new[] { capLeft, capRight, x, x, capLeft, capRight }, new[] { p.Low, p.Low, p.Low, p.High, p.High, p.High }, colour);
            bar.LineWidth = 2;
            bar.MarkerSize = 0;
            bar.LegendText = barNamed ? "" : "95 % interval (beside its point)";
            barNamed = true;
            taken.Add((bx - Cap - 1, Math.Min(low, high) - 2, bx + Cap + 1, Math.Max(low, high) + 2));
        }

        // The legend now has the bars' entry too.
        using (var legendImage = plot.GetLegendImage()) { legendW = legendImage.Width; legendH = legendImage.Height; }
        taken.Add((frame.Right - legendW - 14, frame.Bottom - legendH - 14, frame.Right, frame.Bottom));

        const double h = Charts.NoteHeight;
        foreach (var p in points.OrderBy(p => p.Ns))
        {
            var (px, py) = Pixel(p);
            string text = Text(p);
            double w = Charts.NoteWidth(text);
            var candidates = new List<(double X, double Y)>
            {
                (px + Gap, py - h / 2.0), (px - Gap - w, py - h / 2.0), (px + Gap, py - Gap - h), (px + Gap, py + Gap - 2),
                (px - Gap - w, py - Gap - h), (px - Gap - w, py + Gap - 2), (px - w / 2.0, py - Gap - h - 2), (px - w / 2.0, py + Gap + 2),
            };
            for (int k = 1; k <= 6; k++)
            {
                candidates.Add((px + Gap, py - h / 2.0 - k * (h + 3)));
                candidates.Add((px + Gap, py - h / 2.0 + k * (h + 3)));
                candidates.Add((px - Gap - w, py - h / 2.0 - k * (h + 3)));
                candidates.Add((px - Gap - w, py - h / 2.0 + k * (h + 3)));
            }
            var place = candidates[0];
            foreach (var c in candidates)
            {
                var box = (L: c.X - 1, T: c.Y - 1, R: c.X + w + 1, B: c.Y + h + 1);
                bool inside = box.L >= frame.Left + 2 && box.R <= frame.Right - 2 && box.T >= frame.Top + 2 && box.B <= frame.Bottom - 2;
                if (inside && !taken.Any(t => box.L < t.R && box.R > t.L && box.T < t.B && box.B > t.T)) { place = c; break; }
            }
            taken.Add((place.X - 1, place.Y - 1, place.X + w + 1, place.Y + h + 1));
            // A label pushed away from its point gets a thin leader line to it.
            double nx = Math.Clamp(px, place.X, place.X + w), ny = Math.Clamp(py, place.Y, place.Y + h);
            if (Math.Sqrt((px - nx) * (px - nx) + (py - ny) * (py - ny)) > Gap + 4)
            {
                var end = plot.GetCoordinates(new ScottPlot.Pixel((float)nx, (float)ny));
                var leader = plot.Add.Line(Math.Log10(p.Ns), Y(p), end.X, end.Y);
                leader.Color = ScottPlot.Color.FromHex("#A0A0A0");
                leader.LineWidth = 1;
            }
            var at = plot.GetCoordinates(new ScottPlot.Pixel((float)place.X, (float)place.Y));
            Charts.Note(plot, at.X, at.Y, text);
        }
        return plot;
    }
}
