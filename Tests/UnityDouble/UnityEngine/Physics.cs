// Test double of the physics module, without a physics engine: a Rigidbody holds its state (nothing falls), colliders
// have their documented geometry (bounds, ClosestPoint: the point itself inside the shape, else the nearest point of
// the shape; a non-convex MeshCollider is refused, as PhysX refuses it). Trigger messages follow Unity's rules: after
// each fixed step, for every pair of enabled colliders on active GameObjects of which at least one is a trigger and at
// least one has a Rigidbody, OnTriggerEnter when they begin to overlap, OnTriggerStay while they do, OnTriggerExit when
// they stop, sent to both GameObjects' scripts (disabled ones too, as Unity documents). Overlap is exact for spheres
// against spheres and boxes, and the bounds' overlap otherwise. A test may also declare a contact itself
// (Driver.Contacts). Public members are those of UnityCsReference 2022.3 Modules/Physics/ScriptBindings/Dynamics.bindings.cs.
using System;
using System.Collections.Generic;
using System.Linq;

namespace UnityEngine
{
    public class Rigidbody : Component
    {
        public Vector3 velocity { get; set; }
        public Vector3 angularVelocity { get; set; }
        public float mass { get; set; } = 1f;
        public bool isKinematic { get; set; }
        public bool useGravity { get; set; } = true;
        public RigidbodyInterpolation interpolation { get; set; }
        public Vector3 position { get => transform.position; set => transform.position = value; }
    }

    public enum RigidbodyInterpolation
    {
        None = 0,
        Interpolate = 1,
        Extrapolate = 2,
    }

    public class Collider : Component
    {
        public bool enabled { get; set; } = true;
        public bool isTrigger { get; set; }

        public Rigidbody attachedRigidbody => Owner.InParent<Rigidbody>();

        /// <summary>The point of the collider nearest <paramref name="position"/>; the position itself when inside.</summary>
        public Vector3 ClosestPoint(Vector3 position)
        {
            if (this is MeshCollider mesh && !mesh.convex)
            {
                Debug.LogWarning("Physics.ClosestPoint can only be used with a BoxCollider, SphereCollider, CapsuleCollider and a convex MeshCollider.");
                return position;
            }
            return Closest(position);
        }

        internal virtual Vector3 Closest(Vector3 p) => bounds.ClosestPoint(p);

        /// <summary>The world-space axis-aligned box around the collider.</summary>
        public Bounds bounds => WorldBounds();

        internal virtual Bounds WorldBounds() => new Bounds(transform.position, Vector3.zero);

        /// <summary>The world AABB of a local box (centre, size) under this transform.</summary>
        internal Bounds Box(Vector3 center, Vector3 size)
        {
            Vector3 e = size * 0.5f;
            var b = new Bounds(transform.TransformPoint(center), Vector3.zero);
            for (int i = 0; i < 8; i++)
                b.Encapsulate(transform.TransformPoint(center + new Vector3((i & 1) == 0 ? -e.x : e.x, (i & 2) == 0 ? -e.y : e.y, (i & 4) == 0 ? -e.z : e.z)));
            return b;
        }

        internal float MaxScale()
        {
            Vector3 s = transform.lossyScale;
            return Math.Max(Math.Abs(s.x), Math.Max(Math.Abs(s.y), Math.Abs(s.z)));
        }
    }

    public class BoxCollider : Collider
    {
        public Vector3 center { get; set; }
        public Vector3 size { get; set; } = Vector3.one;

        internal override Bounds WorldBounds() => Box(center, size);

        internal override Vector3 Closest(Vector3 p)
        {
            Vector3 local = transform.InverseTransformPoint(p) - center, e = size * 0.5f;
            var clamped = new Vector3(Mathf.Clamp(local.x, -Math.Abs(e.x), Math.Abs(e.x)), Mathf.Clamp(local.y, -Math.Abs(e.y), Math.Abs(e.y)), Mathf.Clamp(local.z, -Math.Abs(e.z), Math.Abs(e.z)));
            return transform.TransformPoint(clamped + center);
        }
    }

    public class SphereCollider : Collider
    {
        public Vector3 center { get; set; }
        public float radius { get; set; } = 0.5f;

        internal Vector3 WorldCenter => transform.TransformPoint(center);
        internal float WorldRadius => Math.Abs(radius) * MaxScale();

        internal override Bounds WorldBounds() => new Bounds(WorldCenter, Vector3.one * (2 * WorldRadius));

        internal override Vector3 Closest(Vector3 p)
        {
            Vector3 d = p - WorldCenter;
            float r = WorldRadius;
            return d.magnitude <= r ? p : WorldCenter + d.normalized * r;
        }
    }

    public class CapsuleCollider : Collider
    {
        public Vector3 center { get; set; }
        public float radius { get; set; } = 0.5f;
        public float height { get; set; } = 2f;
        public int direction { get; set; } = 1;

