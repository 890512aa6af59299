using Kosmos.PseudoHaptic.Cli.CommandLine;
using Kosmos.PseudoHaptic.Cli.Files;
using Kosmos.PseudoHaptic.Evaluation;

namespace Kosmos.PseudoHaptic.Cli;

/// <summary>
/// <c>pseudohaptic report --scores S.csv --out DIR [--responses R.csv] [--questionnaires DIR] [--svg]</c>: the paper's
/// per-participant Tables 1–3, summary statistics per part (n, mean, SD, median, min, max, 95 % CI, and
/// Cronbach's α when item-level responses are given) and a chart per part. Writes DIR/report.md,
/// DIR/summary.csv, DIR/tableN-ID.csv and DIR/chartN-ID.png (with --svg, DIR/chartN-ID.svg too). A malformed S.csv (or R.csv) exits 2 with one
/// line "FILE:LINE: reason" on stderr and writes nothing.
/// </summary>
public static class ReportCommand
{

    public static CliCommand Define() => new(
        "report",
        "Tables, statistics (n, mean, SD, median, 95 % CI, Cronbach's alpha) and charts of questionnaire scores, as Markdown, CSV and PNG (evaluation.md)",
        Run,
        new[]
        {
            "pseudohaptic report --scores Packages/com.kosmos.pseudohaptic/Documentation~/examples/scores.csv --out out/report --responses Packages/com.kosmos.pseudohaptic/Documentation~/examples/responses.csv",
        },
        CliCommand.Value("--scores", "S.csv", "the scores score wrote (one per participant and part, at most 100,000 participants)", required: true),
        CliCommand.Value("--out", "DIR", "the folder to write; it appears whole or not at all", required: true),
        CliCommand.Value("--responses", "R.csv", "the answers, for Cronbach's alpha and a check of the scores (default: none, no alpha)"),
        CliCommand.Value("--questionnaires", "DIR", "a folder of questionnaire definitions (JSON) (default: the paper's, built in)"),
        CliCommand.Flag("--svg", "write an SVG beside each PNG"));

    public static int Run(string[] args) => Cli.Run(args.Prepend("report").ToArray());

    static int Run(Options o)
    {
        bool svg = o.Flag("--svg");
        string scoresPath = o.Require("--scores");
        string outDir = o.Require("--out");
        string? responsesPath = o.Get("--responses");
        string? questionnaires = o.Get("--questionnaires");
        var inputs = new[] { new NamedPath("--scores", scoresPath), new NamedPath("--responses", responsesPath), new NamedPath("--questionnaires", questionnaires) };
        OutputFolder.Check("--out", outDir, Owns, createParents: false, inputs);
        var catalog = EvaluationInputs.Catalog(questionnaires);

        // Everything is read, checked and rendered before the folder is made; it then appears whole.
        // One score per participant and part: the rows are bounded by the participants, as score's answers are.
        RefuseConditions(scoresPath);
        int maxScores = EvaluationInputs.MaxScoreRows(catalog);
        var scores = ScoresCsv.Parse(EvaluationInputs.OpenText("--scores", scoresPath), EvaluationInputs.Name(scoresPath), catalog, maxScores, 64L * maxScores);
        ResponseSet? responses = responsesPath != null
            ? ResponsesCsv.Parse(EvaluationInputs.OpenText("--responses", responsesPath), EvaluationInputs.Name(responsesPath), catalog, int.MaxValue, long.MaxValue, EvaluationInputs.Participants())
            : null;
        var report = EvaluationReport.Build(catalog, scores, scoresPath, responses, responsesPath);

        var files = new List<(string Name, byte[] Bytes)>();
        var utf8 = new System.Text.UTF8Encoding(false);
        files.Add(("report.md", utf8.GetBytes(report.Markdown())));
        files.Add(("summary.csv", utf8.GetBytes(report.SummaryCsv())));
        foreach (var part in report.Parts)
        {
            if (part.Scores.Count == 0) continue;
            files.Add((part.TableFile, utf8.GetBytes(EvaluationReport.TableCsv(part))));
            files.Add((part.ChartFile, EvaluationCharts.Png(part)));
            if (svg) files.Add((Path.ChangeExtension(part.ChartFile, ".svg"), utf8.GetBytes(EvaluationCharts.Svg(part))));
        }

        OutputFolder.Begin("--out", outDir, Owns, createParents: false, inputs).Build(temp =>
        {
            foreach (var (name, bytes) in files) Temporaries.Guard(() => File.WriteAllBytes(Path.Combine(temp, name), bytes));
        });

        if (report.Disagreements.Count > 0)
            Console.Error.WriteLine(Messages.OneLine($"pseudohaptic report: warning: {report.Disagreements.Count} scores in {scoresPath} differ from {responsesPath} scored again (first: {report.Disagreements[0]})"));
        Console.Out.WriteLine($"{Messages.OneLine(Path.Combine(outDir, "report.md"))}: {files.Count} files");
        foreach (var part in report.Parts)
        {
            var st = part.Statistics;
            Console.Out.WriteLine($"  {part.Questionnaire.Id}: n = {st.N}, mean {Fixed(st.Mean)}, SD {Fixed(st.StandardDeviation)}, 95% CI [{Fixed(st.ConfidenceLow)}, {Fixed(st.ConfidenceHigh)}]{(part.Incomplete > 0 ? $", {part.Incomplete} incomplete" : "")}");
        }
        return 0;
    }

    /// <summary>What an existing --out folder may hold to be replaced: files of an earlier report (no folders).</summary>
    /// <summary>
    /// report summarizes one score per participant and part; a scores file with a condition column (score's output for
    /// answers with conditions) has one per condition, which compare compares: refused in words, not as a "duplicate score".
    /// Only the header is read (the CSV reader's, its record at most 1 MiB).
    /// </summary>
    static void RefuseConditions(string scoresPath)
    {
        using var csv = new CsvReader(EvaluationInputs.OpenText("--scores", scoresPath), EvaluationInputs.Name(scoresPath));
        if (csv.ReadHeader() && csv.Header.Any(name => string.Equals(name.Trim(), "condition", StringComparison.OrdinalIgnoreCase)))
            throw new CliException($"--scores {Messages.Path(scoresPath)}: has a condition column: report summarizes one score per participant and part; compare the conditions with 'pseudohaptic compare', or report each condition's rows apart");
    }

    static readonly OutputFolder.Owns Owns = OutputFolder.FilesNamed("report.md", "summary.csv", "table*.csv", "chart*.png", "chart*.svg");

    static string Fixed(double v) => double.IsFinite(v) ? NumberText.Fixed(v, 2) : "-";
}
