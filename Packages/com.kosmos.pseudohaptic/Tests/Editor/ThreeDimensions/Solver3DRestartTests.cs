using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests.ThreeDimensions
{
    /// <summary>
    /// What a new hold and a new grasp start from, for survivors of the 3d-2 mutation run (quality.md, "In pieces"): each
    /// hold, and each hand that grips again, is judged for reach afresh (the pose it last held does not put its new grasp
    /// out of a hand's reach), and a hold begun without a tracked hand has no grab to break away from until a hand is seen.
    /// Every pose is within the workspace; the jumps are 0.5 m, beyond the 0.33 m a hand can cover in one 30 Hz pose
    /// period at the default 10 m/s.
    /// </summary>
    public class Solver3DRestartTests
    {
        // The tracking-loss hold's settle time would make a regripping second hand wait; without it, it joins at once.
        static readonly WeightProfile TwoHandsNoSettle =
            NamedProfiles.Paper.Without<TrackingLossHold>("paper-no-loss-hold").With(new TwoHands(), "paper-no-loss-hold+two-hands");

        const double Dt = 1 / 90.0;

        [Test]
        public void ANewHoldFollowsItsHandWhereverTheLastHoldEnded()
        {
            var s = new WeightSolver3D(WeightModel.FromMass(1));
            s.BeginHold(Run3D.At(0, 1, 0, 0), 0, 1, 0);
            s.Step(Run3D.At(0, 1, 0, Dt), Dt);
            s.EndHold();
            s.BeginHold(Run3D.At(0, 1.5, 0, 2 * Dt), 0, 1.5, 0);
            Assert.That(s.FollowedHands, Is.EqualTo(1), "the new hold's hand, 0.5 m from where the last hold's was 11 ms before");
            Assert.That(s.FollowedY, Is.EqualTo(1.5));
        }

        [Test]
        public void ANewTwoHandHoldFollowsBothHandsWhereverTheLastHoldEnded()
        {
            var s = new WeightSolver3D(WeightModel.FromMass(1), TwoHandsNoSettle);
            s.BeginHold(Run3D.At(-0.15, 1, 0, 0), Run3D.At(0.15, 1, 0, 0), 0, 1, 0);
            s.Step(Run3D.At(-0.15, 1, 0, Dt), Run3D.At(0.15, 1, 0, Dt), Dt);
            Assert.That(s.FollowedHands, Is.EqualTo(2));
            s.EndHold();
            s.BeginHold(Run3D.At(-0.15, 1, 0, 2 * Dt), Run3D.At(0.15, 1.5, 0, 2 * Dt), 0, 1.25, 0);
            Assert.That(s.FollowedHands, Is.EqualTo(2), "the second hand 0.5 m from where it was in the last hold");
            Assert.That(s.FollowedY, Is.EqualTo(1.25));
        }

        [Test]
        public void AHandThatGripsAgainIsFollowedWhereItGrips([Values(1, 2)] int hand)
        {
            var s = new WeightSolver3D(WeightModel.FromMass(1), TwoHandsNoSettle);
            double t = 0;
            HandPose first = Run3D.At(-0.15, 1, 0, t), second = Run3D.At(0.15, 1, 0, t);
            s.BeginHold(first, second, 0, 1, 0);
            for (int i = 0; i < 10; i++)
            {
                t += Dt;
                s.Step(Run3D.At(-0.15, 1, 0, t), Run3D.At(0.15, 1, 0, t), Dt);
            }
            s.SetGrip(hand, false);
            t += Dt;
            s.Step(Run3D.At(-0.15, 1, 0, t), Run3D.At(0.15, 1, 0, t), Dt);
            Assert.That(s.FollowedHands, Is.EqualTo(1));

            // The same slot grips again 0.5 m higher one frame later (another grasp, or the hand regripping elsewhere).
            s.SetGrip(hand, true);
            t += Dt;
            double y1 = hand == 1 ? 1.5 : 1, y2 = hand == 2 ? 1.5 : 1;
            s.Step(Run3D.At(-0.15, y1, 0, t), Run3D.At(0.15, y2, 0, t), Dt);
            Assert.That(s.FollowedHands, Is.EqualTo(2), "the regripping hand is judged afresh, not against the pose it let go at");
            Assert.That(s.HoldingHands, Is.EqualTo(2));
        }

        [Test]
        public void AHoldBegunUntrackedHasNothingToBreakAwayFromUntilAHandIsSeen()
        {
            // paper-experiment has no offset correction: the measure is the followed point's distance from the object, less
            // the one at the grab, and there is no grab before a hand is seen.
            var s = new WeightSolver3D(WeightModel.FromMass(1), NamedProfiles.PaperExperiment);
            s.BeginHold(HandPose.Lost, 1, 1.2, 1);
            Assert.That(s.BreakAwayMeasure, Is.EqualTo(0.0));
            s.Step(HandPose.Lost, Dt);
            Assert.That(s.BreakAwayMeasure, Is.EqualTo(0.0));
            s.Step(Run3D.At(0.3, 1.0, 0.2, Dt), Dt);
            Assert.That(s.FollowedHands, Is.EqualTo(1));
            Assert.That(s.BreakAwayMeasure, Is.EqualTo(0.0).Within(1e-12), "the grab is where the first hand was seen");
        }
    }
}
