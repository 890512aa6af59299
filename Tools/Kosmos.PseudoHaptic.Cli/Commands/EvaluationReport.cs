using System.Globalization;
using System.Text;
using Kosmos.PseudoHaptic.Evaluation;

namespace Kosmos.PseudoHaptic.Cli;

/// <summary>
/// The content of <c>pseudohaptic report</c>, computed once and rendered as text: per part, the
/// participants' scores (the paper's Tables 1–3), the summary statistics, and Cronbach's α when
/// item-level responses were given. Markdown for people, CSV for programs.
/// </summary>
sealed class EvaluationReport
{
    /// <summary>One questionnaire's results. <see cref="Number"/> is its table number (catalog order, from 1).</summary>
    public sealed record Part(int Number, Questionnaire Questionnaire, IReadOnlyList<ParticipantScore> Scores,
        SummaryStatistics Statistics, CronbachAlpha? Alpha)
    {
        public int Incomplete => Scores.Count(s => !s.IsComplete);
        public string FileStem => $"{Number}-{SafeName(Questionnaire.Id)}";
        public string TableFile => $"table{FileStem}.csv";
        public string ChartFile => $"chart{FileStem}.png";
    }

    public string ScoresSource { get; }
    public string? ResponsesSource { get; }
    public IReadOnlyList<Part> Parts { get; }
    /// <summary>Scores of S.csv that R.csv, scored again, does not reproduce ("P1 immersion"), when R.csv was given.</summary>
    public IReadOnlyList<string> Disagreements { get; }

    EvaluationReport(string scoresSource, string? responsesSource, IReadOnlyList<Part> parts, IReadOnlyList<string> disagreements)
    {
        ScoresSource = scoresSource;
        ResponsesSource = responsesSource;
        Parts = parts;
        Disagreements = disagreements;
    }

    public static EvaluationReport Build(QuestionnaireCatalog catalog, IReadOnlyList<ParticipantScore> scores, string scoresSource,
        ResponseSet? responses, string? responsesSource)
    {
        scores = ParticipantOrder.Sort(scores, s => s.Participant);
        var parts = new List<Part>();
        for (int i = 0; i < catalog.Questionnaires.Count; i++)
        {
            var q = catalog.Questionnaires[i];
            var mine = scores.Where(s => s.QuestionnaireId == q.Id).ToList();
            CronbachAlpha? alpha = responses != null && q.ItemCount > 1 ? CronbachAlpha.Of(responses, q.Id) : null;
            parts.Add(new Part(i + 1, q, mine, SummaryStatistics.OfScores(mine), alpha));
        }

        var disagreements = new List<string>();
        if (responses != null)
            foreach (var s in scores)
            {
                var sheet = responses.Find(s.Participant, s.QuestionnaireId);
                var again = sheet != null ? ScoreCalculator.Score(sheet).Score : null;
                bool same = again.HasValue == s.Score.HasValue && (!again.HasValue || Math.Abs(again.Value - s.Score!.Value) <= 1e-9);
                if (!same) disagreements.Add(s.Participant + " " + s.QuestionnaireId);
            }
        return new EvaluationReport(scoresSource, responsesSource, parts, disagreements);
    }

    // ---- CSV -------------------------------------------------------------------------------------------

    /// <summary>One part's table: participant,score, participants in natural order (P2 before P10); empty score = incomplete.</summary>
    public static string TableCsv(Part part)
    {
        var text = new StringBuilder("participant,score\n");
        foreach (var s in part.Scores)
            text.Append(CsvTable.Escape(s.Participant)).Append(',').Append(s.Score.HasValue ? ScoresCsv.FormatNumber(s.Score.Value) : "").Append('\n');
        return text.ToString();
    }

    public const string SummaryHeader = "questionnaire,title,items,scale_min,scale_max,n,incomplete,mean,sd,median,min,max,ci95_low,ci95_high,alpha,alpha_n";

