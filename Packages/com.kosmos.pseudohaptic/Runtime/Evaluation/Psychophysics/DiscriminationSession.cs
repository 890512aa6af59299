using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Text;

namespace Kosmos.PseudoHaptic.Evaluation
{
    /// <summary>Where an object of a 2AFC pair stands: the left one is presented first.</summary>
    public enum PairSide
    {
        Left,
        Right,
    }

    /// <summary>
    /// The logic of the in-headset weight discrimination task (issue 11), without the engine: one participant
    /// in one condition works through a plan of 2AFC trials (<see cref="ConstantStimuliPlan"/>, rebuilt from its
    /// seed, so a session is reproducible), or through a transformed <see cref="Staircase"/> whose next
    /// comparison depends on the answers (rebuilt from its settings and seed and fed the recorded answers on
    /// resume). Each trial shows two objects of the same look, the standard and the
    /// comparison, left and right as the plan's counterbalancing says (the comparison on the left when it is
    /// "first"); their masses are never shown. The participant lifts each (<see cref="NoteLift"/>) and then
    /// answers which was heavier (<see cref="Answer"/>); a catch trial is answered like any other. Every answer
    /// is written at once to the trials file (<see cref="TrialsCsv"/>, the file <c>pseudohaptic psychometric</c>
    /// reads) through write-then-rename (<see cref="AtomicFile"/>), so the file on disk is always whole; a new
    /// session for the same participant, condition, plan and file resumes at the first trial not yet answered.
    /// A new or resumed session first removes from the file's folder the temporary files that a kill or a power cut
    /// left (<see cref="AtomicFile.RemoveStaleTemporaries"/>; one writer per folder).
    /// </summary>
    /// <remarks>
    /// Rows of other participants and conditions are kept verbatim. An existing file must be one
    /// psychometric accepts, with the header <see cref="TrialsCsv.Header"/>; a row of this participant and
    /// condition must match the plan (same trial number, standard and comparison), else the file was written
    /// with another plan or seed and is refused (<see cref="EvaluationFormatException"/>) and left untouched.
    /// </remarks>
    public sealed class DiscriminationSession
    {
        readonly IReadOnlyList<Trial> plan;     // constant stimuli; null with a staircase
        readonly Staircase staircase;           // null with constant stimuli
        readonly bool[] answered;
        readonly List<string> rows = new List<string>();
        readonly bool[] lifted = new bool[2];

        public string Participant { get; }
        public string Condition { get; }
        public string TrialsPath { get; }
        /// <summary>Whether both objects must have been lifted before an answer is taken (default true).</summary>
        public bool RequireBothLifts { get; set; } = true;

        /// <summary>The constant-stimuli plan; null when the session runs a staircase.</summary>
        public IReadOnlyList<Trial> Plan => plan;
        /// <summary>The staircase; null when the session runs a constant-stimuli plan.</summary>
        public Staircase Staircase => staircase;
        /// <summary>Trials of the plan; with a staircase, the trials so far (its length is not known in advance).</summary>
        public int TrialCount => plan != null ? plan.Count : staircase.Trials.Count + (staircase.Finished ? 0 : 1);
        public int AnsweredCount { get; private set; }
        public int ResumedCount { get; }
        /// <summary>Leftover temporary files of this writer (<see cref="AtomicFile.RemoveStaleTemporaries"/>) removed from the trials file's folder when the session began.</summary>
        public int RemovedTemporaries { get; private set; }
        /// <summary>Index into <see cref="Plan"/> of the trial shown (with a staircase, the number of trials answered); <see cref="TrialCount"/> when finished.</summary>
        public int CurrentIndex { get; private set; }
        public bool IsFinished => plan != null ? CurrentIndex >= plan.Count : staircase.Finished;
        public Trial Current => IsFinished ? null : plan != null ? plan[CurrentIndex] : staircase.Next();

        /// <summary>The mass (or gain) of the object on <paramref name="side"/> in the current trial.</summary>
        public double MassAt(PairSide side)
        {
            var t = Current ?? throw new InvalidOperationException("the session is finished");
            bool comparisonLeft = t.ComparisonFirst;
            return (side == PairSide.Left) == comparisonLeft ? t.Comparison : t.Standard;
        }

        public bool WasLifted(PairSide side) => lifted[(int)side];

        /// <summary>True when an answer is taken now.</summary>
        public bool CanAnswer => !IsSaving && !IsFinished && (!RequireBothLifts || (lifted[0] && lifted[1]));

        /// <summary>
        /// An answer was given (<see cref="Submit"/>) and is in <see cref="FileText"/>, but its write has not been
        /// acknowledged (<see cref="Acknowledge"/>): the trial stays shown and no other answer is taken.
        /// </summary>
        public bool IsSaving { get; private set; }

        /// <summary>"12 / 84".</summary>
        public string ProgressText => plan != null
            ? Math.Min(CurrentIndex + 1, plan.Count).ToString(CultureInfo.InvariantCulture) + " / " + plan.Count.ToString(CultureInfo.InvariantCulture)
            : (staircase.Trials.Count + (staircase.Finished ? 0 : 1)).ToString(CultureInfo.InvariantCulture) + " (reversals " + staircase.ReversalLevels.Count.ToString(CultureInfo.InvariantCulture) + " / " + staircase.StopAfterReversals.ToString(CultureInfo.InvariantCulture) + ")";

