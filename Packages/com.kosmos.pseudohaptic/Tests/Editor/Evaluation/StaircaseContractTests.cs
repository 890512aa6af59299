using System;
using Kosmos.PseudoHaptic.Evaluation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests.Evaluation
{
    /// <summary>
    /// <see cref="Staircase"/>'s contract: every refused setting (parameter, value, message) and its accepted
    /// boundary, the target probability from its formula, a trajectory worked by hand (levels, steps,
    /// reversals, threshold), the clamps and the refused answers.
    /// </summary>
    public class StaircaseContractTests
    {
        // Binary-exact levels and steps, so the trajectory worked by hand is exact.
        static Staircase Make(int down = 2, double step = 0.5, int stop = 3, int last = 2, int halving = 2, double minStep = 0,
            int maxTrials = 200, double start = 1.0, double minLevel = double.NegativeInfinity, double maxLevel = double.PositiveInfinity)
            => new Staircase("P1", "on", 1.0, start, step, down, stop, last, 7, halving, minStep, maxTrials, minLevel, maxLevel);

        static void Refused(TestDelegate make, string param, object actual, string message)
        {
            var e = Assert.Throws<ArgumentOutOfRangeException>(make);
            Assert.That(e.ParamName, Is.EqualTo(param));
            Assert.That(e.ActualValue, Is.EqualTo(actual));
            Assert.That(e.Message, Does.StartWith(message));
        }

        [TestCase(1)]
        [TestCase(4)]
        [TestCase(0)]
        public void DownOtherThanTwoOrThreeIsRefused(int down)
            => Refused(() => Make(down: down), "down", down, "Down must be 2 (1-up-2-down) or 3 (1-up-3-down)");

        [TestCase(0.0)]
        [TestCase(-0.5)]
        [TestCase(double.NaN)]
        [TestCase(double.PositiveInfinity)]
        public void AStepThatIsNotPositiveAndFiniteIsRefused(double step)
            => Refused(() => Make(step: step), "step", step, "Step must be positive and finite");

        [TestCase(double.NaN)]
        [TestCase(double.PositiveInfinity)]
        [TestCase(double.NegativeInfinity)]
        public void AStartThatIsNotFiniteIsRefused(double start)
            => Refused(() => Make(start: start), "start", start, "Start must be finite");

        [Test]
        public void CountsBelowTheirMinimumAreRefused()
        {
            Refused(() => Make(stop: 0, last: 0), "stopAfterReversals", 0, "StopAfterReversals must be ≥ 1");
            Refused(() => Make(stop: 3, last: 0), "lastReversals", 0, "LastReversals must be in 1 … StopAfterReversals");
            Refused(() => Make(stop: 3, last: 4), "lastReversals", 4, "LastReversals must be in 1 … StopAfterReversals");
            Refused(() => Make(halving: -1), "halvingReversals", -1, "HalvingReversals must be ≥ 0");
            Refused(() => Make(minStep: -1e-9), "minStep", -1e-9, "MinStep must be ≥ 0");
            Refused(() => Make(minStep: double.NaN), "minStep", double.NaN, "MinStep must be ≥ 0");
            Refused(() => Make(maxTrials: 0), "maxTrials", 0, "MaxTrials must be ≥ 1");
        }

        [Test]
        public void TheBoundariesAreAccepted()
        {
            Assert.DoesNotThrow(() => Make(down: 3));
            Assert.DoesNotThrow(() => Make(step: double.Epsilon));
            Assert.DoesNotThrow(() => Make(start: -5));
            var s = Make(stop: 1, last: 1, halving: 0, minStep: 0, maxTrials: 1);
            Assert.That(s.StopAfterReversals, Is.EqualTo(1));
            Assert.That(s.LastReversals, Is.EqualTo(1));
            Assert.That(s.HalvingReversals, Is.EqualTo(0));
            Assert.That(s.MaxTrials, Is.EqualTo(1));
            Assert.DoesNotThrow(() => Make(stop: 3, last: 3));
        }

        [Test]
        public void SettingsAreKept()
        {
            var s = new Staircase(null, null, 0.5, 0.7, 0.08, 3, 8, 6, 5, 1, 0.01, 50, 0.1, 2);
            Assert.That(s.Participant, Is.EqualTo(""));
            Assert.That(s.Condition, Is.EqualTo(""));
            Assert.That(s.Standard, Is.EqualTo(0.5));
            Assert.That(s.Start, Is.EqualTo(0.7));
            Assert.That(s.Level, Is.EqualTo(0.7));
            Assert.That(s.InitialStep, Is.EqualTo(0.08));
            Assert.That(s.Step, Is.EqualTo(0.08));
            Assert.That(s.Down, Is.EqualTo(3));
            Assert.That(s.StopAfterReversals, Is.EqualTo(8));
            Assert.That(s.LastReversals, Is.EqualTo(6));
            Assert.That(s.HalvingReversals, Is.EqualTo(1));
            Assert.That(s.MinStep, Is.EqualTo(0.01));
            Assert.That(s.MaxTrials, Is.EqualTo(50));
            Assert.That(s.MinLevel, Is.EqualTo(0.1));
            Assert.That(s.MaxLevel, Is.EqualTo(2));
            Assert.That(s.Finished, Is.False);
            Assert.That(s.Threshold, Is.NaN);
            var t = s.Next();
            Assert.That(t.Index, Is.EqualTo(1));
            Assert.That(t.Participant, Is.EqualTo(""));
            Assert.That(t.Standard, Is.EqualTo(0.5));
            Assert.That(t.Comparison, Is.EqualTo(0.7));
            Assert.That(t.Catch, Is.False);
            Assert.That(s.Next(), Is.SameAs(t), "the same trial until it is answered");
        }

        [Test]
        public void TheTargetIsTheDownthRootOfOneHalf()
        {
            Assert.That(Make(down: 2).TargetProbability, Is.EqualTo(Math.Sqrt(0.5)).Within(1e-15));
            Assert.That(Make(down: 3).TargetProbability, Is.EqualTo(Math.Cbrt(0.5)).Within(1e-15));
            Assert.That(Math.Pow(Make(down: 3).TargetProbability, 3), Is.EqualTo(0.5).Within(1e-15));
        }

        [Test]
        public void OneUpTwoDownWorkedByHand()
        {
            var s = Make(down: 2, step: 0.5, stop: 3, last: 2, halving: 2);
            s.Record(1);
            Assert.That(s.Level, Is.EqualTo(1.0), "one 'heavier' is not enough to step down");
            s.Record(1);
            Assert.That(s.Level, Is.EqualTo(0.5), "two 'heavier': down one step");
            Assert.That(s.ReversalLevels, Is.Empty, "the first move is no reversal");
            s.Record(0);
            Assert.That(s.ReversalLevels, Is.EqualTo(new[] { 0.5 }));
            Assert.That(s.Step, Is.EqualTo(0.25), "halved at the first reversal");
            Assert.That(s.Level, Is.EqualTo(0.75));
            Assert.That(s.Threshold, Is.NaN, "fewer reversals than LastReversals");
            s.Record(0);
            Assert.That(s.Level, Is.EqualTo(1.0), "up again: no reversal");
            Assert.That(s.ReversalLevels.Count, Is.EqualTo(1));
            s.Record(1);
            s.Record(1);
            Assert.That(s.ReversalLevels, Is.EqualTo(new[] { 0.5, 1.0 }));
            Assert.That(s.Step, Is.EqualTo(0.125), "halved at the second reversal");
            Assert.That(s.Level, Is.EqualTo(0.875));
            Assert.That(s.Threshold, Is.EqualTo(0.75));
            Assert.That(s.Finished, Is.False);
            s.Record(1);
            s.Record(0);
            Assert.That(s.ReversalLevels, Is.EqualTo(new[] { 0.5, 1.0, 0.875 }), "a 'not heavier' resets the run of 'heavier'");
            Assert.That(s.Step, Is.EqualTo(0.125), "not halved after HalvingReversals");
            Assert.That(s.Level, Is.EqualTo(1.0));
            Assert.That(s.Threshold, Is.EqualTo((1.0 + 0.875) / 2), "the last two reversals");
            Assert.That(s.Finished, Is.True);
            Assert.That(s.Next(), Is.Null);
            Assert.That(s.Trials.Count, Is.EqualTo(8));
            for (int i = 0; i < 8; i++) Assert.That(s.Trials[i].Index, Is.EqualTo(i + 1));
            Assert.That(s.Trials[1].Comparison, Is.EqualTo(1.0));
            Assert.That(s.Trials[2].Comparison, Is.EqualTo(0.5));
            Assert.That(s.Trials[2].Response, Is.EqualTo(0));
            var e = Assert.Throws<InvalidOperationException>(() => s.Record(1));
            Assert.That(e.Message, Is.EqualTo("the staircase is finished"));
        }

        [Test]
        public void OneUpThreeDownNeedsThreeHeavier()
        {
            var s = Make(down: 3, step: 0.5, stop: 3, last: 1);
            s.Record(1);
            s.Record(1);
            Assert.That(s.Level, Is.EqualTo(1.0));
            s.Record(1);
            Assert.That(s.Level, Is.EqualTo(0.5));
            s.Record(1);
            s.Record(1);
            s.Record(0);
            Assert.That(s.ReversalLevels, Is.EqualTo(new[] { 0.5 }), "two 'heavier' then one 'not': up, a reversal");
            Assert.That(s.Level, Is.EqualTo(0.75));
            Assert.That(s.Threshold, Is.EqualTo(0.5), "LastReversals = 1: the last reversal's level");
        }

        [Test]
        public void TheStepNeverFallsBelowMinStep()
        {
            var s = Make(step: 0.5, stop: 5, last: 1, halving: 4, minStep: 0.2);
            s.Record(1); s.Record(1); // down to 0.5
            s.Record(0);              // reversal 1: step max(0.2, 0.25)
            Assert.That(s.Step, Is.EqualTo(0.25));
            s.Record(1); s.Record(1); // reversal 2: step max(0.2, 0.125)
            Assert.That(s.Step, Is.EqualTo(0.2));
            Assert.That(s.InitialStep, Is.EqualTo(0.5));
        }

        [Test]
        public void HalvingReversalsZeroKeepsTheStep()
        {
            var s = Make(step: 0.5, stop: 3, last: 1, halving: 0);
            s.Record(1); s.Record(1); s.Record(0);
            Assert.That(s.ReversalLevels.Count, Is.EqualTo(1));
            Assert.That(s.Step, Is.EqualTo(0.5));
            Assert.That(s.Level, Is.EqualTo(1.0));
        }

        [Test]
        public void TheLevelStaysWithinItsClamps()
        {
            var low = Make(step: 0.5, start: 0.25, minLevel: 0.125, stop: 10, last: 1);
            low.Record(1); low.Record(1);
            Assert.That(low.Level, Is.EqualTo(0.125), "0.25 − 0.5 clamped up to MinLevel");
            var high = Make(step: 0.5, start: 1.75, maxLevel: 2.0, stop: 10, last: 1);
            high.Record(0);
            Assert.That(high.Level, Is.EqualTo(2.0), "1.75 + 0.5 clamped down to MaxLevel");
            high.Record(0);
            Assert.That(high.Level, Is.EqualTo(2.0));
        }

        [Test]
        public void MaxTrialsEndsTheRunOnceTheLastTrialIsAnswered()
        {
            var s = Make(maxTrials: 2, stop: 10, last: 1);
            s.Record(0);
            Assert.That(s.Finished, Is.False);
            Assert.That(s.Next(), Is.Not.Null);
            Assert.That(s.Finished, Is.False, "a pending trial is still to be answered");
            s.Record(0);
            Assert.That(s.Finished, Is.True);
            Assert.That(s.Next(), Is.Null);
            Assert.That(s.Trials.Count, Is.EqualTo(2));
        }

        [TestCase(-1)]
        [TestCase(2)]
        public void AnAnswerOtherThanZeroOrOneIsRefused(int response)
        {
            var s = Make();
            Refused(() => s.Record(response), "response", response, "response must be 0 or 1");
            Assert.That(s.Trials, Is.Empty, "nothing recorded");
            Assert.That(s.Level, Is.EqualTo(1.0));
        }

        [Test]
        public void TheSidesAreDrawnFromTheSeedOnePerTrial()
        {
            var s = Make(stop: 100, last: 1);
            var draws = new SeededRandom(7);
            int comparisonFirst = 0;
            for (int i = 0; i < 40; i++)
            {
                var t = s.Next();
                Assert.That(t.ComparisonFirst, Is.EqualTo(draws.NextInt(2) == 1), "trial " + (i + 1));
                if (t.ComparisonFirst) comparisonFirst++;
                s.Record(i % 2);
            }
            Assert.That(comparisonFirst, Is.InRange(10, 30), "both orders occur");
        }

        [Test]
        public void TheSameSeedGivesTheSameSides()
        {
            var a = Make();
            var b = Make();
            for (int i = 0; i < 6; i++)
            {
                Assert.That(a.Next().ComparisonFirst, Is.EqualTo(b.Next().ComparisonFirst));
                a.Record(i % 3 == 0 ? 0 : 1);
                b.Record(i % 3 == 0 ? 0 : 1);
            }
        }
    }
}
