using System;

namespace Kosmos.PseudoHaptic.Evaluation
{
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
}
