using System;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>
    /// The decisions issue 24 moved out of the components: the grab's x/z from two hands (<see cref="HeldObject.GrabTarget"/>),
    /// the settings' checks (<see cref="FieldRules"/>), the task's mass source (<see cref="WeightSettings.ExplicitMassError"/>),
    /// and which contacts are fingertips (<see cref="ContactSet"/>).
    /// </summary>
    public sealed class GlueDecisionsTests
    {
        sealed class Space : IParentSpace
        {
            public double HeightOf(Vector3d world) => world.Y;
        }

        static HeldObject Hold()
        {
            var hold = new HeldObject(new Space());
            Assert.That(hold.Configure(WeightModel.FromMass(1), NamedProfiles.Paper, 0.5), Is.True, hold.Error);
            return hold;
        }

        [Test]
        public void TwoHandsPutTheObjectAtTheirMeanPlusTheOffsetItHadWhenTheSecondJoined()
        {
            HeldObject hold = Hold();
            var obj = new Vector3d(0, 0.8, 0.4);
            Assert.That(hold.Begin(1, new Vector3d(-0.05, 0.85, 0.4), double.NaN, obj, 0.8), Is.True);
            Assert.That(hold.Begin(2, new Vector3d(0.05, 0.85, 0.45), double.NaN, obj, 0.8), Is.True);
            // The mean is (0, 0.425); the object sat 2.5 cm behind it in z: that offset is kept.
            hold.Step(1, new Vector3d(0.15, 0.85, 0.4), true, true, double.NaN, 1 / 90.0);
            hold.Step(2, new Vector3d(0.05, 0.85, 0.45), true, true, double.NaN, 1 / 90.0);
            Assert.That(hold.GrabTarget.X, Is.EqualTo(0.1).Within(1e-12), "half of the left hand's 10 cm");
            Assert.That(hold.GrabTarget.Z, Is.EqualTo(0.4).Within(1e-12));
            Assert.That(hold.Horizontal(obj, grabMoves: true).X, Is.EqualTo(0.1).Within(1e-12));
            Assert.That(hold.Horizontal(obj, grabMoves: false).X, Is.EqualTo(0), "the grab does not move x/z unless asked");
        }

        [Test]
        public void ALostHandLeavesTheOtherInChargeWithoutAStep()
        {
            HeldObject hold = Hold();
            var obj = new Vector3d(0, 0.8, 0.4);
            hold.Begin(1, new Vector3d(-0.05, 0.85, 0.4), double.NaN, obj, 0.8);
            hold.Begin(2, new Vector3d(0.05, 0.85, 0.4), double.NaN, obj, 0.8);
            hold.Step(1, new Vector3d(-0.05, 0.85, 0.4), true, true, double.NaN, 1 / 90.0);
            hold.Step(2, new Vector3d(0.05, 0.85, 0.4), true, true, double.NaN, 1 / 90.0);
            hold.TrackObject(new Vector3d(hold.GrabTarget.X, 0.8, hold.GrabTarget.Z));
            hold.Step(1, Vector3d.NaN, false, false, double.NaN, 1 / 90.0); // the left hand is lost
            hold.Step(2, new Vector3d(0.05, 0.85, 0.4), true, true, double.NaN, 1 / 90.0);
            Assert.That(hold.GrabTarget.X, Is.EqualTo(0).Within(1e-12), "re-anchored on the right hand: no step");
            hold.Step(1, Vector3d.NaN, false, false, double.NaN, 1 / 90.0);
            hold.Step(2, new Vector3d(0.15, 0.85, 0.4), true, true, double.NaN, 1 / 90.0);
            Assert.That(hold.GrabTarget.X, Is.EqualTo(0.1).Within(1e-12), "and follows it alone");
        }

        [Test]
        public void WithNoUsableHandTheGrabHasNoTarget()
        {
            HeldObject hold = Hold();
            var obj = new Vector3d(0, 0.8, 0.4);
            hold.Begin(1, new Vector3d(0, 0.85, 0.4), double.NaN, obj, 0.8);
            hold.Step(1, Vector3d.NaN, false, false, double.NaN, 1 / 90.0);
            Assert.That(double.IsNaN(hold.GrabTarget.X), Is.True);
            Assert.That(hold.Horizontal(obj, grabMoves: true), Is.EqualTo(obj), "the object stays where it is");
        }

        [TestCase(0.06, true)]
        [TestCase(1e-9, true)]
        [TestCase(0.0, false)]
        [TestCase(-0.01, false)]
        [TestCase(double.NaN, false)]
        [TestCase(double.PositiveInfinity, false)]
        public void APositiveLengthIsFiniteAndAboveZero(double value, bool ok)
        {
            string error = FieldRules.Positive("Radius", value);
            Assert.That(error == null, Is.EqualTo(ok));
            if (!ok) Assert.That(error, Does.StartWith("Radius must be finite and greater than 0"));
            Assert.That(FieldRules.Positive("Radius", -0.5), Does.EndWith("(was -0.5)"), "the value given");
        }

        [Test]
        public void AReachMayBeZeroButNotNegativeAndARequiredRuleThrowsNamingTheField()
        {
            Assert.That(FieldRules.NonNegative("Reach", 0), Is.Null);
            Assert.That(FieldRules.NonNegative("Reach", -1e-9), Does.Contain("Reach must be finite and at least 0"));
            Assert.That(FieldRules.NonNegative("Reach", -0.5), Does.EndWith("(was -0.5)"), "the value given");
            Assert.That(() => FieldRules.Require(FieldRules.NonNegative("Reach", double.NaN), "Reach", double.NaN),
                Throws.TypeOf<ArgumentOutOfRangeException>().With.Property("ParamName").EqualTo("Reach"));
            Assert.That(FieldRules.First(null, "b", "c"), Is.EqualTo("b"));
            Assert.That(FieldRules.First(null, null), Is.Null);
        }

        [TestCase(MassSource.Explicit, true)]
        [TestCase(MassSource.Rigidbody, false)]
        [TestCase(MassSource.DensityTimesVolume, false)]
        public void ATaskSetsMassesOnlyThroughTheExplicitMass(MassSource source, bool ok)
        {
            string error = WeightSettings.ExplicitMassError("left", source);
            Assert.That(error == null, Is.EqualTo(ok));
            if (!ok) Assert.That(error, Does.StartWith("the left object's Mass Source is " + source).And.Contains("Explicit"));
        }

        [Test]
        public void AContactSetRemembersItsContactsAndGrowsPastFour()
        {
            var set = new ContactSet();
            for (int id = 1; id <= 6; id++) set.Add(id);
            set.Add(3);
            Assert.That(set.Count, Is.EqualTo(6), "no duplicates");
            set.Remove(2);
            Assert.That(set.Contains(2), Is.False);
            Assert.That(set.Contains(6) && set.Contains(1), Is.True);
            set.Remove(99);
            Assert.That(set.Count, Is.EqualTo(5));
            set.Clear();
            Assert.That(set.Contains(1), Is.False);
        }

        [Test]
        public void RemovingAnAbsentContactChangesNothingInAFullOrShrunkSet()
        {
            var set = new ContactSet();
            for (int id = 1; id <= 4; id++) set.Add(id);
            set.Remove(99);
            Assert.That(set.Count, Is.EqualTo(4));
            set.Remove(4);
            set.Remove(4);
            Assert.That(set.Count, Is.EqualTo(3), "the second removal of 4 removes nothing");
            Assert.That(set.Contains(1) && set.Contains(2) && set.Contains(3), Is.True);
        }
    }
}