    /// <summary>One row per part; undefined figures (n &lt; 2, no responses) are empty.</summary>
    public string SummaryCsv()
    {
        var text = new StringBuilder(SummaryHeader).Append('\n');
        foreach (var p in Parts)
        {
            var st = p.Statistics;
            var q = p.Questionnaire;
            var fields = new[]
            {
                CsvTable.Escape(q.Id), CsvTable.Escape(q.Title), Int(q.ItemCount), Int(q.ScaleMin), Int(q.ScaleMax),
                Int(st.N), Int(p.Incomplete), Num(st.Mean), Num(st.StandardDeviation), Num(st.Median), Num(st.Min), Num(st.Max),
                Num(st.ConfidenceLow), Num(st.ConfidenceHigh),
                p.Alpha != null ? Num(p.Alpha.Alpha) : "", p.Alpha != null ? Int(p.Alpha.Participants) : "",
            };
            text.Append(string.Join(",", fields)).Append('\n');
        }
        return text.ToString();
    }

    static string Int(int v) => v.ToString(CultureInfo.InvariantCulture);
    /// <summary>15 significant digits: all a statistic means, without the noise of 3.8499999999999996.</summary>
    static string Num(double v) => double.IsFinite(v) ? v.ToString("G15", CultureInfo.InvariantCulture) : "";

    // ---- Markdown --------------------------------------------------------------------------------------

    /// <summary>Participants per table row, as in the paper's tables (P1–P6, then P7–P12).</summary>
    const int PerRow = 6;

    public string Markdown()
    {
        var md = new StringBuilder();
        int participants = Parts.SelectMany(p => p.Scores).Select(s => s.Participant).Distinct(StringComparer.Ordinal).Count();
        md.Append("# Evaluation report\n\n");
        md.Append($"Scores: `{Cell(ScoresSource)}`, {participants} participant{(participants == 1 ? "" : "s")}. ");
        md.Append(ResponsesSource != null
            ? $"Item-level responses: `{Cell(ResponsesSource)}` (Cronbach's α from the participants who completed a part).\n\n"
            : "No item-level responses given (`--responses R.csv`), so no Cronbach's α.\n\n");
        if (Disagreements.Count > 0)
            md.Append($"**Warning:** {Disagreements.Count} score{(Disagreements.Count == 1 ? "" : "s")} in the scores file differ from the responses scored again: {Cell(string.Join(", ", Disagreements.Take(10)))}{(Disagreements.Count > 10 ? ", …" : "")}.\n\n");
        md.Append("Scoring: answers from 1 to the scale's top, reverse-coded items counted as min + max − x (6 − x on a 5-point scale), ");
        md.Append("a participant's score the mean over the part's items; a part with an unanswered item is incomplete and has no score. ");
        md.Append("Statistics over complete scores: SD with n − 1, 95 % CI = mean ± t(0.975, n − 1)·SD/√n.\n\n");

        md.Append("## Summary\n\n");
        md.Append("| part | n | incomplete | mean | SD | median | min | max | 95 % CI | Cronbach's α |\n");
        md.Append("|---|---:|---:|---:|---:|---:|---:|---:|---|---:|\n");
        foreach (var p in Parts)
        {
            var st = p.Statistics;
            md.Append($"| {Cell(p.Questionnaire.Title)} | {st.N} | {p.Incomplete} | {F2(st.Mean)} | {F2(st.StandardDeviation)} | {F2(st.Median)} | {F2(st.Min)} | {F2(st.Max)} | {Interval(st)} | {AlphaText(p)} |\n");
        }
        md.Append('\n');

        foreach (var p in Parts) AppendPart(md, p);
        return md.ToString();
    }

