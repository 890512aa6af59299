using System;
using System.Collections.Generic;

namespace Kosmos.PseudoHaptic.Evaluation
{
    /// <summary>
    /// The questionnaires of one study, in the order they are reported (Part 1, 2, 3), found by id.
    /// </summary>
    public sealed class QuestionnaireCatalog
    {
        readonly Questionnaire[] parts;
        readonly Dictionary<string, Questionnaire> byId;

        /// <summary>The paper's three parts' ids, as the CSV files name them.</summary>
        public const string WeightDetectionId = "weight-detection";
        public const string ImmersionId = "immersion";
        public const string SelfAssessmentId = "self-assessment";

        /// <summary>The file names of the package's definitions, in report order (Runtime/Evaluation/Questionnaires).</summary>
        public static readonly string[] DefaultFileNames = { "weight-detection.json", "immersion.json", "self-assessment.json" };

        public IReadOnlyList<Questionnaire> Questionnaires => parts;

        public QuestionnaireCatalog(IEnumerable<Questionnaire> questionnaires)
        {
            if (questionnaires == null) throw new ArgumentNullException(nameof(questionnaires));
            var list = new List<Questionnaire>();
            byId = new Dictionary<string, Questionnaire>(StringComparer.Ordinal);
            foreach (var q in questionnaires)
            {
                if (q == null) throw new ArgumentException("null questionnaire", nameof(questionnaires));
                if (byId.ContainsKey(q.Id)) throw new ArgumentException("questionnaire id '" + q.Id + "' appears twice");
                byId.Add(q.Id, q);
                list.Add(q);
            }
            if (list.Count == 0) throw new ArgumentException("no questionnaires", nameof(questionnaires));
            parts = list.ToArray();
        }

        /// <summary>The questionnaire with this id (exact, case-sensitive), or null.</summary>
        public Questionnaire Find(string id)
        {
            Questionnaire q = null;
            return id != null && byId.TryGetValue(id, out q) ? q : null;
        }

        /// <summary>Position in report order, or −1.</summary>
        public int IndexOf(string id)
        {
            for (int i = 0; i < parts.Length; i++)
                if (parts[i].Id == id) return i;
            return -1;
        }

        /// <summary>"'a', 'b', 'c'", for messages.</summary>
        public string DescribeIds()
        {
            var ids = new string[parts.Length];
            for (int i = 0; i < parts.Length; i++) ids[i] = "'" + parts[i].Id + "'";
            return string.Join(", ", ids);
        }
    }
}
