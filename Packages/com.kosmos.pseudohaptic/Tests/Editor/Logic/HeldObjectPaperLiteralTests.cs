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

        /// <summary>The literal solver measures the hand's speed from the grab on: a hand already moving at the grab moves
        /// the object on the first frame; a grab whose pose is unusable starts from the first usable height instead.</summary>
        [TestCase(0.8), TestCase(2e5)]
        public void TheFirstFramesSpeedIsMeasuredFromTheGrabbingHand(double grabX)
        {
            var hold = new HeldObject(new Floor());
            Assert.That(hold.Configure(WeightModel.FromMass(2), NamedProfiles.PaperLiteral, 0.5), Is.True, hold.Error);
            var grab = new Vector3d(grabX, 0.8, 0);
            Assert.That(hold.Begin(1, grab, double.NaN, new Vector3d(0, 0.8, 0), 0.8), Is.True, hold.Error);
            var literal = new PaperLiteralSolver(2);
            literal.BeginHold(grabX == 0.8 ? 0.8 : double.NaN, 0.8);
            for (int i = 1; i <= 5; i++)
            {
                double y = hold.Step(1, new Vector3d(0.8, 0.8 + 0.01 * i, 0), true, true, double.NaN, 1 / 90.0);
                Assert.That(y, Is.EqualTo(literal.Step(hold.Solver3D.FollowedY, true, 1 / 90.0)), "frame " + i);
            }
            if (grabX == 0.8) Assert.That(hold.ObjectY, Is.GreaterThan(0.8), "the lift from the grab on moved it");
        }

        /// <summary>A new mass or cue strength (an inspector edit) rebuilds the literal solver, which mid-hold continues from where the object is.</summary>
        [Test]
        public void ANewMassOrCueStrengthIsAppliedAndMidHoldTheObjectStaysWhereItIs()
        {
            var hold = new HeldObject(new Floor());
            Assert.That(hold.Configure(WeightModel.FromMass(2), NamedProfiles.PaperLiteral, 0.5), Is.True, hold.Error);
            Assert.That(hold.Configure(WeightModel.FromMass(3), NamedProfiles.PaperLiteral, 0.5), Is.True, hold.Error);
            Assert.That(hold.Literal.MassKg, Is.EqualTo(3));
            Assert.That(hold.Configure(WeightModel.FromMass(3), NamedProfiles.PaperLiteral, 0.5, 2.0), Is.True, hold.Error);
            Assert.That(hold.Literal.CueStrength, Is.EqualTo(2.0));
            var start = new Vector3d(0, 0.8, 0);
            Assert.That(hold.Begin(1, start, double.NaN, start, 0.8), Is.True, hold.Error);
            for (int i = 1; i <= 30; i++) hold.Step(1, start + new Vector3d(0, 0.005 * i, 0), true, true, double.NaN, 1 / 90.0);
            double there = hold.ObjectY;
            Assert.That(there, Is.GreaterThan(0.8));
            Assert.That(hold.Configure(WeightModel.FromMass(1), NamedProfiles.PaperLiteral, 0.5, 2.0), Is.True, hold.Error);
            Assert.That(hold.Literal.MassKg, Is.EqualTo(1));
            Assert.That(hold.ObjectY, Is.EqualTo(there), "the new solver starts where the object is");
            Assert.That(hold.Step(1, start + new Vector3d(0, 0.15, 0), true, true, double.NaN, 1 / 90.0), Is.EqualTo(there).Within(1e-9), "a still hand: the object stays");
        }
    }
}
