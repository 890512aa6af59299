using Kosmos.PseudoHaptic.Cli.Plotting;
using Kosmos.PseudoHaptic.Evaluation;

namespace Kosmos.PseudoHaptic.Cli;

/// <summary>
/// One chart per part of the report: each participant's score as a bar rising from the bottom of the scale,
/// the participants named under their bars (in the report's order), the mean as a dashed black line and its
/// 95 % CI as a grey band, both with their figures in the legend (outside the plot, so no bar is hidden).
/// Incomplete participants are grey dots on the scale's bottom, "(incomplete)" under their name.
/// </summary>
static class EvaluationCharts
{
    /// <summary>Above this many participants the bars are numbered rather than named.</summary>
    const int MaxLabelled = 24;

    public const int Height = 500;

    /// <summary>Width of a part's chart: wider for more participants.</summary>
    public static int Width(EvaluationReport.Part part) => Math.Clamp(400 + 50 * part.Scores.Count, 900, 1800);

    public static byte[] Png(EvaluationReport.Part part) => Charts.Png(Plot(part), Width(part), Height);

    public static string Svg(EvaluationReport.Part part) => Charts.Svg(Plot(part), Width(part), Height);

    public static ScottPlot.Plot Plot(EvaluationReport.Part part)
    {
        var q = part.Questionnaire;
        var scores = part.Scores;
        int n = scores.Count;
        var plot = Charts.Create($"Table {part.Number}. {q.Title}", "participant",
            $"score ({NumberText.Format(q.ScaleMin)} to {NumberText.Format(q.ScaleMax)})");

        var colour = Charts.Colour(part.Number - 1);
        var bars = new List<ScottPlot.Bar>();
        var missingX = new List<double>();
        var names = new ScottPlot.TickGenerators.NumericManual();
        for (int i = 0; i < n; i++)
        {
            double x = i + 1;
            if (scores[i].Score is double s)
                bars.Add(new ScottPlot.Bar { Position = x, Value = s, ValueBase = q.ScaleMin, FillColor = colour, LineWidth = 0, Size = 0.7 });
            else
                missingX.Add(x);
            if (n <= MaxLabelled) names.AddMajor(x, scores[i].Score is null ? scores[i].Participant + "\n(incomplete)" : scores[i].Participant);
        }
        if (n <= MaxLabelled) plot.Axes.Bottom.TickGenerator = names;

        if (bars.Count > 0)
        {
            var barPlot = plot.Add.Bars(bars);
            barPlot.LegendText = "score";
        }
        if (missingX.Count > 0)
            Charts.Points(plot, missingX, missingX.Select(_ => (double)q.ScaleMin).ToList(), "incomplete", Charts.Colour(7));

        var st = part.Statistics;
        if (double.IsFinite(st.ConfidenceLow) && double.IsFinite(st.ConfidenceHigh))
        {
            var band = plot.Add.VerticalSpan(st.ConfidenceLow, st.ConfidenceHigh);
            band.FillStyle.Color = Charts.Colour(7).WithAlpha(0.35);
            band.LineStyle.Width = 0;
            band.LegendText = $"95% CI {NumberText.Fixed(st.ConfidenceLow, 2)} to {NumberText.Fixed(st.ConfidenceHigh, 2)}";
        }
        if (double.IsFinite(st.Mean))
        {
            var mean = plot.Add.HorizontalLine(st.Mean);
            mean.Color = Charts.Black;
            mean.LineWidth = 2;
            mean.LinePattern = ScottPlot.LinePattern.Dashed;
            mean.LegendText = $"mean {NumberText.Fixed(st.Mean, 2)}";
        }

        plot.ShowLegend(ScottPlot.Edge.Right);
        plot.Axes.SetLimits(0.4, Math.Max(1, n) + 0.6, q.ScaleMin, q.ScaleMax + 0.1 * (q.ScaleMax - q.ScaleMin));
        return plot;
    }
}
