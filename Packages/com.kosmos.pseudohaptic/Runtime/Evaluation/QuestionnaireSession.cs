using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Text;

namespace Kosmos.PseudoHaptic.Evaluation
{
    /// <summary>
    /// One participant answering questionnaires one item at a time, as an in-headset panel shows them: which
    /// questionnaires in which order, the current item, answering it, going back, and completion. Every
    /// answer is written to the responses file at once, in the format <c>pseudohaptic score</c> reads
    /// (<see cref="ResponsesCsv"/>), through write-then-rename (<see cref="AtomicFile"/>): the file on disk is
    /// always complete, so a crash loses at most the answer being given, and a new session for the same
    /// participant and file resumes at the first item not yet answered (first removing from the file's folder the
    /// temporary files a kill or a power cut left: <see cref="AtomicFile.RemoveStaleTemporaries"/>, one writer per
    /// folder). A changed answer replaces the
    /// participant's earlier row for that item, so the file never holds a duplicate (which score refuses).
    /// </summary>
    /// <remarks>
    /// Rows of other participants (and of questionnaires not in this session) are kept as they are, in their
    /// order. The existing file is checked as strictly as score checks it; a file score would refuse is
    /// refused here too (<see cref="EvaluationFormatException"/>), and left untouched. Its header must be
    /// participant,questionnaire,item,response in that order (any case), so that new rows can be appended
    /// unchanged. One session writes a file at a time: rows another program adds meanwhile are overwritten.
    /// </remarks>
    public sealed class QuestionnaireSession
    {
        readonly Questionnaire[] parts;
        readonly int[] firstStep;       // by part: its first step
        readonly int[] partOfStep;      // by step: the part
        readonly int[] answers;         // by step: the answer, 0 when unanswered (scales may include 0, so see answered)
        readonly bool[] answered;
        readonly int[] rowOfStep;       // by step: index into rows, −1 when unanswered
        readonly List<string> rows = new List<string>();
        readonly string header;

        public QuestionnaireCatalog Catalog { get; }
        public string Participant { get; }

        /// <summary>The responses file, as given.</summary>
        public string ResponsesPath { get; }

        /// <summary>The questionnaires of this session, in the order they are asked.</summary>
        public IReadOnlyList<Questionnaire> Questionnaires => parts;

        /// <summary>Items over all questionnaires.</summary>
        public int StepCount { get; }

        /// <summary>The step shown: 0 … <see cref="StepCount"/> − 1, or <see cref="StepCount"/> once every item is answered.</summary>
        public int StepIndex { get; private set; }

        /// <summary>Items of this session answered (in the file).</summary>
        public int AnsweredCount { get; private set; }

        /// <summary>Answers of this session that were already in the file when it began.</summary>
        public int ResumedCount { get; }
        /// <summary>Leftover temporary files of this writer (<see cref="AtomicFile.RemoveStaleTemporaries"/>) removed from the responses file's folder when the session began.</summary>
        public int RemovedTemporaries { get; }

        /// <summary>Every item answered.</summary>
        public bool IsComplete => AnsweredCount == StepCount;

        /// <summary>Past the last item: nothing to show but the end.</summary>
        public bool IsFinished => StepIndex == StepCount;

        /// <summary>The questionnaire of the current step; null when finished.</summary>
        public Questionnaire CurrentQuestionnaire => IsFinished ? null : parts[partOfStep[StepIndex]];

        /// <summary>The current item; null when finished.</summary>
        public QuestionnaireItem CurrentItem => IsFinished ? null : CurrentQuestionnaire.Items[StepIndex - firstStep[partOfStep[StepIndex]]];

        /// <summary>1-based position of the current item in its questionnaire; 0 when finished.</summary>
        public int CurrentPosition => IsFinished ? 0 : StepIndex - firstStep[partOfStep[StepIndex]] + 1;

        /// <summary>1-based number of the current questionnaire in this session; 0 when finished.</summary>
        public int CurrentPart => IsFinished ? 0 : partOfStep[StepIndex] + 1;

