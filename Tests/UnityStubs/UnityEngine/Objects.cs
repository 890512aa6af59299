// Compile-only. Transcribed from Unity-Technologies/UnityCsReference, branch 2022.3:
//   Runtime/Export/Scripting/UnityEngineObject.bindings.cs   (Object)
//   Runtime/Export/Scripting/Component.bindings.cs           (Component)
//   Runtime/Export/Scripting/Behaviour.bindings.cs           (Behaviour)
//   Runtime/Export/Scripting/MonoBehaviour.bindings.cs       (MonoBehaviour)
//   Runtime/Export/Scripting/GameObject.bindings.cs          (GameObject)
//   Runtime/Export/Scripting/ScriptableObject.bindings.cs    (ScriptableObject)
//   Runtime/Export/BaseClass.cs                              (PrimitiveType)
//   Runtime/Export/Scripting/TextAsset.cs                    (TextAsset)
// Only the members the package calls; every body throws.
namespace UnityEngine
{
    public class Object
    {
        public string name { get => throw null; set => throw null; }
        public static void DestroyImmediate(Object obj) => throw null;
        public static T[] FindObjectsByType<T>(FindObjectsSortMode sortMode) where T : Object => throw null;
        public static implicit operator bool(Object exists) => throw null;
        public static bool operator ==(Object x, Object y) => throw null;
        public static bool operator !=(Object x, Object y) => throw null;
        public override bool Equals(object other) => throw null;
        public override int GetHashCode() => throw null;
    }

    public class Component : Object
    {
        public Transform transform => throw null;
        public GameObject gameObject => throw null;
        public T[] GetComponentsInChildren<T>() => throw null;
        public T GetComponent<T>() => throw null;
        public T GetComponentInParent<T>() => throw null;
    }

    public class Behaviour : Component
    {
        public bool enabled { get => throw null; set => throw null; }
        public bool isActiveAndEnabled => throw null;
    }

    public class MonoBehaviour : Behaviour
    {
    }

    public class ScriptableObject : Object
    {
        public static T CreateInstance<T>() where T : ScriptableObject => throw null;
    }

    public sealed class GameObject : Object
    {
        public GameObject(string name) => throw null;
        public static GameObject CreatePrimitive(PrimitiveType type) => throw null;
        public Transform transform => throw null;
        public T GetComponent<T>() => throw null;
        public T[] GetComponents<T>() => throw null;
        public T AddComponent<T>() where T : Component => throw null;
        public void SetActive(bool value) => throw null;
        public bool activeSelf => throw null;
    }

    public partial class TextAsset : Object
    {
        public TextAsset(string text) => throw null;
        public string text => throw null;
    }

    public enum FindObjectsSortMode
    {
        None = 0,
        InstanceID = 1,
    }

    public enum PrimitiveType
    {
        Sphere = 0,
        Capsule = 1,
        Cylinder = 2,
        Cube = 3,
        Plane = 4,
        Quad = 5,
    }
}
