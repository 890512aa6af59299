using System;
using System.Collections.Generic;

namespace Kosmos.PseudoHaptic.Evaluation
{
    /// <summary>
    /// One participant's score on one questionnaire: the mean of their reverse-coded answers (one cell of
    /// the paper's Tables 1–3), or no score when the part is incomplete. One row of the scores CSV.
    /// </summary>
    public sealed class ParticipantScore
    {
        static readonly int[] None = new int[0];

        public string Participant { get; }
        public string QuestionnaireId { get; }
        /// <summary>The study condition the answers were given in ("" when the study has none).</summary>
        public string Condition { get; }
        /// <summary>The mean, or null when the part is incomplete: an incomplete part is never scored.</summary>
        public double? Score { get; }
        public bool IsComplete => Score.HasValue;
        /// <summary>Items left unanswered, when known (empty when read back from a scores file).</summary>
        public IReadOnlyList<int> MissingItems { get; }

        public ParticipantScore(string participant, string questionnaireId, double? score, IReadOnlyList<int> missingItems = null)
            : this(participant, "", questionnaireId, score, missingItems)
        {
        }

        public ParticipantScore(string participant, string condition, string questionnaireId, double? score, IReadOnlyList<int> missingItems = null)
        {
            if (score.HasValue && (double.IsNaN(score.Value) || double.IsInfinity(score.Value)))
                throw new ArgumentException("score must be finite", nameof(score));
            Participant = participant;
            QuestionnaireId = questionnaireId;
            Condition = condition ?? "";
            Score = score;
            MissingItems = missingItems ?? None;
        }

        public override string ToString() => Participant + "," + QuestionnaireId + "," + (Score.HasValue ? Score.Value.ToString("R", System.Globalization.CultureInfo.InvariantCulture) : "incomplete");
    }
}
