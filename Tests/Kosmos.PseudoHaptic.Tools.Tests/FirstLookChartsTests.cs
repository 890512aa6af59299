using System.Text.RegularExpressions;
using Kosmos.PseudoHaptic.Cli.Plotting;
using NUnit.Framework;
using ScottPlot;
using SkiaSharp;

namespace Kosmos.PseudoHaptic.Tools.Tests;

/// <summary>
/// Issue 32, "the charts a newcomer sees first": each defect a newcomer met, checked on the plots the commands draw
/// (caught through <see cref="Charts.Drawing"/>) and on their pixels: every series' ink seen against the others,
/// shared time axes aligned, limits that show the motion rather than the noise, nothing cut at the canvas' edge,
/// numbers written plainly.
/// </summary>
public class FirstLookChartsTests : CliTestFolder
{
    public FirstLookChartsTests() : base("ph-first-look-") { }

    static string Lift => Path.Combine(RepositoryRoot.Path, "Packages", "com.kosmos.pseudohaptic", "Documentation~", "examples", "lift.csv");
    static string Study => Path.Combine(RepositoryRoot.Path, "Packages", "com.kosmos.pseudohaptic", "Documentation~", "examples", "study");

    (List<ChartInk.Drawn> Drawn, string Stdout) Run(params string[] args)
    {
        (int Code, string Stderr, string Stdout) result = (0, "", "");
        var drawn = ChartInk.Catch(() => result = Capture(() => Cli.Cli.Run(args)));
        Assert.That(result.Code, Is.EqualTo(0), result.Stderr);
        return (drawn, result.Stdout);
    }

    static ChartInk.Drawn Titled(List<ChartInk.Drawn> drawn, string start)
        => drawn.First(d => d.Title().StartsWith(start, StringComparison.Ordinal));

    [Test]
    public void The_ink_check_fails_for_a_line_under_another_and_passes_for_lines_apart()
    {
        // It can fail: a line drawn exactly under another (the golf ball under the hand) is not seen apart from it.
        var xs = Enumerable.Range(0, 50).Select(i => i / 10.0).ToArray();
        var plot = Charts.Create("two lines", "t (s)", "y (m)");
        Charts.Series(plot, xs, xs.Select(Math.Sin).ToArray(), "under", 0);
        Charts.Hand(plot, xs, xs.Select(Math.Sin).ToArray(), "over");
        var drawn = ChartInk.Catch(() => Charts.Png(plot, 600, 400)).Single();
        Assert.Throws<AssertionException>(() => ChartInk.AssertEverySeriesSeen(drawn));
        var apart = Charts.Create("two lines", "t (s)", "y (m)");
        Charts.Series(apart, xs, xs.Select(Math.Sin).ToArray(), "one", 0);
        Charts.Hand(apart, xs, xs.Select(x => Math.Sin(x) + 0.5).ToArray(), "other");
        ChartInk.AssertEverySeriesSeen(ChartInk.Catch(() => Charts.Png(apart, 600, 400)).Single());
    }

    // --- demo -----------------------------------------------------------------------------------------------

    [Test]
    public void Demo_every_line_is_seen_against_the_others_the_golf_ball_under_the_hand_too()
    {
        var (drawn, _) = Run("demo", "--out", Path.Combine(_dir, "demo"), "--trace", Lift);
        Assert.That(drawn.Count, Is.GreaterThanOrEqualTo(8), "every scene's panels");
        foreach (var d in drawn) ChartInk.AssertEverySeriesSeen(d);
    }

