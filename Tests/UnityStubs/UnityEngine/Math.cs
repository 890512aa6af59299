// Compile-only. Transcribed from Unity-Technologies/UnityCsReference, branch 2022.3:
//   Runtime/Export/Math/Vector3.cs, Runtime/Export/Math/Vector2.cs, Runtime/Export/Math/Color.cs,
//   Runtime/Export/Math/Math.bindings.cs + Mathf.cs (Mathf), Runtime/Export/Geometry/Rect.cs,
//   Runtime/Export/Geometry/Bounds.cs, Runtime/Export/XR/Pose.cs
// Structs keep their public fields (so code can assign components); operators and methods throw.
using System;

namespace UnityEngine
{
    public struct Vector3 : IEquatable<Vector3>
    {
        public float x;
        public float y;
        public float z;

        public Vector3(float x, float y, float z)
        {
            this.x = x;
            this.y = y;
            this.z = z;
        }

        public static Vector3 zero => throw null;
        public static Vector3 one => throw null;
        public static Vector3 up => throw null;
        public float sqrMagnitude => throw null;

        public static Vector3 Lerp(Vector3 a, Vector3 b, float t) => throw null;

        public static Vector3 operator +(Vector3 a, Vector3 b) => throw null;
        public static Vector3 operator -(Vector3 a, Vector3 b) => throw null;
        public static Vector3 operator -(Vector3 a) => throw null;
        public static Vector3 operator *(Vector3 a, float d) => throw null;
        public static Vector3 operator *(float d, Vector3 a) => throw null;
        public static Vector3 operator /(Vector3 a, float d) => throw null;
        public static bool operator ==(Vector3 lhs, Vector3 rhs) => throw null;
        public static bool operator !=(Vector3 lhs, Vector3 rhs) => throw null;

        public bool Equals(Vector3 other) => throw null;
        public override bool Equals(object other) => throw null;
        public override int GetHashCode() => throw null;
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

        public bool Equals(Vector2 other) => throw null;
        public override bool Equals(object other) => throw null;
        public override int GetHashCode() => throw null;
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

        public bool Equals(Color other) => throw null;
        public override bool Equals(object other) => throw null;
        public override int GetHashCode() => throw null;
    }

    public struct Rect : IEquatable<Rect>
    {
        public Rect(float x, float y, float width, float height) => throw null;
        public float x { get => throw null; set => throw null; }
        public float y { get => throw null; set => throw null; }
        public float width { get => throw null; set => throw null; }
        public float height { get => throw null; set => throw null; }
        public float xMin { get => throw null; set => throw null; }
        public float xMax { get => throw null; set => throw null; }
        public float yMax { get => throw null; set => throw null; }

        public bool Equals(Rect other) => throw null;
        public override bool Equals(object other) => throw null;
        public override int GetHashCode() => throw null;
    }

    public struct Bounds : IEquatable<Bounds>
    {
        public Vector3 min { get => throw null; set => throw null; }
        public Vector3 ClosestPoint(Vector3 point) => throw null;

        public bool Equals(Bounds other) => throw null;
        public override bool Equals(object other) => throw null;
        public override int GetHashCode() => throw null;
    }

    public partial struct Mathf
    {
        public const float PI = (float)Math.PI;
        public static int CeilToInt(float f) => throw null;
    }

    /// <summary>Only the member the Interaction SDK's grab points are read through.</summary>
    public struct Pose : IEquatable<Pose>
    {
        public Vector3 position;

        public bool Equals(Pose other) => throw null;
        public override bool Equals(object obj) => throw null;
        public override int GetHashCode() => throw null;
    }
}
