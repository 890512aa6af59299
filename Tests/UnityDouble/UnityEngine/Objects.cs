// Test double of UnityEngine's object model with Unity's documented semantics: destroyed objects compare equal to
// null; AddComponent runs Awake and OnEnable at once on an active GameObject; SetActive and enabled run OnEnable and
// OnDisable; Destroy is deferred to the end of the frame, DestroyImmediate is not; FindObjectsByType sees active
// GameObjects only. Public members are those of UnityCsReference 2022.3 (Runtime/Export/Scripting/UnityEngineObject.bindings.cs,
// Component.bindings.cs, Behaviour.bindings.cs, MonoBehaviour.bindings.cs, GameObject.bindings.cs,
// ScriptableObject.bindings.cs, Runtime/Export/BaseClass.cs, TextAsset.cs) that the package uses.
using System;
using System.Collections.Generic;

namespace UnityEngine
{
    public class Object
    {
        static int s_nextId;
        readonly int _instanceId = ++s_nextId;
        string _name = "";

        /// <summary>Destroyed (by Destroy at the end of the frame, or DestroyImmediate): compares equal to null from then on.</summary>
        internal bool IsDestroyed;

        /// <summary>A component's name is its GameObject's.</summary>
        public string name
        {
            get => this is Component c && c.Owner != null ? c.Owner.name : _name;
            set
            {
                if (this is Component c && c.Owner != null) c.Owner.name = value;
                else _name = value ?? "";
            }
        }
        public int GetInstanceID() => _instanceId;

        /// <summary>Destroys at the end of the current frame (Unity's "after the current Update loop").</summary>
        public static void Destroy(Object obj)
        {
            if (!ReferenceEquals(obj, null) && !obj.IsDestroyed) Engine.DeferDestroy(obj);
        }

        public static void DestroyImmediate(Object obj)
        {
            if (!ReferenceEquals(obj, null) && !obj.IsDestroyed) Engine.DestroyNow(obj);
        }

        public static T[] FindObjectsByType<T>(FindObjectsSortMode sortMode) where T : Object => Engine.FindObjects<T>(sortMode);

        public static T FindFirstObjectByType<T>() where T : Object
        {
            T[] all = Engine.FindObjects<T>(FindObjectsSortMode.InstanceID);
            return all.Length > 0 ? all[0] : null;
        }

        internal virtual void OnDestroyInternal() { }

        static bool Alive(Object o) => !ReferenceEquals(o, null) && !o.IsDestroyed;

        public static implicit operator bool(Object exists) => Alive(exists);

        public static bool operator ==(Object x, Object y)
        {
            bool xNull = !Alive(x), yNull = !Alive(y);
            if (xNull || yNull) return xNull && yNull;
            return ReferenceEquals(x, y);
        }

        public static bool operator !=(Object x, Object y) => !(x == y);
        public override bool Equals(object other) => other is Object o ? this == o : other == null && !Alive(this);
        public override int GetHashCode() => _instanceId;
        public override string ToString() => name + " (" + GetType().FullName + ")";
    }

    public class Component : Object
    {
        internal GameObject Owner;

        public Transform transform => Owner.transform;
        public GameObject gameObject => Owner;
        public string tag { get => Owner.tag; set => Owner.tag = value; }

        public T GetComponent<T>() => Owner.GetComponent<T>();
        public T[] GetComponents<T>() => Owner.GetComponents<T>();
        public T GetComponentInParent<T>() => Owner.GetComponentInParent<T>();
        public T GetComponentInChildren<T>() => Owner.GetComponentInChildren<T>();
        public T[] GetComponentsInChildren<T>() => Owner.GetComponentsInChildren<T>();
        public T[] GetComponentsInChildren<T>(bool includeInactive) => Owner.GetComponentsInChildren<T>(includeInactive);
    }

    public class Behaviour : Component
    {
        bool _enabled = true;

        public bool enabled
        {
            get => _enabled;
            set
            {
                if (_enabled == value) return;
                _enabled = value;
                if (Owner != null && !IsDestroyed && Owner.activeInHierarchy) Engine.EnabledChanged(this, value);
            }
        }

        public bool isActiveAndEnabled => _enabled && Owner != null && !IsDestroyed && Owner.activeInHierarchy;
    }

    public class MonoBehaviour : Behaviour
    {
        internal bool AwakeCalled, StartCalled, IsEnabledState;
    }

