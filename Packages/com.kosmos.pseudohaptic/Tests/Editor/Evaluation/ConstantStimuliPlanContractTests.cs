using System;
using System.Collections.Generic;
using System.Linq;
using Kosmos.PseudoHaptic.Evaluation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests.Evaluation
{
    /// <summary>
    /// <see cref="ConstantStimuliPlan"/>'s contract: each refused setting with the words a study designer reads, the
    /// accepted edges, every trial's fields, and the counterbalancing within a level (exactly half the repetitions with
    /// the comparison first; with an odd count the extra one either way, drawn from the seed).
    /// </summary>
    public class ConstantStimuliPlanContractTests
    {
        static ConstantStimuliPlan Plan() => new ConstantStimuliPlan
        {
            Standard = 0.5, Levels = new[] { 0.4, 0.5, 0.6 }, Repetitions = 4, CatchLevels = new[] { 0.25, 1.0 }, CatchRepetitions = 3, Seed = 21,
        };

        static void Refused(Action<ConstantStimuliPlan> spoil, string message)
        {
            var plan = Plan();
            spoil(plan);
            var e = Assert.Throws<ArgumentException>(() => plan.Build("P1"));
            Assert.That(e.Message, Does.StartWith(message));
        }

        [Test]
        public void AStandardThatIsNotFiniteIsRefused()
        {
            Refused(p => p.Standard = double.NaN, "Standard must be finite");
            Refused(p => p.Standard = double.PositiveInfinity, "Standard must be finite");
            Refused(p => p.Standard = double.NegativeInfinity, "Standard must be finite");
        }

        [Test]
        public void NoLevelsAreRefused()
        {
            Refused(p => p.Levels = null, "Levels must not be empty");
            Refused(p => p.Levels = new double[0], "Levels must not be empty");
        }

        [Test]
        public void FewerThanOneRepetitionIsRefusedAndOneIsAPlan()
        {
            Refused(p => p.Repetitions = 0, "Repetitions must be at least 1");
            Refused(p => p.Repetitions = -2, "Repetitions must be at least 1");
            var plan = Plan();
            plan.Repetitions = 1;
            plan.CatchRepetitions = 0;
            Assert.That(plan.Build("P1").Select(t => t.Comparison).OrderBy(c => c), Is.EqualTo(new[] { 0.4, 0.5, 0.6 }));
        }

        [Test]
        public void NegativeCatchRepetitionsAreRefusedAndNoneMeanNoCatchTrials()
        {
            Refused(p => p.CatchRepetitions = -1, "CatchRepetitions must be ≥ 0");
            var plan = Plan();
            plan.CatchRepetitions = 0;
            var trials = plan.Build("P1");
            Assert.That(trials.Count, Is.EqualTo(12));
            Assert.That(trials.Any(t => t.Catch), Is.False);
            plan.CatchLevels = null;
            plan.CatchRepetitions = 2;
            Assert.That(plan.Build("P1").Count, Is.EqualTo(12), "no catch levels, no catch trials");
        }

        [Test]
        public void ALevelThatIsNotFiniteIsRefusedWhereverItIs()
        {
            Refused(p => p.Levels = new[] { 0.4, double.NaN }, "levels must be finite");
            Refused(p => p.Levels = new[] { double.PositiveInfinity }, "levels must be finite");
            Refused(p => p.CatchLevels = new[] { 0.25, double.NegativeInfinity }, "levels must be finite");
        }

        [Test]
        public void EveryTrialCarriesTheStandardItsPlaceTheNamesAndWhetherItIsACatch()
        {
            var trials = Plan().Build("P7", "with cue");
            Assert.That(trials.Count, Is.EqualTo(3 * 4 + 2 * 3));
            for (int i = 0; i < trials.Count; i++)
            {
                var t = trials[i];
                Assert.That(t.Index, Is.EqualTo(i + 1));
                Assert.That(t.Participant, Is.EqualTo("P7"));
                Assert.That(t.Condition, Is.EqualTo("with cue"));
                Assert.That(t.Standard, Is.EqualTo(0.5));
                Assert.That(t.Response, Is.EqualTo(-1), "not yet answered");
                Assert.That(t.Catch, Is.EqualTo(t.Comparison == 0.25 || t.Comparison == 1.0), "trial " + t.Index);
            }
            var counts = trials.GroupBy(t => t.Comparison).ToDictionary(g => g.Key, g => g.Count());
            Assert.That(counts, Is.EquivalentTo(new Dictionary<double, int> { { 0.4, 4 }, { 0.5, 4 }, { 0.6, 4 }, { 0.25, 3 }, { 1.0, 3 } }));
            Assert.That(Plan().Build("P7").All(t => t.Condition == ""), "no condition given, an empty one");
        }

        [Test]
        public void AnEvenCountPutsTheComparisonFirstInExactlyHalf()
        {
            for (int seed = 0; seed < 200; seed++)
            {
                var plan = Plan();
                plan.Seed = seed;
                plan.CatchRepetitions = 2;
                foreach (var level in plan.Build("P1").GroupBy(t => t.Comparison))
                    Assert.That(level.Count(t => t.ComparisonFirst), Is.EqualTo(level.Count() / 2), "seed " + seed + ", level " + level.Key);
            }
        }

        [Test]
        public void AnOddCountPutsTheExtraOneEitherWayByTheSeed()
        {
            int extraFirst = 0, levels = 0;
            for (int seed = 0; seed < 200; seed++)
            {
                var plan = Plan();
                plan.Seed = seed;
                plan.Repetitions = 5;
                foreach (var level in plan.Build("P1").GroupBy(t => t.Comparison))
                {
                    int first = level.Count(t => t.ComparisonFirst), reps = level.Count();
                    Assert.That(first, Is.EqualTo(reps / 2).Or.EqualTo(reps / 2 + 1), "seed " + seed + ", level " + level.Key);
                    extraFirst += first - reps / 2;
                    levels++;
                }
            }
            // 1,000 levels, each a fair coin: 500 ± 16 (one standard deviation); 440–560 is 3.8 of them.
            Assert.That(levels, Is.EqualTo(1000));
            Assert.That(extraFirst, Is.InRange(440, 560));
        }

        /// <summary>A study resumed after an update of the package must get the plan it began with from its seed: this plan
        /// was worked out by a separate implementation of the published generator (SeededRandomKnownAnswerTests) and of
        /// the plan's rules (each level's odd repetition drawn in turn, levels first, then catch levels, then one shuffle).</summary>
        [Test]
        public void ASeedGivesTheSamePlanInEveryVersion()
        {
            var expected = new[]
            {
                "0.6 S", "0.4 C", "0.5 C", "0.6 C", "0.25 S catch", "0.4 C", "0.6 S", "0.4 S", "0.5 S", "0.5 S", "0.6 C",
                "0.25 C catch", "0.25 C catch", "0.5 C", "1 C catch", "1 C catch", "0.4 S", "1 S catch",
            };
            Assert.That(Plan().Build("P1").Select(t => t.Comparison.ToString(System.Globalization.CultureInfo.InvariantCulture)
                + (t.ComparisonFirst ? " C" : " S") + (t.Catch ? " catch" : "")), Is.EqualTo(expected));
        }

        [Test]
        public void TheOrderIsShuffledBeyondTheLevelsOrder()
        {
            // Unshuffled, the plan would list the levels in order, catch trials last.
            int inOrder = 0;
            for (int seed = 0; seed < 50; seed++)
            {
                var plan = Plan();
                plan.Seed = seed;
                var comparisons = plan.Build("P1").Select(t => t.Comparison).ToArray();
                var built = plan.Levels.SelectMany(l => Enumerable.Repeat(l, plan.Repetitions))
                    .Concat(plan.CatchLevels.SelectMany(l => Enumerable.Repeat(l, plan.CatchRepetitions)));
                if (comparisons.SequenceEqual(built)) inOrder++;
            }
            Assert.That(inOrder, Is.EqualTo(0));
        }
    }
}
