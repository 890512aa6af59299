using System.Globalization;
using Kosmos.PseudoHaptic.Cli.CommandLine;
using Kosmos.PseudoHaptic.Cli.Files;
using Kosmos.PseudoHaptic.Evaluation;

namespace Kosmos.PseudoHaptic.Cli;

/// <summary>
/// <c>pseudohaptic score --responses R.csv --out S.csv [--questionnaires DIR]</c>: the paper's scoring of
/// questionnaire answers (reverse coding, per-participant mean per part, incomplete parts unscored).
/// R.csv: participant,questionnaire,item,response; S.csv: participant,questionnaire,score, one row per
/// participant × questionnaire answered, the score empty when the part is incomplete. With an optional
/// <c>condition</c> column in R.csv, S.csv is participant,condition,questionnaire,score (one row per
/// participant × condition × questionnaire); without it the output is unchanged. A malformed R.csv
/// exits 2 with one line "R.csv:LINE: reason" on stderr and writes nothing. Contract in
/// Packages/com.kosmos.pseudohaptic/Documentation~/evaluation.md; other programs depend on it.
/// </summary>
public static class ScoreCommand
{

    public static CliCommand Define() => new(
        "score",
        "Score questionnaire answers as the paper does (reverse-coded items, a mean per part, incomplete parts unscored): one row per participant × questionnaire (evaluation.md)",
        Run,
        new[]
        {
            "pseudohaptic score --responses Packages/com.kosmos.pseudohaptic/Documentation~/examples/responses.csv --out out/scores.csv",
        },
        CliCommand.Value("--responses", "R.csv", "the answers: participant,questionnaire,item,response (optional condition); any number of rows, at most 100,000 participants", required: true),
        CliCommand.Value("--out", "S.csv", "the scores: participant,[condition,]questionnaire,score ('-': standard output)", required: true),
        CliCommand.Value("--questionnaires", "DIR", "a folder of questionnaire definitions (JSON) (default: the paper's, built in)"));

    public static int Run(string[] args) => Cli.Run(args.Prepend("score").ToArray());

    static int Run(Options o)
    {
        string responsesPath = o.Require("--responses");
        string output = o.Require("--out");
        var target = OutputFile.Check("--out", output,
            EvaluationInputs.QuestionnaireFiles(o.Get("--questionnaires")).Prepend(new NamedPath("--responses", responsesPath)).ToArray());
        var catalog = EvaluationInputs.Catalog(o.Get("--questionnaires"));

        // R.csv may have a condition column (issue 11); S.csv then carries it after the participant. Without
        // it there is one set and the output is the scores file as before, byte for byte.
        // Streamed: any number of rows; what is kept is bounded by the participants (EvaluationInputs.MaxParticipants).
        var sets = ResponsesCsv.ParseByCondition(EvaluationInputs.OpenText("--responses", responsesPath), EvaluationInputs.Name(responsesPath), catalog, out bool hasCondition, int.MaxValue, long.MaxValue, EvaluationInputs.Participants());
        var scores = hasCondition ? ScoreCalculator.ScoreAll(sets) : ScoreCalculator.ScoreAll(sets[0].Value);
        target.Write(w => w.Write(ScoresCsv.Format(scores, hasCondition)));
        var participants = new HashSet<string>(StringComparer.Ordinal);
        int answers = 0;
        foreach (var (_, set) in sets)
        {
            participants.UnionWith(set.Participants);
            answers += set.Count;
        }

        int incomplete = scores.Count(s => !s.IsComplete);
        // With --out - the scores go to standard output, so the summary goes to standard error.
        var summary = target.IsStandardOutput ? Console.Error : Console.Out;
        output = Messages.OneLine(output);
        summary.WriteLine($"{output}: {scores.Count} scores of {participants.Count} participants from {answers} answers{(hasCondition ? $" in {sets.Count} conditions" : "")}, {incomplete} incomplete");
        foreach (var s in scores.Where(s => !s.IsComplete))
            summary.WriteLine($"  {Messages.OneLine(s.Participant)}{(hasCondition ? " " + Messages.OneLine(s.Condition) : "")} {s.QuestionnaireId}: incomplete, unanswered items {string.Join(", ", s.MissingItems.Select(i => i.ToString(CultureInfo.InvariantCulture)))}");
        return 0;
    }
}
