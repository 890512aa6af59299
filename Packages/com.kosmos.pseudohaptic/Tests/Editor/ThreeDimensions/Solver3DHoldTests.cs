using System;
using NUnit.Framework;
using static Kosmos.PseudoHaptic.Tests.Run3D;

namespace Kosmos.PseudoHaptic.Tests.ThreeDimensions
{
    /// <summary>
    /// The 3D solver's hold bookkeeping: how many hands are usable, followed and holding; letting go and gripping
    /// again (each hand carries its share only while both hold); ending a hold; a hold begun with a grab offset; and
    /// configuration that fails loudly.
    /// </summary>
    public class Solver3DHoldTests
    {
        const double Pose = 1 / 32.0;

        static WeightSolver3D TwoHanded(double massKg = 2) => new WeightSolver3D(WeightModel.FromMass(massKg), NamedProfiles.Xyz);

        [Test]
        public void HandsAreCountedAsUsableFollowedAndHoldingAndEachCarriesItsShareOnlyWhileBothHold()
        {
            var s = TwoHanded();
            double t = 0;
            s.BeginHold(At(-0.1, 1, 0, t), At(0.1, 1, 0, t), 0, 1, 0);
            Assert.That(s.UsableHands, Is.EqualTo(2));
            Assert.That(s.FollowedHands, Is.EqualTo(2));
            Assert.That(s.HoldingHands, Is.EqualTo(2));
            Assert.That(s.PerHandMassKg, Is.EqualTo(1.0), "each hand carries half of 2 kg");

            s.SetGrip(2, false);
            Assert.That(s.HoldingHands, Is.EqualTo(1), "the second hand let go");
            Assert.That(s.PerHandMassKg, Is.EqualTo(2.0), "the first carries it all");
            t += Pose; s.Step(At(-0.1, 1, 0, t), At(0.1, 1, 0, t), Pose);
            Assert.That(s.UsableHands, Is.EqualTo(2), "still tracked");
            Assert.That(s.FollowedHands, Is.EqualTo(1), "but not followed");

            s.SetGrip(2, true);
            for (int i = 0; i < 8; i++) { t += Pose; s.Step(At(-0.1, 1, 0, t), At(0.1, 1, 0, t), Pose); }
            Assert.That(s.HoldingHands, Is.EqualTo(2), "gripping again, it rejoins once steady");
            Assert.That(s.PerHandMassKg, Is.EqualTo(1.0));

            s.SetGrip(1, false);
            Assert.That(s.HoldingHands, Is.EqualTo(1), "the first hand let go");
            Assert.That(s.PerHandMassKg, Is.EqualTo(2.0));
            t += Pose; s.Step(At(-0.1, 1, 0, t), HandPose.Lost, Pose);
            Assert.That(s.UsableHands, Is.EqualTo(1));
            Assert.That(s.FollowedHands, Is.EqualTo(0), "the one tracked hand has let go");
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => s.SetGrip(3, true)).ParamName, Is.EqualTo("hand"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => s.SetGrip(0, false)).ParamName, Is.EqualTo("hand"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => s.SetGrip(3, false)).Message, Does.Contain("hand must be 1 or 2, got 3."));
            t += Pose; s.Step(HandPose.Lost, At(0.1, 1, 0, t), Pose);
            Assert.That(s.UsableHands, Is.EqualTo(1), "only the second");
            t += Pose; s.Step(HandPose.Lost, HandPose.Lost, Pose);
            Assert.That(s.UsableHands, Is.EqualTo(0));
            s.BeginHold(HandPose.Lost, At(0.1, 1, 0, t), 0, 1, 0);
            Assert.That(s.UsableHands, Is.EqualTo(1), "a hold begun with the second hand only");
            s.BeginHold(At(0.1, 1, 0, t), HandPose.Lost, 0, 1, 0);
            Assert.That(s.UsableHands, Is.EqualTo(1), "a hold begun with the first hand only");
        }

        // The followed point is what the object follows in x, y and z: it must not step when the set of followed hands
        // changes, in any axis, whichever hand lets go, and a hand gripping again after both let go continues from it.
        [Test]
        public void LettingGoAndGrippingAgainNeverMovesTheFollowedPoint([Values(1, 2)] int letGo)
        {
            var s = TwoHanded();
            double t = 0;
            HandPose AtNow(double x, double y, double z) => At(x, y, z, t);
            var left = At(-0.1, 1.0, 0, t);
            var right = At(0.1, 1.2, 0.06, t);
            s.BeginHold(left, right, 0, 1.1, 0.03);
            AssertFollowed(s, 0, 1.1, 0.03, "the hands' midpoint");

            s.SetGrip(letGo, false);
            t += Pose; s.Step(At(-0.1, 1.0, 0, t), At(0.1, 1.2, 0.06, t), Pose);
            AssertFollowed(s, 0, 1.1, 0.03, "hand " + letGo + " let go: the point stays");
            // The other hand moves by (0.02, 0.03, −0.01): the point moves with it.
            t += Pose;
            if (letGo == 2) s.Step(At(-0.08, 1.03, -0.01, t), At(0.1, 1.2, 0.06, t), Pose);
            else s.Step(At(-0.1, 1.0, 0, t), At(0.12, 1.23, 0.05, t), Pose);
            AssertFollowed(s, 0.02, 1.13, 0.02, "following the hand that holds");

            s.SetGrip(3 - letGo, false);
            t += Pose; s.Step(HandPose.Lost, HandPose.Lost, Pose);
            Assert.That(s.FollowedHands, Is.EqualTo(0));
            // The first hand grips again far from where it was: followed from the point, not from its own position.
            s.SetGrip(letGo, true);
            t += Pose;
            if (letGo == 1) s.Step(AtNow(0.3, 0.9, -0.2), HandPose.Lost, Pose); else s.Step(HandPose.Lost, AtNow(0.3, 0.9, -0.2), Pose);
            AssertFollowed(s, 0.02, 1.13, 0.02, "hand " + letGo + " grips again: no step");
            t += Pose;
            if (letGo == 1) s.Step(AtNow(0.31, 0.91, -0.19), HandPose.Lost, Pose); else s.Step(HandPose.Lost, AtNow(0.31, 0.91, -0.19), Pose);
            AssertFollowed(s, 0.03, 1.14, 0.03, "then its motion");
        }

        static void AssertFollowed(WeightSolver3D s, double x, double y, double z, string what)
        {
            Assert.That(s.FollowedX, Is.EqualTo(x).Within(1e-12), what + ": x");
            Assert.That(s.FollowedY, Is.EqualTo(y).Within(1e-12), what + ": y");
            Assert.That(s.FollowedZ, Is.EqualTo(z).Within(1e-12), what + ": z");
        }

        [Test]
        public void AHoldBegunBeforeAnyHandIsTrackedStaysPutThenAnchorsOnTheFirstHand()
        {
            var s = TwoHanded(5);
            s.BeginHold(HandPose.Lost, HandPose.Lost, 0.3, 1.0, 0.2);
            double t = 0;
            for (int i = 0; i < 32; i++)
            {
                t += Pose; s.Step(HandPose.Lost, HandPose.Lost, Pose);
                Assert.That(new[] { s.ObjectX, s.ObjectY, s.ObjectZ }, Is.EqualTo(new[] { 0.3, 1.0, 0.2 }), "lost frame " + i);
            }
            // A hand appears 3 cm from the object in each axis: the object waits (settling), then anchors; it never jumps.
            for (int i = 0; i < 16; i++)
            {
                t += Pose; s.Step(At(0.33, 1.03, 0.23, t), HandPose.Lost, Pose);
                Assert.That(new[] { s.ObjectX, s.ObjectY, s.ObjectZ }, Is.EqualTo(new[] { 0.3, 1.0, 0.2 }).Within(1e-12), "tracked frame " + i);
            }
        }

        [Test]
        public void AReconfiguredSolverMovesExactlyAsOneBuiltForItsNewMass()
        {
            // Built for the golf ball, then configured for 5 kg: every coordinate, frame by frame, as a solver built for
            // 5 kg, through a two-hand diagonal lift, one hand letting go, and a sideways move with the lateral lag.
            var reconfigured = new WeightSolver3D(WeightModel.FromMass(PhysicalConstants.StandardMassKg), NamedProfiles.Xyz);
            reconfigured.Configure(WeightModel.FromMass(5), NamedProfiles.Xyz, 0.5);
            var built = new WeightSolver3D(WeightModel.FromMass(5), NamedProfiles.Xyz);
            double t = 0;
            foreach (var s in new[] { reconfigured, built }) s.BeginHold(At(-0.1, 1, 0, t), At(0.1, 1, 0, t), 0, 1, 0);
            for (int i = 1; i <= 40; i++)
            {
                t += Pose;
                if (i == 20) { reconfigured.SetGrip(2, false); built.SetGrip(2, false); }
                double x = 0.004 * i, y = i <= 20 ? 1 + 0.01 * i : 1.2;
                foreach (var s in new[] { reconfigured, built }) s.Step(At(x - 0.1, y, 0.002 * i, t), At(x + 0.1, y, 0.002 * i, t), Pose);
                Assert.That(new[] { reconfigured.ObjectX, reconfigured.ObjectY, reconfigured.ObjectZ, reconfigured.LagX },
                    Is.EqualTo(new[] { built.ObjectX, built.ObjectY, built.ObjectZ, built.LagX }), "frame " + i);
            }
            Assert.That(built.LagX, Is.Not.EqualTo(0), "the lateral lag was in play");
        }

        [Test]
        public void AnEndedHoldKeepsTheObjectWhereItIs()
        {
            var s = TwoHanded();
            double t = 0;
            s.BeginHold(At(0, 1, 0, t), 0, 1, 0);
            for (int i = 0; i < 5; i++) { t += Pose; s.Step(At(0.02 * (i + 1), 1 + 0.02 * (i + 1), 0, t), Pose); }
            double x = s.ObjectX, y = s.ObjectY, z = s.ObjectZ;
            s.EndHold();
            Assert.That(s.IsHolding, Is.False);
            Assert.That(s.Vertical.IsHolding, Is.False);
            t += Pose; s.Step(At(0.5, 1.5, 0.5, t), Pose);
            Assert.That(new[] { s.ObjectX, s.ObjectY, s.ObjectZ }, Is.EqualTo(new[] { x, y, z }));
        }

        [Test]
        public void AGrabOffsetPlacesTheObjectBelowTheFollowedPointAndNeedsAFollowableHand()
        {
            var s = TwoHanded();
            s.BeginHoldWithGrabOffset(At(-0.1, 1, 0, 0), At(0.1, 1.02, 0, 0), 0.05, 0.06, -0.02);
            Assert.That(s.ObjectY, Is.EqualTo(1.01 - 0.06).Within(1e-12), "below the midpoint of the hands");
            Assert.That(s.ObjectX, Is.EqualTo(0.05));
            Assert.That(s.ObjectZ, Is.EqualTo(-0.02));
            s.BeginHoldWithGrabOffset(HandPose.Lost, At(0.1, 1.0, 0, 0), 0, 0.1, 0);
            Assert.That(s.ObjectY, Is.EqualTo(0.9).Within(1e-12), "the second hand alone will do");
            var ex = Assert.Throws<ArgumentException>(() => s.BeginHoldWithGrabOffset(HandPose.Lost, HandPose.Lost, 0, 0.1, 0));
            Assert.That(ex.ParamName, Is.EqualTo("first"));
            Assert.That(ex.Message, Does.Contain("a grab offset needs a followable hand to place the object relative to."));
            var lowConfidence = new HandPose(0, 1, 0, true, false, 0);
            s.BeginHoldWithGrabOffset(lowConfidence, HandPose.Lost, 0, 0.1, 0);
            Assert.That(s.ObjectY, Is.EqualTo(0.9).Within(1e-12), "a low-confidence hand is followed (not remembered): it will do");
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => s.BeginHoldWithGrabOffset(At(0, 1, 0, 0), HandPose.Lost, 0, 2e5, 0)).ParamName,
                Is.EqualTo("grabOffsetY"));
            var oneHanded = new WeightSolver3D(WeightModel.FromMass(1), NamedProfiles.Paper);
            Assert.That(() => oneHanded.BeginHoldWithGrabOffset(HandPose.Lost, At(0.1, 1.0, 0, 0), 0, 0.1, 0), Throws.ArgumentException,
                "without two hands the second is not followed");
        }

        [Test]
        public void ALowConfidenceHandIsFollowedAndCarriesItsShare()
        {
            // A low-confidence pose is the hand the user sees: followed in every profile (the tracking-loss hold keeps it from
            // what the hold remembers, not from the object), and a second hand of low confidence carries its share.
            var low1 = new HandPose(-0.1, 1, 0, true, false, 0);
            var low2 = new HandPose(0.1, 1, 0, true, false, 0);
            foreach (var profile in new[] { NamedProfiles.Xyz, NamedProfiles.Xyz.With(new TrackingLossHold(requireHighConfidence: false)) })
            {
                var s = new WeightSolver3D(WeightModel.FromMass(2), profile);
                s.BeginHold(At(-0.1, 1, 0, 0), low2, 0, 1, 0);
                for (int i = 1; i <= 8; i++) s.Step(At(-0.1, 1, 0, i * Pose), new HandPose(0.1, 1, 0, true, false, i * Pose), Pose);
                Assert.That(s.FollowedHands, Is.EqualTo(2), profile.Name);
                Assert.That(s.PerHandMassKg, Is.EqualTo(1.0), profile.Name);
                s.BeginHoldWithGrabOffset(low1, HandPose.Lost, 0, 0.1, 0);
                Assert.That(s.ObjectY, Is.EqualTo(0.9).Within(1e-12), "relative to the low-confidence first hand");
                s.BeginHoldWithGrabOffset(HandPose.Lost, low2, 0, 0.1, 0);
                Assert.That(s.ObjectY, Is.EqualTo(0.9).Within(1e-12), "or second");
            }
        }

        [TestCase(true, true, true)]
        [TestCase(true, false, false)]
        [TestCase(false, true, false)]
        public void TheFollowedPointIsHighConfidenceOnlyWhenEveryFollowedHandIs(bool first, bool second, bool seen)
        {
            // Without the tracking-loss hold's requirement both hands are followed whatever their confidence; what a
            // scene's own effect reads as the frame's confidence is that of the least confident.
            var probe = new FrameProbe();
            var s = new WeightSolver3D(WeightModel.FromMass(2), NamedProfiles.Xyz.Without<TrackingLossHold>().With(probe));
            s.BeginHold(At(-0.1, 1, 0, 0), At(0.1, 1, 0, 0), 0, 1, 0);
            s.Step(new HandPose(-0.1, 1, 0, true, first, Pose), new HandPose(0.1, 1, 0, true, second, Pose), Pose);
            Assert.That(s.FollowedHands, Is.EqualTo(2));
            Assert.That(probe.Last.IsHighConfidence, Is.EqualTo(seen));
        }

        [Test]
        public void ARefusedBeginHoldChangesNothing()
        {
            // Bad configuration fails loudly, before anything moves: a running hold goes on as it was, a solver that
            // was not holding still is not.
            var fresh = TwoHanded();
            Assert.That(() => fresh.BeginHold(At(0, 1, 0, 0), 0, double.NaN, 0), Throws.InstanceOf<ArgumentOutOfRangeException>());
            Assert.That(fresh.IsHolding, Is.False);

            var held = TwoHanded();
            var twin = TwoHanded();
            double t = 0;
            held.BeginHold(At(0, 1, 0, t), 0, 1, 0);
            twin.BeginHold(At(0, 1, 0, t), 0, 1, 0);
            for (int i = 0; i < 20; i++)
            {
                t += Pose;
                var hand = At(0.01 * i, 1 + 0.02 * i, 0, t);
                held.Step(hand, Pose);
                twin.Step(hand, Pose);
                if (i == 10)
                {
                    Assert.That(() => held.BeginHold(At(0, 1, 0, t), 0, 2e5, 0), Throws.InstanceOf<ArgumentOutOfRangeException>());
                    Assert.That(() => held.BeginHold(At(0, 1, 0, t), double.NaN, 1, 0), Throws.InstanceOf<ArgumentOutOfRangeException>());
                    Assert.That(() => held.BeginHoldWithGrabOffset(At(0, 1, 0, t), HandPose.Lost, 0, double.NaN, 0), Throws.InstanceOf<ArgumentOutOfRangeException>());
                }
            }
            Assert.That(new[] { held.ObjectX, held.ObjectY, held.ObjectZ }, Is.EqualTo(new[] { twin.ObjectX, twin.ObjectY, twin.ObjectZ }));
        }

        [Test]
        public void ConfigurationFailsNamingWhatIsMissingAndAMassChangeTakesEffectMidHold()
        {
            var s = new WeightSolver3D(WeightModel.FromMass(1), NamedProfiles.Paper);
            Assert.That(Assert.Throws<ArgumentNullException>(() => s.Configure(null, NamedProfiles.Paper, 0.5)).ParamName, Is.EqualTo("model"));
            Assert.That(Assert.Throws<ArgumentNullException>(() => s.Configure(WeightModel.FromMass(1), null, 0.5)).ParamName, Is.EqualTo("profile"));
            Assert.That(new WeightSolver3D(WeightModel.FromMass(1)).Profile, Is.SameAs(NamedProfiles.Paper), "paper by default");
            Assert.That(new WeightSolver3D(WeightModel.FromMass(1), NamedProfiles.Xyz).Profile, Is.SameAs(NamedProfiles.Xyz), "else the one given");
            s.BeginHold(At(0, 1, 0, 0), 0, 1, 0);
            s.Configure(WeightModel.FromMass(3), NamedProfiles.Paper, 0.5);
            Assert.That(s.PerHandMassKg, Is.EqualTo(3.0));
            Assert.That(s.Vertical.Model.MassKg, Is.EqualTo(3.0), "the y solver carries the new mass now");
        }

        [Test]
        public void TheYSolverMeasuresSpeedAgainstTheLaterPoseTimeOfTheFollowedHands()
        {
            // Both hands 2 cm up: hand 1's pose is 1/32 s newer than the last, hand 2's only 1/64 s (it arrived late).
            // The followed point is as new as its newest pose: 0.02 m over 1/32 s is 0.64 m/s.
            var s = TwoHanded();
            s.BeginHold(At(-0.1, 1, 0, 0), At(0.1, 1, 0, 0), 0, 1, 0);
            s.Step(At(-0.1, 1.02, 0, Pose), At(0.1, 1.02, 0, Pose / 2), Pose);
            Assert.That(s.Vertical.State.Estimator.Speed, Is.EqualTo(0.64).Within(1e-12));
            s.Step(At(-0.1, 1.04, 0, 1.5 * Pose), At(0.1, 1.04, 0, 2 * Pose), Pose);
            Assert.That(s.Vertical.State.Estimator.Speed, Is.EqualTo(0.02 / Pose).Within(1e-12), "the newer is hand 2's now");

            // A hand that is tracked but not followed (it let go) lends the followed point nothing, not even its time.
            s.SetGrip(2, false);
            s.Step(At(-0.1, 1.06, 0, 2.5 * Pose), At(0.1, 1.06, 0, 9 * Pose), Pose);
            Assert.That(s.FollowedHands, Is.EqualTo(1));
            Assert.That(s.Vertical.State.Estimator.Speed, Is.EqualTo(0.02 / (0.5 * Pose)).Within(1e-12), "hand 1's time alone");

            // The same with hand 2 alone: its time, measured over a quarter pose (without it, over the frame's 1/32 s).
            s = TwoHanded();
            s.BeginHold(At(-0.1, 1, 0, 0), At(0.1, 1, 0, 0), 0, 1, 0);
            s.SetGrip(1, false);
            s.Step(At(-0.1, 1.02, 0, 9 * Pose), At(0.1, 1.02, 0, Pose / 4), Pose);
            Assert.That(s.Vertical.State.Estimator.Speed, Is.EqualTo(0.02 / (0.25 * Pose)).Within(1e-12), "hand 2's time alone");
        }

        [Test]
        public void AHandJoiningAFollowedHandWaitsForTheSettleTimeOfSteadyTracking([Values(1, 2)] int joining)
        {
            // Settle time 4/32 s, frames of 1/32 s: the joining hand is followed on its fourth steady frame; a frame
            // without it starts the wait again. Hands that come back together are followed at once.
            var s = new WeightSolver3D(WeightModel.FromMass(2), NamedProfiles.Xyz.With(new TrackingLossHold(4 * Pose)));
            double t = 0;
            HandPose One(bool shown) => joining == 1 && !shown ? HandPose.Lost : At(-0.1, 1, 0, t);
            HandPose Two(bool shown) => joining == 2 && !shown ? HandPose.Lost : At(0.1, 1, 0, t);
            int Step(bool shown) { t += Pose; s.Step(One(shown), Two(shown), Pose); return s.FollowedHands; }

            s.BeginHold(One(false), Two(false), 0, 1, 0);
            Assert.That(s.FollowedHands, Is.EqualTo(1));
            Assert.That(new[] { Step(true), Step(true), Step(false), Step(true), Step(true), Step(true) }, Is.EqualTo(new[] { 1, 1, 1, 1, 1, 1 }),
                "three steady frames, a drop, three more: not yet");
            Assert.That(Step(true), Is.EqualTo(2), "the fourth steady frame in a row");
            Assert.That(s.HoldingHands, Is.EqualTo(2));
            Assert.That(s.PerHandMassKg, Is.EqualTo(1.0), "each carries its half from the frame both hold");
            Assert.That(Step(false), Is.EqualTo(1));
            Assert.That(new[] { Step(true), Step(true), Step(true), Step(true) }, Is.EqualTo(new[] { 1, 1, 1, 2 }), "back: it waits again");

            t += Pose; s.Step(HandPose.Lost, HandPose.Lost, Pose);
            Assert.That(s.FollowedHands, Is.EqualTo(0));
            Assert.That(Step(true), Is.EqualTo(2), "both back together: followed at once");
        }
    }
}
