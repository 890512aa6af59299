// Test double of the rendering types the package touches, holding their state (nothing is drawn). Primitives are
// built as Unity documents them: a unit cube (BoxCollider), a sphere of diameter 1 (SphereCollider), a capsule and a
// cylinder 2 tall and 1 across (CapsuleCollider, as Unity gives both), a 1 × 1 quad and a 10 × 10 plane
// (MeshCollider), each with a MeshFilter and a MeshRenderer; their meshes are closed where Unity's are, readable,
// with outward winding (the cylinder has 20 sides here; Unity's side count is not documented). Public members are
// those of UnityCsReference 2022.3 (Runtime/Export/Graphics/Mesh.cs, GraphicsComponents.bindings.cs,
// GraphicsRenderers.bindings.cs, Shaders/*.cs, Camera/Camera.bindings.cs, Modules/TextRendering/TextRendering.bindings.cs,
// Gizmos/Gizmos.bindings.cs) that are used.
using System;
using System.Collections.Generic;

namespace UnityEngine
{
    public sealed class Mesh : Object
    {
        Vector3[] _vertices = new Vector3[0];
        int[] _triangles = new int[0];

        public bool isReadable => IsReadableState;
        internal bool IsReadableState = true;

        /// <summary>A copy, as Unity returns.</summary>
        public Vector3[] vertices { get => (Vector3[])_vertices.Clone(); set => _vertices = (Vector3[])(value ?? new Vector3[0]).Clone(); }
        public int[] triangles { get => (int[])_triangles.Clone(); set => _triangles = (int[])(value ?? new int[0]).Clone(); }
        public int vertexCount => _vertices.Length;
    }

    public sealed class MeshFilter : Component
    {
        public Mesh sharedMesh { get; set; }
    }

    public class Renderer : Component
    {
        MaterialPropertyBlock _block;

        public bool enabled { get; set; } = true;
        public Material sharedMaterial { get; set; }

        public void SetPropertyBlock(MaterialPropertyBlock properties)
        {
            _block = new MaterialPropertyBlock();
            if (properties != null) _block.CopyFrom(properties);
        }

        public void GetPropertyBlock(MaterialPropertyBlock dest)
        {
            dest.Clear();
            if (_block != null) dest.CopyFrom(_block);
        }
    }

    public sealed partial class MaterialPropertyBlock
    {
        readonly Dictionary<int, Color> _colors = new Dictionary<int, Color>();

        public MaterialPropertyBlock() { }
        public void SetColor(int nameID, Color value) => _colors[nameID] = value;
        public Color GetColor(int nameID) => _colors.TryGetValue(nameID, out Color c) ? c : default;
        public void Clear() => _colors.Clear();

        internal void CopyFrom(MaterialPropertyBlock other)
        {
            foreach (var kv in other._colors) _colors[kv.Key] = kv.Value;
        }
    }

    public class MeshRenderer : Renderer
    {
    }

    public class Material : Object
    {
    }

    public sealed partial class Shader : Object
    {
        static readonly Dictionary<string, int> s_ids = new Dictionary<string, int>();

        /// <summary>The same id for the same name, for the process's life.</summary>
        public static int PropertyToID(string name)
        {
            lock (s_ids)
            {
                if (!s_ids.TryGetValue(name, out int id)) s_ids[name] = id = s_ids.Count + 1;
                return id;
            }
        }
    }

    public sealed class Camera : Behaviour
    {
        /// <summary>The first enabled camera tagged MainCamera.</summary>
        public static Camera main
        {
            get
            {
                foreach (Camera c in Engine.FindObjects<Camera>(FindObjectsSortMode.InstanceID))
                    if (c.isActiveAndEnabled && c.gameObject.tag == "MainCamera") return c;
                return null;
            }
        }
    }

    public sealed class Font : Object
    {
        public Material material { get; set; }
    }

    [RequireComponent(typeof(MeshRenderer))]
    public sealed class TextMesh : Component
    {
        public string text { get; set; } = "";
        public Font font { get; set; }
        public int fontSize { get; set; }
        public TextAlignment alignment { get; set; }
        public TextAnchor anchor { get; set; }
        public float characterSize { get; set; } = 1f;
        public Color color { get; set; } = new Color(1f, 1f, 1f);
    }

    public enum TextAlignment
    {
        Left = 0,
        Center = 1,
        Right = 2,
    }

    public enum TextAnchor
    {
        UpperLeft = 0,
        UpperCenter = 1,
        UpperRight = 2,
        MiddleLeft = 3,
        MiddleCenter = 4,
        MiddleRight = 5,
        LowerLeft = 6,
        LowerCenter = 7,
        LowerRight = 8,
    }

    /// <summary>Nothing is drawn; the calls are counted.</summary>
    public sealed class Gizmos
    {
        internal static int Lines, Spheres;

        public static Color color { get; set; }
        public static void DrawLine(Vector3 from, Vector3 to) => Lines++;
        public static void DrawWireSphere(Vector3 center, float radius) => Spheres++;
    }

    /// <summary>GameObject.CreatePrimitive's meshes and colliders.</summary>
    static class Primitives
    {
        internal static GameObject Create(PrimitiveType type)
        {
            var go = new GameObject(type.ToString());
            Mesh mesh = MeshOf(type);
            go.AddComponent<MeshFilter>().sharedMesh = mesh;
            go.AddComponent<MeshRenderer>().sharedMaterial = new Material { name = "Default-Material" };
            switch (type)
            {
                case PrimitiveType.Cube: go.AddComponent<BoxCollider>(); break;
                case PrimitiveType.Sphere: go.AddComponent<SphereCollider>(); break;
                case PrimitiveType.Capsule:
                case PrimitiveType.Cylinder: go.AddComponent<CapsuleCollider>(); break;
                default: go.AddComponent<MeshCollider>().sharedMesh = mesh; break;
            }
            return go;
        }

