using System;
using System.Collections.Generic;

namespace Kosmos.PseudoHaptic.Evaluation
{
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
                            double x = 0, y = 0;
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
