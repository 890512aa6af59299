using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Text;

namespace Kosmos.PseudoHaptic.Evaluation
{
    /// <summary>
    /// The scores file: header participant,questionnaire,score, one row per participant × questionnaire,
    /// the score empty when the part is incomplete. Numbers in the invariant culture, written in their
    /// shortest exact form (4.6, 8, 3.3333333333333335). Read as strictly as the responses: an unknown
    /// questionnaire, a score that is not a number or lies off the questionnaire's scale, a duplicate row
    /// or a malformed row throws <see cref="EvaluationFormatException"/> naming the line.
    /// </summary>
    public static class ScoresCsv
    {
        public static readonly string[] Columns = { "participant", "questionnaire", "score" };
        public const string Header = "participant,questionnaire,score";

        /// <summary>The file's text, header first, "\n" line ends.</summary>
        public static string Format(IEnumerable<ParticipantScore> scores)
        {
            if (scores == null) throw new ArgumentNullException(nameof(scores));
            var text = new StringBuilder(Header).Append('\n');
            foreach (var s in scores)
            {
                text.Append(CsvTable.Escape(s.Participant)).Append(',').Append(CsvTable.Escape(s.QuestionnaireId)).Append(',');
                if (s.Score.HasValue) text.Append(FormatNumber(s.Score.Value));
                text.Append('\n');
            }
            return text.ToString();
        }

        /// <summary>Shortest round-trip invariant form: 4.6, 8, 3.3333333333333335.</summary>
        public static string FormatNumber(double value) => value.ToString("R", CultureInfo.InvariantCulture);

        /// <summary>Reads the scores, in file order, checked against <paramref name="catalog"/>.</summary>
        public static IReadOnlyList<ParticipantScore> Parse(string text, string sourceName, QuestionnaireCatalog catalog)
        {
            if (text == null) throw new ArgumentNullException(nameof(text));
            return Parse(new StringReader(text), sourceName, catalog);
        }

        /// <summary>Reads <paramref name="reader"/> row by row (RFC 4180, <see cref="CsvReader"/>) and disposes it; more than
        /// <paramref name="maxRows"/> data rows is an error naming the first row beyond.</summary>
        public static IReadOnlyList<ParticipantScore> Parse(TextReader reader, string sourceName, QuestionnaireCatalog catalog, int maxRows = int.MaxValue)
        {
            if (catalog == null) throw new ArgumentNullException(nameof(catalog));
            var rows = CsvTable.Stream(reader, sourceName, maxRows, Columns);
            var scores = new List<ParticipantScore>();
            var seen = new Dictionary<string, int>(StringComparer.Ordinal);
            foreach (var row in rows)
            {
                string participant = row[0], questionnaireId = row[1], scoreText = row[2];
                if (participant.Length == 0) throw Fail(sourceName, row, "participant is empty");
                var questionnaire = catalog.Find(questionnaireId);
                if (questionnaire == null)
                    throw Fail(sourceName, row, "unknown questionnaire '" + questionnaireId + "' (expected one of " + catalog.DescribeIds() + ")");

                // Participant ids may hold any character but a line break, so '\n' keeps the key unambiguous.
                string key = participant + "\n" + questionnaireId;
                int firstLine;
                if (seen.TryGetValue(key, out firstLine))
                    throw Fail(sourceName, row, "duplicate score: participant '" + participant + "' and '" + questionnaireId + "' already on line " + firstLine);
                seen.Add(key, row.Line);

                double? score = null;
                if (scoreText.Length > 0)
                {
                    double value;
                    if (!double.TryParse(scoreText, NumberStyles.Float, CultureInfo.InvariantCulture, out value)
                        || double.IsNaN(value) || double.IsInfinity(value))
                        throw Fail(sourceName, row, "score '" + scoreText + "' is not a number (leave it empty for an incomplete part)");
                    if (value < questionnaire.ScaleMin || value > questionnaire.ScaleMax)
                        throw Fail(sourceName, row, "score " + FormatNumber(value) + " for '" + questionnaireId + "' is outside its scale " + questionnaire.ScaleText());
                    score = value;
                }
                scores.Add(new ParticipantScore(participant, questionnaireId, score));
            }
            return scores;
        }

        public static IReadOnlyList<ParticipantScore> Load(string path, QuestionnaireCatalog catalog)
            => Parse(new StreamReader(path, Encoding.UTF8), path, catalog);

        static EvaluationFormatException Fail(string sourceName, CsvTable.Row row, string reason)
            => new EvaluationFormatException(sourceName, row.Line, reason);
    }
}
