using System.Collections.Generic;

namespace Kosmos.PseudoHaptic.Evaluation
{
    /// <summary>
    /// One participant's answers to one questionnaire, item by item, as given; unanswered items stay empty.
    /// Filled through <see cref="ResponseSet"/>, which rejects what does not fit before it gets here.
    /// </summary>
    public sealed class AnswerSheet
    {
        readonly int?[] answers; // by item position in Questionnaire.Items

        public string Participant { get; }
        public Questionnaire Questionnaire { get; }
        public int AnsweredCount { get; private set; }
        public bool IsComplete => AnsweredCount == answers.Length;

        internal AnswerSheet(string participant, Questionnaire questionnaire)
        {
            Participant = participant;
            Questionnaire = questionnaire;
            answers = new int?[questionnaire.ItemCount];
        }

        /// <summary>The answer to the item at this position (0-based, definition order), as given; null if unanswered.</summary>
        public int? AnswerAt(int position) => answers[position];

        /// <summary>The answer at this position after reverse coding; null if unanswered.</summary>
        public int? RecodedAt(int position)
        {
            int? raw = answers[position];
            if (!raw.HasValue) return null;
            var item = Questionnaire.Items[position];
            return Questionnaire.Recode(item.Number, raw.Value);
        }

        /// <summary>Numbers of the items not answered, in definition order.</summary>
        public IReadOnlyList<int> MissingItems()
        {
            var missing = new List<int>();
            for (int i = 0; i < answers.Length; i++)
                if (!answers[i].HasValue) missing.Add(Questionnaire.Items[i].Number);
            return missing;
        }

        /// <summary>Position of the answer to item <paramref name="number"/> if it is already answered, else −1.</summary>
        internal int AnsweredPosition(int number)
        {
            int position = PositionOf(number);
            return position >= 0 && answers[position].HasValue ? position : -1;
        }

        internal void Set(int number, int response)
        {
            int position = PositionOf(number);
            if (!answers[position].HasValue) AnsweredCount++;
            answers[position] = response;
        }

        int PositionOf(int number)
        {
            var items = Questionnaire.Items;
            for (int i = 0; i < items.Count; i++)
                if (items[i].Number == number) return i;
            return -1;
        }
    }
}
