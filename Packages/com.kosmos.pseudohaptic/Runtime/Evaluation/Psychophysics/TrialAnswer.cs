using System;

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
}
