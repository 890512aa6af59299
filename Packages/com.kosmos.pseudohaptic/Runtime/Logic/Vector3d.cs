using System;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// A point or displacement in metres, in doubles, for the engine-free decisions of the Unity layer. Its own
    /// small struct rather than <c>System.Numerics.Vector3</c> (which netstandard2.1 and Unity both have): the
    /// core computes in doubles, a file that says <c>using UnityEngine; using System.Numerics;</c> would find
    /// <c>Vector3</c> ambiguous, and nothing here needs SIMD. The Unity layer converts at its edge.
    /// </summary>
    public readonly struct Vector3d : IEquatable<Vector3d>
    {
        public readonly double X, Y, Z;

        public Vector3d(double x, double y, double z)
        {
            X = x;
            Y = y;
            Z = z;
        }

        public static readonly Vector3d Zero = new Vector3d(0, 0, 0);
        public static readonly Vector3d NaN = new Vector3d(double.NaN, double.NaN, double.NaN);

        public double Length => Math.Sqrt(X * X + Y * Y + Z * Z);
        public double SqrLength => X * X + Y * Y + Z * Z;

        /// <summary>Every coordinate is finite.</summary>
        public bool IsFinite => double.IsFinite(X) && double.IsFinite(Y) && double.IsFinite(Z);

        public static Vector3d operator +(Vector3d a, Vector3d b) => new Vector3d(a.X + b.X, a.Y + b.Y, a.Z + b.Z);
        public static Vector3d operator -(Vector3d a, Vector3d b) => new Vector3d(a.X - b.X, a.Y - b.Y, a.Z - b.Z);
        public static Vector3d operator -(Vector3d a) => new Vector3d(-a.X, -a.Y, -a.Z);
        public static Vector3d operator *(Vector3d a, double k) => new Vector3d(a.X * k, a.Y * k, a.Z * k);
        public static Vector3d operator /(Vector3d a, double k) => new Vector3d(a.X / k, a.Y / k, a.Z / k);

        public static double Distance(Vector3d a, Vector3d b) => (a - b).Length;

        public bool Equals(Vector3d other) => X.Equals(other.X) && Y.Equals(other.Y) && Z.Equals(other.Z);
        public override bool Equals(object obj) => obj is Vector3d v && Equals(v);
        public override int GetHashCode() => X.GetHashCode() ^ (Y.GetHashCode() * 397) ^ (Z.GetHashCode() * 7919);
        public override string ToString() =>
            "(" + X.ToString("0.####", System.Globalization.CultureInfo.InvariantCulture) + ", "
            + Y.ToString("0.####", System.Globalization.CultureInfo.InvariantCulture) + ", "
            + Z.ToString("0.####", System.Globalization.CultureInfo.InvariantCulture) + ")";
    }
}
