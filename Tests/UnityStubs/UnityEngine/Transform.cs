// Compile-only. Transcribed from Unity-Technologies/UnityCsReference, branch 2022.3:
//   Runtime/Transform/ScriptBindings/Transform.bindings.cs
namespace UnityEngine
{
    public class Transform : Component
    {
        public Vector3 position { get => throw null; set => throw null; }
        public Vector3 localPosition { get => throw null; set => throw null; }
        public Vector3 localScale { get => throw null; set => throw null; }
        public Vector3 lossyScale => throw null;
        public Transform parent { get => throw null; set => throw null; }
        public void SetParent(Transform parent, bool worldPositionStays) => throw null;
        public Vector3 TransformPoint(Vector3 position) => throw null;
        public Vector3 InverseTransformPoint(Vector3 position) => throw null;
        public Transform Find(string n) => throw null;
        public int childCount => throw null;
        public Transform GetChild(int index) => throw null;
    }
}
