using Kosmos.PseudoHaptic.Cli;
using Kosmos.PseudoHaptic.Cli.Plotting;
using NUnit.Framework;
using ScottPlot;
using SkiaSharp;

namespace Kosmos.PseudoHaptic.Tools.Tests;

/// <summary>The one chart style (<see cref="Charts"/>): what it writes, and what it draws where.</summary>
[TestFixture]
public sealed class PlottingTests
{
    string _dir = "";

    [SetUp]
    public void SetUp()
    {
        _dir = Path.Combine(Path.GetTempPath(), "ph-charts-" + Guid.NewGuid().ToString("N"));
        Directory.CreateDirectory(_dir);
    }

    [TearDown]
    public void TearDown()
    {
        if (Directory.Exists(_dir)) Directory.Delete(_dir, true);
    }

    static Plot Sample()
    {
        var plot = Charts.Create("A lift", "time (s)", "height (m)");
        Charts.Line(plot, new[] { 0.0, 1.0, 2.0, 3.0 }, new[] { 0.8, 1.0, 1.1, 0.9 }, "hand", Charts.Black, dashed: true);
        Charts.Line(plot, new[] { 0.0, 1.0, 2.0, 3.0 }, new[] { 0.8, 0.9, 0.95, 0.85 }, "box B 2 kg", Charts.Colour(0));
        return plot;
    }

    [TestCase(1000, 560)]
    [TestCase(321, 123)]
    [TestCase(1800, 500)]
    public void Save_WritesANonBlankPngOfTheStatedSize(int width, int height)
    {
        string png = Path.Combine(_dir, "chart.png");
        Charts.Save(Sample(), png, width, height, svg: false);
        ChartFiles.AssertPng(png, width, height);
        Assert.That(Directory.GetFiles(_dir).Select(Path.GetFileName), Is.EqualTo(new[] { "chart.png" }), "no SVG unless asked, no temporary file left");
    }

    [Test]
    public void Save_WithSvgWritesAnSvgOfTheSameSizeBesideThePng()
    {
        string png = Path.Combine(_dir, "sub", "chart.png");
        Charts.Save(Sample(), png, 640, 400, svg: true);
        ChartFiles.AssertPng(png, 640, 400);
        ChartFiles.AssertSvg(Path.Combine(_dir, "sub", "chart.svg"), 640, 400);
        string svgText = File.ReadAllText(Path.Combine(_dir, "sub", "chart.svg"));
        Assert.That(svgText, Does.Contain("box B 2 kg").Or.Contain("<path"), "the SVG carries the chart");
    }

    [Test]
    public void Save_ReplacesAnExistingFileWhole()
    {
        string png = Path.Combine(_dir, "chart.png");
        File.WriteAllText(png, "old");
        Charts.Save(Sample(), png, 300, 200, svg: false);
        ChartFiles.AssertPng(png, 300, 200);
    }

    [TestCase(0, 100, "width")]
    [TestCase(-5, 100, "width")]
    [TestCase(100, 0, "height")]
    [TestCase(Charts.MaxSide + 1, 100, "width")]
    [TestCase(100, Charts.MaxSide + 1, "height")]
    public void Save_RejectsAnImpossibleSizeNamingItAndWritesNothing(int width, int height, string name)
    {
        string png = Path.Combine(_dir, "chart.png");
        Assert.That(() => Charts.Save(Sample(), png, width, height, svg: true),
            Throws.InstanceOf<ArgumentOutOfRangeException>().With.Property("ParamName").EqualTo(name));
        Assert.That(Directory.GetFiles(_dir), Is.Empty);
    }

    [Test]
    public void Create_SetsTitleAndAxisLabels()
    {
        var plot = Charts.Create("Drop", "time (s)", "height (m)");
        Assert.That(plot.Axes.Title.Label.Text, Is.EqualTo("Drop"));
        Assert.That(plot.Axes.Bottom.Label.Text, Is.EqualTo("time (s)"));
        Assert.That(plot.Axes.Left.Label.Text, Is.EqualTo("height (m)"));
    }

    [Test]
    public void Line_IsDrawnWhereTheDataMap()
    {
        var plot = Charts.Create("t", "x", "y");
        var red = Color.FromHex("#DC141E");
        Charts.Line(plot, new[] { 0.0, 10.0 }, new[] { 5.0, 5.0 }, "flat", red);
        plot.Axes.SetLimits(0, 10, 0, 10);
        string png = Path.Combine(_dir, "line.png");
        Charts.Save(plot, png, 400, 300, svg: false);

        Pixel at = plot.GetPixel(new Coordinates(5, 5));
        Pixel off = plot.GetPixel(new Coordinates(5, 2));
        using var bitmap = SKBitmap.Decode(png);
        static bool Reddish(SKColor c) => c.Red > 180 && c.Green < 120 && c.Blue < 120;
        bool hit = Enumerable.Range(-2, 5).Any(dy => Reddish(bitmap.GetPixel((int)at.X, (int)at.Y + dy)));
        Assert.That(hit, Is.True, $"red near ({at.X}, {at.Y})");
        Assert.That(Reddish(bitmap.GetPixel((int)off.X, (int)off.Y)), Is.False, "nothing red at y = 2");
    }

