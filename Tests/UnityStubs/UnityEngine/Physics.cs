// Compile-only. Transcribed from Unity-Technologies/UnityCsReference, branch 2022.3:
//   Modules/Physics/ScriptBindings/Dynamics.bindings.cs (Rigidbody, Collider, BoxCollider, SphereCollider,
//   CapsuleCollider, MeshCollider), Modules/Physics/Managed/Dynamics.cs (RigidbodyInterpolation).
// Rigidbody.velocity is the 2022.3 name (Unity 6 renames it linearVelocity).
namespace UnityEngine
{
    public class Rigidbody : Component
    {
        public Vector3 velocity { get => throw null; set => throw null; }
        public Vector3 angularVelocity { get => throw null; set => throw null; }
        public float mass { get => throw null; set => throw null; }
        public bool isKinematic { get => throw null; set => throw null; }
        public RigidbodyInterpolation interpolation { get => throw null; set => throw null; }
    }

    public enum RigidbodyInterpolation
    {
        None = 0,
        Interpolate = 1,
        Extrapolate = 2,
    }

    public class Collider : Component
    {
        public bool enabled { get => throw null; set => throw null; }
        public bool isTrigger { get => throw null; set => throw null; }
        public Vector3 ClosestPoint(Vector3 position) => throw null;
        public Bounds bounds => throw null;
    }

    public class BoxCollider : Collider
    {
        public Vector3 center { get => throw null; set => throw null; }
        public Vector3 size { get => throw null; set => throw null; }
    }

    public class SphereCollider : Collider
    {
        public Vector3 center { get => throw null; set => throw null; }
        public float radius { get => throw null; set => throw null; }
    }

    public class CapsuleCollider : Collider
    {
        public Vector3 center { get => throw null; set => throw null; }
        public float radius { get => throw null; set => throw null; }
        public float height { get => throw null; set => throw null; }
        public int direction { get => throw null; set => throw null; }
    }

    public class MeshCollider : Collider
    {
        public Mesh sharedMesh { get => throw null; set => throw null; }
        public bool convex { get => throw null; set => throw null; }
    }
}