    void AppendPart(StringBuilder md, Part p)
    {
        var q = p.Questionnaire;
        var reversed = q.Items.Where(i => i.Reverse).Select(i => i.Number.ToString(CultureInfo.InvariantCulture)).ToList();
        md.Append($"## Table {p.Number}. {Cell(q.Title)}\n\n");
        md.Append($"`{Cell(q.Id)}`: {q.ItemCount} item{(q.ItemCount == 1 ? "" : "s")} on a {q.ScaleText()} scale");
        md.Append(reversed.Count > 0 ? $", item{(reversed.Count == 1 ? "" : "s")} {string.Join(", ", reversed)} reverse-coded.\n\n" : ".\n\n");

        if (p.Scores.Count == 0)
        {
            md.Append("No scores.\n\n");
            return;
        }

        for (int start = 0; start < p.Scores.Count; start += PerRow)
        {
            var chunk = p.Scores.Skip(start).Take(PerRow).ToList();
            var names = chunk.Select(s => Cell(s.Participant)).ToList();
            var values = chunk.Select(s => s.Score.HasValue ? ScoreText(q, s.Score.Value) : "incomplete").ToList();
            while (names.Count < Math.Min(PerRow, p.Scores.Count)) { names.Add(""); values.Add(""); }
            if (start == 0)
            {
                md.Append("| ").Append(string.Join(" | ", names)).Append(" |\n");
                md.Append('|').Append(string.Concat(names.Select(_ => "---:|"))).Append('\n');
            }
            else
            {
                md.Append("| ").Append(string.Join(" | ", names.Select(n => n.Length > 0 ? "**" + n + "**" : ""))).Append(" |\n");
            }
            md.Append("| ").Append(string.Join(" | ", values)).Append(" |\n");
        }
        md.Append('\n');

        var st = p.Statistics;
        md.Append($"n = {st.N}, mean {F2(st.Mean)}, SD {F2(st.StandardDeviation)}, median {F2(st.Median)}, range {F2(st.Min)} to {F2(st.Max)}, 95 % CI {Interval(st)}");
        if (p.Alpha != null) md.Append($", Cronbach's α {AlphaText(p)}");
        md.Append(".\n\n");
        var incomplete = p.Scores.Where(s => !s.IsComplete).Select(s => Cell(s.Participant)).ToList();
        if (incomplete.Count > 0) md.Append($"Incomplete, so not scored: {string.Join(", ", incomplete)}.\n\n");
        md.Append($"Data: [{p.TableFile}]({p.TableFile}).\n\n");
        md.Append($"![{Cell(q.Title)}: score per participant]({p.ChartFile})\n\n");
    }

    /// <summary>A cell of Tables 1–3: one decimal at least for multi-item means (4.6, 5.0), up to two (3.33); a single item's answer as it is (8).</summary>
    public static string ScoreText(Questionnaire q, double score)
        => score.ToString(q.ItemCount > 1 ? "0.0#" : "0.##", CultureInfo.InvariantCulture);

    static string F2(double v) => double.IsFinite(v) ? v.ToString("F2", CultureInfo.InvariantCulture) : "—";

    static string Interval(SummaryStatistics st)
        => double.IsFinite(st.ConfidenceLow) ? $"[{F2(st.ConfidenceLow)}, {F2(st.ConfidenceHigh)}]" : "—";

    static string AlphaText(Part p)
    {
        if (p.Alpha == null) return p.Questionnaire.ItemCount > 1 ? "needs responses" : "single item";
        return p.Alpha.IsDefined ? $"{F2(p.Alpha.Alpha)} (n = {p.Alpha.Participants})" : $"— (n = {p.Alpha.Participants})";
    }

    /// <summary>Text safe inside a Markdown table cell.</summary>
    static string Cell(string text) => text.Replace("\\", "\\\\").Replace("|", "\\|").Replace("`", "'").ReplaceLineEndings(" ");

    /// <summary>An id as part of a file name: letters, digits, '-', '_' and '.' kept, anything else '_'.</summary>
    static string SafeName(string id)
    {
        var name = new StringBuilder(id.Length);
        foreach (char c in id) name.Append(char.IsAsciiLetterOrDigit(c) || c is '-' or '_' or '.' ? c : '_');
        return name.ToString().Trim('.');
    }
}
