using System;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>
    /// Issue 14 item 3 through the engine-free hold the Unity layer uses: the object's offset from the hand at the grab
    /// and its extent below the pivot reach the solver, so a bottle grabbed by its neck weighs what one grabbed by its body
    /// weighs, and nothing sinks into its table. Parent space: the table top is y = 0.
    /// </summary>
    public sealed class GrabOffsetTests
    {
        sealed class Table : IParentSpace
        {
            public double HeightOf(Vector3d world) => world.Y;
        }

        /// <summary>A 1 kg bottle, pivot at its centre 0.12 m above the table (bottom 0.12 below it), lifted by a hand at <paramref name="gripAbovePivot"/>.</summary>
        static double[] Lift(double gripAbovePivot, double rise, double lower = 0, int seed = 1)
        {
            var hold = new HeldObject(new Table()) { BottomBelowPivot = 0.12 };
            Assert.That(hold.Configure(WeightModel.FromMass(1), NamedProfiles.Paper, 0.5), Is.True, hold.Error);
            var pivot = new Vector3d(0, 0.12, 0);
            Vector3d grip = pivot + new Vector3d(0, gripAbovePivot, 0);
            var hand = new QuestHand { Seed = seed, Path = t => QuestHand.Lift(grip, rise, 0.2, 0.8)(t) - new Vector3d(0, lower * QuestHand.MinimumJerk((t - 1.3) / 0.6), 0) };
            HandFrame[] frames = hand.Render(2.4);
            Assert.That(hold.Begin(1, grip, double.NaN, pivot, pivot.Y), Is.True, hold.Error);
            var y = new double[frames.Length];
            for (int i = 0; i < frames.Length; i++) y[i] = hold.Step(1, frames[i].Position, frames[i].Tracked, frames[i].HighConfidence, double.NaN, frames[i].Dt);
            return y;
        }

        [Test]
        public void ABottleGrabbedByItsNeckWeighsWhatOneGrabbedByItsBodyWeighs([Values(1, 2, 3)] int seed)
        {
            double[] neck = Lift(0.10, 0.3, seed: seed), body = Lift(0.0, 0.3, seed: seed);
            for (int i = 0; i < neck.Length; i++) Assert.That(neck[i], Is.EqualTo(body[i]).Within(1e-9), "frame " + i);
            Assert.That(neck[neck.Length - 1] - 0.12, Is.LessThan(0.3).And.GreaterThan(0.1), "a 1 kg bottle lags a 0.3 m lift");
        }

        [Test]
        public void NothingSinksIntoTheTableWhenTheHandPushesDown()
        {
            // Lift 5 cm, then push the hand 30 cm down: through the table.
            foreach (double grip in new[] { 0.0, 0.10 })
            {
                double[] y = Lift(grip, 0.05, lower: 0.35);
                foreach (double v in y) Assert.That(v - 0.12, Is.GreaterThanOrEqualTo(-1e-9), "the bottom went below the table (grip " + grip + ")");
                Assert.That(y[y.Length - 1], Is.EqualTo(0.12).Within(1e-6), "resting on the table at the end");
            }
        }

        [Test]
        public void AnInvalidExtentIsRefusedAtTheGrabNamingIt()
        {
            var hold = new HeldObject(new Table());
            hold.Configure(WeightModel.FromMass(1), NamedProfiles.Paper, 0.5);
            hold.BottomBelowPivot = double.NaN;
            Assert.That(hold.Begin(1, new Vector3d(0, 0.2, 0), double.NaN, Vector3d.Zero, 0.1), Is.False);
            Assert.That(hold.Error, Does.Contain("BottomBelowPivot"));
        }
    }
}
