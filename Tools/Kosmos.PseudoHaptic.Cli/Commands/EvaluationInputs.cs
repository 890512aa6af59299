using System.Reflection;
using System.Text;
using Kosmos.PseudoHaptic.Cli.Files;
using Kosmos.PseudoHaptic.Evaluation;

namespace Kosmos.PseudoHaptic.Cli;

/// <summary>The row limit of score and report's input files (public, for tests and other commands).</summary>
public static class EvaluationInputsLimits
{
    /// <summary>See <see cref="EvaluationInputs.MaxRows"/>.</summary>
    public const int MaxRows = 100_000;

    /// <summary>See <see cref="EvaluationInputs.MaxParticipants"/>.</summary>
    public const int MaxParticipants = 100_000;
}

/// <summary>
/// What <c>score</c> and <c>report</c> share: the questionnaire definitions (the package's JSON files, built
/// into the tool, or a folder given with --questionnaires), reading input files, writing outputs by
/// write-then-rename, and the error contract — one line on stderr, exit code 2, nothing written.
/// </summary>
static class EvaluationInputs
{
    /// <summary>
    /// Most data rows score and report read from one file (100,000: a study of 4,500 participants answering all
    /// 22 items), so their memory is bounded whatever the file (report of 100,000 scores: 110 MB peak); a row
    /// beyond is refused naming its line.
    /// </summary>
    public const int MaxRows = EvaluationInputsLimits.MaxRows;

    /// <summary>Most characters the fields of one file may hold together (64 a row on average), so long fields cannot
    /// add up past the memory bound either; the row that passes it is refused naming its line.</summary>
    public const long MaxCharacters = 64L * MaxRows;

    /// <summary>
    /// Most participants score and report keep from one file (100,000: a 10,000-participant study is a tenth of it).
    /// score streams its answers, so the rows are not counted: it keeps one sheet per participant, questionnaire and
    /// condition (about 1 kB each), and the participants' and conditions' names at most <see cref="MaxNameCharacters"/>.
    /// </summary>
    public const int MaxParticipants = EvaluationInputsLimits.MaxParticipants;

    /// <summary>Most characters of distinct participant and condition names kept (64 a participant on average).</summary>
    public const long MaxNameCharacters = 64L * MaxParticipants;

    /// <summary>What score and report keep of an answers file, bounded by participants, not rows.</summary>
    public static ParticipantLimit Participants() => new(MaxParticipants, MaxNameCharacters);

    /// <summary>Most rows report reads from a scores file: one score per participant and part.</summary>
    public static int MaxScoreRows(QuestionnaireCatalog catalog) => MaxParticipants * Math.Max(1, catalog.Questionnaires.Count);

    /// <summary>The package's definitions as built in, or those of <paramref name="directory"/> when given.</summary>
    public static QuestionnaireCatalog Catalog(string? directory)
    {
        if (directory != null)
        {
            if (!Directory.Exists(directory)) throw new CliException($"--questionnaires {Messages.Path(directory)}: " + (File.Exists(directory) ? "is a file, not a folder" : "does not exist"));
            return QuestionnaireJson.LoadDirectory(directory);
        }
        var assembly = typeof(EvaluationInputs).Assembly;
        var named = new List<KeyValuePair<string, string>>();
        foreach (string file in QuestionnaireCatalog.DefaultFileNames)
        {
            using Stream? stream = assembly.GetManifestResourceStream("Questionnaires/" + file)
                ?? throw new InvalidOperationException($"built-in questionnaire {file} is missing from the tool");
            using var reader = new StreamReader(stream, Encoding.UTF8);
            named.Add(new KeyValuePair<string, string>(file, reader.ReadToEnd()));
        }
        return QuestionnaireJson.ParseAll(named);
    }

    /// <summary>The questionnaire definitions a --questionnaires folder holds, as inputs an output may not be.</summary>
    public static IEnumerable<NamedPath> QuestionnaireFiles(string? directory)
    {
        if (directory == null || !Directory.Exists(directory)) yield break;
        foreach (var file in Directory.GetFiles(directory, "*.json"))
            yield return new NamedPath("--questionnaires", file);
    }

    /// <summary>An input file named by <paramref name="option"/>, read as it is parsed (one row at a time).</summary>
    public static TextReader OpenText(string option, string path) => InputFile.OpenText(option, path);

    /// <summary>The name messages give a file: its path with control characters escaped.</summary>
    public static string Name(string path) => Messages.OneLine(path);

    /// <summary>Writes by the tool's output rules (<see cref="OutputFile"/>).</summary>
    public static void WriteText(string path, string text) => OutputFile.Check("--out", path).Write(w => w.Write(text));

    public static void WriteBytes(string path, byte[] bytes) => OutputFile.Check("--out", path).WriteBytes(bytes);

    public static string OneLine(string text) => Messages.OneLine(text);
}