        /// <summary>"3 / 10": the current item's position in its questionnaire and the questionnaire's length; "" when finished.</summary>
        public string ProgressText => IsFinished ? "" :
            CurrentPosition.ToString(CultureInfo.InvariantCulture) + " / " + CurrentQuestionnaire.ItemCount.ToString(CultureInfo.InvariantCulture);

        /// <summary>The answer already given to the current item, if any.</summary>
        public int? CurrentAnswer => IsFinished ? (int?)null : AnswerAt(StepIndex);

        public bool CanGoBack => !IsSaving && StepIndex > 0;

        /// <summary>The current item is answered and not the end: moving on skips nothing.</summary>
        public bool CanGoForward => !IsSaving && !IsFinished && answered[StepIndex];

        /// <summary>
        /// An answer was given (<see cref="Submit"/>) and is in <see cref="FileText"/>, but its write has not been
        /// acknowledged (<see cref="Acknowledge"/>): the item stays shown, and no answer or paging is taken.
        /// </summary>
        public bool IsSaving { get; private set; }

        int pendingStep, pendingValue, pendingRow;
        string pendingPrevious;

        /// <summary>
        /// Starts or resumes <paramref name="participant"/>'s session over <paramref name="questionnaireIds"/> (all of
        /// the catalog's, in its order, when null), reading <paramref name="responsesPath"/> if it exists.
        /// </summary>
        /// <exception cref="ArgumentException">An empty participant id, or one with line breaks or surrounding spaces; an unknown or repeated questionnaire id.</exception>
        /// <exception cref="EvaluationFormatException">The responses file exists but score would refuse it, or its header is not in the order rows are appended in.</exception>
        public QuestionnaireSession(QuestionnaireCatalog catalog, string participant, string responsesPath, IEnumerable<string> questionnaireIds = null)
        {
            Catalog = catalog ?? throw new ArgumentNullException(nameof(catalog));
            if (string.IsNullOrWhiteSpace(participant)) throw new ArgumentException("the participant id is empty", nameof(participant));
            if (participant.Trim() != participant || participant.IndexOf('\n') >= 0 || participant.IndexOf('\r') >= 0)
                throw new ArgumentException("the participant id '" + participant + "' has surrounding spaces or a line break", nameof(participant));
            if (string.IsNullOrEmpty(responsesPath)) throw new ArgumentException("the responses file path is empty", nameof(responsesPath));
            Participant = participant;
            ResponsesPath = responsesPath;

            var chosen = new List<Questionnaire>();
            if (questionnaireIds == null) chosen.AddRange(catalog.Questionnaires);
            else
                foreach (string id in questionnaireIds)
                {
                    var q = catalog.Find(id);
                    if (q == null) throw new ArgumentException("unknown questionnaire '" + id + "' (expected one of " + catalog.DescribeIds() + ")", nameof(questionnaireIds));
                    if (chosen.Contains(q)) throw new ArgumentException("questionnaire '" + id + "' is listed twice", nameof(questionnaireIds));
                    chosen.Add(q);
                }
            if (chosen.Count == 0) throw new ArgumentException("no questionnaires to ask", nameof(questionnaireIds));
            parts = chosen.ToArray();

            firstStep = new int[parts.Length];
            int steps = 0;
            for (int p = 0; p < parts.Length; p++)
            {
                firstStep[p] = steps;
                steps += parts[p].ItemCount;
            }
            StepCount = steps;
            partOfStep = new int[steps];
            for (int p = 0; p < parts.Length; p++)
                for (int i = 0; i < parts[p].ItemCount; i++) partOfStep[firstStep[p] + i] = p;
            answers = new int[steps];
            answered = new bool[steps];
            rowOfStep = new int[steps];
            for (int s = 0; s < steps; s++) rowOfStep[s] = -1;

            header = ResponsesCsv.Header;
            // The session starts or resumes in this folder: temporary files of writes a kill or power cut stopped go.
            RemovedTemporaries = AtomicFile.RemoveStaleTemporaries(Path.GetDirectoryName(Path.GetFullPath(responsesPath)));
            if (File.Exists(responsesPath))
            {
                string text = File.ReadAllText(responsesPath, Encoding.UTF8);
                // An empty file (created by hand, say) is a new one; anything else must be a valid responses file.
                if (text.Trim().Trim('\uFEFF').Length > 0) header = Load(text);
            }
            ResumedCount = AnsweredCount;
            StepIndex = NextUnanswered(-1);
        }

