using System;
using Kosmos.PseudoHaptic.Evaluation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests.Evaluation
{
    /// <summary>The answers at one comparison level: their proportion, what a level refuses, how answers are grouped.</summary>
    public class StimulusLevelTests
    {
        [Test]
        public void TheProportionIsHeavierOverTrialsAndZeroWithoutTrials()
        {
            Assert.That(new StimulusLevel(0.6, 4, 3).Proportion, Is.EqualTo(0.75));
            Assert.That(new StimulusLevel(0.6, 0, 0).Proportion, Is.EqualTo(0));
        }

        [TestCase(double.NaN)]
        [TestCase(double.PositiveInfinity)]
        [TestCase(double.NegativeInfinity)]
        public void ANonFiniteLevelIsRefused(double level)
        {
            var e = Assert.Throws<ArgumentException>(() => new StimulusLevel(level, 2, 1));
            Assert.That(e.ParamName, Is.EqualTo("level"));
            Assert.That(e.Message, Does.StartWith("level must be finite"));
        }

        [TestCase(-1, 0)]
        [TestCase(2, -1)]
        [TestCase(2, 3)]
        public void CountsOutsideZeroToTrialsAreRefused(int trials, int heavier)
        {
            var e = Assert.Throws<ArgumentOutOfRangeException>(() => new StimulusLevel(0.5, trials, heavier));
            Assert.That(e.ParamName, Is.EqualTo("heavier"));
            Assert.That(e.Message, Does.StartWith("need 0 ≤ heavier ≤ trials"));
        }

        [Test]
        public void GroupingRefusesMissingListsListsOfTwoLengthsAndAnswersOtherThanZeroOrOne()
        {
            Assert.That(() => StimulusLevel.Group(null, new[] { 1 }), Throws.ArgumentNullException.With.Property("ParamName").EqualTo("levels"));
            Assert.That(() => StimulusLevel.Group(new[] { 0.5 }, null), Throws.ArgumentNullException.With.Property("ParamName").EqualTo("responses"));
            Assert.That(() => StimulusLevel.Group(new[] { 0.5, 0.6 }, new[] { 1 }),
                Throws.ArgumentException.With.Message.StartsWith("levels and responses differ in length"));
            var e = Assert.Throws<ArgumentException>(() => StimulusLevel.Group(new[] { 0.5, 0.6 }, new[] { 1, 2 }));
            Assert.That(e.ParamName, Is.EqualTo("responses"));
            Assert.That(e.Message, Does.StartWith("responses must be 0 or 1"));
        }

        // −0 and 0 are one level, written 0 whichever came first.
        [Test]
        public void GroupingMakesMinusZeroAndZeroOneLevelZero()
        {
            var levels = StimulusLevel.Group(new[] { -0.0, 0.0, 0.1 }, new[] { 1, 0, 1 });
            Assert.That(levels.Length, Is.EqualTo(2));
            Assert.That(levels[0].Trials, Is.EqualTo(2));
            Assert.That(levels[0].Heavier, Is.EqualTo(1));
            Assert.That(1 / levels[0].Level, Is.EqualTo(double.PositiveInfinity), "+0, not −0");
        }

        [Test]
        public void AnswersHeavierAtOrBelowEveryLighterOneAreAPerfectSeparationEvenWhereTheyMeet()
        {
            // "Heavier" at 0.4 and 0.5, "not heavier" at 0.5 and 0.6: the answers meet at one level, and the likelihood
            // still has no finite maximum (a decreasing step there).
            var fit = PsychometricFit.Fit(new[] { new StimulusLevel(0.4, 2, 2), new StimulusLevel(0.5, 2, 1), new StimulusLevel(0.6, 2, 0) });
            Assert.That(fit.Estimable, Is.False);
            Assert.That(fit.Reason, Is.EqualTo("perfect separation: every 'heavier' answer lies at or below every 'not heavier' one"));
        }
    }
}
