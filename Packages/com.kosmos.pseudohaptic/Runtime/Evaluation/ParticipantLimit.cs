using System;
using System.Collections.Generic;

namespace Kosmos.PseudoHaptic.Evaluation
{
    /// <summary>
    /// What a streamed answers file may make a reader keep: it keeps one sheet per participant, questionnaire and
    /// condition, however many rows the file has, so its memory is bounded by the participants and the characters
    /// of their names, never by the rows. The row that would pass either bound is refused, naming its line.
    /// </summary>
    public sealed class ParticipantLimit
    {
        readonly HashSet<string> participants = new HashSet<string>(StringComparer.Ordinal);
        readonly HashSet<string> conditions = new HashSet<string>(StringComparer.Ordinal);
        // Keyed by both names (ordinal), so that no two pairs can meet whatever characters the names hold.
        readonly HashSet<(string Participant, string Condition)> pairs = new HashSet<(string Participant, string Condition)>();
        long characters;

        public ParticipantLimit(int maxParticipants, long maxCharacters)
        {
            MaxParticipants = maxParticipants;
            MaxCharacters = maxCharacters;
        }

        /// <summary>No bound.</summary>
        public static ParticipantLimit None => new ParticipantLimit(int.MaxValue, long.MaxValue);

        public int MaxParticipants { get; }
        public long MaxCharacters { get; }

        /// <summary>Distinct participants seen so far.</summary>
        public int Participants => participants.Count;

        /// <summary>Distinct participant × condition pairs seen so far (each has its own sheets, the empty condition's included:
        /// a row of a file with conditions that leaves its condition blank); without conditions, the participants.</summary>
        public int Pairs => pairs.Count;

        /// <summary>Counts a participant and a condition (their names' characters count once each); returns why the row is refused, or null.</summary>
        public string Admit(string participant, string condition = "")
        {
            bool newParticipant = !participants.Contains(participant), newCondition = condition.Length > 0 && !conditions.Contains(condition);
            var pair = (participant, condition);
            bool newPair = !pairs.Contains(pair);
            if (!newParticipant && !newCondition && !newPair) return null;
            if (newPair && Pairs >= MaxParticipants)
                return "more than " + MaxParticipants + (condition.Length > 0 || conditions.Count > 0 ? " participant × condition pairs" : " participants")
                    + " (the most one file may hold: a reader keeps every participant's answers, not the rows)";
            long add = (newParticipant ? participant.Length : 0) + (newCondition ? condition.Length : 0);
            if (characters + add > MaxCharacters)
                return "the participants' and conditions' names add up to more than " + MaxCharacters + " characters";
            if (newParticipant) participants.Add(participant);
            if (newCondition) conditions.Add(condition);
            if (newPair) pairs.Add(pair);
            characters += add;
            return null;
        }
    }
}