        Vector3 Axis => direction == 0 ? Vector3.right : direction == 2 ? Vector3.forward : Vector3.up;

        internal override Bounds WorldBounds()
        {
            Vector3 size = Vector3.one * (2 * radius) + Axis * Math.Max(0, height - 2 * radius);
            return Box(center, size);
        }

        internal override Vector3 Closest(Vector3 p)
        {
            // The nearest point of the axis segment, then out by the radius (uniform scale assumed).
            float half = Math.Max(0, height / 2 - radius);
            Vector3 a = transform.TransformPoint(center - Axis * half), b = transform.TransformPoint(center + Axis * half);
            Vector3 ab = b - a;
            float t = ab.sqrMagnitude > 0 ? Mathf.Clamp01(Vector3.Dot(p - a, ab) / ab.sqrMagnitude) : 0;
            Vector3 onAxis = a + ab * t, d = p - onAxis;
            float r = Math.Abs(radius) * MaxScale();
            return d.magnitude <= r ? p : onAxis + d.normalized * r;
        }
    }

    public class MeshCollider : Collider
    {
        public Mesh sharedMesh { get; set; }
        public bool convex { get; set; }

        internal override Bounds WorldBounds()
        {
            if (sharedMesh == null || sharedMesh.vertices.Length == 0) return new Bounds(transform.position, Vector3.zero);
            Vector3[] v = sharedMesh.vertices;
            var b = new Bounds(transform.TransformPoint(v[0]), Vector3.zero);
            foreach (Vector3 p in v) b.Encapsulate(transform.TransformPoint(p));
            return b;
        }
    }

    /// <summary>The trigger contacts of the double's one scene (no forces, no collisions).</summary>
    internal static class PhysicsScene
    {
        static readonly HashSet<(Collider, Collider)> s_touching = new HashSet<(Collider, Collider)>();
        static readonly HashSet<(Collider, Collider)> s_declared = new HashSet<(Collider, Collider)>();

        internal static void Declare(Collider a, Collider b, bool touching)
        {
            var key = Key(a, b);
            if (touching) s_declared.Add(key);
            else s_declared.Remove(key);
        }

        static (Collider, Collider) Key(Collider a, Collider b) => a.GetInstanceID() < b.GetInstanceID() ? (a, b) : (b, a);

        static bool Live(Collider c) => c != null && c.enabled && c.gameObject.activeInHierarchy;

        internal static void Step()
        {
            var colliders = new List<Collider>();
            foreach (GameObject go in Engine.GameObjects)
                foreach (Component c in go.Components)
                    if (c is Collider collider && Live(collider)) colliders.Add(collider);
            var now = new HashSet<(Collider, Collider)>();
            for (int i = 0; i < colliders.Count; i++)
                for (int j = i + 1; j < colliders.Count; j++)
                {
                    Collider a = colliders[i], b = colliders[j];
                    if (!(a.isTrigger || b.isTrigger) || (a.attachedRigidbody == null && b.attachedRigidbody == null)) continue;
                    if (ReferenceEquals(a.attachedRigidbody, b.attachedRigidbody) && a.attachedRigidbody != null) continue;
                    if (Overlap(a, b)) now.Add(Key(a, b));
                }
            foreach (var pair in s_declared)
                if (Live(pair.Item1) && Live(pair.Item2)) now.Add(pair);
            foreach (var pair in now) Message(pair, s_touching.Contains(pair) ? "OnTriggerStay" : "OnTriggerEnter");
            foreach (var pair in s_touching)
                if (!now.Contains(pair) && pair.Item1 != null && pair.Item2 != null) Message(pair, "OnTriggerExit");
            s_touching.Clear();
            s_touching.UnionWith(now);
        }

        static void Message((Collider, Collider) pair, string message)
        {
            Send(pair.Item1, pair.Item2, message);
            if (pair.Item1 != null && pair.Item2 != null) Send(pair.Item2, pair.Item1, message);
        }

        static void Send(Collider self, Collider other, string message)
        {
            if (self == null || other == null) return;
            foreach (Component c in self.gameObject.Components.ToArray())
                if (c is MonoBehaviour mb && !mb.IsDestroyed) Engine.Send(mb, message, other);
        }

        static bool Overlap(Collider a, Collider b)
        {
            if (a is SphereCollider sa && b is SphereCollider sb)
                return (sa.WorldCenter - sb.WorldCenter).magnitude <= sa.WorldRadius + sb.WorldRadius;
            if (a is SphereCollider s1 && b is BoxCollider) return (b.Closest(s1.WorldCenter) - s1.WorldCenter).magnitude <= s1.WorldRadius;
            if (b is SphereCollider s2 && a is BoxCollider) return (a.Closest(s2.WorldCenter) - s2.WorldCenter).magnitude <= s2.WorldRadius;
            return a.bounds.Intersects(b.bounds);
        }

        internal static void Reset()
        {
            s_touching.Clear();
            s_declared.Clear();
        }
    }
}
