using System;
using Kosmos.PseudoHaptic.Simulation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>
    /// Issue 31's cue strength s in the core: the gain is G^s, s = 1 is today's bit for bit, the standard weight stays rigid,
    /// a heavier object's gain stays in (0, 1), the order of the masses is kept, every gain within the cap; validated when set.
    /// </summary>
    public class CueStrengthTests
    {
        static readonly double[] Masses = { 0.001, 0.01, 0.045, 0.1, 0.3, 0.6, 1, 2, 5, 20, 1000, 1e6 };
        static readonly double[] Strengths = { 1.0 / 3, 0.5, 0.8, 1.25, 2, 3 };

        [Test]
        public void AtStrengthOneEveryNamedProfileIsTodaysOutputBitForBit([ValueSource(typeof(NamedProfiles), nameof(NamedProfiles.PipelineNames))] string profile, [Values(0.045, 0.5, 2, 10)] double massKg)
        {
            var frames = QuestLikeInput.Headset(new Random(31), 31).Render(HandPath.StartAt(0.8).Hold(0.3).MoveTo(1.3, 0.8).Hold(0.3).MoveTo(0.9, 0.6).Hold(0.5));
            var plain = Run.Replay(Run.Solver(massKg, NamedProfiles.Get(profile), 0.7), frames);
            var solver = Run.Solver(massKg, NamedProfiles.Get(profile), 0.7);
            solver.CueStrength = 2;   // set and set back: nothing of it stays
            solver.CueStrength = 1;
            var again = Run.Replay(solver, frames);
            for (int i = 0; i < frames.Length; i++)
                Assert.That(BitConverter.DoubleToInt64Bits(again[i]), Is.EqualTo(BitConverter.DoubleToInt64Bits(plain[i])), $"frame {i}");
            Assert.That(WeightSolver.StrengthenedGain(0.3241, 1, 3), Is.EqualTo(0.3241), "no power taken at s = 1");
        }

        [Test]
        public void TheGainIsGToTheSWithinTheCapAndKeepsTheOrderOfTheMasses([Values("paper", "gain")] string profile)
        {
            foreach (double s in Strengths)
            {
                double previous = double.PositiveInfinity;
                foreach (double m in Masses)
                {
                    var one = Run.Solver(m, NamedProfiles.Get(profile));
                    var strong = Run.Solver(m, NamedProfiles.Get(profile)).At(s);
                    double g = one.Gain, gs = strong.Gain;
                    Assert.That(gs, Is.EqualTo(Math.Min(Math.Pow(g, s), 3)).Within(1e-15), $"{m} kg at s = {s}");
                    Assert.That(gs, Is.LessThanOrEqualTo(previous), $"{m} kg at s = {s}: a heavier mass never gets a larger gain");
                    if (g < 1) Assert.That(gs, Is.GreaterThan(0).And.LessThan(1), $"{m} kg at s = {s}: a heavier object never moves down while the hand goes up, and still lags");
                    if (g < 1 && previous < 3) Assert.That(gs, Is.LessThan(previous), $"{m} kg at s = {s}: strictly below a lighter object that is below the cap");
                    previous = gs;
                }
                Assert.That(Run.Solver(PhysicalConstants.StandardMassKg, NamedProfiles.Get(profile)).At(s).Gain, Is.EqualTo(1.0), "the golf ball's G = 1 at every s");
            }
        }

        [Test]
        public void TheStrengthScalesHowFarAHeavyObjectLagsAndALightOneLeadsMonotonically()
        {
            var frames = Run.Headset().Render(Run.Lift(0.3, 0.8));
            foreach (double m in new[] { 0.01, 2.0 })
            {
                double last = double.NaN;
                foreach (double s in new[] { 1.0 / 3, 0.5, 1, 2, 3 })
                {
                    double offset = Math.Abs(frames[frames.Length - 1].HandY - Run.Last(Run.Replay(Run.Solver(m, NamedProfiles.PaperExperiment).At(s), frames)));
                    if (!double.IsNaN(last)) Assert.That(offset, Is.GreaterThanOrEqualTo(last), $"{m} kg: s = {s} departs at least as far as the weaker strength");
                    last = offset;
                }
            }
        }

        [Test]
        public void AStrengthOutsideItsBoundsOrNotFiniteThrowsNamingTheField()
        {
            foreach (double bad in new[] { double.NaN, double.PositiveInfinity, double.NegativeInfinity, 0, -1, 0.3, 3.01 })
            {
                var e = Assert.Throws<ArgumentOutOfRangeException>(() => Run.Solver(2).CueStrength = bad);
                Assert.That(e.Message, Does.Contain("CueStrength"), bad.ToString());
                Assert.Throws<ArgumentOutOfRangeException>(() => new WeightSolver3D(WeightModel.FromMass(2)).CueStrength = bad);
                Assert.Throws<ArgumentOutOfRangeException>(() => new PaperLiteralSolver(2).CueStrength = bad);
            }
            var solver = Run.Solver(2);
            Assert.Throws<ArgumentOutOfRangeException>(() => solver.CueStrength = 5);
            Assert.That(solver.CueStrength, Is.EqualTo(1), "a refused value leaves the strength as it was");
            Assert.That(() => Run.Solver(2).CueStrength = WeightSolver.MinCueStrength, Throws.Nothing);
            Assert.That(() => Run.Solver(2).CueStrength = WeightSolver.MaxCueStrength, Throws.Nothing);
        }

        [Test]
        public void ChangingTheStrengthMidHoldGlidesAndNeverJumps()
        {
            var frames = Run.Headset(jitterSd: 0.001).Render(Run.Lift(0.3, 0.8));
            var solver = Run.Solver(2, NamedProfiles.PaperExperiment);
            solver.BeginHold(frames[0].HandY, frames[0].HandY, frames[0].PoseTime);
            double y = solver.ObjectY;
            for (int i = 1; i < frames.Length; i++)
            {
                if (i == frames.Length / 2) solver.CueStrength = 3;
                double hand = Math.Abs(frames[i].HandY - frames[i - 1].HandY);
                double next = solver.Step(frames[i].ToSample(), frames[i].Time - frames[i - 1].Time);
                // P8's bound: no step beyond max(G, 1) × the hand's own plus 1 cm (G < 1 for 2 kg at either strength).
                Assert.That(Math.Abs(next - y), Is.LessThanOrEqualTo(hand + 0.01), $"frame {i}: no jump");
                y = next;
            }
        }

        [Test]
        public void TheThreeDimensionalSolverAndTheLiteralOneCarryTheStrength()
        {
            var solver3D = new WeightSolver3D(WeightModel.FromMass(2), NamedProfiles.Xyz) { CueStrength = 2 };
            Assert.That(solver3D.Vertical.Gain, Is.EqualTo(Math.Pow(new WeightSolver3D(WeightModel.FromMass(2), NamedProfiles.Xyz).Vertical.Gain, 2)).Within(1e-15));
            var frames = Run.Headset().Render(Run.Lift(0.3, 0.8));
            double End(double s)
            {
                var literal = new PaperLiteralSolver(2) { CueStrength = s };
                literal.BeginHold(frames[0].HandY, frames[0].HandY);
                for (int i = 1; i < frames.Length; i++) literal.Step(frames[i].HandY, frames[i].Tracked, frames[i].Time - frames[i - 1].Time);
                return literal.ObjectY - frames[0].HandY;
            }
            Assert.That(End(0.5), Is.GreaterThan(End(1)), "a weaker cue lifts a heavy object further");
            Assert.That(End(2), Is.LessThan(End(1)));
        }
    }
}
