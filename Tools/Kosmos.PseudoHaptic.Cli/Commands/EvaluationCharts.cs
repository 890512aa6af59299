using Kosmos.PseudoHaptic.Cli.Plotting;
using Kosmos.PseudoHaptic.Evaluation;

namespace Kosmos.PseudoHaptic.Cli;

/// <summary>
/// One chart per part of the report: each participant's score as a stem from the bottom of the scale with a
/// marker on top (a bar chart drawn with lines), the mean as a dashed line and its 95 % CI as dotted ones;
/// incomplete participants as grey dots on the axis. x is the participant's place in the report's order.
/// The figures go in the x-axis label rather than a legend, which would hide the tallest stems.
/// </summary>
static class EvaluationCharts
{
    /// <summary>Above this many participants the markers carry no name labels.</summary>
    const int MaxLabelled = 24;

    public static byte[] Png(EvaluationReport.Part part)
    {
        var q = part.Questionnaire;
        var scores = part.Scores;
        int n = scores.Count;
        var chart = new LineChart(Math.Clamp(300 + 45 * n, 900, 1800), 500)
        {
            Title = $"Table {part.Number}. {q.Title}",
            XLabel = AxisLabel(part.Statistics),
            YLabel = "score",
            XMin = 0.5,
            XMax = Math.Max(1, n) + 0.5,
            YMin = q.ScaleMin,
            YMax = q.ScaleMax + 0.1 * (q.ScaleMax - q.ScaleMin),
            ShowLegend = false,
        };

        var stemX = new List<double>();
        var stemY = new List<double>();
        var topX = new List<double>();
        var topY = new List<double>();
        var topLabels = new List<string?>();
        var missingX = new List<double>();
        var missingY = new List<double>();
        for (int i = 0; i < n; i++)
        {
            double x = i + 1;
            if (scores[i].Score is double s)
            {
                stemX.AddRange(new[] { x, x, double.NaN });
                stemY.AddRange(new[] { (double)q.ScaleMin, s, double.NaN });
                topX.Add(x);
                topY.Add(s);
                topLabels.Add(n <= MaxLabelled ? scores[i].Participant : null);
            }
            else
            {
                missingX.Add(x);
                missingY.Add(q.ScaleMin);
            }
        }

        var colour = Palette.Get(part.Number - 1);
        if (stemX.Count > 0) chart.AddLine(stemX, stemY, colour, "");
        if (topX.Count > 0) chart.AddPoints(topX, topY, colour, "score", topLabels);
        if (missingX.Count > 0)
            chart.AddPoints(missingX, missingY, Palette.Get(7), "incomplete",
                n <= MaxLabelled ? missingX.Select(x => (string?)(scores[(int)x - 1].Participant + " incomplete")).ToList() : null);

        var st = part.Statistics;
        double[] across = { 0.5, Math.Max(1, n) + 0.5 };
        if (double.IsFinite(st.Mean)) chart.AddLine(across, new[] { st.Mean, st.Mean }, Rgb.Black, "mean", dashed: true);
        if (double.IsFinite(st.ConfidenceLow))
        {
            var ci = Palette.Get(7);
            chart.AddLine(across, new[] { st.ConfidenceLow, st.ConfidenceLow }, ci, "95% CI", dashed: true);
            chart.AddLine(across, new[] { st.ConfidenceHigh, st.ConfidenceHigh }, ci, "", dashed: true);
        }
        return chart.ToPng();
    }

    static string AxisLabel(SummaryStatistics st)
    {
        if (!double.IsFinite(st.Mean)) return "participant (no complete scores)";
        string label = $"participant; mean {NumberText.Fixed(st.Mean, 2)} (black)";
        if (double.IsFinite(st.ConfidenceLow))
            label += $", 95% CI {NumberText.Fixed(st.ConfidenceLow, 2)} to {NumberText.Fixed(st.ConfidenceHigh, 2)} (grey)";
        return label;
    }
}
