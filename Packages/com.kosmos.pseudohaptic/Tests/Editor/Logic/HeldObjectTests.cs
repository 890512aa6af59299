using System;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>
    /// What the play-mode PseudoHapticWeight tests assert that is not engine-specific, through the engine-free
    /// <see cref="HeldObject"/> the component delegates to, on scripted Quest hands.
    /// </summary>
    public sealed class HeldObjectTests
    {
        sealed class Floor : IParentSpace
        {
            public double HeightOf(Vector3d world) => world.Y;
        }

        static HeldObject Object(double massKg, double standardSpeed = 0.5, WeightProfile profile = null)
        {
            var hold = new HeldObject(new Floor());
            Assert.That(hold.Configure(WeightModel.FromMass(massKg), profile ?? NamedProfiles.Paper, standardSpeed), Is.True, hold.Error);
            return hold;
        }

        /// <summary>Lifts from the floor by <paramref name="rise"/> m over <paramref name="seconds"/> s, then holds 0.3 s; the last height.</summary>
        static double Lift(HeldObject hold, double rise, double seconds, int seed = 1, double frameRate = 90)
        {
            var start = new Vector3d(0, 0, 0);
            HandFrame[] frames = new QuestHand { Seed = seed, FrameRate = frameRate, Path = QuestHand.Lift(start, rise, 0.1, seconds) }.Render(seconds + 0.4);
            Assert.That(hold.Begin(1, start, double.NaN, start, 0), Is.True, hold.Error);
            double y = double.NaN;
            foreach (HandFrame f in frames)
            {
                y = hold.Step(1, f.Position, f.Tracked, f.HighConfidence, double.NaN, f.Dt);
                Assert.That(double.IsFinite(y) && y >= 0, Is.True, "t = " + f.Time + ": " + y);
            }
            return y;
        }

        [Test]
        public void TheGolfBallStaysWithTheHand([Values(72.0, 90.0, 120.0)] double frameRate)
        {
            HeldObject ball = Object(PhysicalConstants.StandardMassKg);
            Assert.That(Lift(ball, 0.25, 0.75, frameRate: frameRate), Is.EqualTo(0.25).Within(0.005));
        }

        [Test]
        public void HeavierObjectsEndLowerAfterTheSameLift([Range(1, 20)] int seed)
        {
            double previous = double.PositiveInfinity;
            foreach (double mass in new[] { 0.01, 0.045, 0.2, 0.5, 1, 2, 5 })
            {
                double y = Lift(Object(mass), 0.3, 0.8, seed);
                Assert.That(y, Is.LessThanOrEqualTo(previous + 1e-4), mass + " kg ended higher than a lighter object");
                previous = y;
            }
            Assert.That(previous, Is.LessThan(0.3 * 0.5), "5 kg lags well behind the hand");
        }

        [Test]
        public void LighterThanTheGolfBallLeadsTheHandWithinTheGainCap()
        {
            double y = Lift(Object(0.01), 0.1, 0.6);
            Assert.That(y, Is.GreaterThan(0.1));
            Assert.That(y, Is.LessThanOrEqualTo(0.1 * SolverLimits.Default.MaxGain + 1e-3));
        }

        [Test]
        public void AnInvalidConfigurationKeepsTheLastValidOneAndSaysWhy()
        {
            HeldObject hold = Object(1);
            Assert.That(hold.Configure(WeightModel.FromMass(2), NamedProfiles.Paper, double.NaN), Is.False);
            Assert.That(hold.Error, Does.Contain("standardSpeed"));
            Assert.That(hold.Solver.Model.MassKg, Is.EqualTo(1), "the last valid configuration");
            Assert.That(hold.Configure(WeightModel.FromMass(2), NamedProfiles.Paper, 0.5), Is.True);
            Assert.That(hold.Error, Is.Null);
        }

        [Test]
        public void LostTrackingAndGarbagePosesNeverReachTheAnswer()
        {
            HeldObject hold = Object(1);
            Assert.That(hold.Begin(1, new Vector3d(0, 0.05, 0), double.NaN, Vector3d.Zero, 0), Is.True);
            var random = new Random(5);
            double[] garbage = { double.NaN, double.PositiveInfinity, double.NegativeInfinity, 1e30, -1e30 };
            for (int i = 0; i < 2000; i++)
            {
                double g = garbage[random.Next(garbage.Length)];
                var p = i % 3 == 0 ? new Vector3d(0, g, 0) : new Vector3d(0, 0.05 + 0.2 * random.NextDouble(), 0);
                double y = hold.Step(1, p, i % 5 != 0, true, double.NaN, i % 11 == 0 ? double.NaN : 1 / 90.0);
                Assert.That(double.IsFinite(y) && y >= 0, Is.True, "frame " + i + ": " + y);
                Assert.That(Math.Abs(hold.HandPoint.Y), Is.LessThan(1), "a garbage pose never becomes the hand point");
            }
            // After all that, the point is the hand again: no precision lost to a huge pose.
            for (int i = 0; i < 3; i++) hold.Step(1, new Vector3d(0, 0.123, 0), true, true, double.NaN, 1 / 90.0);
            Assert.That(hold.HandPoint.Y, Is.EqualTo(0.123).Within(1e-9));
        }
    }
}
