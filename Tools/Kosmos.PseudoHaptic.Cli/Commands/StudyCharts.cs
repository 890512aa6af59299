using System.Globalization;
using Kosmos.PseudoHaptic.Cli.Files;
using Kosmos.PseudoHaptic.Cli.Plotting;
using Kosmos.PseudoHaptic.Evaluation;

namespace Kosmos.PseudoHaptic.Cli;

/// <summary>
/// The charts of <c>psychometric</c> and <c>compare</c>, through the project's chart style (<see cref="Charts"/>):
/// a psychometric chart per participant × condition (proportion "heavier" at each level with its 95 % Wilson
/// interval, the fitted curve, the PSE and the JND marked), a summary of PSEs and JNDs across participants, and
/// paired lines per participant for each questionnaire's conditions.
/// </summary>
static class StudyCharts
{
    const int Width = 1000, Height = 600;

    public static byte[] Psychometric(string participant, string condition, IReadOnlyList<PsychometricRow> rows, IReadOnlyList<TrialAnswer> answers)
    {
        string title = $"{participant}{(condition.Length > 0 ? " — " + condition : "")}: proportion judged heavier";
        var plot = Charts.Create(Messages.OneLine(title), "comparison", "proportion 'comparison heavier'");
        double xmin = double.PositiveInfinity, xmax = double.NegativeInfinity;
        foreach (var r in rows)
            foreach (var l in r.Fit.Levels) { xmin = Math.Min(xmin, l.Level); xmax = Math.Max(xmax, l.Level); }
        if (!(xmax > xmin)) { xmin -= 0.5; xmax += 0.5; }
        double pad = 0.05 * (xmax - xmin);

        for (int s = 0; s < rows.Count; s++)
        {
            var r = rows[s];
            var colour = Charts.Colour(s);
            string std = rows.Count > 1 ? $"standard {NumberText.Format(r.Standard)}: " : "";
            var levels = r.Fit.Levels.Where(l => l.Trials > 0).ToList();
            var barX = new List<double>();
            var barY = new List<double>();
            foreach (var l in levels)
            {
                WilsonInterval.Compute(l.Heavier, l.Trials, 0.95, out double lo, out double hi);
                barX.AddRange(new[] { l.Level, l.Level, double.NaN });
                barY.AddRange(new[] { lo, hi, double.NaN });
            }
            Charts.Points(plot, levels.Select(l => l.Level).ToArray(), levels.Select(l => l.Proportion).ToArray(), std + "proportion (95 % Wilson)", colour);
            if (barX.Count > 0) Charts.Line(plot, barX, barY, "", colour);
            if (!r.Fit.Estimable)
            {
                Charts.Note(plot, xmin, 0.95 - 0.07 * s, $"{std}not estimable: {r.Fit.Reason}");
                continue;
            }
            var f = r.Fit;
            const int n = 200;
            var cx = new double[n + 1];
            var cy = new double[n + 1];
            for (int i = 0; i <= n; i++)
            {
                cx[i] = xmin - pad + (xmax - xmin + 2 * pad) * i / n;
                cy[i] = f.Psi(cx[i]);
            }
            Charts.Line(plot, cx, cy, std + "fit", colour);
            // PSE: where the curve crosses 50 %; JND: from the PSE to where it reaches 75 %.
            Charts.Line(plot, new[] { f.Pse, f.Pse }, new[] { 0.0, 0.5 }, $"{std}PSE {G(f.Pse)}", colour, dashed: true);
            double at75 = f.Pse + f.Jnd;
            Charts.Line(plot, new[] { f.Pse, at75, at75 }, new[] { 0.75, 0.75, 0.0 }, $"{std}JND {G(f.Jnd)}", Charts.Colour(s + 5), dashed: true);
            if (r.Bootstrap.HasIntervals)
                Charts.Line(plot, new[] { r.Bootstrap.PseLow, r.Bootstrap.PseHigh }, new[] { 0.5, 0.5 }, $"{std}PSE 95 % CI [{G(r.Bootstrap.PseLow)}, {G(r.Bootstrap.PseHigh)}]", Charts.Black);
        }
        plot.Legend.Alignment = ScottPlot.Alignment.LowerRight; // an increasing curve leaves that corner empty
        plot.Axes.SetLimits(xmin - pad, xmax + pad, -0.03, 1.03);
        FixedTicks(plot.Axes.Bottom, xmax - xmin + 2 * pad);
        return Charts.Png(plot, Width, Height);
    }

