using System;
using System.Collections.Generic;

namespace Kosmos.PseudoHaptic.Evaluation
{
    /// <summary>
    /// All the answers of a study, checked as they arrive against the questionnaires: the questionnaire
    /// must exist, the item must be one of its items, the answer must be a whole number on its scale, and no
    /// participant may answer the same item twice. The one place these rules live: the CSV reader turns a
    /// refusal into an error naming the line, and an in-headset panel can use the same set directly.
    /// Sheets are kept by participant as they first answered, each one's in catalog order
    /// (<see cref="ScoreCalculator.ScoreAll(ResponseSet)"/> reports them in <see cref="ParticipantOrder"/>).
    /// </summary>
    public sealed class ResponseSet
    {
        readonly List<string> participants = new List<string>();
        readonly Dictionary<string, AnswerSheet[]> sheetsByParticipant = new Dictionary<string, AnswerSheet[]>(StringComparer.Ordinal);

        public QuestionnaireCatalog Catalog { get; }
        public int Count { get; private set; }

        /// <summary>Participant ids in the order they first answered.</summary>
        public IReadOnlyList<string> Participants => participants;

        public ResponseSet(QuestionnaireCatalog catalog)
        {
            Catalog = catalog ?? throw new ArgumentNullException(nameof(catalog));
        }

        /// <summary>Adds the answer, or leaves the set unchanged and returns why it cannot be accepted.</summary>
        public string TryAdd(Response response)
            => TryAdd(response.Participant, response.QuestionnaireId, response.Item, response.Value);

        /// <summary>
        /// Adds an answer read as a number (so that "3.5" or "1e20" is refused in words, not cast), or leaves
        /// the set unchanged and returns why it cannot be accepted.
        /// </summary>
        public string TryAdd(string participant, string questionnaireId, int item, double value)
        {
            if (string.IsNullOrWhiteSpace(participant)) return "participant is empty";
            int q = Catalog.IndexOf(questionnaireId);
            if (q < 0)
                return "unknown questionnaire '" + questionnaireId + "' (expected one of " + Catalog.DescribeIds() + ")";
            var questionnaire = Catalog.Questionnaires[q];
            string why = questionnaire.Reject(item, value);
            if (why != null) return why;

            AnswerSheet[] sheets;
            if (!sheetsByParticipant.TryGetValue(participant, out sheets))
            {
                sheets = new AnswerSheet[Catalog.Questionnaires.Count];
                sheetsByParticipant.Add(participant, sheets);
                participants.Add(participant);
            }
            var sheet = sheets[q] ?? (sheets[q] = new AnswerSheet(participant, questionnaire));
            if (sheet.AnsweredPosition(item) >= 0)
                return "duplicate answer: participant '" + participant + "' already answered '" + questionnaire.Id + "' item " + item;
            sheet.Set(item, (int)value);
            Count++;
            return null;
        }

        /// <summary>Adds the answer or throws <see cref="ArgumentException"/> saying why it cannot be accepted.</summary>
        public void Add(Response response)
        {
            string why = TryAdd(response);
            if (why != null) throw new ArgumentException(why, nameof(response));
        }

        /// <summary>Every sheet with at least one answer: by participant (first appearance), then questionnaire (catalog order).</summary>
        public IReadOnlyList<AnswerSheet> Sheets()
        {
            var all = new List<AnswerSheet>();
            foreach (var participant in participants)
                foreach (var sheet in sheetsByParticipant[participant])
                    if (sheet != null) all.Add(sheet);
            return all;
        }

        /// <summary>The sheets of one questionnaire, by participant (first appearance).</summary>
        public IReadOnlyList<AnswerSheet> SheetsOf(string questionnaireId)
        {
            var list = new List<AnswerSheet>();
            int q = Catalog.IndexOf(questionnaireId);
            if (q < 0) return list;
            foreach (var participant in participants)
            {
                var sheet = sheetsByParticipant[participant][q];
                if (sheet != null) list.Add(sheet);
            }
            return list;
        }

        /// <summary>One participant's sheet for one questionnaire, or null if they gave it no answer.</summary>
        public AnswerSheet Find(string participant, string questionnaireId)
        {
            AnswerSheet[] sheets = null;
            int q = Catalog.IndexOf(questionnaireId);
            if (q < 0 || participant == null || !sheetsByParticipant.TryGetValue(participant, out sheets)) return null;
            return sheets[q];
        }
    }
}
