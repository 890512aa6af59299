// Compile-only. Transcribed from Unity-Technologies/UnityCsReference, branch 2022.3:
//   Runtime/Export/Graphics/Mesh.cs + Mesh.bindings.cs (Mesh), Runtime/Export/Graphics/GraphicsComponents.bindings.cs
//   (MeshFilter), Runtime/Export/Graphics/GraphicsRenderers.bindings.cs (Renderer, MeshRenderer),
//   Runtime/Export/Shaders/Material.bindings.cs (Material), Runtime/Export/Shaders/MaterialPropertyBlock.cs
//   (MaterialPropertyBlock), Runtime/Export/Shaders/Shader.bindings.cs (Shader.PropertyToID),
//   Runtime/Export/Camera/Camera.bindings.cs (Camera),
//   Modules/TextRendering/TextRendering.bindings.cs (Font, TextMesh, TextAnchor, TextAlignment),
//   Runtime/Export/Gizmos/Gizmos.bindings.cs (Gizmos)
namespace UnityEngine
{
    public sealed class Mesh : Object
    {
        public bool isReadable => throw null;
        public Vector3[] vertices { get => throw null; set => throw null; }
        public int[] triangles { get => throw null; set => throw null; }
    }

    public sealed class MeshFilter : Component
    {
        public Mesh sharedMesh { get => throw null; set => throw null; }
    }

    public class Renderer : Component
    {
        public Material sharedMaterial { get => throw null; set => throw null; }
        public void SetPropertyBlock(MaterialPropertyBlock properties) => throw null;
    }

    public sealed partial class MaterialPropertyBlock
    {
        public MaterialPropertyBlock() => throw null;
        public void SetColor(int nameID, Color value) => throw null;
    }

    public class MeshRenderer : Renderer
    {
    }

    public class Material : Object
    {
    }

    public sealed partial class Shader : Object
    {
        public static int PropertyToID(string name) => throw null;
    }

    public sealed class Camera : Behaviour
    {
        public static Camera main => throw null;
    }

    public sealed class Font : Object
    {
        public Material material { get => throw null; set => throw null; }
    }

    public sealed class TextMesh : Component
    {
        public string text { get => throw null; set => throw null; }
        public Font font { get => throw null; set => throw null; }
        public int fontSize { get => throw null; set => throw null; }
        public TextAlignment alignment { get => throw null; set => throw null; }
        public TextAnchor anchor { get => throw null; set => throw null; }
        public float characterSize { get => throw null; set => throw null; }
        public Color color { get => throw null; set => throw null; }
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

    public sealed class Gizmos
    {
        public static Color color { get => throw null; set => throw null; }
        public static void DrawLine(Vector3 from, Vector3 to) => throw null;
        public static void DrawWireSphere(Vector3 center, float radius) => throw null;
    }
}
