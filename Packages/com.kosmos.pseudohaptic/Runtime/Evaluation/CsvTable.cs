using System;
using System.Collections.Generic;
using System.Text;

namespace Kosmos.PseudoHaptic.Evaluation
{
    /// <summary>
    /// A CSV file with a header naming its columns, the shape of both the responses and the scores files.
    /// Columns are found by name (case-insensitive, any order; extra columns are ignored); fields may be
    /// quoted ("a, b", "say ""hi"""), but a quoted field may not span lines; surrounding spaces of unquoted
    /// fields are dropped; blank lines are skipped; the header is line 1. Every fault throws
    /// <see cref="EvaluationFormatException"/> naming the line.
    /// </summary>
    public sealed class CsvTable
    {
        /// <summary>One data row: its 1-based line and its fields in the order of the requested columns.</summary>
        public readonly struct Row
        {
            public int Line { get; }
            readonly string[] fields;

            internal Row(int line, string[] fields)
            {
                Line = line;
                this.fields = fields;
            }

            /// <summary>The field of the <paramref name="column"/>-th requested column.</summary>
            public string this[int column] => fields[column];
        }

        public string SourceName { get; }
        public IReadOnlyList<Row> Rows { get; }

        CsvTable(string sourceName, List<Row> rows)
        {
            SourceName = sourceName;
            Rows = rows;
        }

        /// <summary>Parses <paramref name="text"/>, which must have (at least) the <paramref name="columns"/>.</summary>
        public static CsvTable Parse(string text, string sourceName, params string[] columns)
        {
            if (text == null) throw new ArgumentNullException(nameof(text));
            if (columns == null || columns.Length == 0) throw new ArgumentException("no columns requested", nameof(columns));
            if (text.Length > 0 && text[0] == '\uFEFF') text = text.Substring(1);
            string expected = string.Join(",", columns);

            string[] lines = text.Split('\n');
            int headerAt = -1;
            for (int i = 0; i < lines.Length && headerAt < 0; i++)
                if (!IsBlank(lines[i])) headerAt = i;
            if (headerAt < 0) throw new EvaluationFormatException(sourceName, 1, "empty file: expected the header " + expected);

            int headerLine = headerAt + 1;
            string[] header = SplitOrThrow(lines[headerAt], sourceName, headerLine);
            var index = new int[columns.Length];
            for (int c = 0; c < columns.Length; c++)
            {
                index[c] = -1;
                for (int h = 0; h < header.Length; h++)
                {
                    if (!string.Equals(header[h], columns[c], StringComparison.OrdinalIgnoreCase)) continue;
                    if (index[c] >= 0) throw new EvaluationFormatException(sourceName, headerLine, "column '" + columns[c] + "' appears twice in the header");
                    index[c] = h;
                }
                if (index[c] < 0)
                    throw new EvaluationFormatException(sourceName, headerLine,
                        "missing column '" + columns[c] + "': the header must name " + expected + " (found " + Quote(header) + ")");
            }

            var rows = new List<Row>();
            for (int i = headerAt + 1; i < lines.Length; i++)
            {
                if (IsBlank(lines[i])) continue;
                int line = i + 1;
                string[] fields = SplitOrThrow(lines[i], sourceName, line);
                if (fields.Length != header.Length)
                    throw new EvaluationFormatException(sourceName, line,
                        "expected " + header.Length + " fields (" + string.Join(",", header) + "), found " + fields.Length);
                var picked = new string[columns.Length];
                for (int c = 0; c < columns.Length; c++) picked[c] = fields[index[c]];
                rows.Add(new Row(line, picked));
            }
            return new CsvTable(sourceName, rows);
        }

        /// <summary>A field as CSV writes it: quoted when it holds a comma, quote, line break or edge space.</summary>
        public static string Escape(string field)
        {
            if (string.IsNullOrEmpty(field)) return "";
            bool quote = field.IndexOfAny(new[] { ',', '"', '\n', '\r' }) >= 0 || field.Trim() != field;
            return quote ? "\"" + field.Replace("\"", "\"\"") + "\"" : field;
        }

        static bool IsBlank(string line) => line.Trim().Length == 0;

        static string[] SplitOrThrow(string line, string sourceName, int lineNumber)
        {
            string error;
            string[] fields = Split(line, out error);
            if (fields == null) throw new EvaluationFormatException(sourceName, lineNumber, error);
            return fields;
        }

        /// <summary>The fields of one line, or null with <paramref name="error"/> set.</summary>
        internal static string[] Split(string line, out string error)
        {
            error = null;
            if (line.EndsWith("\r", StringComparison.Ordinal)) line = line.Substring(0, line.Length - 1);
            var fields = new List<string>();
            var field = new StringBuilder();
            int i = 0;
            while (true)
            {
                // Leading spaces are not part of an unquoted field, nor do they stop a field being quoted.
                while (i < line.Length && (line[i] == ' ' || line[i] == '\t')) i++;
                if (i < line.Length && line[i] == '"')
                {
                    i++;
                    field.Length = 0;
                    bool closed = false;
                    while (i < line.Length)
                    {
                        char ch = line[i++];
                        if (ch != '"') { field.Append(ch); continue; }
                        if (i < line.Length && line[i] == '"') { field.Append('"'); i++; continue; }
                        closed = true;
                        break;
                    }
                    if (!closed) { error = "unterminated quoted field (a field may not span lines)"; return null; }
                    while (i < line.Length && (line[i] == ' ' || line[i] == '\t')) i++;
                    if (i < line.Length && line[i] != ',') { error = "unexpected text after a quoted field"; return null; }
                    fields.Add(field.ToString());
                }
                else
                {
                    int start = i;
                    while (i < line.Length && line[i] != ',')
                    {
                        if (line[i] == '"') { error = "a quote inside an unquoted field"; return null; }
                        i++;
                    }
                    fields.Add(line.Substring(start, i - start).Trim());
                }
                if (i >= line.Length) return fields.ToArray();
                i++; // the comma
            }
        }

        static string Quote(string[] header)
        {
            var shown = string.Join(",", header);
            return shown.Length > 80 ? shown.Substring(0, 80) + "…" : shown;
        }
    }
}
