using System;
using System.Collections.Generic;
using System.IO;

namespace Kosmos.PseudoHaptic.Evaluation
{
    /// <summary>
    /// A CSV file with a header naming its columns, the shape of both the responses and the scores files,
    /// read by <see cref="CsvReader"/> (RFC 4180: quoted fields may hold commas, doubled quotes and line
    /// breaks; every row has as many fields as the header). Columns are found by name (case-insensitive, any
    /// order; extra columns are ignored); surrounding spaces of fields are dropped; blank lines are skipped.
    /// Every fault throws <see cref="EvaluationFormatException"/> naming the line.
    /// </summary>
    public sealed class CsvTable
    {
        /// <summary>One data row: its 1-based first and last line and its fields in the order of the requested columns.</summary>
        public readonly struct Row
        {
            public int Line { get; }
            /// <summary>The row's last line (after <see cref="Line"/> when a quoted field holds a line break).</summary>
            public int EndLine { get; }
            readonly string[] fields;

            internal Row(int line, int endLine, string[] fields)
            {
                Line = line;
                EndLine = endLine;
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
            return new CsvTable(sourceName, new List<Row>(Stream(new StringReader(text), sourceName, columns)));
        }

        /// <summary>
        /// The rows of <paramref name="reader"/> one at a time, in constant memory per row; the header is
        /// checked before the first row is returned. Disposes <paramref name="reader"/> at the end.
        /// </summary>
        public static IEnumerable<Row> Stream(TextReader reader, string sourceName, params string[] columns)
            => Stream(reader, sourceName, int.MaxValue, columns);

        /// <summary>As <see cref="Stream(TextReader, string, string[])"/>; a data row beyond <paramref name="maxRows"/> is an error naming its line.</summary>
        public static IEnumerable<Row> Stream(TextReader reader, string sourceName, int maxRows, params string[] columns)
            => Stream(reader, sourceName, maxRows, long.MaxValue, columns);

        /// <summary>
        /// As <see cref="Stream(TextReader, string, int, string[])"/>; the requested fields of all rows together
        /// may hold at most <paramref name="maxCharacters"/> characters (what a caller keeps stays bounded even
        /// when every row is near the 1 MiB row limit).
        /// </summary>
        public static IEnumerable<Row> Stream(TextReader reader, string sourceName, int maxRows, long maxCharacters, params string[] columns)
        {
            if (reader == null) throw new ArgumentNullException(nameof(reader));
            if (columns == null || columns.Length == 0) throw new ArgumentException("no columns requested", nameof(columns));
            if (maxRows < 0) throw new ArgumentOutOfRangeException(nameof(maxRows));
            if (maxCharacters < 0) throw new ArgumentOutOfRangeException(nameof(maxCharacters));
            return StreamRows(reader, sourceName, maxRows, maxCharacters, columns, Array.Empty<string>(), Array.Empty<bool>());
        }

        /// <summary>
        /// As <see cref="Stream(TextReader, string, int, long, string[])"/>, with <paramref name="optional"/> columns
        /// after the required ones in each row (an absent optional column reads as null); <paramref name="present"/>
        /// (one flag per optional column) is filled once the header has been read.
        /// </summary>
        public static IEnumerable<Row> Stream(TextReader reader, string sourceName, int maxRows, long maxCharacters, string[] columns, string[] optional, bool[] present)
        {
            if (reader == null) throw new ArgumentNullException(nameof(reader));
            if (columns == null || columns.Length == 0) throw new ArgumentException("no columns requested", nameof(columns));
            if (optional == null || present == null || present.Length != optional.Length) throw new ArgumentException("one flag per optional column", nameof(present));
            if (maxRows < 0) throw new ArgumentOutOfRangeException(nameof(maxRows));
            if (maxCharacters < 0) throw new ArgumentOutOfRangeException(nameof(maxCharacters));
            return StreamRows(reader, sourceName, maxRows, maxCharacters, columns, optional, present);
        }

        static IEnumerable<Row> StreamRows(TextReader reader, string sourceName, int maxRows, long maxCharacters, string[] columns, string[] optional, bool[] present)
        {
            using (var csv = new CsvReader(reader, sourceName))
            {
                string expected = string.Join(",", columns);
                if (!csv.ReadHeader()) throw csv.Error(1, "empty file: expected the header " + expected);
                var index = new int[columns.Length + optional.Length];
                for (int c = 0; c < columns.Length; c++)
                {
                    index[c] = csv.IndexOf(columns[c], StringComparison.OrdinalIgnoreCase);
                    if (index[c] < 0)
                        throw csv.Error(csv.HeaderLine, "missing column '" + columns[c] + "': the header must name " + expected + " (found " + Quote(csv.Header) + ")");
                }
                for (int c = 0; c < optional.Length; c++)
                {
                    index[columns.Length + c] = csv.IndexOf(optional[c], StringComparison.OrdinalIgnoreCase);
                    present[c] = index[columns.Length + c] >= 0;
                }
                int count = 0;
                long characters = 0;
                while (csv.Read())
                {
                    if (++count > maxRows)
                        throw csv.Error(csv.Line, "more than " + maxRows.ToString(System.Globalization.CultureInfo.InvariantCulture) + " rows (the limit for this file)");
                    var picked = new string[index.Length];
                    for (int c = 0; c < index.Length; c++)
                    {
                        if (index[c] < 0) continue; // an absent optional column reads as null
                        picked[c] = csv[index[c]];
                        characters += picked[c].Length;
                    }
                    if (characters > maxCharacters)
                        throw csv.Error(csv.Line, "more than " + maxCharacters.ToString(System.Globalization.CultureInfo.InvariantCulture) + " characters of data (the limit for this file)");
                    yield return new Row(csv.Line, csv.EndLine, picked);
                }
            }
        }

        /// <summary>A field as CSV writes it: quoted when it holds a comma, quote, line break or edge space.</summary>
        /// <summary>
        /// The lines of <paramref name="text"/> as the reader numbers them (line n at index n − 1): a line ends at "\r\n",
        /// "\n" or a lone "\r" (a file saved with old Mac line ends), its end not included.
        /// </summary>
        public static string[] Lines(string text) => (text ?? "").Replace("\r\n", "\n").Replace('\r', '\n').Split('\n');

        public static string Escape(string field)
        {
            if (string.IsNullOrEmpty(field)) return "";
            bool quote = field.IndexOfAny(new[] { ',', '"', '\n', '\r' }) >= 0 || field.Trim() != field;
            return quote ? "\"" + field.Replace("\"", "\"\"") + "\"" : field;
        }

        /// <summary>The fields of one line, or null with <paramref name="error"/> set.</summary>
        internal static string[] Split(string line, out string error)
        {
            error = null;
            try
            {
                using (var csv = new CsvReader(new StringReader(line), ""))
                {
                    if (!csv.ReadHeader()) return new[] { "" };
                    if (csv.Read()) { error = "more than one row"; return null; }
                    var fields = new string[csv.Header.Count];
                    for (int i = 0; i < fields.Length; i++) fields[i] = csv.Header[i];
                    return fields;
                }
            }
            catch (EvaluationFormatException e)
            {
                error = e.Reason;
                return null;
            }
        }

        static string Quote(IReadOnlyList<string> header)
        {
            var shown = string.Join(",", header);
            return shown.Length > 80 ? shown.Substring(0, 80) + "…" : shown;
        }
    }
}
