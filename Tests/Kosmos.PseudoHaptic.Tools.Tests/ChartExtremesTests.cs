using System.Globalization;
using System.Text;
using NUnit.Framework;
using SkiaSharp;

namespace Kosmos.PseudoHaptic.Tools.Tests;

/// <summary>
/// Every chart type rendered with extreme inputs (issue 25): long names, one and twelve conditions, nothing
/// estimable, every participant incomplete. Each PNG is checked for clipped text (ink touching the image's border:
/// a label cut by the edge) and for every series being visible (its colour's pixels present), and a chart with
/// nothing to draw must say so in ink rather than show empty axes.
/// </summary>
public class ChartExtremesTests : CliTestFolder
{
    public ChartExtremesTests() : base("ph-chart-extremes-") { }

    const string LongName = "Participant with a remarkably long identifier from the second site";
    const string LongCondition = "pseudo-haptic feedback with the offset correction and the speed cap";

    static readonly SKColor Blue = new(0x1f, 0x77, 0xb4), Orange = new(0xff, 0x7f, 0x0e), Grey = new(0x7f, 0x7f, 0x7f), Black = new(0, 0, 0);

    static string F(double v) => v.ToString("R", CultureInfo.InvariantCulture);

    (int code, string stderr) Run(params string[] args)
    {
        var (code, stderr, _) = Capture(() => Cli.Cli.Run(args));
        return (code, stderr);
    }

    /// <summary>No ink in the outermost pixels: text or lines cut by the image's edge.</summary>
    public static void AssertNothingClipped(string png)
    {
        using var bitmap = SKBitmap.Decode(png);
        Assert.That(bitmap, Is.Not.Null, png);
        int w = bitmap.Width, h = bitmap.Height, touching = 0;
        for (int x = 0; x < w; x++)
            foreach (int y in new[] { 0, 1, h - 2, h - 1 })
                if (Ink(bitmap.GetPixel(x, y))) touching++;
        for (int y = 0; y < h; y++)
            foreach (int x in new[] { 0, 1, w - 2, w - 1 })
                if (Ink(bitmap.GetPixel(x, y))) touching++;
        Assert.That(touching, Is.Zero, $"{Path.GetFileName(png)}: {touching} inked pixels on the border (clipped text or lines)");
    }

    static bool Ink(SKColor c) => c.Red < 200 || c.Green < 200 || c.Blue < 200;

    /// <summary>At least <paramref name="least"/> pixels within a small distance of the series' colour.</summary>
    static void AssertVisible(string png, SKColor colour, string series, int least = 40)
    {
        using var bitmap = SKBitmap.Decode(png);
        int count = 0;
        for (int y = 0; y < bitmap.Height; y++)
            for (int x = 0; x < bitmap.Width; x++)
            {
                var c = bitmap.GetPixel(x, y);
                if (Math.Abs(c.Red - colour.Red) + Math.Abs(c.Green - colour.Green) + Math.Abs(c.Blue - colour.Blue) <= 30) count++;
            }
        Assert.That(count, Is.GreaterThanOrEqualTo(least), $"{Path.GetFileName(png)}: the {series} series is visible");
    }

    static IEnumerable<string> Pngs(string dir) => Directory.GetFiles(dir, "*.png").OrderBy(f => f, StringComparer.Ordinal);

    /// <summary>Trials for each (participant, condition): a steep observer, or one who always says "heavier" (not estimable).</summary>
    string Trials(IEnumerable<(string Participant, string Condition, bool Estimable)> groups)
    {
        var sb = new StringBuilder("participant,condition,standard,comparison,response\n");
        var rng = new Random(7);
        foreach (var (p, c, estimable) in groups)
            foreach (double level in new[] { 0.35, 0.4, 0.45, 0.5, 0.55, 0.6, 0.65, 1.0 })
                for (int k = 0; k < (level == 1.0 ? 2 : 10); k++)
                {
                    double pHeavier = 1 / (1 + Math.Exp(-(level - 0.5) / 0.04));
                    int response = estimable ? (rng.NextDouble() < pHeavier ? 1 : 0) : 1;
                    sb.Append($"\"{p}\",\"{c}\",0.5,{F(level)},{response}\n");
                }
        return Write("trials.csv", sb.ToString());
    }

    [Test]
    public void The_clipping_check_sees_a_title_cut_by_the_edge()
    {
        // A title far wider than its chart runs off both edges: the check must refuse it (it can fail).
        var plot = Kosmos.PseudoHaptic.Cli.Plotting.Charts.Create(string.Concat(Enumerable.Repeat(LongName + " ", 4)), "x (m)", "y (m)");
        string png = Path.Combine(_dir, "cut.png");
        File.WriteAllBytes(png, Kosmos.PseudoHaptic.Cli.Plotting.Charts.Png(plot, 400, 300));
        Assert.Throws<AssertionException>(() => AssertNothingClipped(png));
    }