        /// <summary>The answer given to step <paramref name="step"/>, if any.</summary>
        public int? AnswerAt(int step)
        {
            if ((uint)step >= (uint)StepCount) throw new ArgumentOutOfRangeException(nameof(step));
            return answered[step] ? answers[step] : (int?)null;
        }

        /// <summary>The questionnaire and item of step <paramref name="step"/>.</summary>
        public QuestionnaireItem ItemAt(int step, out Questionnaire questionnaire)
        {
            if ((uint)step >= (uint)StepCount) throw new ArgumentOutOfRangeException(nameof(step));
            int p = partOfStep[step];
            questionnaire = parts[p];
            return questionnaire.Items[step - firstStep[p]];
        }

        /// <summary>
        /// Answers the current item with <paramref name="value"/>, writes the file, and moves on to the next item
        /// not yet answered (after this one, else the first before it, else the end). If the file cannot be
        /// written the session stays as it was and the I/O error is thrown. (The headset does the same in two
        /// steps, <see cref="Submit"/> and <see cref="Acknowledge"/>, with the write off the main thread.)
        /// </summary>
        /// <exception cref="InvalidOperationException">The session is finished, or an answer is waiting for its write.</exception>
        /// <exception cref="ArgumentOutOfRangeException">The value is not on the questionnaire's scale.</exception>
        public void Answer(int value)
        {
            Submit(value);
            try
            {
                Save();
            }
            catch
            {
                Withdraw();
                throw;
            }
            Acknowledge();
        }

        /// <summary>
        /// Takes <paramref name="value"/> as the current item's answer into memory (it is then in
        /// <see cref="FileText"/>, replacing an earlier answer to the item, and <see cref="IsSaving"/>): the item does not
        /// move on until the file holding it has been written and <see cref="Acknowledge"/> is called.
        /// </summary>
        /// <exception cref="InvalidOperationException">The session is finished, or an answer is waiting for its write.</exception>
        /// <exception cref="ArgumentOutOfRangeException">The value is not on the questionnaire's scale.</exception>
        public void Submit(int value)
        {
            if (IsFinished) throw new InvalidOperationException("the session is finished: every item is answered");
            if (IsSaving) throw new InvalidOperationException("the last answer is still being saved");
            var questionnaire = CurrentQuestionnaire;
            var item = CurrentItem;
            string why = questionnaire.Reject(item.Number, value);
            if (why != null) throw new ArgumentOutOfRangeException(nameof(value), why);

            int step = StepIndex;
            string row = ResponsesCsv.FormatRow(new Response(Participant, questionnaire.Id, item.Number, value));
            int at = rowOfStep[step];
            pendingPrevious = at >= 0 ? rows[at] : null;
            if (at >= 0) rows[at] = row;
            else
            {
                rows.Add(row);
                at = rows.Count - 1;
            }
            pendingStep = step;
            pendingValue = value;
            pendingRow = at;
            IsSaving = true;
        }

        /// <summary>The file holding the submitted answer was written: the answer counts and the next item is shown.</summary>
        public void Acknowledge()
        {
            if (!IsSaving) throw new InvalidOperationException("no answer is waiting for its write");
            IsSaving = false;
            int step = pendingStep;
            if (rowOfStep[step] < 0)
            {
                rowOfStep[step] = pendingRow;
                AnsweredCount++;
            }
            answers[step] = pendingValue;
            answered[step] = true;
            StepIndex = NextUnanswered(step);
        }

