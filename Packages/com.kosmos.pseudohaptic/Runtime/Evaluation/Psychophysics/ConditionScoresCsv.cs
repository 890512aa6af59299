using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;

namespace Kosmos.PseudoHaptic.Evaluation
{
    /// <summary>
    /// Reads a scores file with conditions (participant,condition,questionnaire,score by name; the
    /// questionnaire is any non-empty text, so definitions of one's own need no catalog here). An empty score
    /// is an incomplete part; a score that is not a finite number, an empty participant or questionnaire, or a
    /// participant × condition × questionnaire given twice throws <see cref="EvaluationFormatException"/>.
    /// </summary>
    public static class ConditionScoresCsv
    {
        public static readonly string[] Columns = { "participant", "condition", "questionnaire", "score" };

        public static List<ConditionScore> Read(TextReader reader, string sourceName, int maxRows = int.MaxValue, long maxCharacters = long.MaxValue)
        {
            var scores = new List<ConditionScore>();
            var seen = new Dictionary<string, int>(StringComparer.Ordinal);
            foreach (var row in CsvTable.Stream(reader, sourceName, maxRows, maxCharacters, Columns))
            {
                string participant = row[0].Trim(), condition = row[1].Trim(), questionnaire = row[2].Trim(), text = row[3].Trim();
                if (participant.Length == 0) throw new EvaluationFormatException(sourceName, row.Line, "participant is empty");
                if (questionnaire.Length == 0) throw new EvaluationFormatException(sourceName, row.Line, "questionnaire is empty");
                string key = participant + "\n" + condition + "\n" + questionnaire;
                int first;
                if (seen.TryGetValue(key, out first))
                    throw new EvaluationFormatException(sourceName, row.Line, "duplicate score: participant '" + participant + "', condition '" + condition + "' and '" + questionnaire + "' already on line " + first.ToString(CultureInfo.InvariantCulture));
                seen.Add(key, row.Line);
                double? score = null;
                if (text.Length > 0)
                {
                    double value;
                    if (!double.TryParse(text, NumberStyles.Float, CultureInfo.InvariantCulture, out value) || double.IsNaN(value) || double.IsInfinity(value))
                        throw new EvaluationFormatException(sourceName, row.Line, "score '" + row[3] + "' is not a finite number (leave it empty for an incomplete part)");
                    score = value;
                }
                scores.Add(new ConditionScore(participant, condition, questionnaire, score, row.Line));
            }
            return scores;
        }
    }
}