    [Test]
    public void Offset_panels_show_each_mass_its_own_threshold_from_the_core()
    {
        var (drawn, _) = Run("demo", "--out", Path.Combine(_dir, "demo"), "--trace", Lift);
        var correction = NamedProfiles.Paper.Find<OffsetCorrection>()!;
        var panels = drawn.Where(d => d.Title().StartsWith("Offset", StringComparison.Ordinal)).ToList();
        Assert.That(panels, Has.Count.EqualTo(2), "offset-correction and recorded-hand");
        foreach (var (panel, masses) in panels.Zip(new[] { new[] { PhysicalConstants.StandardMassKg, PaperExperiment1.Mass(PaperExperiment1.BoxBDensity), 5.0 }, new[] { PhysicalConstants.StandardMassKg }.Concat(PaperExperiment1.BoxDensities.Select(PaperExperiment1.Mass)).ToArray() }))
        {
            var lines = panel.Plot.GetPlottables().OfType<ScottPlot.Plottables.HorizontalLine>().Select(l => l.Y).ToList();
            Assert.That(lines.OrderBy(y => y).ToList(), Is.EqualTo(masses.Select(correction.ThresholdFor).OrderBy(y => y).ToList()).Within(1e-12), "one threshold per mass, T(m) of the core");
            Assert.That(lines.Distinct().Count(), Is.GreaterThan(1), "the thresholds differ with the mass");
        }
    }

    [Test]
    public void The_xyz_panels_share_one_time_axis_show_motion_not_noise_and_the_summary_has_the_two_hand_carry()
    {
        var (drawn, stdout) = Run("demo", "--out", Path.Combine(_dir, "demo"));
        var panels = drawn.SkipWhile(d => !d.Title().StartsWith("Sideways", StringComparison.Ordinal)).Take(3).ToList();
        Assert.That(panels.Select(d => d.Plot.Axes.Left.Label.Text), Is.EqualTo(new[] { "x: hand − object (m)", "z: hand − object (m)", "y: height (m)" }));
        Assert.That(panels, Has.Count.EqualTo(3));
        var lefts = panels.Select(ChartInk.DataLeft).ToList();
        Assert.That(lefts.Distinct().Count(), Is.EqualTo(1), "the data areas start at the same pixel: " + string.Join(", ", lefts));
        var rights = panels.Select(d => { d.Plot.RenderInMemory(d.Width, d.Height); return d.Plot.RenderManager.LastRender.DataRect.Right; }).ToList();
        Assert.That(rights.Distinct().Count(), Is.EqualTo(1), "and end at the same pixel");
        Assert.That(panels.Select(d => d.Plot.Axes.GetLimits()).Select(l => (l.Left, l.Right)).Distinct().Count(), Is.EqualTo(1), "the same time span");
        foreach (var d in panels)
        {
            var limits = d.Plot.Axes.GetLimits();
            Assert.That(limits.Top - limits.Bottom, Is.GreaterThanOrEqualTo(0.1), $"{d.Plot.Axes.Left.Label.Text}: a span of metres, not the jitter's millimetres");
        }
        Assert.That(stdout, Does.Contain("two-hand carry"), "the two-hand sideways carry in the summary");
        var row = stdout.Split('\n').First(l => l.StartsWith("box 0.5 kg", StringComparison.Ordinal));
        Assert.That(row.Split(" ", StringSplitOptions.RemoveEmptyEntries).Length, Is.EqualTo(3 + 5), row);
    }

    // --- accuracy's Pareto chart -----------------------------------------------------------------------------

    static Kosmos.PseudoHaptic.Cli.Accuracy.AccuracyReport ParetoReport()
    {
        // The committed page's figures: no-filter and the default coincide (3.04 mm [2.92, 3.15] each).
        var rows = new (string Key, double Rms, double Half, double Lag)[]
        {
            ("no-filter", 3.04, 0.115, 70), ("deadband", 3.04, 0.115, 70), ("ma3", 5.95, 0.09, 106), ("ma5", 8.99, 0.095, 137),
            ("window-1s", 35.07, 0.065, 380), ("exp-30ms", 5.50, 0.09, 96), ("one-euro", 3.50, 0.11, 75), ("alpha-beta", 3.82, 0.09, 79),
            ("deadband+one-euro", 3.50, 0.11, 75), ("paper-literal", 35.15, 0.06, 563),
        };
        var summary = rows.Select(r => new Kosmos.PseudoHaptic.Cli.Accuracy.SummaryRow(r.Key, "estimators",
            new Kosmos.PseudoHaptic.Cli.Accuracy.Interval(r.Rms, r.Rms - r.Half, r.Rms + r.Half, 24), default!, 0,
            new Kosmos.PseudoHaptic.Cli.Accuracy.Interval(r.Lag, r.Lag - 2, r.Lag + 2, 24), false, default!, 0, default!)).ToList();
        return new Kosmos.PseudoHaptic.Cli.Accuracy.AccuracyReport(1, 0.5, 0.5, Array.Empty<Kosmos.PseudoHaptic.Cli.Accuracy.AccuracySource>(),
            Array.Empty<Kosmos.PseudoHaptic.Cli.Accuracy.AccuracyConfig>(), Array.Empty<Kosmos.PseudoHaptic.Cli.Accuracy.SourceResult>(),
            Array.Empty<Kosmos.PseudoHaptic.Cli.Accuracy.RestResult>(), summary, null, Array.Empty<Kosmos.PseudoHaptic.Cli.Accuracy.LongRunRow>(), Array.Empty<string>());
    }