        void Withdraw()
        {
            IsSaving = false;
            if (rowOfStep[pendingStep] >= 0) rows[pendingRow] = pendingPrevious;
            else rows.RemoveAt(pendingRow);
        }

        /// <summary>Shows the previous item (its answer can then be changed); false at the first.</summary>
        public bool Back()
        {
            if (!CanGoBack) return false;
            StepIndex--;
            return true;
        }

        /// <summary>Shows the next item without changing the current answer; false unless the current item is answered.</summary>
        public bool Forward()
        {
            if (!CanGoForward) return false;
            StepIndex++;
            return true;
        }

        /// <summary>The file's text as this session has written it (or would write it).</summary>
        public string FileText()
        {
            var text = new StringBuilder(header.Length + 1 + rows.Count * 40);
            text.Append(header).Append('\n');
            foreach (string row in rows) text.Append(row).Append('\n');
            return text.ToString();
        }

        void Save() => DiscriminationSession.Save(ResponsesPath, FileText());

        /// <summary>After <paramref name="from"/>, the first unanswered step; else the first unanswered before it; else the end.</summary>
        int NextUnanswered(int from)
        {
            for (int s = from + 1; s < StepCount; s++) if (!answered[s]) return s;
            for (int s = 0; s <= from && s < StepCount; s++) if (!answered[s]) return s;
            return StepCount;
        }

        /// <summary>Checks the file as score would, keeps its rows verbatim, and finds this session's answers. Returns the header line.</summary>
        string Load(string text)
        {
            // Score's own check: anything it would refuse is refused here, before a row is appended to it.
            ResponsesCsv.Parse(text, ResponsesPath, Catalog);

            if (text.Length > 0 && text[0] == '\uFEFF') text = text.Substring(1);
            string[] lines = CsvTable.Lines(text); // numbered as the reader numbers them
            var table = CsvTable.Parse(text, ResponsesPath, ResponsesCsv.Columns);

            int headerAt = 0;
            while (headerAt < lines.Length && lines[headerAt].Trim().Length == 0) headerAt++;
            string headerLine = lines[headerAt].TrimEnd('\r');
            string[] names = CsvTable.Split(headerLine, out _);
            bool inOrder = names != null && names.Length == ResponsesCsv.Columns.Length;
            for (int c = 0; inOrder && c < names.Length; c++)
                inOrder = string.Equals(names[c], ResponsesCsv.Columns[c], StringComparison.OrdinalIgnoreCase);
            if (!inOrder)
                throw new EvaluationFormatException(ResponsesPath, headerAt + 1,
                    "answers are appended as " + ResponsesCsv.Header + ", so the header must name exactly these columns in this order");

            foreach (var row in table.Rows)
            {
                // A quoted field may hold a line break: the row is kept verbatim over all its lines.
                var verbatim = new StringBuilder(lines[row.Line - 1].TrimEnd('\r'));
                for (int l = row.Line; l < row.EndLine && l < lines.Length; l++) verbatim.Append('\n').Append(lines[l].TrimEnd('\r'));
                rows.Add(verbatim.ToString());
                if (row[0] != Participant) continue;
                int p = Array.IndexOf(parts, Catalog.Find(row[1]));
                if (p < 0) continue;
                int item = int.Parse(row[2], NumberStyles.AllowLeadingSign, CultureInfo.InvariantCulture);
                int step = -1;
                for (int i = 0; i < parts[p].ItemCount; i++)
                    if (parts[p].Items[i].Number == item) { step = firstStep[p] + i; break; }
                if (step < 0) continue; // the check above refuses unknown items, so this does not happen
                answers[step] = (int)double.Parse(row[3], NumberStyles.Float, CultureInfo.InvariantCulture);
                answered[step] = true;
                rowOfStep[step] = rows.Count - 1;
                AnsweredCount++;
            }
            return headerLine;
        }
    }
}
