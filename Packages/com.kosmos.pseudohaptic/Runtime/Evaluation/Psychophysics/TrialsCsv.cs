using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Text;

namespace Kosmos.PseudoHaptic.Evaluation
{
    /// <summary>
    /// The trials file written in the headset and read by <c>pseudohaptic psychometric</c>:
    /// <c>participant,condition,trial,standard,comparison,first,catch,response</c> (first = "comparison" or
    /// "standard"; catch = 1 or 0; response = 1 or 0). psychometric needs only participant, standard,
    /// comparison and response (condition optional); the other columns are for the experimenter, catch also for
    /// leaving catch trials out of a fit (<c>psychometric --without-catch</c>, and <c>tune</c> always).
    /// </summary>
    public static class TrialsCsv
    {
        public const string Header = "participant,condition,trial,standard,comparison,first,catch,response";

        public static string FormatRow(Trial t)
        {
            if (t == null) throw new ArgumentNullException(nameof(t));
            if (t.Response != 0 && t.Response != 1) throw new InvalidOperationException("trial " + t.Index + " has no answer yet");
            return CsvTable.Escape(t.Participant) + "," + CsvTable.Escape(t.Condition) + ","
                   + t.Index.ToString(CultureInfo.InvariantCulture) + ","
                   + t.Standard.ToString("R", CultureInfo.InvariantCulture) + ","
                   + t.Comparison.ToString("R", CultureInfo.InvariantCulture) + ","
                   + (t.ComparisonFirst ? "comparison" : "standard") + ","
                   + (t.Catch ? "1" : "0") + ","
                   + t.Response.ToString(CultureInfo.InvariantCulture);
        }

        /// <summary>A whole file of answered trials, header first, "\n" line ends.</summary>
        public static string Format(IEnumerable<Trial> trials)
        {
            var text = new StringBuilder(Header).Append('\n');
            foreach (var t in trials) text.Append(FormatRow(t)).Append('\n');
            return text.ToString();
        }

        public static readonly string[] RequiredColumns = { "participant", "standard", "comparison", "response" };

        /// <summary>
        /// Reads answered trials: columns by name (any order, case-insensitive), <c>participant</c>,
        /// <c>standard</c>, <c>comparison</c>, <c>response</c> required, <c>condition</c> optional (default ""),
        /// others ignored. A missing column, an empty participant, a number that does not parse or is not
        /// finite, a standard or comparison weight that is not positive (a weight in kg: a Weber fraction of a
        /// negative standard means nothing), or a response other than 0 or 1 throws
        /// <see cref="EvaluationFormatException"/> naming the line.
        /// </summary>
        public static List<TrialAnswer> Read(TextReader reader, string sourceName, int maxRows = int.MaxValue, long maxCharacters = long.MaxValue)
            => Read(reader, sourceName, maxRows, maxCharacters, leaveOutCatch: false, out _);

        /// <summary>
        /// As <see cref="Read(TextReader, string, int, long)"/>; with <paramref name="leaveOutCatch"/> the rows whose
        /// <c>catch</c> column is 1 (attention checks at levels no attentive participant misses, not levels of the
        /// psychometric function) are read, checked and left out, counted in <paramref name="leftOut"/>; a catch value
        /// other than 0 or 1 is refused naming the line; a file without the column has no catch trials.
        /// </summary>
        public static List<TrialAnswer> Read(TextReader reader, string sourceName, int maxRows, long maxCharacters, bool leaveOutCatch, out int leftOut)
        {
            var answers = new List<TrialAnswer>();
            leftOut = 0;
            string[] optional = leaveOutCatch ? new[] { "condition", "catch" } : new[] { "condition" }; // otherwise catch is ignored, as any other column
            var present = new bool[optional.Length];
            foreach (var row in CsvTable.Stream(reader, sourceName, maxRows, maxCharacters, RequiredColumns, optional, present))
            {
                string participant = row[0].Trim();
                if (participant.Length == 0) throw new EvaluationFormatException(sourceName, row.Line, "participant is empty");
                double standard = Weight(sourceName, row, "standard", row[1]);
                double comparison = Weight(sourceName, row, "comparison", row[2]);
                string response = row[3].Trim();
                if (response != "0" && response != "1")
                    throw new EvaluationFormatException(sourceName, row.Line, "response '" + row[3] + "' must be 1 (comparison judged heavier) or 0");
                if (leaveOutCatch && row[5] != null)
                {
                    string isCatch = row[5].Trim();
                    if (isCatch != "0" && isCatch != "1")
                        throw new EvaluationFormatException(sourceName, row.Line, "catch '" + row[5] + "' must be 1 (a catch trial) or 0");
                    if (isCatch == "1")
                    {
                        leftOut++;
                        continue;
                    }
                }
                answers.Add(new TrialAnswer(participant, (row[4] ?? "").Trim(), standard, comparison, response == "1" ? 1 : 0, row.Line));
            }
            return answers;
        }

        /// <summary>A weight in kg: a finite number above zero.</summary>
        static double Weight(string sourceName, CsvTable.Row row, string column, string text)
        {
            double value = Number(sourceName, row, column, text);
            if (!(value > 0))
                throw new EvaluationFormatException(sourceName, row.Line, column + " " + text.Trim() + " is not a positive weight (kg)");
            return value;
        }

        static double Number(string sourceName, CsvTable.Row row, string column, string text)
        {
            double value;
            if (!double.TryParse(text.Trim(), NumberStyles.Float, CultureInfo.InvariantCulture, out value))
                throw new EvaluationFormatException(sourceName, row.Line, column + " '" + text + "' is not a number");
            if (double.IsNaN(value) || double.IsInfinity(value))
                throw new EvaluationFormatException(sourceName, row.Line, column + " '" + text + "' is not a finite number");
            return value;
        }
    }
}