    [TestCase(1)]
    [TestCase(12)]
    public void Psychometric_charts_with_long_names_and_many_conditions_are_whole(int conditions)
    {
        var groups = Enumerable.Range(1, conditions).SelectMany(c => new[] { (LongName, LongCondition + " " + c, true), ("P2", "c" + c, true) });
        string outDir = Path.Combine(_dir, "fits");
        var (code, stderr) = Run("psychometric", "--trials", Trials(groups), "--out", outDir, "--bootstrap", "20");
        Assert.That(code, Is.EqualTo(0), stderr);
        foreach (var png in Pngs(outDir)) AssertNothingClipped(png);
        string summary = Path.Combine(outDir, "summary.png");
        AssertVisible(summary, Blue, "PSE");
        AssertVisible(summary, Orange, "JND");
        foreach (var fit in Pngs(outDir).Where(p => Path.GetFileName(p).StartsWith("fit-", StringComparison.Ordinal)))
            AssertVisible(fit, Blue, "proportion and fit");
    }

    [Test]
    public void Psychometric_without_an_estimable_fit_says_so_instead_of_empty_axes()
    {
        string outDir = Path.Combine(_dir, "fits");
        var (code, stderr) = Run("psychometric", "--trials", Trials(new[] { (LongName, "", false), ("P2", "", false) }), "--out", outDir, "--bootstrap", "0");
        Assert.That(code, Is.EqualTo(0), stderr);
        string summary = Path.Combine(outDir, "summary.png");
        AssertNothingClipped(summary);
        using var bitmap = SKBitmap.Decode(summary);
        var (_, ink) = ChartFiles.Ink(bitmap);
        Assert.That(ink, Is.InRange(0.005, 0.2), "a title and a sentence, no axes full of ticks");
        foreach (var png in Pngs(outDir)) AssertNothingClipped(png);
    }

    [TestCase(2)]
    [TestCase(3)]
    [TestCase(12)]
    public void Compare_charts_with_long_condition_names_are_whole_and_name_their_tests(int conditions)
    {
        var sb = new StringBuilder("participant,condition,questionnaire,score\n");
        var rng = new Random(3);
        for (int p = 1; p <= 8; p++)
            for (int c = 1; c <= conditions; c++)
                sb.Append($"\"{(p == 1 ? LongName : "P" + p)}\",\"{LongCondition} {c}\",weight-detection,{F(Math.Round(2 + 2 * rng.NextDouble() + 0.1 * c, 2))}\n");
        string outDir = Path.Combine(_dir, "compare");
        var (code, stderr) = Run("compare", "--scores", Write("scores.csv", sb.ToString()), "--out", outDir);
        Assert.That(code, Is.EqualTo(0), stderr);
        foreach (var png in Pngs(outDir))
        {
            AssertNothingClipped(png);
            AssertVisible(png, Grey, "participants");
            AssertVisible(png, Black, "mean");
        }
    }

    [TestCase(1, false)]
    [TestCase(30, false)]
    [TestCase(3, true)]
    public void Report_charts_with_one_many_or_only_incomplete_participants_are_whole(int participants, bool allIncomplete)
    {
        var sb = new StringBuilder("participant,questionnaire,score\n");
        for (int p = 1; p <= participants; p++)
            sb.Append($"\"{(p == 1 ? LongName : "P" + p)}\",weight-detection,{(allIncomplete ? "" : F(1 + (p * 7 % 40) / 10.0))}\n");
        string outDir = Path.Combine(_dir, "report");
        var (code, stderr) = Run("report", "--scores", Write("scores.csv", sb.ToString()), "--out", outDir);
        Assert.That(code, Is.EqualTo(0), stderr);
        foreach (var png in Pngs(outDir))
        {
            AssertNothingClipped(png);
            if (!allIncomplete) AssertVisible(png, Blue, "score bars");
            else AssertVisible(png, Grey, "incomplete bars", 20);
        }
    }

    [Test]
    public void Demo_charts_are_whole_and_draw_the_hand_over_every_object()
    {
        string outDir = Path.Combine(_dir, "demo");
        var (code, stderr) = Run("demo", "--out", outDir);
        Assert.That(code, Is.EqualTo(0), stderr);
        foreach (var png in Pngs(outDir))
        {
            AssertNothingClipped(png);
            AssertVisible(png, Black, "hand");
            AssertVisible(png, Blue, "first object");
            AssertVisible(png, Orange, "second object");
        }
    }
}
