using System;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// The world pose of the tracking origin (the rig: the space the headset reports hands in) as a position and
    /// a heading about +y, as Unity's <c>Quaternion.Euler(0, yaw, 0)</c>: a point p in the rig's frame lies at
    /// <c>position + R_y(yaw)·p</c> in the world, with Unity's left-handed convention
    /// R_y(θ)·(x, y, z) = (x cos θ + z sin θ, y, −x sin θ + z cos θ). The solver works in the rig's frame (issue 26),
    /// so what the rig does (walking, turning, teleporting, riding) carries the object rigidly and only the hand's
    /// own motion is weighed.
    /// </summary>
    public readonly struct RigFrame
    {
        public readonly double X;
        public readonly double Y;
        public readonly double Z;

        /// <summary>Degrees about +y.</summary>
        public readonly double YawDegrees;

        readonly double _cos;
        readonly double _sin;

        public RigFrame(double x, double y, double z, double yawDegrees)
        {
            X = x;
            Y = y;
            Z = z;
            YawDegrees = yawDegrees;
            double radians = yawDegrees * (Math.PI / 180.0);
            _cos = Math.Cos(radians);
            _sin = Math.Sin(radians);
        }

        /// <summary>The rig at the world's origin, unturned: rig and world frames coincide.</summary>
        public static RigFrame Origin => new RigFrame(0, 0, 0, 0);

        /// <summary>A world point in the rig's frame: R_y(−yaw)·(p − position). NaN stays NaN (x and z mix).</summary>
        public void ToRig(double x, double y, double z, out double rigX, out double rigY, out double rigZ)
        {
            double dx = x - X, dz = z - Z;
            rigX = dx * _cos - dz * _sin;
            rigY = y - Y;
            rigZ = dx * _sin + dz * _cos;
        }

        /// <summary>A point of the rig's frame in the world: position + R_y(yaw)·p.</summary>
        public void ToWorld(double x, double y, double z, out double worldX, out double worldY, out double worldZ)
        {
            worldX = X + x * _cos + z * _sin;
            worldY = Y + y;
            worldZ = Z - x * _sin + z * _cos;
        }

        /// <summary>A world hand pose in the rig's frame; tracking, confidence and time stay as they are.</summary>
        public HandPose ToRig(in HandPose world)
        {
            ToRig(world.X, world.Y, world.Z, out double x, out double y, out double z);
            return new HandPose(x, y, z, world.IsTracked, world.IsHighConfidence, world.PoseTime);
        }
    }
}
