using System;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>
    /// Issue 31: a profile named paper-literal (the preset, or a Unity asset set to it) runs the paper as printed in the
    /// component's hold: <see cref="PaperLiteralSolver"/> on the followed hand, bit for bit, with the user's cue strength.
    /// </summary>
    public sealed class HeldObjectPaperLiteralTests
    {
        sealed class Floor : IParentSpace
        {
            public double HeightOf(Vector3d world) => world.Y;
        }

        [TestCase(2.0, 1.0), TestCase(0.3, 1.0), TestCase(2.0, 0.5)]
        public void TheHoldRunsTheLiteralSolverOnTheFollowedHand(double massKg, double cueStrength)
        {
            // The profile as a Unity asset builds it: its own instance, named after the preset, with a second hand's slot.
            var asset = new WeightProfile(NamedProfiles.PaperLiteralName, NamedProfiles.PaperLiteral.Effects);
            var hold = new HeldObject(new Floor());
            Assert.That(hold.Configure(WeightModel.FromMass(massKg), asset, 0.5, cueStrength), Is.True, hold.Error);
            Assert.That(hold.Literal, Is.Not.Null);
            var start = new Vector3d(0, 0.8, 0);
            HandFrame[] frames = new QuestHand { Seed = 3, Path = QuestHand.Lift(start, 0.3, 0.2, 0.8) }.Render(2.0);
            Assert.That(hold.Begin(1, start, double.NaN, start, 0.8), Is.True, hold.Error);
            var literal = new PaperLiteralSolver(massKg) { CueStrength = cueStrength };
            literal.BeginHold(0.8, 0.8);
            foreach (HandFrame f in frames)
            {
                double y = hold.Step(1, f.Position, f.Tracked, f.HighConfidence, double.NaN, f.Dt);
                double expected = literal.Step(hold.Solver3D.FollowedY, hold.Solver3D.FollowedHands > 0, f.Dt);
                Assert.That(y, Is.EqualTo(expected), "t = " + f.Time);
                Assert.That(hold.ObjectY, Is.EqualTo(y));
            }
            Assert.That(hold.Offset, Is.EqualTo(hold.LastHand.Y - hold.ObjectY));
        }

        [Test]
        public void AnyOtherProfileKeepsThePipeline()
        {
            var hold = new HeldObject(new Floor());
            Assert.That(hold.Configure(WeightModel.FromMass(2), NamedProfiles.Paper, 0.5), Is.True, hold.Error);
            Assert.That(hold.Literal, Is.Null);
            Assert.That(hold.Configure(WeightModel.FromMass(2), NamedProfiles.PaperLiteral, 0.5), Is.True, hold.Error);
            Assert.That(hold.Literal, Is.Not.Null);
            Assert.That(hold.Configure(WeightModel.FromMass(2), NamedProfiles.PaperExperiment, 0.5), Is.True, hold.Error);
            Assert.That(hold.Literal, Is.Null, "switching away from paper-literal returns to the pipeline");
        }
    }
}
