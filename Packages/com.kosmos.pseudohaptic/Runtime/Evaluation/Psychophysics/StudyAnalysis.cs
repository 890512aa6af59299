using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;

namespace Kosmos.PseudoHaptic.Evaluation
{
    /// <summary>One answered 2AFC trial as read from a trials file.</summary>
    public sealed class TrialAnswer
    {
        public string Participant { get; }
        public string Condition { get; }
        public double Standard { get; }
        public double Comparison { get; }
        public int Response { get; }
        public int Line { get; }

        public TrialAnswer(string participant, string condition, double standard, double comparison, int response, int line)
        {
            Participant = participant;
            Condition = condition ?? "";
            Standard = standard;
            Comparison = comparison;
            Response = response;
            Line = line;
        }
    }

    public static partial class TrialsCsv
    {
        public static readonly string[] RequiredColumns = { "participant", "standard", "comparison", "response" };

        /// <summary>
        /// Reads answered trials: columns by name (any order, case-insensitive), <c>participant</c>,
        /// <c>standard</c>, <c>comparison</c>, <c>response</c> required, <c>condition</c> optional (default ""),
        /// others ignored. A missing column, an empty participant, a number that does not parse or is not
        /// finite, or a response other than 0 or 1 throws <see cref="EvaluationFormatException"/> naming the line.
        /// </summary>
        public static List<TrialAnswer> Read(TextReader reader, string sourceName, int maxRows = int.MaxValue, long maxCharacters = long.MaxValue)
        {
            var present = new bool[1];
            var answers = new List<TrialAnswer>();
            foreach (var row in CsvTable.Stream(reader, sourceName, maxRows, maxCharacters, RequiredColumns, new[] { "condition" }, present))
            {
                string participant = row[0].Trim();
                if (participant.Length == 0) throw new EvaluationFormatException(sourceName, row.Line, "participant is empty");
                double standard = Number(sourceName, row, "standard", row[1]);
                double comparison = Number(sourceName, row, "comparison", row[2]);
                string response = row[3].Trim();
                if (response != "0" && response != "1")
                    throw new EvaluationFormatException(sourceName, row.Line, "response '" + row[3] + "' must be 1 (comparison judged heavier) or 0");
                answers.Add(new TrialAnswer(participant, (row[4] ?? "").Trim(), standard, comparison, response == "1" ? 1 : 0, row.Line));
            }
            return answers;
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

    /// <summary>One row of fits.csv: the fit of one participant × condition × standard, with its bootstrap.</summary>
    public sealed class PsychometricRow
    {
        public string Participant { get; }
        public string Condition { get; }
        public double Standard { get; }
        public PsychometricFit Fit { get; }
        public PsychometricBootstrap Bootstrap { get; }
        public double Weber => Fit.Jnd / Standard;

        public PsychometricRow(string participant, string condition, double standard, PsychometricFit fit, PsychometricBootstrap bootstrap)
        {
            Participant = participant;
            Condition = condition;
            Standard = standard;
            Fit = fit;
            Bootstrap = bootstrap;
        }
    }

    /// <summary>
    /// The fits of a trials file: one per participant × condition × standard, participants in
    /// <see cref="ParticipantOrder"/>, conditions in the order they first appear, standards ascending. Each
    /// group's bootstrap has its own seed, drawn in that order from <see cref="SeededRandom"/>(seed), so the
    /// same file and seed give the same numbers.
    /// </summary>
    public static class PsychometricAnalysis
    {
        public static IReadOnlyList<PsychometricRow> Fit(IReadOnlyList<TrialAnswer> answers, double lapse, int resamples, long seed)
        {
            if (answers == null) throw new ArgumentNullException(nameof(answers));
            var conditionOrder = new Dictionary<string, int>(StringComparer.Ordinal);
            var groups = new Dictionary<string, List<TrialAnswer>>(StringComparer.Ordinal);
            var keys = new List<TrialAnswer>(); // the first answer of each group stands for it
            foreach (var a in answers)
            {
                if (!conditionOrder.ContainsKey(a.Condition)) conditionOrder.Add(a.Condition, conditionOrder.Count);
                string key = a.Participant + "\n" + a.Condition + "\n" + a.Standard.ToString("R", CultureInfo.InvariantCulture);
                List<TrialAnswer> list;
                if (!groups.TryGetValue(key, out list))
                {
                    groups.Add(key, list = new List<TrialAnswer>());
                    keys.Add(a);
                }
                list.Add(a);
            }
            keys.Sort((x, y) =>
            {
                int c = ParticipantOrder.Instance.Compare(x.Participant, y.Participant);
                if (c != 0) return c;
                c = conditionOrder[x.Condition].CompareTo(conditionOrder[y.Condition]);
                return c != 0 ? c : x.Standard.CompareTo(y.Standard);
            });
            var seeds = new SeededRandom(seed);
            var rows = new List<PsychometricRow>(keys.Count);
            foreach (var k in keys)
            {
                var list = groups[k.Participant + "\n" + k.Condition + "\n" + k.Standard.ToString("R", CultureInfo.InvariantCulture)];
                var x = new double[list.Count];
                var y = new int[list.Count];
                for (int i = 0; i < list.Count; i++) { x[i] = list[i].Comparison; y[i] = list[i].Response; }
                var fit = PsychometricFit.Fit(x, y, lapse);
                long groupSeed = unchecked((long)seeds.NextUInt64());
                var boot = PsychometricBootstrap.Run(fit, resamples, groupSeed);
                rows.Add(new PsychometricRow(k.Participant, k.Condition, k.Standard, fit, boot));
            }
            return rows;
        }
    }

    /// <summary>One score of a scores file with conditions.</summary>
    public sealed class ConditionScore
    {
        public string Participant { get; }
        public string Condition { get; }
        public string Questionnaire { get; }
        public double? Score { get; }
        public int Line { get; }

        public ConditionScore(string participant, string condition, string questionnaire, double? score, int line)
        {
            Participant = participant;
            Condition = condition;
            Questionnaire = questionnaire;
            Score = score;
            Line = line;
        }
    }

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

    /// <summary>One row of comparisons.csv: a pair of conditions of one questionnaire, or (<see cref="Friedman"/> set) the omnibus test.</summary>
    public sealed class ComparisonRow
    {
        public string Questionnaire { get; }
        public string ConditionA { get; }
        public string ConditionB { get; }
        public PairedComparison Pair { get; }
        public FriedmanTest Friedman { get; }
        public double PHolm { get; internal set; } = double.NaN;
        /// <summary>The participants of the pair, aligned with <see cref="A"/> and <see cref="B"/>.</summary>
        public IReadOnlyList<string> Participants { get; }
        public IReadOnlyList<double> A { get; }
        public IReadOnlyList<double> B { get; }

        internal ComparisonRow(string questionnaire, string a, string b, PairedComparison pair, FriedmanTest friedman, IReadOnlyList<string> participants, IReadOnlyList<double> va, IReadOnlyList<double> vb)
        {
            Questionnaire = questionnaire;
            ConditionA = a;
            ConditionB = b;
            Pair = pair;
            Friedman = friedman;
            Participants = participants;
            A = va;
            B = vb;
        }

        /// <summary>The method column: friedman; t+wilcoxon-exact; t+wilcoxon-normal; or what could be computed.</summary>
        public string Method
        {
            get
            {
                if (Friedman != null) return double.IsNaN(Friedman.Statistic) ? "friedman-undefined" : "friedman";
                bool t = !double.IsNaN(Pair.T), w = !double.IsNaN(Pair.WP);
                string wilcoxon = Pair.WilcoxonExact ? "wilcoxon-exact" : "wilcoxon-normal";
                if (t && w) return "t+" + wilcoxon;
                if (t) return "t";
                if (w) return wilcoxon;
                return "none";
            }
        }
    }

    /// <summary>
    /// compare's analysis: per questionnaire (in the order first seen), the conditions it has (in the order
    /// first seen in the file); with k ≥ 3 conditions Friedman's test over the participants complete in all of
    /// them comes first; then each pair a &lt; b (file order) over the participants with a complete score in
    /// both (<see cref="PairedComparison"/> of b − a). p_holm: with k ≥ 3, Holm's correction of the pairs'
    /// Wilcoxon p within the questionnaire; with two conditions, the single Wilcoxon p unchanged.
    /// </summary>
    public static class ConditionComparison
    {
        public static IReadOnlyList<ComparisonRow> Compare(IReadOnlyList<ConditionScore> scores)
        {
            if (scores == null) throw new ArgumentNullException(nameof(scores));
            var questionnaires = new List<string>();
            var conditionOrder = new Dictionary<string, int>(StringComparer.Ordinal);
            var byQuestionnaire = new Dictionary<string, List<ConditionScore>>(StringComparer.Ordinal);
            foreach (var s in scores)
            {
                if (!conditionOrder.ContainsKey(s.Condition)) conditionOrder.Add(s.Condition, conditionOrder.Count);
                List<ConditionScore> list;
                if (!byQuestionnaire.TryGetValue(s.Questionnaire, out list))
                {
                    byQuestionnaire.Add(s.Questionnaire, list = new List<ConditionScore>());
                    questionnaires.Add(s.Questionnaire);
                }
                list.Add(s);
            }

            var rows = new List<ComparisonRow>();
            foreach (string q in questionnaires)
            {
                var conditions = new List<string>();
                var value = new Dictionary<string, Dictionary<string, double>>(StringComparer.Ordinal); // condition → participant → score
                var participants = new List<string>();
                var seenParticipant = new HashSet<string>(StringComparer.Ordinal);
                foreach (var s in byQuestionnaire[q])
                {
                    if (!value.ContainsKey(s.Condition)) { value.Add(s.Condition, new Dictionary<string, double>(StringComparer.Ordinal)); conditions.Add(s.Condition); }
                    if (s.Score.HasValue) value[s.Condition][s.Participant] = s.Score.Value;
                    if (seenParticipant.Add(s.Participant)) participants.Add(s.Participant);
                }
                conditions.Sort((x, y) => conditionOrder[x].CompareTo(conditionOrder[y]));
                participants = ParticipantOrder.Sort(participants, p => p);
                int k = conditions.Count;
                if (k < 2) continue;

                if (k >= 3)
                {
                    var complete = new List<IReadOnlyList<double>>();
                    foreach (string p in participants)
                    {
                        var row = new double[k];
                        bool all = true;
                        for (int j = 0; j < k && all; j++)
                        {
                            double v;
                            if (value[conditions[j]].TryGetValue(p, out v)) row[j] = v; else all = false;
                        }
                        if (all) complete.Add(row);
                    }
                    var f = FriedmanTest.Compute(complete, k);
                    rows.Add(new ComparisonRow(q, "*", "*", null, f, new string[0], new double[0], new double[0]));
                }

                int firstPair = rows.Count;
                for (int i = 0; i < k; i++)
                    for (int j = i + 1; j < k; j++)
                    {
                        var who = new List<string>();
                        var va = new List<double>();
                        var vb = new List<double>();
                        foreach (string p in participants)
                        {
                            double x, y;
                            if (value[conditions[i]].TryGetValue(p, out x) && value[conditions[j]].TryGetValue(p, out y))
                            {
                                who.Add(p);
                                va.Add(x);
                                vb.Add(y);
                            }
                        }
                        rows.Add(new ComparisonRow(q, conditions[i], conditions[j], PairedComparison.Compute(va, vb), null, who, va, vb));
                    }
                var ps = new double[rows.Count - firstPair];
                for (int i = 0; i < ps.Length; i++) ps[i] = rows[firstPair + i].Pair.WP;
                double[] adjusted = k >= 3 ? Holm.Adjust(ps) : ps;
                for (int i = 0; i < ps.Length; i++) rows[firstPair + i].PHolm = adjusted[i];
            }
            return rows;
        }
    }
}
