using System;
using System.Collections.Generic;

namespace Kosmos.PseudoHaptic.Evaluation
{
    /// <summary>
    /// The paper's scoring (section 6): each answer counted from 1 (strongly disagree / not at all) to the
    /// scale's top, negatively worded items reversed (min + max − x, i.e. 6 − x on 5 points), and the
    /// participant's score on a part is the mean over its items. A part with any item unanswered gets no
    /// score and is reported incomplete, never averaged over the items that happen to be there.
    /// </summary>
    public static class ScoreCalculator
    {
        /// <summary>The score of one sheet.</summary>
        public static ParticipantScore Score(AnswerSheet sheet)
        {
            if (sheet == null) throw new ArgumentNullException(nameof(sheet));
            string id = sheet.Questionnaire.Id;
            if (!sheet.IsComplete) return new ParticipantScore(sheet.Participant, id, null, sheet.MissingItems());

            // Integer sum, one division: 46/10 is the double nearest 4.6, so it prints as "4.6".
            long sum = 0;
            int n = sheet.Questionnaire.ItemCount;
            for (int i = 0; i < n; i++) sum += sheet.RecodedAt(i).Value;
            return new ParticipantScore(sheet.Participant, id, (double)sum / n);
        }

        /// <summary>
        /// One score per participant × questionnaire answered: participants in <see cref="ParticipantOrder"/>
        /// (P2 before P10), each one's parts in catalog order.
        /// </summary>
        public static IReadOnlyList<ParticipantScore> ScoreAll(ResponseSet responses)
        {
            if (responses == null) throw new ArgumentNullException(nameof(responses));
            var scores = new List<ParticipantScore>();
            foreach (var sheet in responses.Sheets()) scores.Add(Score(sheet));
            return ParticipantOrder.Sort(scores, s => s.Participant);
        }

        /// <summary>
        /// Scores answers given in several conditions (issue 11): participants in <see cref="ParticipantOrder"/>,
        /// each one's conditions in the order given, each condition's parts in catalog order; every score
        /// carries its condition.
        /// </summary>
        public static IReadOnlyList<ParticipantScore> ScoreAll(IReadOnlyList<KeyValuePair<string, ResponseSet>> byCondition)
        {
            if (byCondition == null) throw new ArgumentNullException(nameof(byCondition));
            var scores = new List<ParticipantScore>();
            foreach (var pair in byCondition)
                foreach (var sheet in pair.Value.Sheets())
                {
                    var s = Score(sheet);
                    scores.Add(new ParticipantScore(s.Participant, pair.Key, s.QuestionnaireId, s.Score, s.MissingItems));
                }
            return ParticipantOrder.Sort(scores, s => s.Participant);
        }

        /// <summary>Scores plain answers; throws <see cref="ArgumentException"/> on one that does not fit.</summary>
        public static IReadOnlyList<ParticipantScore> ScoreAll(QuestionnaireCatalog catalog, IEnumerable<Response> responses)
        {
            if (responses == null) throw new ArgumentNullException(nameof(responses));
            var set = new ResponseSet(catalog);
            foreach (var r in responses) set.Add(r);
            return ScoreAll(set);
        }
    }
}
