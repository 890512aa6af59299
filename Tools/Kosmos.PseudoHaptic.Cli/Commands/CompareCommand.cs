using System.Globalization;
using System.Text;
using Kosmos.PseudoHaptic.Cli.CommandLine;
using Kosmos.PseudoHaptic.Cli.Files;
using Kosmos.PseudoHaptic.Evaluation;

namespace Kosmos.PseudoHaptic.Cli;

/// <summary>
/// <c>pseudohaptic compare --scores S.csv --out DIR [--svg]</c> (issue 11; --svg in the twenty-second session, as issue 13 asks of every chart): within-participant comparisons of
/// conditions per questionnaire (<see cref="ConditionComparison"/>): paired t, Wilcoxon signed-rank, mean
/// difference with its 95 % t interval, d_z and r; with three or more conditions Friedman's test first and
/// Holm-corrected Wilcoxon p. Writes DIR/comparisons.csv, DIR/report.md and a chart per questionnaire (with --svg, an SVG beside each).
/// Malformed input or a bad option: exit 2, one stderr line naming S.csv:LINE or the option, nothing written.
/// </summary>
public static class CompareCommand
{
    public const string Header = "questionnaire,condition_a,condition_b,n,mean_diff,diff_lo,diff_hi,t,t_p,w,w_p,dz,r,p_holm,method";

    public static CliCommand Define() => new(
        "compare",
        "Compare conditions within participants per questionnaire: paired t, Wilcoxon signed-rank, the mean difference with its 95 % interval, d_z, r; with three or more conditions Friedman's test and Holm-corrected p (evaluation.md §8)",
        Run,
        new[]
        {
            "pseudohaptic compare --scores Packages/com.kosmos.pseudohaptic/Documentation~/examples/study/psychophysics.csv --out out/compare",
        },
        CliCommand.Value("--scores", "S.csv", "participant,condition,questionnaire,score (what score writes from answers with a condition column)", required: true),
        CliCommand.Value("--out", "DIR", "the folder to write; it appears whole or not at all", required: true),
        CliCommand.Flag("--svg", "write an SVG beside each PNG"));

    public static int Run(string[] args) => Cli.Run(args.Prepend("compare").ToArray());

    static int Run(Options o)
    {
        string scoresPath = o.Require("--scores");
        string outDir = o.Require("--out");
        var inputs = new[] { new NamedPath("--scores", scoresPath) };
        OutputFolder.Check("--out", outDir, Owns, createParents: false, inputs);

        var scores = ConditionScoresCsv.Read(EvaluationInputs.OpenText("--scores", scoresPath), EvaluationInputs.Name(scoresPath), EvaluationInputs.MaxRows, EvaluationInputs.MaxCharacters);
        var rows = ConditionComparison.Compare(scores);
        var utf8 = new UTF8Encoding(false);
        bool svg = o.Flag("--svg");
        var files = new List<(string Name, byte[] Bytes)> { ("comparisons.csv", utf8.GetBytes(ComparisonsCsv(rows))) };
        var charts = new List<(string File, string Questionnaire)>();
        foreach (string q in rows.Select(r => r.Questionnaire).Distinct())
        {
            string name = $"chart{charts.Count + 1}-{PsychometricCommand.Slug(q)}.png";
            var these = scores.Where(s => s.Questionnaire == q).ToList();
            var tests = rows.Where(r => r.Questionnaire == q).ToList();
            files.Add((name, StudyCharts.PairedLines(q, these, tests).Png()));
            if (svg) files.Add((Path.ChangeExtension(name, ".svg"), utf8.GetBytes(StudyCharts.PairedLines(q, these, tests).Svg())));
            charts.Add((name, q));
        }
        files.Add(("report.md", utf8.GetBytes(Report(scoresPath, scores, rows, charts))));

        OutputFolder.Begin("--out", outDir, Owns, createParents: false, inputs).Build(temp =>
        {
            foreach (var (name, bytes) in files) File.WriteAllBytes(Path.Combine(temp, name), bytes);
        });

        Console.Out.WriteLine($"{Messages.OneLine(Path.Combine(outDir, "comparisons.csv"))}: {rows.Count} rows; {files.Count} files");
        foreach (var r in rows)
        {
            if (r.Friedman != null)
                Console.Out.WriteLine($"  {Messages.OneLine(r.Questionnaire)}: Friedman χ² = {G(r.Friedman.Statistic)}, df = {r.Friedman.DegreesOfFreedom}, {NumberText.P(r.Friedman.P)} (n = {r.Friedman.N})");
            else
                Console.Out.WriteLine($"  {Messages.OneLine(r.Questionnaire)}: {Messages.OneLine(r.ConditionB)} − {Messages.OneLine(r.ConditionA)} = {G(r.Pair.MeanDifference)} (n = {r.Pair.N}), t test {NumberText.P(r.Pair.TP)}, Wilcoxon {NumberText.P(r.Pair.WP)}, Holm-corrected {NumberText.P(r.PHolm)}");
        }
        return 0;
    }

    static readonly OutputFolder.Owns Owns = OutputFolder.FilesNamed("comparisons.csv", "report.md", "chart*.png", "chart*.svg");

