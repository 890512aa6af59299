// Test double of UnityEngine's value types, with Unity's documented semantics (single-precision maths, Vector3 ==
// within 1e-5, Quaternion products as Unity composes rotations, Bounds as an AABB). Public members are those of
// Unity-Technologies/UnityCsReference 2022.3 (Runtime/Export/Math/Vector3.cs, Vector2.cs, Quaternion.cs, Color.cs,
// Mathf.cs, Runtime/Export/Geometry/Rect.cs, Bounds.cs, Runtime/Export/XR/Pose.cs) that the package or the double
// uses; the bodies are written here from Unity's documentation, not copied.
using System;

namespace UnityEngine
{
    public struct Vector3 : IEquatable<Vector3>
    {
        public const float kEpsilon = 0.00001F;
        public float x;
        public float y;
        public float z;

        public Vector3(float x, float y, float z)
        {
            this.x = x;
            this.y = y;
            this.z = z;
        }

        public Vector3(float x, float y)
        {
            this.x = x;
            this.y = y;
            z = 0F;
        }

        public static Vector3 zero => new Vector3(0F, 0F, 0F);
        public static Vector3 one => new Vector3(1F, 1F, 1F);
        public static Vector3 up => new Vector3(0F, 1F, 0F);
        public static Vector3 down => new Vector3(0F, -1F, 0F);
        public static Vector3 right => new Vector3(1F, 0F, 0F);
        public static Vector3 left => new Vector3(-1F, 0F, 0F);
        public static Vector3 forward => new Vector3(0F, 0F, 1F);
        public static Vector3 back => new Vector3(0F, 0F, -1F);

        public float sqrMagnitude => x * x + y * y + z * z;
        public float magnitude => (float)Math.Sqrt(x * x + y * y + z * z);

        public Vector3 normalized
        {
            get
            {
                float m = magnitude;
                return m > kEpsilon ? this / m : zero;
            }
        }

        public static float Dot(Vector3 a, Vector3 b) => a.x * b.x + a.y * b.y + a.z * b.z;

        public static Vector3 Cross(Vector3 a, Vector3 b) =>
            new Vector3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);

        public static float Distance(Vector3 a, Vector3 b) => (a - b).magnitude;

        public static Vector3 Scale(Vector3 a, Vector3 b) => new Vector3(a.x * b.x, a.y * b.y, a.z * b.z);

        /// <summary>Clamped to t in [0, 1], as Unity's Lerp.</summary>
        public static Vector3 Lerp(Vector3 a, Vector3 b, float t)
        {
            t = Mathf.Clamp01(t);
            return new Vector3(a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t, a.z + (b.z - a.z) * t);
        }

        public static Vector3 ProjectOnPlane(Vector3 vector, Vector3 planeNormal)
        {
            float sqr = Dot(planeNormal, planeNormal);
            if (sqr < Mathf.Epsilon) return vector;
            return vector - planeNormal * (Dot(vector, planeNormal) / sqr);
        }

        public static Vector3 operator +(Vector3 a, Vector3 b) => new Vector3(a.x + b.x, a.y + b.y, a.z + b.z);
        public static Vector3 operator -(Vector3 a, Vector3 b) => new Vector3(a.x - b.x, a.y - b.y, a.z - b.z);
        public static Vector3 operator -(Vector3 a) => new Vector3(-a.x, -a.y, -a.z);
        public static Vector3 operator *(Vector3 a, float d) => new Vector3(a.x * d, a.y * d, a.z * d);
        public static Vector3 operator *(float d, Vector3 a) => new Vector3(a.x * d, a.y * d, a.z * d);
        public static Vector3 operator /(Vector3 a, float d) => new Vector3(a.x / d, a.y / d, a.z / d);

        /// <summary>Unity's ==: the vectors differ by less than 1e-5 in length.</summary>
        public static bool operator ==(Vector3 lhs, Vector3 rhs)
        {
            float dx = lhs.x - rhs.x, dy = lhs.y - rhs.y, dz = lhs.z - rhs.z;
            return dx * dx + dy * dy + dz * dz < kEpsilon * kEpsilon;
        }

        public static bool operator !=(Vector3 lhs, Vector3 rhs) => !(lhs == rhs);

        /// <summary>Exact, as Unity's Equals.</summary>
        public bool Equals(Vector3 other) => x == other.x && y == other.y && z == other.z;
        public override bool Equals(object other) => other is Vector3 v && Equals(v);
        public override int GetHashCode() => x.GetHashCode() ^ (y.GetHashCode() << 2) ^ (z.GetHashCode() >> 2);

