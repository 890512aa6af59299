namespace Kosmos.PseudoHaptic.Evaluation
{
    /// <summary>
    /// One question of a questionnaire (paper section 5): its number within the part (1-based), its wording,
    /// and whether it is negatively worded and so scored reversed (Part 1 Q4, Q7; Part 2 Q3, Q5, Q8, Q9).
    /// </summary>
    public sealed class QuestionnaireItem
    {
        public int Number { get; }
        public string Text { get; }
        public bool Reverse { get; }

        public QuestionnaireItem(int number, string text, bool reverse)
        {
            Number = number;
            Text = text ?? "";
            Reverse = reverse;
        }

        public override string ToString() => Reverse ? "Q" + Number + " (reversed)" : "Q" + Number;
    }
}