    static string G(double v) => double.IsFinite(v) ? v.ToString("G4", CultureInfo.InvariantCulture) : "-";

    static string N(double v) => double.IsFinite(v) ? NumberText.Format(v) : "";

    /// <summary>
    /// comparisons.csv. A Friedman row has condition_a = condition_b = "*", n = participants complete in all
    /// conditions, t = χ²_F and t_p its p (df = k − 1), method "friedman"; the other numbers empty. Figures that
    /// are not defined (too few pairs, no variation) are empty, never NaN.
    /// </summary>
    public static string ComparisonsCsv(IReadOnlyList<ComparisonRow> rows)
    {
        var text = new StringBuilder(Header).Append('\n');
        foreach (var r in rows)
        {
            text.Append(CsvTable.Escape(r.Questionnaire)).Append(',').Append(CsvTable.Escape(r.ConditionA)).Append(',').Append(CsvTable.Escape(r.ConditionB)).Append(',');
            if (r.Friedman != null)
            {
                var f = r.Friedman;
                text.Append(f.N.ToString(CultureInfo.InvariantCulture)).Append(",,,,").Append(N(f.Statistic)).Append(',').Append(N(f.P)).Append(",,,,,,").Append(r.Method);
            }
            else
            {
                var p = r.Pair;
                text.Append(p.N.ToString(CultureInfo.InvariantCulture)).Append(',')
                    .Append(N(p.MeanDifference)).Append(',').Append(N(p.DifferenceLow)).Append(',').Append(N(p.DifferenceHigh)).Append(',')
                    .Append(N(p.T)).Append(',').Append(N(p.TP)).Append(',').Append(N(p.W)).Append(',').Append(N(p.WP)).Append(',')
                    .Append(N(p.Dz)).Append(',').Append(N(p.R)).Append(',').Append(N(r.PHolm)).Append(',').Append(r.Method);
            }
            text.Append('\n');
        }
        return text.ToString();
    }

    static string Report(string scoresPath, IReadOnlyList<ConditionScore> scores, IReadOnlyList<ComparisonRow> rows, List<(string File, string Questionnaire)> charts)
    {
        string cell(double v) => double.IsFinite(v) ? v.ToString("G4", CultureInfo.InvariantCulture) : "—";
        // p plainly: "< 0.001" or three significant digits, never E notation.
        string pcell(double v) => !double.IsFinite(v) ? "—" : v < 0.001 ? "< 0.001" : NumberText.Plain(v, 3);
        var md = new StringBuilder("# Condition comparisons\n\n");
        md.Append($"Source: `{Messages.OneLine(Path.GetFileName(scoresPath))}`, {scores.Count} scores, {scores.Select(s => s.Participant).Distinct().Count()} participants, conditions {string.Join(", ", scores.Select(s => "'" + Messages.OneLine(s.Condition) + "'").Distinct())}.\n\n");
        md.Append("Per questionnaire and pair of conditions (a, b), over the participants with a complete score in both, on the differences b − a: ");
        md.Append("paired t test (two-sided) with the 95 % t interval of the mean difference and d_z = mean / SD; Wilcoxon signed-rank test (zero differences dropped, average ranks for ties, ");
        md.Append("W = sum of the ranks of the positive differences; exact p when N ≤ 25 non-zero differences without ties, else the normal approximation with tie and continuity correction), r = Z/√N. ");
        md.Append("With three or more conditions, Friedman's test (χ² with tie correction, df = k − 1) over the participants complete in all of them, and the pairs' Wilcoxon p Holm-corrected.\n\n");
        if (rows.Count == 0) md.Append("No questionnaire has two conditions to compare.\n\n");
        foreach (var (file, q) in charts)
        {
            md.Append($"## {Cell(q)}\n\n");
            foreach (var r in rows.Where(r => r.Questionnaire == q && r.Friedman != null))
                md.Append($"Friedman: χ² = {cell(r.Friedman.Statistic)}, df = {r.Friedman.DegreesOfFreedom}, {NumberText.P(r.Friedman.P)}, n = {r.Friedman.N}.\n\n");
            md.Append("| a | b | n | mean b − a | 95 % CI | t | p (t) | W | p (W) | d_z | r | p (Holm) | method |\n");
            md.Append("|---|---|---:|---:|---|---:|---:|---:|---:|---:|---:|---:|---|\n");
            foreach (var r in rows.Where(r => r.Questionnaire == q && r.Pair != null))
            {
                var p = r.Pair;
                md.Append($"| {Cell(r.ConditionA)} | {Cell(r.ConditionB)} | {p.N} | {cell(p.MeanDifference)} | {(double.IsFinite(p.DifferenceLow) ? $"[{cell(p.DifferenceLow)}, {cell(p.DifferenceHigh)}]" : "—")} | {cell(p.T)} | {pcell(p.TP)} | {cell(p.W)} | {pcell(p.WP)} | {cell(p.Dz)} | {cell(p.R)} | {pcell(r.PHolm)} | {r.Method} |\n");
            }
            md.Append($"\n![{Cell(q)}: paired lines per participant]({file})\n\n");
        }
        return md.ToString();
    }

    static string Cell(string text) => Messages.OneLine(text).Replace("|", "\\|");
}