    [Test]
    public void The_pareto_chart_keeps_its_ticks_inside_shows_no_filter_beside_the_default_and_its_bars()
    {
        var costs = Kosmos.PseudoHaptic.Cli.Accuracy.BenchmarkCosts.Read(Path.Combine(RepositoryRoot.Path, Kosmos.PseudoHaptic.Cli.Accuracy.AccuracyMarkdown.CostsPath));
        string png = Path.Combine(_dir, "pareto.png");
        var drawn = ChartInk.Catch(() => Kosmos.PseudoHaptic.Cli.Accuracy.ParetoChart.Save(png, ParetoReport(), costs, false));
        ChartExtremesTests.AssertNothingClipped(png);
        var chart = drawn.Single();
        var seen = ChartInk.Visibility(chart);
        // Every estimator's marker and every 95 % bar shows (no-filter is not under the default, a bar not under its marker).
        // (A leader line runs from its point to its label, touching both by design: only seen, not apart.)
        var hidden = seen.Where(v => v.Own > 0 && (v.Seen < 0.5 * v.Own || v.Distinct < 0.1 * v.Own && !v.Name.StartsWith("LinePlot", StringComparison.Ordinal))).Select(v => $"{v.Name}: {v.Seen}/{v.Own}, {v.Distinct} apart").ToList();
        Assert.That(hidden, Is.Empty);
        // The bars: paths of six points (an I), the first named in the legend.
        var plottables = chart.Plot.GetPlottables().ToList();
        var barNames = plottables.Select((p, i) => (p, i)).Where(x => x.p is ScottPlot.Plottables.Scatter sc && sc.Data.GetScatterPoints().Count == 6).Select(x => $"Scatter #{x.i}").ToHashSet();
        var bars = seen.Where(v => v.Name.StartsWith("95 %", StringComparison.Ordinal) || barNames.Contains(v.Name)).ToList();
        Assert.That(bars.Count, Is.GreaterThanOrEqualTo(8), "a bar per estimator on scale: " + string.Join(", ", seen.Select(v => $"{v.Name} {v.Own}")));
        Assert.That(bars.Min(b => b.Distinct), Is.GreaterThanOrEqualTo(15), "every bar at least 15 pixels clear of the others");
    }

    // --- study charts ------------------------------------------------------------------------------------------

