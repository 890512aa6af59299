using Kosmos.PseudoHaptic.Evaluation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests.Evaluation
{
    /// <summary>
    /// What a streamed answers file may make a reader keep (README, "Bounded memory": at most so many participants, or
    /// participant × condition pairs, and so many characters of their and the conditions' names; the row that would
    /// pass either is refused, saying which). Rows of participants and pairs already counted always pass.
    /// </summary>
    public class ParticipantLimitTests
    {
        [Test]
        public void ExactlyTheMostParticipantsAreKeptAndTheNextIsRefusedNamingTheLimit()
        {
            var limit = new ParticipantLimit(3, long.MaxValue);
            Assert.That(limit.Admit("P1"), Is.Null);
            Assert.That(limit.Admit("P2"), Is.Null);
            Assert.That(limit.Admit("P1"), Is.Null, "a participant already kept");
            Assert.That(limit.Admit("P3"), Is.Null, "the third of three");
            string why = limit.Admit("P4");
            Assert.That(why, Does.Contain("more than 3 participants"));
            Assert.That(why, Does.Contain("the most one file may hold"));
            Assert.That(why, Does.Not.Contain("condition"), "this file has no conditions");
            Assert.That(limit.Participants, Is.EqualTo(3), "the refused one is not kept");
            Assert.That(limit.Pairs, Is.EqualTo(3), "without conditions, the participants");
            Assert.That(limit.Admit("P4"), Is.Not.Null, "still refused");
            Assert.That(limit.Admit("P2"), Is.Null, "the rows of participants kept still pass");
            Assert.That(limit.Admit("P3"), Is.Null);
        }

        [Test]
        public void WithConditionsEachParticipantConditionPairCountsAndTheNextIsRefusedNamingPairs()
        {
            // One participant answering after three experiences keeps three sets of sheets.
            var limit = new ParticipantLimit(3, long.MaxValue);
            Assert.That(limit.Admit("P1", "visual"), Is.Null);
            Assert.That(limit.Admit("P1", "pseudo-haptic"), Is.Null);
            Assert.That(limit.Admit("P1", "visual"), Is.Null, "a pair already kept");
            Assert.That(limit.Admit("P1", "none"), Is.Null, "the third pair of three");
            Assert.That(limit.Participants, Is.EqualTo(1));
            Assert.That(limit.Pairs, Is.EqualTo(3));
            string why = limit.Admit("P1", "both");
            Assert.That(why, Does.Contain("more than 3 participant × condition pairs"));
            Assert.That(limit.Admit("P2", "visual"), Does.Contain("more than 3 participant × condition pairs"), "a new participant in a known condition is a new pair");
            Assert.That(limit.Pairs, Is.EqualTo(3));
            Assert.That(limit.Admit("P1", "pseudo-haptic"), Is.Null, "the rows of pairs kept still pass");
            Assert.That(limit.Admit("P1", "none"), Is.Null);
        }

        [Test]
        public void APairOfKnownParticipantAndKnownConditionIsStillANewPair()
        {
            var limit = new ParticipantLimit(3, long.MaxValue);
            Assert.That(limit.Admit("P1", "visual"), Is.Null);
            Assert.That(limit.Admit("P2", "haptic"), Is.Null);
            Assert.That(limit.Admit("P1", "haptic"), Is.Null);
            Assert.That(limit.Pairs, Is.EqualTo(3));
            Assert.That(limit.Participants, Is.EqualTo(2));
            Assert.That(limit.Admit("P2", "visual"), Does.Contain("more than 3 participant × condition pairs"));
        }

        [Test]
        public void PairsAreToldApartEvenWhenTheNamesRunTogetherAlike()
        {
            // "P1" + "0a" and "P10" + "a" are two participants in two conditions: two pairs, not one.
            var limit = new ParticipantLimit(4, long.MaxValue);
            Assert.That(limit.Admit("P1", "0a"), Is.Null);
            Assert.That(limit.Admit("P10", "a"), Is.Null);
            Assert.That(limit.Admit("P1", "b"), Is.Null);
            Assert.That(limit.Admit("P10", "b"), Is.Null);
            Assert.That(limit.Pairs, Is.EqualTo(4));
            Assert.That(limit.Admit("P1", "c"), Does.Contain("more than 4 participant × condition pairs"));
        }

        [Test]
        public void ABlankConditionInAFileWithConditionsIsAPairOfItsOwn()
        {
            // A file with a condition column that one row leaves blank keeps a set of sheets for P1 in condition "" besides
            // P1 in "visual" (ResponsesCsv.ParseByCondition): two pairs, so a limit of one refuses the second.
            var limit = new ParticipantLimit(1, long.MaxValue);
            Assert.That(limit.Admit("P1", "visual"), Is.Null);
            Assert.That(limit.Admit("P1", ""), Does.Contain("more than 1 participant × condition pairs"));
            limit = new ParticipantLimit(2, long.MaxValue);
            Assert.That(limit.Admit("P1", ""), Is.Null);
            Assert.That(limit.Admit("P1", "visual"), Is.Null);
            Assert.That(limit.Pairs, Is.EqualTo(2));
            Assert.That(limit.Admit("P2", ""), Does.Contain("more than 2 participant × condition pairs"));
        }

        [Test]
        public void AFileWhoseFirstConditionComesAfterRowsWithoutOneIsRefusedNamingPairs()
        {
            // Rows that leave the condition blank, then the file's first named condition: the refusal counts pairs, though
            // no condition was kept yet (P1 in "visual" is a set of sheets besides P1 in "").
            var limit = new ParticipantLimit(1, long.MaxValue);
            Assert.That(limit.Admit("P1", ""), Is.Null);
            Assert.That(limit.Admit("P1", "visual"), Does.Contain("more than 1 participant × condition pairs"));
        }

        [Test]
        public void PairsAreToldApartWhateverCharactersTheNamesHold()
        {
            // Any character may be in an id, the control characters included: "a\u0001b" in "c", "a" in "x" and "a" in
            // "b\u0001c" are three pairs (three sets of sheets), so a limit of two refuses the third.
            var limit = new ParticipantLimit(2, long.MaxValue);
            Assert.That(limit.Admit("a\u0001b", "c"), Is.Null);
            Assert.That(limit.Admit("a", "x"), Is.Null);
            Assert.That(limit.Pairs, Is.EqualTo(2));
            Assert.That(limit.Admit("a", "b\u0001c"), Does.Contain("more than 2 participant × condition pairs"));
        }

        [Test]
        public void NamesCountOnceEachUpToExactlyTheLimitAndTheRowPassingItIsRefusedNamingIt()
        {
            // P1 (2) + visual (6) + haptic (6) + P2 (2) = 16 characters however many rows repeat them.
            var limit = new ParticipantLimit(100, 16);
            Assert.That(limit.Admit("P1", "visual"), Is.Null);
            Assert.That(limit.Admit("P1", "haptic"), Is.Null, "P1 is counted once");
            Assert.That(limit.Admit("P2", "visual"), Is.Null, "visual is counted once: 16 of 16");
            Assert.That(limit.Admit("P2", "haptic"), Is.Null, "nothing new to count");
            Assert.That(limit.Admit("P1", "visual"), Is.Null);
            Assert.That(limit.Admit("P3", "visual"), Is.EqualTo("the participants' and conditions' names add up to more than 16 characters"));
            Assert.That(limit.Admit("P1", "x"), Is.EqualTo("the participants' and conditions' names add up to more than 16 characters"), "a new condition's name counts");
            Assert.That(limit.Participants, Is.EqualTo(2));
            Assert.That(limit.Pairs, Is.EqualTo(4));
        }

        [Test]
        public void WithoutConditionsOnlyTheParticipantsNamesCount()
        {
            var limit = new ParticipantLimit(100, 5);
            Assert.That(limit.Admit("P1"), Is.Null);
            Assert.That(limit.Admit("P1"), Is.Null);
            Assert.That(limit.Admit("P22"), Is.Null, "2 + 3 = 5 of 5");
            Assert.That(limit.Admit("P3"), Does.Contain("more than 5 characters"));
            Assert.That(limit.Admit("P22"), Is.Null);
            Assert.That(limit.Participants, Is.EqualTo(2));
        }

        [Test]
        public void NoneKeepsEverything()
        {
            var limit = ParticipantLimit.None;
            for (int i = 0; i < 1000; i++) Assert.That(limit.Admit("P" + i, i % 2 == 0 ? "visual" : ""), Is.Null);
            Assert.That(limit.Participants, Is.EqualTo(1000));
        }
    }
}
