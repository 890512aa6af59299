using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests.ThreeDimensions
{
    /// <summary>
    /// The 3D layer's plausibility gate at its exact edge (<see cref="SolverLimits.WorkspaceRadius"/>: "a pose farther than
    /// this from where the hold began is not tracked"): along each axis, either way, a hand exactly the radius from the
    /// grab is followed and one a micrometre further is not. The radius is 2 m and the offsets exact in binary; the hand
    /// was lost for 2 s first, so reach allows any place within the workspace.
    /// </summary>
    public class WorkspaceBoundaryTests
    {
        const double X0 = 0.5, Z0 = -0.25; // the grab, off every axis

        static int FollowedAfterALossAt(int axis, double offset)
        {
            var profile = NamedProfiles.Xyz.WithLimits(new SolverLimits(workspaceRadius: 2));
            var s = new WeightSolver3D(WeightModel.FromMass(1), profile);
            s.BeginHold(Run3D.At(X0, 1, Z0, 0), X0, 1, Z0);
            for (int i = 0; i < 180; i++) s.Step(HandPose.Lost, 1 / 90.0);
            double x = X0 + (axis == 0 ? offset : 0), y = 1 + (axis == 1 ? offset : 0), z = Z0 + (axis == 2 ? offset : 0);
            s.Step(Run3D.At(x, y, z, 2.0), 1 / 90.0);
            return s.FollowedHands;
        }

        [Test]
        public void AHandExactlyTheRadiusFromTheGrabIsFollowedAndOneFurtherIsNot([Values(0, 1, 2)] int axis, [Values(1.0, -1.0)] double sign)
        {
            Assert.That(FollowedAfterALossAt(axis, 2 * sign), Is.EqualTo(1), "exactly 2 m from the grab");
            Assert.That(FollowedAfterALossAt(axis, 2.000001 * sign), Is.EqualTo(0), "2 m and a micrometre");
            Assert.That(FollowedAfterALossAt(axis, 1.9 * sign), Is.EqualTo(1), "well within");
        }
    }
}
