using System;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests.ThreeDimensions
{
    /// <summary>
    /// x and z are the same to the 3D layer (gravity is along y alone): a hold mirrored across the plane x = z moves
    /// mirrored. Over 150 seeds each, two hands under <c>xyz</c> (lateral inertia, two hands, height deceleration) and under
    /// <c>paper-experiment</c> with lateral inertia (no offset correction: break-away measured from the grab), on Quest-like
    /// input with jitter, each hand lost for a while, one letting go and gripping again elsewhere, a one-pose glitch, the
    /// object grabbed off the hands' midpoint: every frame, the mirrored run's x is the run's z and the other way round, and
    /// y, the strain and the counts are the same. A slip on one axis only (a re-anchoring, a grab offset or a mean that
    /// drops or misplaces z, say) breaks it; the tolerance is rounding's, 10⁻¹², since a sum of three squares is added in
    /// the other order when mirrored.
    /// </summary>
    public class AxisSymmetryTests
    {
        const double Tolerance = 1e-12;

        static HandPose Mirror(in HandPose p) => p.IsTracked ? new HandPose(p.Z, p.Y, p.X, p.IsTracked, p.IsHighConfidence, p.PoseTime) : p;

        [Test]
        public void AHoldMirroredAcrossXEqualsZMovesMirrored([Values("xyz", "paper-experiment+lateral")] string profileName, [Range(1, 150)] int seed)
        {
            // xyz measures break-away by the strain (offset correction); paper-experiment, without it, by distance from the grab.
            var profile = profileName == "xyz" ? NamedProfiles.Xyz : NamedProfiles.PaperExperiment.With(new LateralInertia(), profileName);
            var rng = new Random(seed);
            double R(double a, double b) => a + (b - a) * rng.NextDouble();
            double x1 = R(-0.3, 0), z1 = R(-0.2, 0.2), x2 = R(0, 0.3), z2 = R(-0.2, 0.2), carryX = R(-0.4, 0.4), carryZ = R(-0.4, 0.4);
            double lift = R(0.1, 0.5), start = R(0.2, 0.6);
            HandPath3D Hand(double hx, double hz) => (double t, out double x, out double y, out double z) =>
            {
                double s = Headset3D.MinJerk(t, start, 0.9, 0, 1);
                x = hx + carryX * s;
                y = 1.0 + lift * Headset3D.MinJerk(t, start - 0.1, 0.8, 0, 1);
                z = hz + carryZ * s;
            };
            var headset = new Headset3D { JitterSd = 0.002, Seed = seed, Wobble = 0.1 }
                .Drop(1, R(0.3, 1.0), R(0.05, 0.4))
                .Drop(2, R(0.5, 1.5), R(0.05, 0.6));
            var frames = headset.Render(Hand(x1, z1), Hand(x2, z2), 2.5);
            int glitchAt = rng.Next(30, frames.Count - 30), letGoAt = rng.Next(30, frames.Count - 60), gripAt = letGoAt + rng.Next(5, 40);
            int letGo = rng.Next(1, 3);
            double glitchX = R(-0.1, 0.1), glitchZ = R(-0.1, 0.1), massKg = R(0.05, 8);
            double objX = R(-0.1, 0.1), objZ = R(-0.1, 0.1);

            var run = new WeightSolver3D(WeightModel.FromMass(massKg), profile);
            var mirrored = new WeightSolver3D(WeightModel.FromMass(massKg), profile);
            run.BeginHold(frames.A[0], frames.B[0], objX, 1.0, objZ);
            mirrored.BeginHold(Mirror(frames.A[0]), Mirror(frames.B[0]), objZ, 1.0, objX);
            bool sideways = false;
            for (int i = 1; i < frames.Count; i++)
            {
                HandPose a = frames.A[i], b = frames.B[i];
                if (i == glitchAt && a.IsTracked) a = new HandPose(a.X + glitchX, a.Y, a.Z + glitchZ, true, true, a.PoseTime);
                if (i == letGoAt) { run.SetGrip(letGo, false); mirrored.SetGrip(letGo, false); }
                if (i == gripAt) { run.SetGrip(letGo, true); mirrored.SetGrip(letGo, true); }
                if (i >= gripAt && letGo == 1 && a.IsTracked) a = new HandPose(a.X + 0.05, a.Y, a.Z - 0.03, true, true, a.PoseTime);
                if (i >= gripAt && letGo == 2 && b.IsTracked) b = new HandPose(b.X - 0.04, b.Y, b.Z + 0.02, true, true, b.PoseTime);
                run.Step(a, b, frames.Dt[i]);
                mirrored.Step(Mirror(a), Mirror(b), frames.Dt[i]);

                string at = $"seed {seed}, frame {i}";
                Assert.That(mirrored.ObjectX, Is.EqualTo(run.ObjectZ).Within(Tolerance), "x ↔ z, " + at);
                Assert.That(mirrored.ObjectZ, Is.EqualTo(run.ObjectX).Within(Tolerance), "z ↔ x, " + at);
                Assert.That(mirrored.ObjectY, Is.EqualTo(run.ObjectY).Within(Tolerance), "y, " + at);
                Assert.That(mirrored.FollowedX, Is.EqualTo(run.FollowedZ).Within(Tolerance), "followed x ↔ z, " + at);
                Assert.That(mirrored.LagX, Is.EqualTo(run.LagZ).Within(Tolerance), "lag x ↔ z, " + at);
                Assert.That(mirrored.LagZ, Is.EqualTo(run.LagX).Within(Tolerance), "lag z ↔ x, " + at);
                Assert.That(mirrored.Strain, Is.EqualTo(run.Strain).Within(Tolerance), "strain, " + at);
                Assert.That(mirrored.BreakAwayMeasure, Is.EqualTo(run.BreakAwayMeasure).Within(Tolerance), "break-away measure, " + at);
                Assert.That(mirrored.FollowedHands, Is.EqualTo(run.FollowedHands), "followed hands, " + at);
                Assert.That(mirrored.HoldingHands, Is.EqualTo(run.HoldingHands), "holding hands, " + at);
                sideways |= Math.Abs(run.LagX) > 1e-3 && Math.Abs(run.LagZ) > 1e-3;
            }
            Assert.That(run.IsHolding, Is.True, "seed " + seed);
            if (Math.Abs(carryX) > 0.2 && Math.Abs(carryZ) > 0.2 && massKg > 1)
                Assert.That(sideways, Is.True, $"seed {seed}: a heavy object carried both ways lags on both axes");
        }
    }
}
