using System.Collections.Generic;
using Kosmos.PseudoHaptic.Evaluation;

namespace Kosmos.PseudoHaptic.Tests.Evaluation
{
    /// <summary>
    /// Questionnaires built in code with the paper's shapes (so scoring tests do not depend on the JSON's
    /// wording): 10 items on 1–5 with 4 and 7 reversed; 10 with 3, 5, 8, 9 reversed; one item on 1–10.
    /// </summary>
    internal static class SampleQuestionnaires
    {
        public static Questionnaire Part(string id, int items, int min, int max, params int[] reversed)
        {
            var list = new List<QuestionnaireItem>();
            for (int n = 1; n <= items; n++) list.Add(new QuestionnaireItem(n, "Item " + n, System.Array.IndexOf(reversed, n) >= 0));
            return new Questionnaire(id, id, min, max, list);
        }

        public static QuestionnaireCatalog Paper() => new QuestionnaireCatalog(new[]
        {
            Part(QuestionnaireCatalog.WeightDetectionId, 10, 1, 5, 4, 7),
            Part(QuestionnaireCatalog.ImmersionId, 10, 1, 5, 3, 5, 8, 9),
            Part(QuestionnaireCatalog.SelfAssessmentId, 1, 1, 10),
        });

        /// <summary>Adds the answers[i] to item i + 1.</summary>
        public static void Answer(ResponseSet set, string participant, string questionnaireId, params int[] answers)
        {
            for (int i = 0; i < answers.Length; i++) set.Add(new Response(participant, questionnaireId, i + 1, answers[i]));
        }
    }
}