        public DiscriminationSession(string participant, string condition, string trialsPath, ConstantStimuliPlan planSettings)
        {
            if (planSettings == null) throw new ArgumentNullException(nameof(planSettings));
            Check(participant, ref condition, trialsPath);
            Participant = participant;
            Condition = condition;
            TrialsPath = trialsPath;
            plan = planSettings.Build(participant, condition);
            answered = new bool[plan.Count];
            LoadIfPresent();
            ResumedCount = AnsweredCount;
            CurrentIndex = NextUnanswered(0);
        }

        /// <summary>
        /// A session run by a transformed staircase (1-up-2-down or 1-up-3-down), made by
        /// <paramref name="makeStaircase"/> for this participant and condition; on resume the answers in the file
        /// are fed to a new staircase again, so the same settings and seed must be given.
        /// </summary>
        public DiscriminationSession(string participant, string condition, string trialsPath, Func<string, string, Staircase> makeStaircase)
        {
            if (makeStaircase == null) throw new ArgumentNullException(nameof(makeStaircase));
            Check(participant, ref condition, trialsPath);
            Participant = participant;
            Condition = condition;
            TrialsPath = trialsPath;
            staircase = makeStaircase(participant, condition) ?? throw new ArgumentException("no staircase made", nameof(makeStaircase));
            answered = new bool[0];
            LoadIfPresent();
            ResumedCount = AnsweredCount;
            CurrentIndex = AnsweredCount;
        }

        static void Check(string participant, ref string condition, string trialsPath)
        {
            if (string.IsNullOrWhiteSpace(participant)) throw new ArgumentException("the participant id is empty", nameof(participant));
            if (participant.Trim() != participant || participant.IndexOfAny(new[] { '\n', '\r' }) >= 0)
                throw new ArgumentException("the participant id '" + participant + "' has surrounding spaces or a line break", nameof(participant));
            condition = condition ?? "";
            if (condition.Trim() != condition || condition.IndexOfAny(new[] { '\n', '\r' }) >= 0)
                throw new ArgumentException("the condition '" + condition + "' has surrounding spaces or a line break", nameof(condition));
            if (string.IsNullOrEmpty(trialsPath)) throw new ArgumentException("the trials file path is empty", nameof(trialsPath));
        }

        void LoadIfPresent()
        {
            // The session starts or resumes in this folder: temporary files of writes a kill or power cut stopped go.
            RemovedTemporaries = AtomicFile.RemoveStaleTemporaries(Path.GetDirectoryName(Path.GetFullPath(TrialsPath)));
            if (!File.Exists(TrialsPath)) return;
            string text = File.ReadAllText(TrialsPath, Encoding.UTF8);
            if (text.Trim().Trim('\uFEFF').Length > 0) Load(text);
        }

        /// <summary>The participant lifted the object on <paramref name="side"/>.</summary>
        public void NoteLift(PairSide side)
        {
            if (!IsFinished) lifted[(int)side] = true;
        }

        /// <summary>
        /// Records "the object on <paramref name="heavier"/> was heavier" for the current trial (1 when that is
        /// the comparison), writes the file and moves to the next trial. False (nothing recorded) when the
        /// session is finished or the objects have not both been lifted yet. If the file cannot be written the
        /// session stays as it was and the I/O error is thrown. (The headset does the same in two steps,
        /// <see cref="Submit"/> and <see cref="Acknowledge"/>, with the write off the main thread.)
        /// </summary>
        public bool Answer(PairSide heavier)
        {
            if (!Submit(heavier)) return false;
            try
            {
                Save(TrialsPath, FileText());
            }
            catch
            {
                Withdraw();
                throw;
            }
            Acknowledge();
            return true;
        }

        /// <summary>
        /// Takes the answer "the object on <paramref name="heavier"/> was heavier" into memory (it is then in
        /// <see cref="FileText"/>, and <see cref="IsSaving"/>): the trial does not move on until the file holding it
        /// has been written and <see cref="Acknowledge"/> is called. False when no answer is taken now.
        /// </summary>
        public bool Submit(PairSide heavier)
        {
            if (!CanAnswer) return false;
            var trial = Current;
            bool comparisonLeft = trial.ComparisonFirst;
            trial.Response = (heavier == PairSide.Left) == comparisonLeft ? 1 : 0;
            rows.Add(TrialsCsv.FormatRow(trial));
            IsSaving = true;
            return true;
        }

        /// <summary>The file holding the submitted answer was written: the answer counts and the next trial is shown.</summary>
        public void Acknowledge()
        {
            if (!IsSaving) throw new InvalidOperationException("no answer is waiting for its write");
            IsSaving = false;
            var trial = Current;
            AnsweredCount++;
            lifted[0] = lifted[1] = false;
            if (plan != null)
            {
                answered[CurrentIndex] = true;
                CurrentIndex = NextUnanswered(CurrentIndex + 1);
            }
            else
            {
                staircase.Record(trial.Response);
                CurrentIndex = AnsweredCount;
            }
        }

