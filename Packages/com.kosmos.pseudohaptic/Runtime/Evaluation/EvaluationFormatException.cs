using System;
using System.Globalization;

namespace Kosmos.PseudoHaptic.Evaluation
{
    /// <summary>
    /// A file that cannot be used as it stands: a malformed responses or scores CSV, a broken questionnaire
    /// definition. Carries the file's name and the 1-based line (0 when no single line is to blame), and
    /// reads as one line, "source:line: reason", the way compilers report.
    /// </summary>
    public sealed class EvaluationFormatException : Exception
    {
        /// <summary>The file's name as the caller gave it (a path, or a label such as "immersion.json").</summary>
        public string SourceName { get; }
        /// <summary>1-based line number (the CSV header is line 1); 0 when the fault is the whole file's.</summary>
        public int Line { get; }
        /// <summary>The reason alone, without source and line.</summary>
        public string Reason { get; }

        public EvaluationFormatException(string sourceName, int line, string reason)
            : base(Format(sourceName, line, reason))
        {
            SourceName = sourceName ?? "";
            Line = line;
            Reason = reason ?? "";
        }

        static string Format(string sourceName, int line, string reason)
        {
            string where = string.IsNullOrEmpty(sourceName) ? "<input>" : sourceName;
            if (line > 0) where += ":" + line.ToString(CultureInfo.InvariantCulture);
            // One line, always: a reason quoting a bad field must not break the message in two.
            string oneLine = (reason ?? "").Replace("\r", " ").Replace("\n", " ");
            return where + ": " + oneLine;
        }
    }
}