        public override string ToString() => "(" + x.ToString("F2", System.Globalization.CultureInfo.InvariantCulture) + ", "
            + y.ToString("F2", System.Globalization.CultureInfo.InvariantCulture) + ", " + z.ToString("F2", System.Globalization.CultureInfo.InvariantCulture) + ")";
    }

    public struct Vector2 : IEquatable<Vector2>
    {
        public float x;
        public float y;

        public Vector2(float x, float y)
        {
            this.x = x;
            this.y = y;
        }

        public bool Equals(Vector2 other) => x == other.x && y == other.y;
        public override bool Equals(object other) => other is Vector2 v && Equals(v);
        public override int GetHashCode() => x.GetHashCode() ^ (y.GetHashCode() << 2);
    }

    /// <summary>A unit quaternion (x, y, z, w); products compose rotations right to left, as in Unity.</summary>
    public struct Quaternion : IEquatable<Quaternion>
    {
        public float x;
        public float y;
        public float z;
        public float w;

        public Quaternion(float x, float y, float z, float w)
        {
            this.x = x;
            this.y = y;
            this.z = z;
            this.w = w;
        }

        public static Quaternion identity => new Quaternion(0F, 0F, 0F, 1F);

        public static Quaternion operator *(Quaternion a, Quaternion b) => new Quaternion(
            a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
            a.w * b.y + a.y * b.w + a.z * b.x - a.x * b.z,
            a.w * b.z + a.z * b.w + a.x * b.y - a.y * b.x,
            a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z);

        /// <summary>Rotates the point.</summary>
        public static Vector3 operator *(Quaternion q, Vector3 p)
        {
            // v' = v + 2w(u × v) + 2u × (u × v), u = (x, y, z)
            var u = new Vector3(q.x, q.y, q.z);
            Vector3 t = 2F * Vector3.Cross(u, p);
            return p + q.w * t + Vector3.Cross(u, t);
        }

        public static Quaternion Inverse(Quaternion q)
        {
            float n = q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w;
            return n > 0 ? new Quaternion(-q.x / n, -q.y / n, -q.z / n, q.w / n) : identity;
        }

        public static Quaternion AngleAxis(float angle, Vector3 axis)
        {
            Vector3 n = axis.normalized;
            if (n.sqrMagnitude == 0) return identity;
            double half = angle * Math.PI / 360.0;
            float s = (float)Math.Sin(half);
            return new Quaternion(n.x * s, n.y * s, n.z * s, (float)Math.Cos(half));
        }

        /// <summary>Unity's order: z, then x, then y (extrinsic), degrees.</summary>
        public static Quaternion Euler(float x, float y, float z) =>
            AngleAxis(y, Vector3.up) * AngleAxis(x, Vector3.right) * AngleAxis(z, Vector3.forward);

        public static Quaternion Euler(Vector3 euler) => Euler(euler.x, euler.y, euler.z);

        public static float Dot(Quaternion a, Quaternion b) => a.x * b.x + a.y * b.y + a.z * b.z + a.w * b.w;

        /// <summary>The angle between two rotations, degrees.</summary>
        public static float Angle(Quaternion a, Quaternion b)
        {
            float dot = Math.Min(Math.Abs(Dot(a, b)), 1F);
            return dot > 1F - 1e-6F ? 0F : (float)(2.0 * Math.Acos(dot) * 180.0 / Math.PI);
        }

        public Vector3 eulerAngles
        {
            get
            {
                // Inverse of Euler(): y (yaw) from the rotated forward, x (pitch), then z (roll).
                Vector3 f = this * Vector3.forward, u = this * Vector3.up;
                float pitch = (float)(Math.Asin(Mathf.Clamp(-f.y, -1F, 1F)) * 180.0 / Math.PI);
                float yaw = (float)(Math.Atan2(f.x, f.z) * 180.0 / Math.PI);
                Quaternion noRoll = Euler(pitch, yaw, 0F);
                Vector3 u0 = noRoll * Vector3.up;
                float roll = (float)(Math.Atan2(Vector3.Dot(Vector3.Cross(u0, u), f), Vector3.Dot(u0, u)) * 180.0 / Math.PI);
                return new Vector3(Repeat360(pitch), Repeat360(yaw), Repeat360(roll));
            }
        }

        static float Repeat360(float a) => a < 0 ? a + 360F : a;

        public bool Equals(Quaternion other) => x == other.x && y == other.y && z == other.z && w == other.w;
        public override bool Equals(object other) => other is Quaternion q && Equals(q);
        public override int GetHashCode() => x.GetHashCode() ^ (y.GetHashCode() << 2) ^ (z.GetHashCode() >> 2) ^ (w.GetHashCode() >> 1);
        public static bool operator ==(Quaternion a, Quaternion b) => Dot(a, b) > 1F - 1e-6F;
        public static bool operator !=(Quaternion a, Quaternion b) => !(a == b);
    }

    public struct Color : IEquatable<Color>
    {
        public float r;
        public float g;
        public float b;
        public float a;

        public Color(float r, float g, float b, float a)
        {
            this.r = r;
            this.g = g;
            this.b = b;
            this.a = a;
        }

        public Color(float r, float g, float b)
        {
            this.r = r;
            this.g = g;
            this.b = b;
            a = 1f;
        }

        public bool Equals(Color other) => r == other.r && g == other.g && b == other.b && a == other.a;
        public override bool Equals(object other) => other is Color c && Equals(c);
        public override int GetHashCode() => r.GetHashCode() ^ (g.GetHashCode() << 2) ^ (b.GetHashCode() >> 2) ^ (a.GetHashCode() >> 1);
    }

    public struct Rect : IEquatable<Rect>
    {
        float _x, _y, _width, _height;

        public Rect(float x, float y, float width, float height)
        {
            _x = x;
            _y = y;
            _width = width;
            _height = height;
        }

        public float x { get => _x; set => _x = value; }
        public float y { get => _y; set => _y = value; }
        public float width { get => _width; set => _width = value; }
        public float height { get => _height; set => _height = value; }

        /// <summary>Moving the left edge keeps the right edge where it is.</summary>
        public float xMin { get => _x; set { float max = xMax; _x = value; _width = max - _x; } }
        public float xMax { get => _x + _width; set => _width = value - _x; }
        public float yMax { get => _y + _height; set => _height = value - _y; }

        public bool Equals(Rect other) => _x == other._x && _y == other._y && _width == other._width && _height == other._height;
        public override bool Equals(object other) => other is Rect r && Equals(r);
        public override int GetHashCode() => _x.GetHashCode() ^ (_width.GetHashCode() << 2) ^ (_y.GetHashCode() >> 2) ^ (_height.GetHashCode() >> 1);
    }

    /// <summary>An axis-aligned box: centre and half-size.</summary>
    public struct Bounds : IEquatable<Bounds>
    {
        Vector3 _center, _extents;

        public Bounds(Vector3 center, Vector3 size)
        {
            _center = center;
            _extents = size * 0.5F;
        }

        public Vector3 center { get => _center; set => _center = value; }
        public Vector3 extents { get => _extents; set => _extents = value; }
        public Vector3 size { get => _extents * 2F; set => _extents = value * 0.5F; }
        public Vector3 min { get => _center - _extents; set => SetMinMax(value, max); }
        public Vector3 max { get => _center + _extents; set => SetMinMax(min, value); }

        public void SetMinMax(Vector3 min, Vector3 max)
        {
            _extents = (max - min) * 0.5F;
            _center = min + _extents;
        }

        public void Encapsulate(Vector3 point) => SetMinMax(
            new Vector3(Math.Min(min.x, point.x), Math.Min(min.y, point.y), Math.Min(min.z, point.z)),
            new Vector3(Math.Max(max.x, point.x), Math.Max(max.y, point.y), Math.Max(max.z, point.z)));

        public bool Contains(Vector3 point)
        {
            Vector3 lo = min, hi = max;
            return point.x >= lo.x && point.x <= hi.x && point.y >= lo.y && point.y <= hi.y && point.z >= lo.z && point.z <= hi.z;
        }

        public bool Intersects(Bounds other)
        {
            Vector3 a = min, b = max, c = other.min, d = other.max;
            return a.x <= d.x && b.x >= c.x && a.y <= d.y && b.y >= c.y && a.z <= d.z && b.z >= c.z;
        }

        /// <summary>The point of the box nearest <paramref name="point"/> (the point itself when inside).</summary>
        public Vector3 ClosestPoint(Vector3 point)
        {
            Vector3 lo = min, hi = max;
            return new Vector3(Mathf.Clamp(point.x, lo.x, hi.x), Mathf.Clamp(point.y, lo.y, hi.y), Mathf.Clamp(point.z, lo.z, hi.z));
        }

        public bool Equals(Bounds other) => _center.Equals(other._center) && _extents.Equals(other._extents);
        public override bool Equals(object other) => other is Bounds b && Equals(b);
        public override int GetHashCode() => _center.GetHashCode() ^ (_extents.GetHashCode() << 2);
    }

    public partial struct Mathf
    {
        public const float PI = (float)Math.PI;
        public static readonly float Epsilon = float.Epsilon;

        public static int CeilToInt(float f) => (int)Math.Ceiling(f);
        public static float Clamp(float value, float min, float max) => value < min ? min : value > max ? max : value;
        public static float Clamp01(float value) => Clamp(value, 0F, 1F);
        public static float Min(float a, float b) => a < b ? a : b;
        public static float Max(float a, float b) => a > b ? a : b;
        public static float Abs(float f) => Math.Abs(f);
        public static float Sqrt(float f) => (float)Math.Sqrt(f);
    }

    /// <summary>A position and a rotation.</summary>
    public struct Pose : IEquatable<Pose>
    {
        public Vector3 position;
        public Quaternion rotation;

        public Pose(Vector3 position, Quaternion rotation)
        {
            this.position = position;
            this.rotation = rotation;
        }

        public static Pose identity => new Pose(Vector3.zero, Quaternion.identity);

        public bool Equals(Pose other) => position.Equals(other.position) && rotation.Equals(other.rotation);
        public override bool Equals(object obj) => obj is Pose p && Equals(p);
        public override int GetHashCode() => position.GetHashCode() ^ (rotation.GetHashCode() << 1);
    }
}