        void Withdraw()
        {
            IsSaving = false;
            rows.RemoveAt(rows.Count - 1);
            Current.Response = -1;
        }

        /// <summary>Writes <paramref name="text"/> to <paramref name="path"/> durably (<see cref="AtomicFile"/>), making its folder first.</summary>
        public static void Save(string path, string text)
        {
            string full = Path.GetFullPath(path);
            AtomicFile.CreateDirectory(Path.GetDirectoryName(full));
            AtomicFile.WriteAllText(full, text);
        }

        /// <summary>The file's text as this session has written it (or would write it).</summary>
        public string FileText()
        {
            var text = new StringBuilder(TrialsCsv.Header).Append('\n');
            foreach (string row in rows) text.Append(row).Append('\n');
            return text.ToString();
        }

        int NextUnanswered(int from)
        {
            for (int i = from; i < plan.Count; i++) if (!answered[i]) return i;
            for (int i = 0; i < from && i < plan.Count; i++) if (!answered[i]) return i;
            return plan.Count;
        }

        void Load(string text)
        {
            // psychometric's own check first: a file it would refuse is refused here, before anything is added.
            TrialsCsv.Read(new StringReader(text), TrialsPath);
            var present = new bool[0];
            var columns = TrialsCsv.Header.Split(',');
            string[] lines = CsvTable.Lines(text.Length > 0 && text[0] == '\uFEFF' ? text.Substring(1) : text); // numbered as the reader numbers them
            foreach (var row in CsvTable.Stream(new StringReader(text), TrialsPath, int.MaxValue, long.MaxValue, columns, new string[0], present))
            {
                var verbatim = new StringBuilder(lines[row.Line - 1].TrimEnd('\r'));
                for (int l = row.Line; l < row.EndLine && l < lines.Length; l++) verbatim.Append('\n').Append(lines[l].TrimEnd('\r'));
                rows.Add(verbatim.ToString());
                if (row[0].Trim() != Participant || row[1].Trim() != Condition) continue;
                int index = 0;
                if (staircase != null)
                {
                    // The staircase is run again on the recorded answers, which must follow it trial by trial.
                    var next = staircase.Next();
                    if (next == null || !int.TryParse(row[2].Trim(), NumberStyles.None, CultureInfo.InvariantCulture, out index) || index != next.Index
                        || double.Parse(row[4].Trim(), NumberStyles.Float, CultureInfo.InvariantCulture) != next.Comparison)
                        throw new EvaluationFormatException(TrialsPath, row.Line, "this row does not follow the staircase (trial " + (next != null ? next.Index.ToString(CultureInfo.InvariantCulture) + " at " + next.Comparison.ToString("R", CultureInfo.InvariantCulture) : "none: it had finished") + "): was the file written with other settings or seed?");
                    staircase.Record(row[7].Trim() == "1" ? 1 : 0);
                    AnsweredCount++;
                    continue;
                }
                if (!int.TryParse(row[2].Trim(), NumberStyles.None, CultureInfo.InvariantCulture, out index) || index < 1 || index > plan.Count)
                    throw new EvaluationFormatException(TrialsPath, row.Line, "trial '" + row[2] + "' is not one of this plan's 1 … " + plan.Count.ToString(CultureInfo.InvariantCulture));
                var t = plan[index - 1];
                double standard = double.Parse(row[3].Trim(), NumberStyles.Float, CultureInfo.InvariantCulture);
                double comparison = double.Parse(row[4].Trim(), NumberStyles.Float, CultureInfo.InvariantCulture);
                if (standard != t.Standard || comparison != t.Comparison)
                    throw new EvaluationFormatException(TrialsPath, row.Line, "trial " + index.ToString(CultureInfo.InvariantCulture) + " does not match the plan (standard " + t.Standard.ToString("R", CultureInfo.InvariantCulture) + ", comparison " + t.Comparison.ToString("R", CultureInfo.InvariantCulture) + "): was the file written with another plan or seed?");
                if (answered[index - 1])
                    throw new EvaluationFormatException(TrialsPath, row.Line, "trial " + index.ToString(CultureInfo.InvariantCulture) + " of participant '" + Participant + "' is answered twice");
                t.Response = row[7].Trim() == "1" ? 1 : 0;
                answered[index - 1] = true;
                AnsweredCount++;
            }
            // Rows are appended in the header's order, so the header must be exactly that.
            int headerAt = 0;
            while (headerAt < lines.Length && lines[headerAt].Trim().Length == 0) headerAt++;
            string header = headerAt < lines.Length ? lines[headerAt].TrimEnd('\r').Trim() : "";
            if (!string.Equals(header, TrialsCsv.Header, StringComparison.OrdinalIgnoreCase))
                throw new EvaluationFormatException(TrialsPath, headerAt + 1, "answers are appended as " + TrialsCsv.Header + ", so the header must be exactly that");
        }
    }
}
