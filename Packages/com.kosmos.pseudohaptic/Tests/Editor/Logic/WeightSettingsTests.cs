using System;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>Mass resolution, the user's speed and the release velocity, as PseudoHapticWeight asks for them.</summary>
    public sealed class WeightSettingsTests
    {
        static bool Volume(out double v, out string e) { v = 0.008; e = null; return true; }

        [Test]
        public void MassComesFromTheRigidbodyTheDensityTimesTheVolumeOrTheExplicitValue()
        {
            int asked = 0;
            VolumeQuery counting = (out double v, out string e) => { asked++; return Volume(out v, out e); };
            Assert.That(WeightSettings.TryCreateModel(MassSource.Rigidbody, 1.5, 1000, 3, counting, "box", out WeightModel m, out string error), Is.True, error);
            Assert.That(m.MassKg, Is.EqualTo(1.5));
            Assert.That(WeightSettings.TryCreateModel(MassSource.Explicit, double.NaN, 1000, 3, counting, "box", out m, out error), Is.True, error);
            Assert.That(m.MassKg, Is.EqualTo(3));
            Assert.That(asked, Is.EqualTo(0), "the volume is read only when the mass needs it");
            Assert.That(WeightSettings.TryCreateModel(MassSource.DensityTimesVolume, 1.5, 250, 3, counting, "box", out m, out error), Is.True, error);
            Assert.That(m.MassKg, Is.EqualTo(2).Within(1e-12), "250 kg/m³ × 8 L");
            Assert.That(asked, Is.EqualTo(1));
        }

        [Test]
        public void EachFailureSaysWhy()
        {
            Assert.That(WeightSettings.TryCreateModel(MassSource.Rigidbody, double.NaN, 1000, 1, Volume, "crate", out _, out string error), Is.False);
            Assert.That(error, Does.Contain("no Rigidbody").And.Contain("'crate'"), "the object named, quoted");
            VolumeQuery unreadable = (out double v, out string e) => { v = 0; e = "mesh 'bottle' is not readable"; return false; };
            Assert.That(WeightSettings.TryCreateModel(MassSource.DensityTimesVolume, 1, 1000, 1, unreadable, "b", out _, out error), Is.False);
            Assert.That(error, Does.Contain("not readable"));
            Assert.That(WeightSettings.TryCreateModel(MassSource.DensityTimesVolume, 1, 1000, 1, null, "b", out _, out error), Is.False);
            Assert.That(error, Does.Contain("collider"));
            Assert.That(WeightSettings.TryCreateModel(MassSource.Explicit, 1, 1000, -2, Volume, "b", out _, out error), Is.False);
            Assert.That(error, Is.Not.Empty, "the core's message");
            Assert.That(WeightSettings.TryCreateModel(MassSource.DensityTimesVolume, 1, double.NaN, 1, Volume, "b", out _, out error), Is.False);
        }

        [Test]
        public void TheMassIsWrittenBackUnlessItCameFromTheRigidbody()
        {
            Assert.That(WeightSettings.WritesRigidbodyMass(MassSource.Rigidbody), Is.False);
            Assert.That(WeightSettings.WritesRigidbodyMass(MassSource.Explicit), Is.True);
            Assert.That(WeightSettings.WritesRigidbodyMass(MassSource.DensityTimesVolume), Is.True);
        }

        [Test]
        public void TheUsersSpeedIsTheExplicitOneOrTheStoredOne()
        {
            Assert.That(WeightSettings.StandardSpeed(StandardSpeedSource.Explicit, 0.7, 0.4), Is.EqualTo(0.7));
            Assert.That(WeightSettings.StandardSpeed(StandardSpeedSource.UserCalibration, 0.7, 0.4), Is.EqualTo(0.4));
        }

        /// <summary>A hand rising at 0.5 m/s with 30 Hz poses under 90 Hz frames, released while rising.</summary>
        [Test]
        public void TheReleaseVelocityIsTheHandsTheObjectsOrZero()
        {
            var box = new BoxScene.Box(new Vector3d(0, 0.8, 0), 0.2);
            HeldObject hold = box.Hold;
            HandFrame[] frames = new QuestHand { Path = t => new Vector3d(0, 0.8 + 0.5 * t, 0) }.Render(0.4);
            hold.Begin(1, frames[0].Position, double.NaN, box.Position, box.Position.Y);
            foreach (HandFrame f in frames)
            {
                double y = hold.Step(1, f.Position, f.Tracked, true, double.NaN, f.Dt);
                hold.TrackObject(new Vector3d(0, y, 0));
            }
            Assert.That(hold.ReleaseVelocity(ReleaseVelocity.Hand).Y, Is.EqualTo(0.5).Within(0.05));
            Assert.That(hold.ReleaseVelocity(ReleaseVelocity.Object).Y, Is.GreaterThan(0.1), "the 0.2 kg object rises too");
            Assert.That(hold.ReleaseVelocity(ReleaseVelocity.Zero), Is.EqualTo(Vector3d.Zero));
        }

        [Test]
        public void AStillHandReleasesWithoutVelocityAndGarbageIsIgnored()
        {
            var v = new VelocityTracker();
            v.Reset(new Vector3d(0, 1, 0), 0);
            v.Add(new Vector3d(0, 1.1, 0), 0.1);
            Assert.That(v.VelocityAt(0.1).Y, Is.EqualTo(1).Within(1e-9));
            v.Add(Vector3d.NaN, 0.15);
            v.Add(new Vector3d(0, 1.1, 0), 0.3); // a repeated pose is no news
            Assert.That(v.VelocityAt(0.3), Is.EqualTo(Vector3d.Zero), "still for 0.2 s");
        }

        [Test]
        public void TheVelocityReadsZeroFromExactlyStillAfterSecondsWithoutMotion()
        {
            // The last change of position at t = 0, so that now − last is StillAfter to the last bit at now = StillAfter.
            var v = new VelocityTracker();
            v.Reset(new Vector3d(0, 1, 0), -0.0625);
            v.Add(new Vector3d(0, 1.0625, 0), 0);
            const double justBefore = 0.09999999999999999; // the double below 0.1 (Unity's profile has no Math.BitDecrement)
            Assert.That(justBefore, Is.LessThan(VelocityTracker.StillAfter));
            Assert.That(v.VelocityAt(justBefore).Y, Is.EqualTo(1).Within(1e-9), "not yet still");
            Assert.That(v.VelocityAt(VelocityTracker.StillAfter), Is.EqualTo(Vector3d.Zero), "still for StillAfter seconds: zero");
        }

        static readonly Vector3d Up = new Vector3d(0, 1, 0);

        [Test]
        public void AVelocityNeedsTwoPosesAtLeastAWindowApartAndIsKeptUntilTheNextWindow()
        {
            var v = new VelocityTracker();
            v.Add(Up, 10);
            Assert.That(v.VelocityAt(10), Is.EqualTo(Vector3d.Zero), "one pose has no velocity");
            v.Add(Up * 1.0625, 10.0625);
            Assert.That(v.VelocityAt(10.0625).Y, Is.EqualTo(1).Within(1e-9), "the first pose anchors the second");

            v.Reset(Up, 0);
            v.Add(Up * 1.5, VelocityTracker.Window);
            Assert.That(v.VelocityAt(VelocityTracker.Window).Y, Is.EqualTo(0.5 / VelocityTracker.Window).Within(1e-9), "exactly a window apart");

            v.Reset(Up, 0);
            v.Add(Up * 1.0625, 0.0625);
            v.Add(Up * 1.0725, 0.078125); // a change sooner than a window after the last measurement
            Assert.That(v.VelocityAt(0.078125).Y, Is.EqualTo(1).Within(1e-9), "not measured over less than a window");
            v.Add(Up * 1.0825, 0.078125); // another pose at the same time
            Assert.That(v.VelocityAt(0.078125).Y, Is.EqualTo(1).Within(1e-9), "a pose at the same time does not discard the velocity");
        }

        [Test]
        public void NonFinitePosesAndTimesNeitherAnchorNorDelayTheVelocity()
        {
            var v = new VelocityTracker();
            v.Reset(Vector3d.NaN, 0);
            v.Add(Up, 0.015625);
            v.Add(Up * 1.0625, 0.078125);
            Assert.That(v.VelocityAt(0.078125).Y, Is.EqualTo(1).Within(1e-9), "a NaN reset leaves the first finite pose as the anchor");

            v.Reset(Up, 0);
            v.Add(Vector3d.NaN, 0.0625);
            v.Add(Up * 1.125, 0.125);
            Assert.That(v.VelocityAt(0.125).Y, Is.EqualTo(1).Within(1e-9), "a NaN pose is ignored");

            v.Reset(Up, 0);
            v.Add(Up * 1.0625, double.NaN);
            v.Add(Up * 1.125, 0.125);
            Assert.That(v.VelocityAt(0.125).Y, Is.EqualTo(1).Within(1e-9), "a pose at a NaN time is ignored");
        }

        [Test]
        public void FollowingMovesXAndZOnlyWithATrackedFiniteHand()
        {
            var obj = new Vector3d(1, 2, 3);
            Assert.That(GrabFollow.Horizontal(obj, new Vector3d(5, 9, 7), new Vector3d(0.1, 0, 0), true, true), Is.EqualTo(new Vector3d(5.1, 2, 7)));
            Assert.That(GrabFollow.Horizontal(obj, new Vector3d(5, 9, 7), Vector3d.Zero, false, true), Is.EqualTo(obj));
            Assert.That(GrabFollow.Horizontal(obj, Vector3d.NaN, Vector3d.Zero, true, true), Is.EqualTo(obj));
            Assert.That(GrabFollow.Horizontal(obj, new Vector3d(5, 9, 7), Vector3d.Zero, true, false), Is.EqualTo(obj));
            Assert.That(GrabFollow.PinchStrength(0.01), Is.EqualTo(1));
            Assert.That(GrabFollow.PinchStrength(0.05), Is.EqualTo(0));
            Assert.That(GrabFollow.PinchStrength(0.0275), Is.EqualTo(0.5).Within(1e-12));
            Assert.That(GrabFollow.PinchStrength(double.NaN), Is.EqualTo(0));
        }

        [Test]
        public void AGrabOfSeveralHandsFollowsTheirMeanAndIsTrackedOnlyWhenEveryHandIs()
        {
            var none = new GrabCentre();
            Assert.That(none.Count, Is.EqualTo(0));
            Assert.That(none.Point.IsFinite || none.IsTracked, Is.False, "no hand: no point, not tracked");
            var two = new GrabCentre();
            two.Add(new Vector3d(0, 1, 0));
            two.Add(new Vector3d(0.2, 1.2, 0), true, false);
            Assert.That(two.Point.X, Is.EqualTo(0.1).Within(1e-12));
            Assert.That(two.Point.Y, Is.EqualTo(1.1).Within(1e-12));
            Assert.That(two.IsTracked && !two.IsHighConfidence, Is.True);
            two.Add(new Vector3d(0, 1, 0), false, false);
            Assert.That(two.IsTracked, Is.False, "one lost hand makes the grab untracked");
        }
    
        [Test]
        public void ConfiguringFromSettingsReportsTheFieldKeepsTheLastValidOneAndWritesTheRigidbodyMassOnlyWhenItCameFromElsewhere()
        {
            var hold = new HeldObject(new BoxScene.Box(Vector3d.Zero, 1));
            Assert.That(WeightSettings.TryConfigure(hold, MassSource.DensityTimesVolume, 3, 500, 0, Volume, "box", NamedProfiles.Paper, null, 0.5, out double write, out string error), Is.True, error);
            Assert.That(write, Is.EqualTo(4).Within(1e-12), "500 kg/m³ × 8 L, written back to the Rigidbody");
            Assert.That(hold.MassKg, Is.EqualTo(4).Within(1e-12));
            Assert.That(WeightSettings.TryConfigure(hold, MassSource.Explicit, double.NaN, 0, 2, Volume, "box", NamedProfiles.Paper, null, 0.5, out write, out error), Is.True);
            Assert.That(double.IsNaN(write), Is.True, "no Rigidbody: nothing to write");
            Assert.That(WeightSettings.TryConfigure(hold, MassSource.Rigidbody, 3, 0, 0, Volume, "box", NamedProfiles.Paper, null, 0.5, out write, out error), Is.True);
            Assert.That(double.IsNaN(write), Is.True, "the mass came from the Rigidbody");
            Assert.That(WeightSettings.TryConfigure(hold, MassSource.Explicit, 3, 0, -1, Volume, "box", NamedProfiles.Paper, null, 0.5, out write, out error), Is.False);
            Assert.That(error, Does.Contain("mass"), "the core names the field");
            Assert.That(WeightSettings.TryConfigure(hold, MassSource.Explicit, 3, 0, 1, Volume, "box", null, "profile 'p': bad", 0.5, out write, out error), Is.False);
            Assert.That(error, Is.EqualTo("profile 'p': bad"));
            Assert.That(hold.MassKg, Is.EqualTo(3).Within(1e-12), "the last valid configuration is kept");
        }

        [Test]
        public void WithoutAProfileOrWithAStrengthTheHoldRefusesItIsNotConfigured()
        {
            var hold = new HeldObject(new BoxScene.Box(Vector3d.Zero, 1));
            Assert.That(WeightSettings.TryConfigure(hold, MassSource.Explicit, double.NaN, 0, 2, Volume, "box", null, null, 0.5, out _, out string error), Is.False);
            Assert.That(error, Does.Contain("no profile"));
            Assert.That(WeightSettings.TryConfigure(hold, MassSource.Explicit, double.NaN, 0, 2, Volume, "box", NamedProfiles.Paper, null, 0.5, out _, out error, cueStrength: 10), Is.False);
            Assert.That(error, Does.Contain("CueStrength"), "the hold's reason");
        }

        [Test]
        public void TheCueStrengthIsTheUsersStoredOneOrOne()
        {
            Assert.That(WeightSettings.CueStrength(true, 1.7), Is.EqualTo(1.7));
            Assert.That(WeightSettings.CueStrength(false, 1.7), Is.EqualTo(1.0), "the paper's cue");
        }

        [Test]
        public void TheWatchAsksForAConfigurationAfterASettingTheAssetOrItsVersionChanged()
        {
            Assert.That(new ConfigurationWatch().IsStale(null, 0), Is.True, "never configured, even with no asset at version 0");
            var watch = new ConfigurationWatch();
            object asset = new object();
            Assert.That(watch.IsStale(asset, 1), Is.True, "never configured");
            watch.Configured(asset, 1);
            Assert.That(watch.IsStale(asset, 1), Is.False);
            Assert.That(watch.IsStale(asset, 2), Is.True, "the asset changed");
            Assert.That(watch.IsStale(new object(), 1), Is.True, "another asset");
            Assert.That(watch.IsStale(null, 0), Is.True, "the asset was removed");
            watch.MarkDirty();
            Assert.That(watch.IsStale(asset, 1), Is.True, "a setting changed");
        }

        [Test]
        public void AGrabDriverMovesXAndZOnlyWhenAskedAndTheSolverDoesNot()
        {
            var paper = new HeldObject(new BoxScene.Box(Vector3d.Zero, 1));
            Assert.That(paper.Configure(WeightModel.FromMass(1), NamedProfiles.Paper, 0.5), Is.True);
            var xyz = new HeldObject(new BoxScene.Box(Vector3d.Zero, 1));
            Assert.That(xyz.Configure(WeightModel.FromMass(1), NamedProfiles.Xyz, 0.5), Is.True);
            Assert.That(GrabFollow.GrabMovesHorizontal(true, null), Is.True, "no hold yet: the driver moves them");
            Assert.That(GrabFollow.GrabMovesHorizontal(true, paper), Is.True);
            Assert.That(GrabFollow.GrabMovesHorizontal(true, xyz), Is.False, "lateral inertia: the solver moves them");
            Assert.That(GrabFollow.GrabMovesHorizontal(false, null), Is.False, "not asked");
            Assert.That(GrabFollow.GrabMovesHorizontal(false, paper), Is.False, "not asked");
        }

        [Test]
        public void ThePinchStrengthIsFullAtTouchingTipsAndAlwaysBetweenZeroAndOne()
        {
            Assert.That(GrabFollow.PinchStrength(0), Is.EqualTo(1), "tips touching");
            Assert.That(GrabFollow.PinchStrength(0.02, 0.02, 0.02), Is.EqualTo(1), "open = closed: a binary pinch, closed at the threshold");
            Assert.That(GrabFollow.PinchStrength(0.0201, 0.02, 0.02), Is.EqualTo(0), "…and open beyond it");
            Assert.That(GrabFollow.PinchStrength(double.PositiveInfinity), Is.EqualTo(0), "tips infinitely far apart");
            Assert.That(GrabFollow.PinchStrength(-0.01), Is.EqualTo(0), "a negative distance is no hand's");
            Assert.That(GrabFollow.PinchStrength(0.02, double.NaN, 0.04), Is.EqualTo(0), "a NaN threshold pinches nothing between");
            Assert.That(GrabFollow.PinchStrength(0.02, 0.015, double.NaN), Is.EqualTo(0), "…nor a NaN open");
            Assert.That(GrabFollow.PinchStrength(0.03, 0.02, 0.01), Is.EqualTo(0), "open below closed: beyond both is open");
            Assert.That(GrabFollow.PinchStrength(0.015, 0.02, 0.01), Is.EqualTo(1), "…and at or below closed is closed");
            var random = new System.Random(3);
            double[] specials = { 0, -0.01, double.NaN, double.PositiveInfinity, 0.015, 0.04 };
            for (int i = 0; i < 500; i++)
            {
                double closed = i % 7 == 0 ? 0.02 : 0.05 * random.NextDouble();
                double open = i % 7 == 0 ? 0.02 : 0.05 * random.NextDouble();
                double d = i % 5 == 0 ? specials[i / 5 % specials.Length] : i % 3 == 0 ? open : 0.06 * random.NextDouble();
                double s = GrabFollow.PinchStrength(d, closed, open);
                Assert.That(s >= 0 && s <= 1, Is.True, "d " + d + ", closed " + closed + ", open " + open + ": " + s);
            }
        }

        [Test]
        public void AGrabOfSeveralHandsIsTrackedAndConfidentUnlessAnyHandIsNot()
        {
            var one = new GrabCentre();
            one.Add(new Vector3d(0, 1, 0));
            Assert.That(one.IsTracked && one.IsHighConfidence, Is.True, "one good hand");
            var lost = new GrabCentre();
            lost.Add(Vector3d.Zero, false, false);
            lost.Add(Vector3d.Zero, false, false);
            Assert.That(lost.IsTracked, Is.False, "two lost hands");
            var unsure = new GrabCentre();
            unsure.Add(Vector3d.Zero, true, false);
            unsure.Add(Vector3d.Zero, true, false);
            Assert.That(unsure.IsTracked && !unsure.IsHighConfidence, Is.True, "two low-confidence hands");
        }
}
}
