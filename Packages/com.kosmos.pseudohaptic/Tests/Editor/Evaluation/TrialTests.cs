using System;
using Kosmos.PseudoHaptic.Evaluation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests.Evaluation
{
    /// <summary>A 2AFC trial and a trials file's answer: masses must be finite; no participant or condition is the empty one.</summary>
    public class TrialTests
    {
        [TestCase(double.NaN)]
        [TestCase(double.PositiveInfinity)]
        [TestCase(double.NegativeInfinity)]
        public void ANonFiniteStandardOrComparisonIsRefusedNamingIt(double bad)
        {
            var standard = Assert.Throws<ArgumentException>(() => new Trial(1, "P1", "on", bad, 0.6, true, false));
            Assert.That(standard.ParamName, Is.EqualTo("standard"));
            Assert.That(standard.Message, Does.StartWith("standard must be finite"));
            var comparison = Assert.Throws<ArgumentException>(() => new Trial(1, "P1", "on", 0.5, bad, true, false));
            Assert.That(comparison.ParamName, Is.EqualTo("comparison"));
            Assert.That(comparison.Message, Does.StartWith("comparison must be finite"));
        }

        [Test]
        public void NoParticipantOrConditionIsTheEmptyOne()
        {
            var t = new Trial(1, null, null, 0.5, 0.6, true, false);
            Assert.That(t.Participant, Is.EqualTo(""));
            Assert.That(t.Condition, Is.EqualTo(""));
            Assert.That(new Trial(1, "P1", "on", 0.5, 0.6, true, false).Condition, Is.EqualTo("on"));
            Assert.That(new TrialAnswer("P1", null, 0.5, 0.6, 1, 2).Condition, Is.EqualTo(""));
            Assert.That(new TrialAnswer("P1", "on", 0.5, 0.6, 1, 2).Condition, Is.EqualTo("on"));
        }
    }
}
