using Kosmos.PseudoHaptic.Cli.Plotting;
using NUnit.Framework;
using ScottPlot;
using SkiaSharp;

namespace Kosmos.PseudoHaptic.Tools.Tests;

/// <summary>
/// Pixel checks of a chart's own plottables (issue 32), on the ScottPlot plots a command draws (caught through
/// <see cref="Charts.Drawing"/>): how much of each series' ink is seen in the chart, against what it draws alone;
/// where a plot's data area lies. Limits and the legend are held fixed while a series is taken out, so only its
/// own pixels change.
/// </summary>
public static class ChartInk
{
    public sealed record Drawn(Plot Plot, int Width, int Height);

    /// <summary>Every plot drawn by <paramref name="run"/> on this thread, in order.</summary>
    public static List<Drawn> Catch(Action run)
    {
        var drawn = new List<Drawn>();
        var before = Charts.Drawing;
        Charts.Drawing = (plot, w, h) => drawn.Add(new Drawn(plot, w, h));
        try { run(); }
        finally { Charts.Drawing = before; }
        return drawn;
    }

    /// <summary>The plot's title (the first line), to find a chart among those caught.</summary>
    public static string Title(this Drawn d) => d.Plot.Axes.Title.Label.Text ?? "";

    /// <summary>Pixels of the image (RGBA as SKColor).</summary>
    static SKColor[] Pixels(Plot plot, int w, int h)
    {
        using var bitmap = SKBitmap.Decode(plot.GetImageBytes(w, h, ImageFormat.Png));
        return bitmap.Pixels;
    }

    /// <summary>
    /// For each visible plottable: its name (legend text, or its type and index), the pixels of the data area it
    /// changes in the chart (seen), those it changes drawn alone on the same axes (own), and those of its own that no
    /// other plottable draws within a pixel (distinct: where a reader can tell it from the others).
    /// </summary>
    public static List<(string Name, int Seen, int Own, int Distinct)> Visibility(Drawn d, Func<string, bool>? only = null)
    {
        var plot = d.Plot;
        plot.RenderInMemory(d.Width, d.Height);
        plot.Axes.SetLimits(plot.Axes.GetLimits());
        bool showHidden = plot.Legend.ShowItemsFromHiddenPlottables;
        double opacity = plot.Legend.HiddenItemOpacity;
        plot.Legend.ShowItemsFromHiddenPlottables = true;
        plot.Legend.HiddenItemOpacity = 1;
        var all = plot.GetPlottables().Where(p => p.IsVisible).ToList();
        var result = new List<(string, int, int, int)>();
        int w = d.Width, h = d.Height;
        try
        {
            var full = Pixels(plot, w, h);
            var area = plot.RenderManager.LastRender.DataRect;
            foreach (var p in all) p.IsVisible = false;
            var empty = Pixels(plot, w, h);
            for (int i = 0; i < all.Count; i++)
            {
                var p = all[i];
                string name = p.LegendItems.Select(l => l.LabelText).FirstOrDefault(t => !string.IsNullOrEmpty(t)) ?? $"{p.GetType().Name} #{i}";
                if (only != null && !only(name)) continue;
                foreach (var q in all) q.IsVisible = q == p;
                var own = Mask(Pixels(plot, w, h), empty, area, w);
                foreach (var q in all) q.IsVisible = q != p;
                var without = Pixels(plot, w, h);
                Assert.That(plot.RenderManager.LastRender.DataRect, Is.EqualTo(area), "the layout holds while a series is hidden");
                int seen = Mask(full, without, area, w).Count(b => b);
                // The others' ink, grown by a pixel: a line one pixel off another is not told apart from it.
                var others = Mask(without, empty, area, w);
                int mine = 0, distinct = 0;
                for (int k = 0; k < own.Length; k++)
                {
                    if (!own[k]) continue;
                    mine++;
                    int x = k % w, y = k / w;
                    bool near = false;
                    for (int dy = -1; dy <= 1 && !near; dy++)
                        for (int dx = -1; dx <= 1 && !near; dx++)
                            near = x + dx >= 0 && x + dx < w && y + dy >= 0 && y + dy < h && others[(y + dy) * w + x + dx];
                    if (!near) distinct++;
                }
                result.Add((name, seen, mine, distinct));
            }
        }
        finally
        {
            foreach (var q in all) q.IsVisible = true;
            plot.Legend.ShowItemsFromHiddenPlottables = showHidden;
            plot.Legend.HiddenItemOpacity = opacity;
        }
        return result;
    }

    /// <summary>Pixels of the data area where the two images differ clearly.</summary>
    static bool[] Mask(SKColor[] a, SKColor[] b, PixelRect area, int width)
    {
        var mask = new bool[a.Length];
        for (int y = (int)area.Top; y < (int)area.Bottom; y++)
            for (int x = (int)area.Left; x < (int)area.Right; x++)
            {
                SKColor p = a[y * width + x], q = b[y * width + x];
                if (Math.Abs(p.Red - q.Red) + Math.Abs(p.Green - q.Green) + Math.Abs(p.Blue - q.Blue) > 60) mask[y * width + x] = true;
            }
        return mask;
    }

    /// <summary>
    /// Every plottable that draws ink shows at least <paramref name="share"/> of it in the chart (not hidden under
    /// the others), and at least <paramref name="distinct"/> of it, and <paramref name="least"/> pixels, where no other
    /// plottable draws (so it can be told apart from them).
    /// </summary>
    public static void AssertEverySeriesSeen(Drawn d, double share = 0.5, double distinct = 0.1, int least = 20)
    {
        var failures = Visibility(d)
            .Where(v => v.Own > 0 && (v.Seen < share * v.Own || v.Distinct < distinct * v.Own || v.Distinct < Math.Min(least, v.Own)))
            .Select(v => $"{v.Name}: {v.Seen} of its {v.Own} pixels seen, {v.Distinct} apart from the others").ToList();
        Assert.That(failures, Is.Empty, $"'{d.Title()}' / '{d.Plot.Axes.Left.Label.Text}': series hidden under or lost in others");
    }

    /// <summary>The data area's left edge, px, as laid out at the chart's size.</summary>
    public static float DataLeft(Drawn d)
    {
        d.Plot.RenderInMemory(d.Width, d.Height);
        return d.Plot.RenderManager.LastRender.DataRect.Left;
    }
}
