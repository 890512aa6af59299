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

    /// <summary>Characters per line of a name under an axis (wrapped at spaces, a longer word kept whole).</summary>
    const int LabelChars = 18;

    /// <summary>
    /// One participant × condition: the proportion judged heavier at each comparison level with its 95 % Wilson
    /// interval, the fitted curve, the PSE (50 %) and the JND (to 75 %), the standard marked. The axis spans the
    /// levels that carry most trials; catch levels far outside are not drawn (at the edge they would look like data)
    /// but named, with their answers, in a note at the upper left.
    /// </summary>
    public static Figure Psychometric(string participant, string condition, IReadOnlyList<PsychometricRow> rows, IReadOnlyList<TrialAnswer> answers)
    {
        string title = Charts.Wrap(Messages.OneLine($"{participant}{(condition.Length > 0 ? " — " + condition : "")}: proportion judged heavier"), 70);
        var plot = Charts.Create(title, "comparison weight (kg)", "proportion judged heavier");
        var all = rows.SelectMany(r => r.Fit.Levels.Where(l => l.Trials > 0)).ToList();
        if (all.Count == 0)
            return new Figure(Charts.Empty(title, "No trials to draw."), Width, Height);
        // The main levels: those with at least a quarter of the most trials at one level (catch trials have few).
        int most = all.Max(l => l.Trials);
        var main = all.Where(l => l.Trials * 4 >= most).ToList();
        double xmin = main.Min(l => l.Level), xmax = main.Max(l => l.Level);
        foreach (var r in rows) { xmin = Math.Min(xmin, r.Standard); xmax = Math.Max(xmax, r.Standard); }
        if (!(xmax > xmin)) { xmin -= 0.5; xmax += 0.5; }
        double pad = 0.08 * (xmax - xmin);
        bool Outside(double x) => x < xmin - 0.6 * pad || x > xmax + 0.6 * pad;

        var standards = rows.Select(r => r.Standard).Distinct().ToList();
        foreach (var standard in standards)
        {
            var line = plot.Add.VerticalLine(standard);
            line.Color = ScottPlot.Color.FromHex("#505050");
            line.LineWidth = 1.5f;
            line.LinePattern = ScottPlot.LinePattern.DenselyDashed;
            line.LegendText = $"standard {G(standard)} kg";
        }
        var catchNotes = new List<string>();
        for (int s = 0; s < rows.Count; s++)
        {
            var r = rows[s];
            var colour = Charts.Colour(s);
            string std = rows.Count > 1 ? $"standard {G(r.Standard)} kg: " : "";
            var levels = r.Fit.Levels.Where(l => l.Trials > 0).ToList();
            var inside = levels.Where(l => !Outside(l.Level)).ToList();
            var barX = new List<double>();
            var barY = new List<double>();
            foreach (var l in inside)
            {
                WilsonInterval.Compute(l.Heavier, l.Trials, 0.95, out double lo, out double hi);
                barX.AddRange(new[] { l.Level, l.Level, double.NaN });
                barY.AddRange(new[] { lo, hi, double.NaN });
            }
            Charts.Points(plot, inside.Select(l => l.Level).ToArray(), inside.Select(l => l.Proportion).ToArray(), std + "proportion (95 % Wilson)", colour, shape: s);
            if (barX.Count > 0) Charts.Line(plot, barX, barY, "", colour);
            // Catch levels far off the axis are not drawn (at the edge they would read as data): the note names them.
            var off = levels.Where(l => Outside(l.Level)).ToList();
            catchNotes.AddRange(off.Select(l => $"{std}catch trials at {G(l.Level)} kg: {l.Heavier} of {l.Trials} heavier"));
            if (!r.Fit.Estimable)
            {
                catchNotes.Add($"{std}not estimable: {r.Fit.Reason}");
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
            // PSE: where the curve crosses 50 %; JND: from the PSE to PSE + JND, where the curve without lapses reaches 75 %
            // (the fitted curve there: 75 %, or 75 % − L/2 with lapses L, where the line ends on it).
            Charts.Line(plot, new[] { f.Pse, f.Pse }, new[] { 0.0, 0.5 }, $"{std}PSE {G(f.Pse)} kg", colour, dashed: true);
            double at75 = f.Pse + f.Jnd, onCurve = f.Lapse > 0 ? f.Psi(at75) : 0.75;
            Charts.Line(plot, new[] { f.Pse, at75, at75 }, new[] { onCurve, onCurve, 0.0 }, $"{std}JND {G(f.Jnd)} kg", Charts.Colour(s + 5), dashed: true);
            if (r.Bootstrap.HasIntervals)
                Charts.Line(plot, new[] { r.Bootstrap.PseLow, r.Bootstrap.PseHigh }, new[] { 0.5, 0.5 }, $"{std}PSE 95 % CI [{G(r.Bootstrap.PseLow)}, {G(r.Bootstrap.PseHigh)}] kg", Charts.Black);
        }
        Charts.LegendBelow(plot);
        plot.Axes.SetLimits(xmin - pad, xmax + pad, -0.03, 1.03);
        // The catch trials and any unfitted standard in a note at the upper left (low weights judged heavier: empty).
        if (catchNotes.Count > 0) Charts.Note(plot, xmin - 0.85 * pad, 0.99, string.Join("\n", catchNotes.Select(n => Charts.Wrap(n, 60))));
        FixedTicks(plot.Axes.Bottom, xmax - xmin + 2 * pad);
        return new Figure(plot, Width, Height + 40 * (rows.Count - 1));
    }

    /// <summary>
    /// PSE − standard and JND with their 95 % intervals, one column per participant × condition × standard, grouped
    /// by condition (a line between groups, the condition under its participants). Without an estimable fit, a
    /// sentence saying so.
    /// </summary>
    public static Figure PsychometricSummary(IReadOnlyList<PsychometricRow> rows)
    {
        const string title = "PSE − standard and JND per participant (95 % bootstrap intervals)";
        if (!rows.Any(r => r.Fit.Estimable))
            return new Figure(Charts.Empty(title, $"No fit is estimable ({rows.Count} participant × condition × standard groups): " +
                string.Join("; ", rows.Select(r => r.Fit.Reason).Distinct().Take(3)) + ". See fits.csv."), Width, 300);
        var conditions = rows.Select(r => r.Condition).Distinct().ToList();
        var ordered = rows.OrderBy(r => conditions.IndexOf(r.Condition)).ThenBy(r => r.Standard).ToList(); // stable: participants keep their order
        bool manyStandards = rows.Select(q => q.Standard).Distinct().Count() > 1;
        var plot = Charts.Create(title, conditions.Count > 1 ? "participant, grouped by condition" : "participant", "weight (kg)");
        var px = new List<double>(); var py = new List<double>();
        var jx = new List<double>(); var jy = new List<double>();
        var pbx = new List<double>(); var pby = new List<double>();
        var jbx = new List<double>(); var jby = new List<double>();
        var ticks = new List<double>(); var labels = new List<string>();
        // Names wrapped to what a column's width holds (about 8.5 px a character), never beyond LabelChars.
        int chars = Math.Clamp((int)((SummaryWidth(ordered.Count) - 150) / (double)Math.Max(1, ordered.Count) / 8.5), 4, LabelChars);
        for (int i = 0; i < ordered.Count; i++)
        {
            var r = ordered[i];
            double x = i + 1;
            ticks.Add(x);
            string name = Messages.OneLine(r.Participant) + (manyStandards ? " @" + G(r.Standard) + " kg" : "");
            bool firstOfGroup = i == 0 || ordered[i - 1].Condition != r.Condition;
            labels.Add(Charts.Wrap(name, chars) + (conditions.Count > 1 && firstOfGroup ? "\n" + Charts.Wrap("[" + Messages.OneLine(r.Condition) + "]", LabelChars) : ""));
            if (i > 0 && firstOfGroup)
            {
                var separator = plot.Add.VerticalLine(x - 0.5);
                separator.Color = ScottPlot.Color.FromHex("#909090");
                separator.LineWidth = 1;
            }
            if (!r.Fit.Estimable) continue;
            px.Add(x - 0.12); py.Add(r.Fit.Pse - r.Standard);
            jx.Add(x + 0.12); jy.Add(r.Fit.Jnd);
            if (r.Bootstrap.HasIntervals)
            {
                pbx.AddRange(new[] { x - 0.12, x - 0.12, double.NaN }); pby.AddRange(new[] { r.Bootstrap.PseLow - r.Standard, r.Bootstrap.PseHigh - r.Standard, double.NaN });
                jbx.AddRange(new[] { x + 0.12, x + 0.12, double.NaN }); jby.AddRange(new[] { r.Bootstrap.JndLow, r.Bootstrap.JndHigh, double.NaN });
            }
        }
        Charts.Line(plot, new[] { 0.5, ordered.Count + 0.5 }, new[] { 0.0, 0.0 }, "", Charts.Black);
        Charts.Points(plot, px, py, "PSE − standard", Charts.Colour(0), shape: 0);
        if (pbx.Count > 0) Charts.Line(plot, pbx, pby, "", Charts.Colour(0));
        Charts.Points(plot, jx, jy, "JND", Charts.Colour(1), shape: 1);
        if (jbx.Count > 0) Charts.Line(plot, jbx, jby, "", Charts.Colour(1));
        int lines = labels.Count > 0 ? labels.Max(l => l.Split('\n').Length) : 1;
        if (ordered.Count <= 40)
        {
            plot.Axes.Bottom.SetTicks(ticks.ToArray(), labels.ToArray());
            // The first and last labels are centred on their columns: room for half of their widest line at the sides.
            double Half(string label) => label.Split('\n').Max(l => Charts.NoteWidth(l)) * 15 / Charts.NoteSize / 2;
            plot.Axes.Right.MinimumSize = (float)Math.Max(10, Half(labels[^1]) - 0.5 * (SummaryWidth(ordered.Count) - 150) / ordered.Count + 10);
            plot.Axes.Left.MinimumSize = (float)Math.Max(0, Half(labels[0]) - 0.5 * (SummaryWidth(ordered.Count) - 150) / ordered.Count + 10);
            plot.Axes.Bottom.MinimumSize = 30 + 20 * lines;
        }
        Charts.LegendBelow(plot);
        plot.Axes.SetLimitsX(0.5, ordered.Count + 0.5);
        var all = py.Concat(jy).Concat(pby).Concat(jby).Where(double.IsFinite).Append(0.0).ToList();
        double low = all.Min(), high = all.Max(), span = Math.Max(high - low, 1e-9);
        plot.Axes.SetLimitsY(low - 0.08 * span, high + 0.08 * span);
        return new Figure(plot, SummaryWidth(ordered.Count), Height + 20 * lines);
    }

    /// <summary>Widest summary, px: a two-column paper's full text width (about 7 in) at about 170 dpi, one column (3.5 in) at 340 dpi.</summary>
    public const int MaxSummaryWidth = 1200;

    /// <summary>The summary's width for <paramref name="columns"/> participant × condition columns: 110 px each, 900 to <see cref="MaxSummaryWidth"/>.</summary>
    public static int SummaryWidth(int columns) => Math.Clamp(300 + 110 * columns, 900, MaxSummaryWidth);

    /// <summary>
    /// One line per participant through their scores in each condition, the conditions' means in black; under the
    /// plot, every test with its name: Friedman's (three or more conditions) and, per pair, the mean difference with
    /// the paired t test's p and the Wilcoxon signed-rank p (Holm-corrected with three or more conditions).
    /// </summary>
    public static Figure PairedLines(string questionnaire, IReadOnlyList<ConditionScore> scores, IReadOnlyList<ComparisonRow> rows)
    {
        var conditions = scores.Select(s => s.Condition).Distinct().ToList();
        string title = Charts.Wrap(Messages.OneLine($"{questionnaire}: score per participant and condition"), 70);
        var plot = Charts.Create(title, "condition", ScoreAxis(questionnaire));
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
        Charts.Points(plot, mx, my, "", Charts.Black, shape: 1);
        var finite = ly.Where(double.IsFinite).ToList();
        if (finite.Count > 0)
        {
            double low = finite.Min(), high = finite.Max(), span = Math.Max(high - low, 1e-9);
            plot.Axes.SetLimitsY(low - 0.08 * span, high + 0.08 * span);
        }
        // Names that fit under their column are written there; otherwise every condition gets a short code (C1, C2, …)
        // and the key is listed with the tests, so no name is cut or broken inside a word.
        int chars = Math.Max(8, 100 / Math.Max(1, conditions.Count));
        var full = conditions.Select(c => Messages.OneLine(c.Length == 0 ? "(none)" : c)).ToList();
        bool coded = full.Any(n => n.Split(' ').Any(word => word.Length > chars) || Charts.Wrap(n, chars).Split('\n').Length > 3);
        string Name(string condition) => coded ? "C" + (conditions.IndexOf(condition) + 1) : Messages.OneLine(condition);
        var names = coded ? full.Select((_, i) => "C" + (i + 1)).ToArray() : full.Select(n => Charts.Wrap(n, chars)).ToArray();
        int lines = names.Length > 0 ? names.Max(n => n.Split('\n').Length) : 1;
        plot.Axes.Bottom.SetTicks(Enumerable.Range(1, conditions.Count).Select(i => (double)i).ToArray(), names);
        plot.Axes.Bottom.MinimumSize = 30 + 20 * lines;
        plot.Axes.SetLimitsX(0.5, conditions.Count + 0.5);
        Charts.LegendBelow(plot);
        int width = Math.Clamp(300 + 160 * conditions.Count, 900, 2400);

        var tests = new List<string>();
        if (coded) tests.Add("Conditions: " + string.Join("; ", full.Select((n, i) => $"C{i + 1} = {n}")));
        var friedman = rows.FirstOrDefault(r => r.Friedman != null)?.Friedman;
        if (friedman != null)
            tests.Add($"Friedman test over {friedman.K} conditions: χ²({friedman.DegreesOfFreedom}) = {G(friedman.Statistic)}, {NumberText.P(friedman.P)} (n = {friedman.N} complete participants)");
        else if (conditions.Count >= 3)
            tests.Add("Friedman test: not computed (too few participants complete in every condition)");
        foreach (var r in rows.Where(r => r.Pair != null))
        {
            var pr = r.Pair;
            string pair = $"{Name(r.ConditionB)} − {Name(r.ConditionA)}";
            if (!double.IsFinite(pr.MeanDifference)) { tests.Add($"{pair}: too few pairs (n = {pr.N})"); continue; }
            string wilcoxon = conditions.Count >= 3 && double.IsFinite(r.PHolm) ? $"Wilcoxon signed-rank {NumberText.P(pr.WP)}, Holm-corrected {NumberText.P(r.PHolm)}" : $"Wilcoxon signed-rank {NumberText.P(pr.WP)}";
            tests.Add($"{pair} = {G(pr.MeanDifference)} (n = {pr.N}): paired t test {NumberText.P(pr.TP)}; {wilcoxon}");
        }
        if (tests.Count == 0) return new Figure(plot, width, Height + 20 * lines);
        var text = Charts.TextPanel(tests, width);
        return new Figure(new[] { plot, text.Plot }, width, new[] { Height + 20 * lines, text.Height });
    }

    static string G(double v) => double.IsFinite(v) ? v.ToString("G4", CultureInfo.InvariantCulture) : "n/a";

    /// <summary>
    /// The y axis of a questionnaire's paired lines, with its unit: a built-in questionnaire's score on its scale
    /// ("score (1 to 5)"); the psychometric figures run.sh and evaluation.md turn into scores, PSE and JND in kg and
    /// the Weber fraction (no unit); anything else "score" with its name, the unit being the file's own.
    /// </summary>
    public static string ScoreAxis(string questionnaire)
    {
        switch (questionnaire.Trim().ToLowerInvariant())
        {
            case "pse": return "PSE (kg)";
            case "jnd": return "JND (kg)";
            case "weber": return "Weber fraction (JND / standard)";
        }
        var q = EvaluationInputs.Catalog(null).Questionnaires.FirstOrDefault(x => x.Id == questionnaire);
        return q != null ? $"score ({NumberText.Format(q.ScaleMin)} to {NumberText.Format(q.ScaleMax)})" : Charts.Wrap($"{Messages.OneLine(questionnaire)} score", 40);
    }

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
