using System;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>
    /// <see cref="RigFrame"/>: the tracking origin's world pose (issue 26) as Unity's <c>Quaternion.Euler(0, yaw, 0)</c>
    /// with a position. Expected values are written from Unity's left-handed convention (a turn of +90° about +y takes
    /// forward, +z, to the right, +x, and +x to −z), with cos 30° = √3/2 and sin 30° = 1/2 written out, never from the
    /// struct's own trigonometry; round trips and distances over many seeds.
    /// </summary>
    public class RigFrameTests
    {
        const double Exact = 1e-12;
        static readonly double Cos30 = Math.Sqrt(3) / 2, Sin30 = 0.5;

        static void AssertPoint(double x, double y, double z, double ex, double ey, double ez, double within, string what)
        {
            Assert.That(x, Is.EqualTo(ex).Within(within), what + ": x");
            Assert.That(y, Is.EqualTo(ey).Within(within), what + ": y");
            Assert.That(z, Is.EqualTo(ez).Within(within), what + ": z");
        }

        [Test]
        public void AQuarterTurnTakesForwardToTheRightAndTheRightToBack()
        {
            var rig = new RigFrame(0, 0, 0, 90);
            rig.ToWorld(0, 0, 1, out double x, out double y, out double z);
            AssertPoint(x, y, z, 1, 0, 0, Exact, "the rig's forward (+z) is the world's right (+x)");
            rig.ToWorld(1, 0, 0, out x, out y, out z);
            AssertPoint(x, y, z, 0, 0, -1, Exact, "the rig's right (+x) is the world's back (−z)");
            rig.ToWorld(0, 2, 0, out x, out y, out z);
            AssertPoint(x, y, z, 0, 2, 0, Exact, "up stays up");
            rig.ToRig(1, 0, 0, out x, out y, out z);
            AssertPoint(x, y, z, 0, 0, 1, Exact, "the world's right is the rig's forward");
            rig.ToRig(0, 0, -1, out x, out y, out z);
            AssertPoint(x, y, z, 1, 0, 0, Exact, "the world's back is the rig's right");

            var left = new RigFrame(0, 0, 0, -90);
            left.ToWorld(1, 0, 0, out x, out y, out z);
            AssertPoint(x, y, z, 0, 0, 1, Exact, "a quarter turn the other way takes +x to +z");
            var half = new RigFrame(0, 0, 0, 180);
            half.ToWorld(0.3, 0.7, 0.4, out x, out y, out z);
            AssertPoint(x, y, z, -0.3, 0.7, -0.4, Exact, "a half turn faces the other way");
        }

        /// <summary>A rig standing at (2, 1.5, −3), turned 30°: the point (1, 0.25, 2) of its frame lies at
        /// (2 + cos 30° + 2 sin 30°, 1.75, −3 − sin 30° + 2 cos 30°) in the world, and back.</summary>
        [Test]
        public void ATurnedAndMovedRigPlacesAPointAsUnityWould([Values(30.0, 390.0, -330.0)] double yaw)
        {
            var rig = new RigFrame(2, 1.5, -3, yaw);
            double ex = 2 + 1 * Cos30 + 2 * Sin30, ey = 1.5 + 0.25, ez = -3 - 1 * Sin30 + 2 * Cos30;
            rig.ToWorld(1, 0.25, 2, out double x, out double y, out double z);
            AssertPoint(x, y, z, ex, ey, ez, 1e-9, $"to the world at yaw {yaw}°");
            rig.ToRig(ex, ey, ez, out x, out y, out z);
            AssertPoint(x, y, z, 1, 0.25, 2, 1e-9, $"to the rig at yaw {yaw}°");
            Assert.That(rig.YawDegrees, Is.EqualTo(yaw));
        }

        [Test]
        public void AnUnturnedRigOnlyTranslates()
        {
            var rig = new RigFrame(1.25, -0.5, 3.75, 0);
            rig.ToRig(2, 1, 1, out double x, out double y, out double z);
            AssertPoint(x, y, z, 0.75, 1.5, -2.75, 0, "world to rig: minus the rig's position, exactly");
            rig.ToWorld(0.75, 1.5, -2.75, out x, out y, out z);
            AssertPoint(x, y, z, 2, 1, 1, 0, "rig to world: plus it");
            RigFrame.Origin.ToRig(0.3, -7, 11, out x, out y, out z);
            AssertPoint(x, y, z, 0.3, -7, 11, 0, "at the origin, unturned, the frames coincide");
        }

        [Test]
        public void RoundTripsAreExactAndDistancesKeptOverManySeeds()
        {
            for (int seed = 0; seed < 500; seed++)
            {
                var random = new Random(seed);
                double U(double range) => (random.NextDouble() * 2 - 1) * range;
                var rig = new RigFrame(U(100), U(10), U(100), U(720));
                double px = U(100), py = U(10), pz = U(100), qx = U(100), qy = U(10), qz = U(100);

                rig.ToRig(px, py, pz, out double rx, out double ry, out double rz);
                rig.ToWorld(rx, ry, rz, out double wx, out double wy, out double wz);
                AssertPoint(wx, wy, wz, px, py, pz, 1e-9, $"seed {seed}: world → rig → world");
                rig.ToWorld(px, py, pz, out wx, out wy, out wz);
                rig.ToRig(wx, wy, wz, out rx, out ry, out rz);
                AssertPoint(rx, ry, rz, px, py, pz, 1e-9, $"seed {seed}: rig → world → rig");

                // Rigid: the distance between two points, and each one's height above the other, are the same in both frames.
                rig.ToRig(px, py, pz, out double ax, out double ay, out double az);
                rig.ToRig(qx, qy, qz, out double bx, out double by, out double bz);
                double world = Math.Sqrt((px - qx) * (px - qx) + (py - qy) * (py - qy) + (pz - qz) * (pz - qz));
                double inRig = Math.Sqrt((ax - bx) * (ax - bx) + (ay - by) * (ay - by) + (az - bz) * (az - bz));
                Assert.That(inRig, Is.EqualTo(world).Within(1e-9), $"seed {seed}: distance");
                Assert.That(ay - by, Is.EqualTo(py - qy).Within(1e-9), $"seed {seed}: heights");

                // The rig's own origin is its world position.
                rig.ToWorld(0, 0, 0, out wx, out wy, out wz);
                AssertPoint(wx, wy, wz, rig.X, rig.Y, rig.Z, 0, $"seed {seed}: the rig's origin");
            }
        }

        [Test]
        public void AHandPoseMovesIntoTheRigAndKeepsItsTrackingConfidenceAndTime()
        {
            var rig = new RigFrame(2, 1.5, -3, 90);
            var world = new HandPose(2 + 0.2, 1.5 + 0.4, -3 - 0.1, isTracked: false, isHighConfidence: false, poseTime: 12.5);
            var inRig = rig.ToRig(world);
            // World offset (0.2, 0.4, −0.1) from the rig, turned back by 90°: (x, z) ↦ (−z, x).
            AssertPoint(inRig.X, inRig.Y, inRig.Z, 0.1, 0.4, 0.2, Exact, "the pose's position");
            Assert.That(inRig.IsTracked, Is.False);
            Assert.That(inRig.IsHighConfidence, Is.False);
            Assert.That(inRig.PoseTime, Is.EqualTo(12.5));
            var tracked = rig.ToRig(new HandPose(2, 1.5, -3, true, true, 3));
            Assert.That(tracked.IsTracked && tracked.IsHighConfidence, Is.True);
            Assert.That(tracked.PoseTime, Is.EqualTo(3));
        }
    }
}
