using System.Globalization;
using Kosmos.PseudoHaptic.Cli.Plotting;

namespace Kosmos.PseudoHaptic.Cli.Accuracy;

/// <summary>
/// Error against compute: one point per estimator at (ns per update from the benchmark, RMS error from the
/// summary), log x, each labelled with its key and added lag. Lower-left is better; the default is drawn in
/// its own colour, the paper-literal baseline in another. Points far above the rest (more than 3× the median
/// error) are drawn on the top edge, their labels giving the true error, so the cluster that matters is not
/// squashed. Labels are placed beside their point where they overlap no other label, point or the legend.
/// </summary>
public static class ParetoChart
{
    const int Width = 1000, Height = 600, LabelScale = 1, Gap = 7;

    sealed record Point(string Key, double Ns, double RmsMm, string Label, int Group);

    public static void Save(string path, AccuracyReport report, IReadOnlyDictionary<string, double> costs)
    {
        var groups = new[]
        {
            (Label: "estimators", Colour: Palette.Get(0)),
            (Label: "default (deadband)", Colour: Palette.Get(1)),
            (Label: "paper-literal baseline", Colour: Palette.Get(2)),
        };
        var points = new List<Point>();
        foreach (var key in EstimatorCatalog.EstimatorKeys.Append(EstimatorCatalog.PaperLiteral))
        {
            var row = report.Summary.FirstOrDefault(r => r.Config == key);
            if (row == null || !costs.TryGetValue(key, out double ns) || !(ns > 0) || !double.IsFinite(row.RmsMm)) continue;
            string lag = row.AddedLagMs.ToString("+0;-0;0", CultureInfo.InvariantCulture) + (row.LagWidened ? "*" : "");
            int group = key == EstimatorCatalog.Default ? 1 : key == EstimatorCatalog.PaperLiteral ? 2 : 0;
            points.Add(new Point(key, ns, row.RmsMm, $"{key} {lag} ms", group));
        }
        if (points.Count == 0) throw new CliException("option --costs: none of the estimators has a benchmark figure; run the benchmarks first");

        var sorted = points.Select(p => p.RmsMm).OrderBy(v => v).ToList();
        double median = sorted[sorted.Count / 2];
        bool Off(Point p) => p.RmsMm > 3 * median;
        double top = Math.Max(1, 1.3 * points.Where(p => !Off(p)).Select(p => p.RmsMm).DefaultIfEmpty(1).Max());
        double Y(Point p) => Off(p) ? 0.97 * top : p.RmsMm;
        string Text(Point p) => Off(p) ? $"{p.Label}, {p.RmsMm.ToString("0.0", CultureInfo.InvariantCulture)} mm (off scale)" : p.Label;

        double xMin = Math.Pow(10, Math.Floor(Math.Log10(points.Min(p => p.Ns)))), xMax = Math.Pow(10, Math.Ceiling(Math.Log10(points.Max(p => p.Ns))));
        if (xMax <= xMin) xMax = xMin * 10;
        var chart = new LineChart(Width, Height)
        {
            Title = $"RMS error vs ns per update, {report.MassKg.ToString("0.###", CultureInfo.InvariantCulture)} kg, Quest-like input (label: added lag)",
            XLabel = "ns per update (BenchmarkDotNet, log scale)",
            YLabel = "RMS error vs reference, mm",
            LogX = true,
            XMin = xMin,
            XMax = xMax,
            YMin = 0,
            YMax = top,
            LegendPosition = LegendPosition.BottomRight,
        };
        for (int g = 0; g < groups.Length; g++)
        {
            var mine = points.Where(p => p.Group == g).ToList();
            if (mine.Count > 0) chart.AddPoints(mine.Select(p => p.Ns).ToList(), mine.Select(Y).ToList(), groups[g].Colour, groups[g].Label);
        }
        var raster = chart.Render();

        // The plot frame and the legend box, in pixels, as the chart laid them out.
        var (left, upper) = chart.DataToPixel(xMin, top);
        var (right, lower) = chart.DataToPixel(xMax, 0);
        int s = chart.TextScale, inner = 4 * s, rowHeight = BitmapFont.MeasureHeight(s);
        var legendLabels = groups.Where((g, i) => points.Any(p => p.Group == i)).Select(g => g.Label).ToList();
        int legendW = inner + 14 * s + 2 * inner + legendLabels.Max(l => BitmapFont.MeasureWidth(l, s)) + inner;
        int legendH = 2 * inner + legendLabels.Count * rowHeight + (legendLabels.Count - 1) * 2 * s;
        var taken = new List<(double L, double T, double R, double B)> { (right - 10 - legendW - 4, lower - 10 - legendH - 4, right, lower) };
        foreach (var p in points)
        {
            var (px, py) = chart.DataToPixel(p.Ns, Y(p));
            taken.Add((px - 6, py - 6, px + 6, py + 6));
        }

        int h = BitmapFont.MeasureHeight(LabelScale);
        var caption = new Rgb(0x20, 0x20, 0x20);
        foreach (var p in points.OrderBy(p => p.Ns))
        {
            var (px, py) = chart.DataToPixel(p.Ns, Y(p));
            string text = Text(p);
            int w = BitmapFont.MeasureWidth(text, LabelScale);
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
                bool inside = box.L >= left + 2 && box.R <= right - 2 && box.T >= upper + 2 && box.B <= lower - 2;
                if (inside && !taken.Any(t => box.L < t.R && box.R > t.L && box.T < t.B && box.B > t.T)) { place = c; break; }
            }
            int x = (int)Math.Round(place.X), y = (int)Math.Round(place.Y);
            taken.Add((x - 1, y - 1, x + w + 1, y + h + 1));
            // A label pushed away from its point gets a thin leader line to it.
            double nx = Math.Clamp(px, x, x + w), ny = Math.Clamp(py, y, y + h);
            if (Math.Sqrt((px - nx) * (px - nx) + (py - ny) * (py - ny)) > Gap + 4)
                raster.DrawLine(px, py, nx, ny, new Rgb(0xA0, 0xA0, 0xA0), 1);
            BitmapFont.DrawText(raster, x, y, text, caption, LabelScale);
        }

        string? directory = Path.GetDirectoryName(Path.GetFullPath(path));
        if (!string.IsNullOrEmpty(directory)) Directory.CreateDirectory(directory);
        File.WriteAllBytes(path, raster.ToPng());
    }
}
