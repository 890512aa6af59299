using System.Globalization;
using Kosmos.PseudoHaptic.Cli.Files;
using Kosmos.PseudoHaptic.Evaluation;

namespace Kosmos.PseudoHaptic.Cli;

/// <summary>
/// <c>pseudohaptic score --responses R.csv --out S.csv [--questionnaires DIR]</c>: the paper's scoring of
/// questionnaire answers (reverse coding, per-participant mean per part, incomplete parts unscored).
/// R.csv: participant,questionnaire,item,response; S.csv: participant,questionnaire,score, one row per
/// participant × questionnaire answered, the score empty when the part is incomplete. A malformed R.csv
/// exits 2 with one line "R.csv:LINE: reason" on stderr and writes nothing. Contract in
/// Packages/com.kosmos.pseudohaptic/Documentation~/evaluation.md; other programs depend on it.
/// </summary>
public static class ScoreCommand
{
    public const string Usage = "pseudohaptic score --responses R.csv --out S.csv [--questionnaires DIR]";

    public static int Run(string[] args) => EvaluationInputs.Guard("score", Usage, () =>
    {
        var o = new Options(args, "--responses", "--out", "--questionnaires");
        string responsesPath = o.Require("--responses");
        string output = o.Require("--out");
        var target = OutputFile.Check("--out", output,
            EvaluationInputs.QuestionnaireFiles(o.Get("--questionnaires")).Prepend(new NamedPath("--responses", responsesPath)).ToArray());
        var catalog = EvaluationInputs.Catalog(o.Get("--questionnaires"));

        var responses = ResponsesCsv.Parse(EvaluationInputs.OpenText("--responses", responsesPath), EvaluationInputs.Name(responsesPath), catalog, EvaluationInputs.MaxRows);
        var scores = ScoreCalculator.ScoreAll(responses);
        target.Write(w => w.Write(ScoresCsv.Format(scores)));

        int incomplete = scores.Count(s => !s.IsComplete);
        // With --out - the scores go to standard output, so the summary goes to standard error.
        var summary = target.IsStandardOutput ? Console.Error : Console.Out;
        output = Messages.OneLine(output);
        summary.WriteLine($"{output}: {scores.Count} scores of {responses.Participants.Count} participants from {responses.Count} answers, {incomplete} incomplete");
        foreach (var s in scores.Where(s => !s.IsComplete))
            summary.WriteLine($"  {Messages.OneLine(s.Participant)} {s.QuestionnaireId}: incomplete, unanswered items {string.Join(", ", s.MissingItems.Select(i => i.ToString(CultureInfo.InvariantCulture)))}");
        return 0;
    });
}