    [Test]
    public void Line_ANonFinitePointBreaksTheLineButNamesItOnce()
    {
        var plot = Charts.Create("t", "x", "y");
        Charts.Line(plot, new[] { 0.0, 1.0, 2.0, 3.0, 4.0 }, new[] { 1.0, 2.0, double.NaN, 3.0, 4.0 }, "broken", Charts.Colour(0));
        var parts = plot.GetPlottables().OfType<ScottPlot.Plottables.Scatter>().ToList();
        Assert.That(parts.Select(p => p.Data.GetScatterPoints().Count), Is.EqualTo(new[] { 2, 2 }));
        Assert.That(plot.GetPlottables().SelectMany(p => p.LegendItems).Count(i => i.LabelText == "broken"), Is.EqualTo(1));
    }

    [Test]
    public void DegenerateDataStillGivesAChart()
    {
        var plot = Charts.Create("odd", "x", "y");
        Charts.Line(plot, Array.Empty<double>(), Array.Empty<double>(), "empty", Charts.Colour(0));
        Charts.Line(plot, new[] { double.NaN, double.NaN }, new[] { 1.0, 2.0 }, "all NaN", Charts.Colour(1));
        Charts.Line(plot, new[] { 1.0, 2.0, double.PositiveInfinity, 4.0 }, new[] { 1.0, double.NegativeInfinity, 3.0, 4.0 }, "inf", Charts.Colour(2));
        Charts.Line(plot, new[] { 3.0 }, new[] { 3.0 }, "single", Charts.Colour(3));
        Charts.Points(plot, new[] { 1.0, 1.0 }, new[] { 2.0, double.NaN }, "pts", Charts.Colour(4));
        string png = Path.Combine(_dir, "odd.png");
        Charts.Save(plot, png, 300, 200, svg: true);
        ChartFiles.AssertPng(png, 300, 200);

        var empty = Charts.Create("nothing yet", "x", "y");
        string blank = Path.Combine(_dir, "empty.png");
        Charts.Save(empty, blank, 300, 200, svg: false);
        ChartFiles.AssertPng(blank, 300, 200);
        Assert.That(empty.Legend.IsVisible, Is.False, "no legend without a named series");
    }

    [Test]
    public void Line_AndPoints_RejectMismatchedArrays()
    {
        var plot = Charts.Create("t", "x", "y");
        Assert.That(() => Charts.Line(plot, new double[3], new double[2], "bad", Charts.Colour(0)), Throws.ArgumentException);
        Assert.That(() => Charts.Points(plot, new double[1], new double[2], "bad", Charts.Colour(0)), Throws.ArgumentException);
    }

    [Test]
    public void Points_LeaveOutNonFinitePoints()
    {
        var plot = Charts.Create("t", "x", "y");
        var scatter = Charts.Points(plot, new[] { 1.0, double.NaN, 3.0 }, new[] { 1.0, 2.0, double.PositiveInfinity }, "p", Charts.Colour(0));
        Assert.That(scatter.Data.GetScatterPoints().Select(c => (c.X, c.Y)), Is.EqualTo(new[] { (1.0, 1.0) }));
    }

    [Test]
    public void Colour_WrapsAroundForAnyIndexAndTheColoursDiffer()
    {
        Assert.That(Charts.Colour(Charts.ColourCount), Is.EqualTo(Charts.Colour(0)));
        Assert.That(Charts.Colour(-1), Is.EqualTo(Charts.Colour(Charts.ColourCount - 1)));
        Assert.That(Enumerable.Range(0, Charts.ColourCount).Select(Charts.Colour).Distinct().Count(), Is.EqualTo(Charts.ColourCount));
    }

    [Test]
    public void LogTicks_NameOneTwoAndFiveOfEachDecadeAndSpaceDecadesEqually()
    {
        var plot = Charts.Create("log", "ns", "mm");
        plot.Axes.Bottom.TickGenerator = Charts.LogTicks(10, 1000);
        plot.Axes.SetLimits(1, 3, 0, 1);
        plot.RenderInMemory(800, 400);
        var ticks = plot.Axes.Bottom.TickGenerator.Ticks.ToList();
        var major = ticks.Where(t => t.IsMajor).ToList();
        Assert.That(major.Select(t => t.Label).ToArray(), Is.EqualTo(new[] { "10", "20", "50", "100", "200", "500", "1000" }));
        Assert.That(major.Select(t => t.Position), Is.EqualTo(new[] { 1, Math.Log10(20), Math.Log10(50), 2, Math.Log10(200), Math.Log10(500), 3 }).Within(1e-12));
        Assert.That(ticks.Count(t => !t.IsMajor), Is.EqualTo(12), "3, 4, 6, 7, 8, 9 of two decades");
    }
}
