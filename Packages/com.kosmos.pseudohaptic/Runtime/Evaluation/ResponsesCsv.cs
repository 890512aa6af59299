using System;
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
        /// <paramref name="maxRows"/> data rows is an error naming the first row beyond.</summary>
        public static ResponseSet Parse(TextReader reader, string sourceName, QuestionnaireCatalog catalog, int maxRows = int.MaxValue)
        {
            if (catalog == null) throw new ArgumentNullException(nameof(catalog));
            var rows = CsvTable.Stream(reader, sourceName, maxRows, Columns);
            var set = new ResponseSet(catalog);
            foreach (var row in rows)
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
            return set;
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
