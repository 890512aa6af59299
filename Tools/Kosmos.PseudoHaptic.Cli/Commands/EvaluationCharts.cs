using Kosmos.PseudoHaptic.Cli.Plotting;
using Kosmos.PseudoHaptic.Evaluation;

namespace Kosmos.PseudoHaptic.Cli;

/// <summary>
/// One chart per part of the report: each participant's score as a bar rising from the bottom of the scale,
/// the participants named under their bars (in the report's order, long names wrapped), the mean as a dashed
/// black line and its 95 % CI as a grey band behind the bars, both with their figures in the legend (under the
/// plot, so no bar is hidden). An incomplete participant is an empty outlined bar the height of the scale,
/// "incomplete" under their name.
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
        // A figure of the part's scores (the report's Table N holds the numbers): titled as a figure, not a table.
        var plot = Charts.Create($"{q.Title}: score per participant", "participant",
            $"score ({NumberText.Format(q.ScaleMin)} to {NumberText.Format(q.ScaleMax)})");

        var colour = Charts.Colour(part.Number - 1);
        var st = part.Statistics;
        // The interval first, so the bars are drawn over it.
        if (double.IsFinite(st.ConfidenceLow) && double.IsFinite(st.ConfidenceHigh))
        {
            var band = plot.Add.VerticalSpan(st.ConfidenceLow, st.ConfidenceHigh);
            band.FillStyle.Color = Charts.Colour(7).WithAlpha(0.3);
            band.LineStyle.Width = 0;
            band.LegendText = $"95% CI {NumberText.Fixed(st.ConfidenceLow, 2)} to {NumberText.Fixed(st.ConfidenceHigh, 2)}";
        }
        var bars = new List<ScottPlot.Bar>();
        var missing = new List<ScottPlot.Bar>();
        var names = new ScottPlot.TickGenerators.NumericManual();
        for (int i = 0; i < n; i++)
        {
            double x = i + 1;
            if (scores[i].Score is double s)
                bars.Add(new ScottPlot.Bar { Position = x, Value = s, ValueBase = q.ScaleMin, FillColor = colour, LineWidth = 0, Size = 0.7 });
            else
                missing.Add(new ScottPlot.Bar { Position = x, Value = q.ScaleMax, ValueBase = q.ScaleMin, FillColor = ScottPlot.Color.FromHex("#F2F2F2"), LineColor = Charts.Colour(7), LineWidth = 1.5f, Size = 0.7 });
            if (n <= MaxLabelled) names.AddMajor(x, Charts.Wrap(scores[i].Participant, 12) + (scores[i].Score is null ? "\nincomplete" : ""));
        }
        if (n <= MaxLabelled)
        {
            plot.Axes.Bottom.TickGenerator = names;
            int lines = scores.Select(p => Charts.Wrap(p.Participant, 12).Split('\n').Length + (p.Score is null ? 1 : 0)).DefaultIfEmpty(1).Max();
            plot.Axes.Bottom.MinimumSize = 30 + 20 * lines;
        }

        if (bars.Count > 0)
        {
            var barPlot = plot.Add.Bars(bars);
            barPlot.LegendText = "score";
        }
        if (missing.Count > 0)
        {
            var empty = plot.Add.Bars(missing);
            empty.LegendText = "incomplete (no score)";
        }
        if (double.IsFinite(st.Mean))
        {
            var mean = plot.Add.HorizontalLine(st.Mean);
            mean.Color = Charts.Black;
            mean.LineWidth = 2;
            mean.LinePattern = ScottPlot.LinePattern.Dashed;
            mean.LegendText = $"mean {NumberText.Fixed(st.Mean, 2)}";
        }

        Charts.LegendBelow(plot);
        plot.Axes.SetLimits(0.4, Math.Max(1, n) + 0.6, q.ScaleMin, q.ScaleMax + 0.1 * (q.ScaleMax - q.ScaleMin));
        return plot;
    }
}
