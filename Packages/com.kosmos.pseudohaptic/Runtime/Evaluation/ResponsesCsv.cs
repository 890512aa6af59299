using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Text;

namespace Kosmos.PseudoHaptic.Evaluation
{
    /// <summary>
    /// The responses file: header participant,questionnaire,item,response (by name, any order), one answer
    /// a row. Read strictly, since scores must be trustworthy: an unknown questionnaire or item, an item or
    /// response that is not a number, a response off the scale or not whole, a duplicate answer, or a
    /// malformed row throws <see cref="EvaluationFormatException"/> naming the line. Unanswered items are
    /// simply absent; an empty response field is an error, not a skip.
    /// </summary>
    public static class ResponsesCsv
    {
        public static readonly string[] Columns = { "participant", "questionnaire", "item", "response" };
        public const string Header = "participant,questionnaire,item,response";

        /// <summary>Reads every answer of <paramref name="text"/> into a set checked against <paramref name="catalog"/>.</summary>
        public static ResponseSet Parse(string text, string sourceName, QuestionnaireCatalog catalog)
        {
            if (text == null) throw new ArgumentNullException(nameof(text));
            return Parse(new StringReader(text), sourceName, catalog);
        }

        /// <summary>Reads <paramref name="reader"/> row by row (RFC 4180, <see cref="CsvReader"/>) and disposes it; more than
        /// <paramref name="maxRows"/> data rows, or more than <paramref name="maxCharacters"/> characters in their fields, is an error naming the row.</summary>
        public static ResponseSet Parse(TextReader reader, string sourceName, QuestionnaireCatalog catalog, int maxRows = int.MaxValue, long maxCharacters = long.MaxValue)
            => Parse(reader, sourceName, catalog, maxRows, maxCharacters, ParticipantLimit.None);

        /// <summary>As above, keeping at most what <paramref name="limit"/> allows (rows are streamed: their number is not bounded by memory).</summary>
        public static ResponseSet Parse(TextReader reader, string sourceName, QuestionnaireCatalog catalog, int maxRows, long maxCharacters, ParticipantLimit limit)
        {
            if (catalog == null) throw new ArgumentNullException(nameof(catalog));
            if (limit == null) throw new ArgumentNullException(nameof(limit));
            var rows = CsvTable.Stream(reader, sourceName, maxRows, maxCharacters, Columns);
            var set = new ResponseSet(catalog);
            foreach (var row in rows)
            {
                string why = limit.Admit(row[0]);
                if (why != null) throw Fail(sourceName, row, why);
                Add(set, sourceName, row);
            }
            return set;
        }

        /// <summary>
        /// Reads a responses file that may have a <c>condition</c> column (issue 11): one set per condition, in
        /// the order the conditions first appear. Without the column (<paramref name="hasCondition"/> false)
        /// there is one set, condition "", read exactly as <see cref="Parse(TextReader, string, QuestionnaireCatalog)"/>.
        /// </summary>
        public static IReadOnlyList<KeyValuePair<string, ResponseSet>> ParseByCondition(TextReader reader, string sourceName, QuestionnaireCatalog catalog, out bool hasCondition, int maxRows = int.MaxValue, long maxCharacters = long.MaxValue)
            => ParseByCondition(reader, sourceName, catalog, out hasCondition, maxRows, maxCharacters, ParticipantLimit.None);

        /// <summary>As above, keeping at most what <paramref name="limit"/> allows.</summary>
        public static IReadOnlyList<KeyValuePair<string, ResponseSet>> ParseByCondition(TextReader reader, string sourceName, QuestionnaireCatalog catalog, out bool hasCondition, int maxRows, long maxCharacters, ParticipantLimit limit)
        {
            if (catalog == null) throw new ArgumentNullException(nameof(catalog));
            if (limit == null) throw new ArgumentNullException(nameof(limit));
            var present = new bool[1];
            var sets = new List<KeyValuePair<string, ResponseSet>>();
            var byCondition = new Dictionary<string, ResponseSet>(StringComparer.Ordinal);
            foreach (var row in CsvTable.Stream(reader, sourceName, maxRows, maxCharacters, Columns, new[] { "condition" }, present))
            {
                string condition = row[4] ?? "";
                string why = limit.Admit(row[0], condition);
                if (why != null) throw Fail(sourceName, row, why);
                ResponseSet set;
                if (!byCondition.TryGetValue(condition, out set))
                {
                    set = new ResponseSet(catalog);
                    byCondition.Add(condition, set);
                    sets.Add(new KeyValuePair<string, ResponseSet>(condition, set));
                }
                Add(set, sourceName, row);
            }
            hasCondition = present[0];
            if (sets.Count == 0) sets.Add(new KeyValuePair<string, ResponseSet>("", new ResponseSet(catalog)));
            return sets;
        }

        static void Add(ResponseSet set, string sourceName, CsvTable.Row row)
        {
            string participant = row[0], questionnaireId = row[1], itemText = row[2], responseText = row[3];
            int item;
            if (!int.TryParse(itemText, NumberStyles.AllowLeadingSign, CultureInfo.InvariantCulture, out item))
                throw Fail(sourceName, row, "item '" + itemText + "' is not a whole number");
            double value;
            if (!double.TryParse(responseText, NumberStyles.Float, CultureInfo.InvariantCulture, out value)
                || double.IsNaN(value) || double.IsInfinity(value))
                throw Fail(sourceName, row, responseText.Length == 0
                    ? "response is empty (leave an unanswered item out instead)"
                    : "response '" + responseText + "' is not a number");
            string why = set.TryAdd(participant, questionnaireId, item, value);
            if (why != null) throw Fail(sourceName, row, why);
        }

        public static ResponseSet Load(string path, QuestionnaireCatalog catalog)
            => Parse(new StreamReader(path, Encoding.UTF8), path, catalog);

        /// <summary>One row, as a panel appends it (no trailing newline).</summary>
        public static string FormatRow(Response response)
            => CsvTable.Escape(response.Participant) + "," + CsvTable.Escape(response.QuestionnaireId) + ","
               + response.Item.ToString(CultureInfo.InvariantCulture) + "," + response.Value.ToString(CultureInfo.InvariantCulture);

        static EvaluationFormatException Fail(string sourceName, CsvTable.Row row, string reason)
            => new EvaluationFormatException(sourceName, row.Line, reason);
    }
}