    /// <summary>PSE − standard and JND with their 95 % intervals, one column per participant × condition × standard.</summary>
    public static byte[] PsychometricSummary(IReadOnlyList<PsychometricRow> rows)
    {
        var plot = Charts.Create("PSE − standard and JND per participant (95 % bootstrap intervals)", "participant", "comparison − standard");
        var px = new List<double>(); var py = new List<double>();
        var jx = new List<double>(); var jy = new List<double>();
        var pbx = new List<double>(); var pby = new List<double>();
        var jbx = new List<double>(); var jby = new List<double>();
        var ticks = new List<double>(); var labels = new List<string>();
        for (int i = 0; i < rows.Count; i++)
        {
            var r = rows[i];
            double x = i + 1;
            ticks.Add(x);
            labels.Add(Messages.OneLine(r.Participant + (r.Condition.Length > 0 ? " " + r.Condition : "") + (rows.Select(q => q.Standard).Distinct().Count() > 1 ? " @" + NumberText.Format(r.Standard) : "")));
            if (!r.Fit.Estimable) continue;
            px.Add(x - 0.12); py.Add(r.Fit.Pse - r.Standard);
            jx.Add(x + 0.12); jy.Add(r.Fit.Jnd);
            if (r.Bootstrap.HasIntervals)
            {
                pbx.AddRange(new[] { x - 0.12, x - 0.12, double.NaN }); pby.AddRange(new[] { r.Bootstrap.PseLow - r.Standard, r.Bootstrap.PseHigh - r.Standard, double.NaN });
                jbx.AddRange(new[] { x + 0.12, x + 0.12, double.NaN }); jby.AddRange(new[] { r.Bootstrap.JndLow, r.Bootstrap.JndHigh, double.NaN });
            }
        }
        Charts.Line(plot, new[] { 0.5, rows.Count + 0.5 }, new[] { 0.0, 0.0 }, "", Charts.Black);
        Charts.Points(plot, px, py, "PSE − standard", Charts.Colour(0));
        if (pbx.Count > 0) Charts.Line(plot, pbx, pby, "", Charts.Colour(0));
        Charts.Points(plot, jx, jy, "JND", Charts.Colour(1));
        if (jbx.Count > 0) Charts.Line(plot, jbx, jby, "", Charts.Colour(1));
        int longest = labels.Count > 0 ? labels.Max(l => l.Length) : 0;
        if (rows.Count <= 60)
        {
            plot.Axes.Bottom.SetTicks(ticks.ToArray(), labels.ToArray());
            if (longest > 4)
            {
                // Names turned, so that long ones do not run into each other.
                plot.Axes.Bottom.TickLabelStyle.Rotation = 35;
                plot.Axes.Bottom.TickLabelStyle.Alignment = ScottPlot.Alignment.MiddleLeft;
                plot.Axes.Bottom.MinimumSize = 40 + 8 * Math.Min(longest, 30);
            }
        }
        plot.Axes.SetLimitsX(0.5, rows.Count + 0.5);
        var all = py.Concat(jy).Concat(pby).Concat(jby).Where(double.IsFinite).Append(0.0).ToList();
        double low = all.Min(), high = all.Max(), span = Math.Max(high - low, 1e-9);
        plot.Axes.SetLimitsY(low - 0.05 * span, high + 0.3 * span); // room above for the legend
        return Charts.Png(plot, Math.Clamp(300 + 45 * rows.Count, 900, 3000), Height + (longest > 4 ? 6 * Math.Min(longest, 30) : 0));
    }