        static Mesh MeshOf(PrimitiveType type)
        {
            var v = new List<Vector3>();
            var t = new List<int>();
            switch (type)
            {
                case PrimitiveType.Cube:
                    for (int axis = 0; axis < 3; axis++)
                        for (int sign = -1; sign <= 1; sign += 2) Face(v, t, axis, sign);
                    break;
                case PrimitiveType.Cylinder:
                    Prism(v, t, 20, 0.5f, 1f);
                    break;
                case PrimitiveType.Sphere:
                case PrimitiveType.Capsule:
                    Sphere(v, t, 0.5f, type == PrimitiveType.Capsule ? 0.5f : 0f);
                    break;
                case PrimitiveType.Quad:
                    Quad(v, t, 0.5f, false);
                    break;
                default:
                    Quad(v, t, 5f, true);
                    break;
            }
            return new Mesh { name = type.ToString(), vertices = v.ToArray(), triangles = t.ToArray() };
        }

        /// <summary>One face of the unit cube, four vertices, two outward triangles.</summary>
        static void Face(List<Vector3> v, List<int> t, int axis, int sign)
        {
            Vector3 n = axis == 0 ? Vector3.right : axis == 1 ? Vector3.up : Vector3.forward;
            Vector3 u = axis == 0 ? Vector3.up : axis == 1 ? Vector3.forward : Vector3.right;
            Vector3 w = Vector3.Cross(n, u);
            Vector3 c = n * (0.5f * sign);
            int i = v.Count;
            v.Add(c - 0.5f * u - 0.5f * w);
            v.Add(c + 0.5f * u - 0.5f * w);
            v.Add(c + 0.5f * u + 0.5f * w);
            v.Add(c - 0.5f * u + 0.5f * w);
            if (sign > 0) t.AddRange(new[] { i, i + 1, i + 2, i, i + 2, i + 3 });
            else t.AddRange(new[] { i, i + 2, i + 1, i, i + 3, i + 2 });
        }

        /// <summary>A closed prism of <paramref name="sides"/> sides, radius r, from y = −h to y = h.</summary>
        static void Prism(List<Vector3> v, List<int> t, int sides, float r, float h)
        {
            int top = v.Count;
            v.Add(new Vector3(0, h, 0));
            int bottom = v.Count;
            v.Add(new Vector3(0, -h, 0));
            int ring = v.Count;
            for (int k = 0; k < sides; k++)
            {
                double a = 2 * Math.PI * k / sides;
                v.Add(new Vector3((float)(r * Math.Cos(a)), h, (float)(r * Math.Sin(a))));
                v.Add(new Vector3((float)(r * Math.Cos(a)), -h, (float)(r * Math.Sin(a))));
            }
            for (int k = 0; k < sides; k++)
            {
                int a0 = ring + 2 * k, a1 = ring + 2 * ((k + 1) % sides);
                t.AddRange(new[] { top, a1, a0 });
                t.AddRange(new[] { bottom, a0 + 1, a1 + 1 });
                t.AddRange(new[] { a0, a1, a1 + 1, a0, a1 + 1, a0 + 1 });
            }
        }

        /// <summary>A UV sphere of radius r, its halves pulled apart by <paramref name="stretch"/> (a capsule).</summary>
        static void Sphere(List<Vector3> v, List<int> t, float r, float stretch)
        {
            const int rings = 12, segments = 16;
            for (int i = 0; i <= rings; i++)
            {
                double phi = Math.PI * i / rings;
                float y = (float)(r * Math.Cos(phi)) + (i <= rings / 2 ? stretch : -stretch);
                for (int j = 0; j < segments; j++)
                {
                    double th = 2 * Math.PI * j / segments;
                    v.Add(new Vector3((float)(r * Math.Sin(phi) * Math.Cos(th)), y, (float)(r * Math.Sin(phi) * Math.Sin(th))));
                }
            }
            for (int i = 0; i < rings; i++)
                for (int j = 0; j < segments; j++)
                {
                    int a = i * segments + j, b = i * segments + (j + 1) % segments, c = a + segments, d = b + segments;
                    t.AddRange(new[] { a, b, d, a, d, c });
                }
        }

        static void Quad(List<Vector3> v, List<int> t, float half, bool horizontal)
        {
            if (horizontal)
            {
                v.AddRange(new[] { new Vector3(-half, 0, -half), new Vector3(half, 0, -half), new Vector3(half, 0, half), new Vector3(-half, 0, half) });
                t.AddRange(new[] { 0, 2, 1, 0, 3, 2 });
            }
            else
            {
                v.AddRange(new[] { new Vector3(-half, -half, 0), new Vector3(half, -half, 0), new Vector3(half, half, 0), new Vector3(-half, half, 0) });
                t.AddRange(new[] { 0, 2, 1, 0, 3, 2 });
            }
        }
    }
}

namespace UnityEngine
{
    public enum ColorSpace
    {
        Uninitialized = -1,
        Gamma = 0,
        Linear = 1,
    }
}

namespace UnityEngine.Rendering
{
    /// <summary>Runtime/Export/Graphics/GraphicsEnums.cs: only the APIs the package names, with their real numbers.</summary>
    public enum GraphicsDeviceType
    {
        OpenGLES3 = 11,
        Vulkan = 21,
    }
}