    public class ScriptableObject : Object
    {
        public static T CreateInstance<T>() where T : ScriptableObject => (T)CreateInstance(typeof(T));

        public static ScriptableObject CreateInstance(Type type)
        {
            var instance = (ScriptableObject)Activator.CreateInstance(type, true);
            Engine.ScriptableObjectCreated(instance);
            return instance;
        }
    }

    public sealed class GameObject : Object
    {
        internal readonly List<Component> Components = new List<Component>();
        bool _activeSelf = true;
        internal int Layer;

        /// <summary>A prefab asset's root (the editor double's asset database), not an object of the scene.</summary>
        internal bool IsAsset;
        string _tag = "Untagged";

        public GameObject() : this("New Game Object") { }

        public GameObject(string name)
        {
            this.name = name;
            var t = new Transform { Owner = this };
            Components.Add(t);
            Engine.GameObjectCreated(this);
        }

        public static GameObject CreatePrimitive(PrimitiveType type) => Primitives.Create(type);

        /// <summary>The first active GameObject of that name (Unity's GameObject.Find, without paths).</summary>
        public static GameObject Find(string name)
        {
            foreach (GameObject go in Engine.GameObjects)
                if (go.activeInHierarchy && go.name == name) return go;
            return null;
        }

        public Transform transform => (Transform)Components[0];
        public bool activeSelf => _activeSelf;
        public bool activeInHierarchy => !IsDestroyed && _activeSelf && (transform.parent == null || transform.parent.gameObject.activeInHierarchy);
        public string tag { get => _tag; set => _tag = value; }
        public int layer { get => Layer; set => Layer = value; }

        public void SetActive(bool value)
        {
            if (_activeSelf == value) return;
            Engine.ChangeActive(this, () => _activeSelf = value);
        }

        /// <summary>How many component searches ran (GetComponent and its kin), for tests of per-frame work.</summary>
        internal static long Searches;

        public T GetComponent<T>()
        {
            Searches++;
            foreach (Component c in Components)
                if (!c.IsDestroyed && c is T t) return t;
            return default;
        }

        public T[] GetComponents<T>()
        {
            Searches++;
            var list = new List<T>();
            foreach (Component c in Components)
                if (!c.IsDestroyed && c is T t) list.Add(t);
            return list.ToArray();
        }

        /// <summary>On this GameObject or its parents, active ones only (as Unity's default).</summary>
        public T GetComponentInParent<T>()
        {
            Searches++;
            for (Transform t = transform; t != null; t = t.parent)
            {
                if (!t.gameObject.activeInHierarchy) continue;
                T found = t.gameObject.GetComponent<T>();
                if (found != null) return found;
            }
            return default;
        }

        public T GetComponentInChildren<T>()
        {
            T[] all = GetComponentsInChildren<T>(false);
            return all.Length > 0 ? all[0] : default;
        }

        public T[] GetComponentsInChildren<T>() => GetComponentsInChildren<T>(false);

        /// <summary>Depth first, this GameObject first; inactive GameObjects only when asked.</summary>
        public T[] GetComponentsInChildren<T>(bool includeInactive)
        {
            Searches++;
            return InChildren<T>(includeInactive);
        }

        /// <summary>The engine's own search, not counted in <see cref="Searches"/>.</summary>
        internal T[] InChildren<T>(bool includeInactive)
        {
            var list = new List<T>();
            Collect(transform, includeInactive, list);
            return list.ToArray();
        }

        /// <summary>The engine's own search on this GameObject and its parents, not counted.</summary>
        internal T InParent<T>() where T : class
        {
            for (Transform t = transform; t != null; t = t.parent)
                foreach (Component c in t.gameObject.Components)
                    if (!c.IsDestroyed && c is T found) return found;
            return null;
        }

        static void Collect<T>(Transform t, bool includeInactive, List<T> into)
        {
            if (!includeInactive && !t.gameObject.activeInHierarchy) return;
            foreach (Component c in t.gameObject.Components)
                if (!c.IsDestroyed && c is T found) into.Add(found);
            for (int i = 0; i < t.childCount; i++) Collect(t.GetChild(i), includeInactive, into);
        }

        public T AddComponent<T>() where T : Component => (T)AddComponent(typeof(T));

        public Component AddComponent(Type componentType) => Engine.AddComponent(this, componentType);
    }

    public partial class TextAsset : Object
    {
        readonly string _text;

        public TextAsset() : this("") { }

        public TextAsset(string text) => _text = text ?? "";

        public string text => _text;
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