    [Test]
    public void Psychometric_charts_put_catch_trials_in_a_note_not_at_the_edges_and_the_summary_fits_a_page()
    {
        var (drawn, _) = Run("psychometric", "--trials", Path.Combine(Study, "trials.csv"), "--out", Path.Combine(_dir, "fits"), "--bootstrap", "20");
        var fits = drawn.Where(d => d.Title().Contains("proportion judged heavier", StringComparison.Ordinal)).ToList();
        Assert.That(fits, Has.Count.EqualTo(16));
        foreach (var d in fits)
        {
            var limits = d.Plot.Axes.GetLimits();
            foreach (var scatter in d.Plot.GetPlottables().OfType<ScottPlot.Plottables.Scatter>().Where(sc => sc.LineWidth == 0 && sc.MarkerSize > 0))
                foreach (var point in scatter.Data.GetScatterPoints())
                    Assert.That(point.X, Is.InRange(limits.Left + 0.03 * (limits.Right - limits.Left), limits.Right - 0.03 * (limits.Right - limits.Left)),
                        $"{d.Title()}: {scatter.LegendText} at {point.X} kg is drawn at the plot's edge");
            Assert.That(d.Plot.Axes.Bottom.Label.Text, Is.EqualTo("comparison weight (kg)"), "the x label is the axis' name, no catch counts");
            var notes = string.Join("\n", d.Plot.GetPlottables().OfType<ScottPlot.Plottables.Text>().Select(t => t.LabelText))
                        + string.Join("\n", d.Plot.GetPlottables().SelectMany(p => p.LegendItems).Select(l => l.LabelText));
            Assert.That(notes, Does.Contain("catch trials at 0.25 kg").And.Contain("catch trials at 1 kg"), "the catch trials named in a note or the legend");
        }
        var summary = Titled(drawn, "PSE − standard and JND");
        Assert.That(summary.Width, Is.LessThanOrEqualTo(SummaryMaxWidth), "summary.png fits a page's width");
        using var png = SKBitmap.Decode(Path.Combine(_dir, "fits", "summary.png"));
        Assert.That(png.Width, Is.LessThanOrEqualTo(SummaryMaxWidth));
    }

    /// <summary>A two-column paper's full width is about 7 in; at 150 px per inch, 1050 px; 1200 px leaves it readable at 100 % on screen.</summary>
    const int SummaryMaxWidth = 1200;

    [Test]
    public void Compare_charts_name_the_unit_and_write_p_plainly()
    {
        string folder = Path.Combine(_dir, "compare");
        var (drawn, stdout) = Run("compare", "--scores", Path.Combine(Study, "psychophysics.csv"), "--out", folder);
        Assert.That(stdout, Does.Not.Match(@"\dE[-+]\d"), "p written plainly on the console");
        var charts = drawn.Where(d => d.Title().Contains("per participant and condition", StringComparison.Ordinal)).ToList();
        Assert.That(charts, Has.Count.EqualTo(2));
        Assert.That(charts.Select(d => d.Plot.Axes.Left.Label.Text), Is.EqualTo(new[] { "JND (kg)", "PSE (kg)" }));
        var text = string.Join("\n", drawn.SelectMany(d => d.Plot.GetPlottables().OfType<ScottPlot.Plottables.Text>()).Select(t => t.LabelText));
        Assert.That(text, Does.Contain("p < 0.001"), "the JND's t test p of 3.0e-5");
        Assert.That(text, Does.Not.Match(@"\dE[-+]?\d"), "no E notation");

        (drawn, _) = Run("compare", "--scores", Path.Combine(Study, "scores.csv"), "--out", Path.Combine(_dir, "compare2"));
        Assert.That(drawn.Select(d => d.Plot.Axes.Left.Label.Text).First(), Is.EqualTo("score (1 to 5)"), "a questionnaire's score on its scale");
    }

    [Test]
    public void Report_charts_are_not_titled_as_tables()
    {
        string examples = Path.Combine(RepositoryRoot.Path, "Packages", "com.kosmos.pseudohaptic", "Documentation~", "examples");
        var (drawn, _) = Run("report", "--scores", Path.Combine(examples, "scores.csv"), "--out", Path.Combine(_dir, "report"));
        Assert.That(drawn, Is.Not.Empty);
        foreach (var d in drawn) Assert.That(d.Title(), Does.Not.Match(@"^Table \d"), "a figure, not a table");
    }

    [TestCase(3.004e-05, "p < 0.001")]
    [TestCase(0.0007, "p < 0.001")]
    [TestCase(0.001, "p = 0.00100")]
    [TestCase(0.0078125, "p = 0.00781")]
    [TestCase(0.9175, "p = 0.918")]
    [TestCase(1.0, "p = 1.00")]
    public void P_is_written_plainly(double p, string text) => Assert.That(Kosmos.PseudoHaptic.Cli.NumberText.P(p), Is.EqualTo(text));
}