    /// <summary>One line per participant through their scores in each condition; the conditions' means in black.</summary>
    public static byte[] PairedLines(string questionnaire, IReadOnlyList<ConditionScore> scores, IReadOnlyList<ComparisonRow> pairs)
    {
        var conditions = scores.Select(s => s.Condition).Distinct().ToList();
        var plot = Charts.Create(Messages.OneLine($"{questionnaire}: score per participant and condition"), "condition", "score");
        var participants = ParticipantOrder.Sort(scores.Select(s => s.Participant).Distinct(), p => p);
        var lookup = scores.Where(s => s.Score.HasValue).ToDictionary(s => (s.Participant, s.Condition), s => s.Score!.Value);
        var lx = new List<double>();
        var ly = new List<double>();
        for (int p = 0; p < participants.Count; p++)
        {
            // A small spread keeps coinciding lines apart; a missing score breaks the line.
            double jitter = participants.Count > 1 ? 0.06 * (p / (participants.Count - 1.0) - 0.5) : 0;
            for (int c = 0; c < conditions.Count; c++)
            {
                if (lookup.TryGetValue((participants[p], conditions[c]), out double v)) { lx.Add(c + 1 + jitter); ly.Add(v); }
                else { lx.Add(double.NaN); ly.Add(double.NaN); }
            }
            lx.Add(double.NaN); ly.Add(double.NaN);
        }
        if (lx.Count > 0) Charts.Line(plot, lx, ly, $"participant ({participants.Count})", Charts.Colour(7));
        Charts.Points(plot, lx, ly, "", Charts.Colour(7));
        var mx = new List<double>();
        var my = new List<double>();
        for (int c = 0; c < conditions.Count; c++)
        {
            var values = scores.Where(s => s.Condition == conditions[c] && s.Score.HasValue).Select(s => s.Score!.Value).ToList();
            if (values.Count == 0) continue;
            mx.Add(c + 1);
            my.Add(values.Average());
        }
        Charts.Line(plot, mx, my, "mean", Charts.Black);
        Charts.Points(plot, mx, my, "", Charts.Black);
        // The pairs' mean differences and (Holm-corrected) Wilcoxon p in the axis label, where no line runs.
        var notes = pairs.Where(r => double.IsFinite(r.Pair.MeanDifference))
            .Select(r => $"{Messages.OneLine(r.ConditionB)} − {Messages.OneLine(r.ConditionA)} = {G(r.Pair.MeanDifference)}{(double.IsFinite(r.PHolm) ? $", p = {G(r.PHolm)}" : "")}").ToList();
        plot.XLabel(notes.Count > 0 && notes.Count <= 3 ? "condition; " + string.Join("; ", notes) : "condition");
        var finite = ly.Where(double.IsFinite).ToList();
        if (finite.Count > 0)
        {
            double low = finite.Min(), high = finite.Max(), span = Math.Max(high - low, 1e-9);
            plot.Axes.SetLimitsY(low - 0.05 * span, high + 0.3 * span); // room above for the legend
        }
        plot.Axes.Bottom.SetTicks(Enumerable.Range(1, conditions.Count).Select(i => (double)i).ToArray(), conditions.Select(c => Messages.OneLine(c.Length == 0 ? "(none)" : c)).ToArray());
        plot.Axes.SetLimitsX(0.5, conditions.Count + 0.5);
        return Charts.Png(plot, Math.Clamp(300 + 200 * conditions.Count, 800, 2000), Height);
    }

    static string G(double v) => v.ToString("G4", CultureInfo.InvariantCulture);

    /// <summary>Ticks every 1, 2 or 5 × 10^k (about eight across), each labelled with the decimals that step needs.</summary>
    static void FixedTicks(ScottPlot.IAxis axis, double range)
    {
        if (!(range > 0) || !double.IsFinite(range)) return;
        double raw = range / 8, power = Math.Pow(10, Math.Floor(Math.Log10(raw)));
        double step = raw / power < 1.5 ? power : raw / power < 3.5 ? 2 * power : raw / power < 7.5 ? 5 * power : 10 * power;
        int decimals = Math.Max(0, -(int)Math.Floor(Math.Log10(step) + 1e-9));
        string format = "F" + decimals.ToString(CultureInfo.InvariantCulture);
        axis.TickGenerator = new ScottPlot.TickGenerators.NumericFixedInterval(step)
        {
            LabelFormatter = v => v.ToString(format, CultureInfo.InvariantCulture),
        };
    }
}
