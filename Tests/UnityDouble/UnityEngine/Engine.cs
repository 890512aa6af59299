// The double's engine: the live objects of the one scene and the MonoBehaviour life cycle in Unity's documented order
// ("Order of execution for event functions", Unity 2022.3 manual): Awake and OnEnable when a script becomes active;
// per frame, Start for scripts that have not started, then the fixed steps (FixedUpdate, the physics step and its
// OnTrigger messages) as many as the frame's time holds, then Update, then LateUpdate, then Application.onBeforeRender,
// then the objects Destroy was called on are destroyed (OnDisable, then OnDestroy). Within a phase, scripts run in
// [DefaultExecutionOrder] order, then in the order they were added. A message that throws is logged (Debug.LogException),
// as Unity does, and the loop goes on. Internal: the test driver (Driver/) runs it.
using System;
using System.Collections.Generic;
using System.Linq;
using System.Reflection;

namespace UnityEngine
{
    internal static class Engine
    {
        static readonly List<GameObject> s_gameObjects = new List<GameObject>();
        static readonly List<MonoBehaviour> s_behaviours = new List<MonoBehaviour>();
        static readonly List<ScriptableObject> s_scriptables = new List<ScriptableObject>();
        static readonly List<Object> s_pendingDestroy = new List<Object>();
        static readonly Dictionary<(Type, string, int), MethodInfo> s_messages = new Dictionary<(Type, string, int), MethodInfo>();

        internal static IReadOnlyList<GameObject> GameObjects => s_gameObjects;

        internal static void GameObjectCreated(GameObject go) => s_gameObjects.Add(go);

        internal static Component AddComponent(GameObject go, Type type)
        {
            if (go.IsDestroyed) throw new MissingReferenceException("The GameObject '" + go.name + "' has been destroyed.");
            if (type == null || !typeof(Component).IsAssignableFrom(type) || type.IsAbstract || type == typeof(Transform))
            {
                Debug.LogError("AddComponent: '" + type + "' cannot be added to '" + go.name + "'.");
                return null;
            }
            for (Type t = type; t != null && t != typeof(MonoBehaviour); t = t.BaseType)
                if (t.IsDefined(typeof(DisallowMultipleComponent), false))
                    foreach (Component existing in go.Components)
                        if (!existing.IsDestroyed && t.IsInstanceOfType(existing))
                        {
                            Debug.LogError("Can't add component '" + type.Name + "' to " + go.name + " because such a component is already added to the game object!");
                            return null;
                        }
            foreach (RequireComponent required in type.GetCustomAttributes(typeof(RequireComponent), true))
                if (required.m_Type0 != null && go.Components.All(c => c.IsDestroyed || !required.m_Type0.IsInstanceOfType(c)))
                    AddComponent(go, required.m_Type0);
            var component = (Component)Activator.CreateInstance(type, true);
            component.Owner = go;
            go.Components.Add(component);
            if (component is MonoBehaviour mb)
            {
                s_behaviours.Add(mb);
                if (go.activeInHierarchy)
                {
                    Awake(mb);
                    if (mb.enabled && !mb.IsDestroyed && go.activeInHierarchy) Enable(mb);
                }
            }
            return component;
        }

        internal static void ScriptableObjectCreated(ScriptableObject so)
        {
            s_scriptables.Add(so);
            Send(so, "Awake");
            Send(so, "OnEnable");
        }

        static void Awake(MonoBehaviour mb)
        {
            mb.AwakeCalled = true;
            Send(mb, "Awake");
        }

        static void Enable(MonoBehaviour mb)
        {
            mb.IsEnabledState = true;
            Send(mb, "OnEnable");
        }

        static void Disable(MonoBehaviour mb)
        {
            mb.IsEnabledState = false;
            Send(mb, "OnDisable");
        }

        internal static void EnabledChanged(Behaviour b, bool value)
        {
            if (!(b is MonoBehaviour mb)) return;
            if (value && !mb.IsEnabledState)
            {
                if (!mb.AwakeCalled) Awake(mb);
                Enable(mb);
            }
            else if (!value && mb.IsEnabledState) Disable(mb);
        }

        /// <summary>Runs <paramref name="change"/> and then Awake/OnEnable or OnDisable for the scripts under <paramref name="root"/> whose activity changed.</summary>
        internal static void ChangeActive(GameObject root, Action change)
        {
            var scripts = new List<(MonoBehaviour, bool)>();
            foreach (MonoBehaviour mb in root.InChildren<MonoBehaviour>(true))
                scripts.Add((mb, mb.gameObject.activeInHierarchy));
            change();
            foreach ((MonoBehaviour mb, bool was) in scripts)
            {
                if (mb.IsDestroyed) continue;
                bool now = mb.gameObject.activeInHierarchy;
                if (!was && now)
                {
                    if (!mb.AwakeCalled) Awake(mb);
                    if (mb.enabled && !mb.IsEnabledState && mb.gameObject.activeInHierarchy) Enable(mb);
                }
                else if (was && !now && mb.IsEnabledState) Disable(mb);
            }
        }

        internal static void ParentChanged(Transform t) { }

        internal static void DeferDestroy(Object obj)
        {
            if (!s_pendingDestroy.Contains(obj)) s_pendingDestroy.Add(obj);
        }

        internal static void DestroyNow(Object obj)
        {
            switch (obj)
            {
                case Transform t:
                    Debug.LogError("Destroying the Transform component of '" + t.gameObject.name + "' is not permitted. Destroy the GameObject instead.");
                    return;
                case GameObject go:
                    DestroyGameObject(go);
                    return;
                case Component c:
                    if (c is MonoBehaviour mb)
                    {
                        if (mb.IsEnabledState) Disable(mb);
                        if (mb.AwakeCalled) Send(mb, "OnDestroy");
                        s_behaviours.Remove(mb);
                    }
                    c.IsDestroyed = true;
                    c.Owner.Components.Remove(c);
                    c.OnDestroyInternal();
                    return;
                case ScriptableObject so:
                    Send(so, "OnDisable");
                    Send(so, "OnDestroy");
                    so.IsDestroyed = true;
                    s_scriptables.Remove(so);
                    return;
                default:
                    obj.IsDestroyed = true;
                    obj.OnDestroyInternal();
                    return;
            }
        }

        static void DestroyGameObject(GameObject go)
        {
            MonoBehaviour[] scripts = go.InChildren<MonoBehaviour>(true);
            foreach (MonoBehaviour mb in scripts)
                if (!mb.IsDestroyed && mb.IsEnabledState) Disable(mb);
            foreach (MonoBehaviour mb in scripts)
                if (!mb.IsDestroyed && mb.AwakeCalled) Send(mb, "OnDestroy");
            go.transform.DetachForDestroy();
            MarkDestroyed(go.transform);
        }

        static void MarkDestroyed(Transform t)
        {
            GameObject go = t.gameObject;
            var children = new List<Transform>(t.Children);
            foreach (Transform child in children) MarkDestroyed(child);
            foreach (Component c in go.Components)
            {
                c.IsDestroyed = true;
                if (c is MonoBehaviour mb) s_behaviours.Remove(mb);
                c.OnDestroyInternal();
            }
            go.IsDestroyed = true;
            s_gameObjects.Remove(go);
        }

        internal static T[] FindObjects<T>(FindObjectsSortMode sortMode) where T : Object
        {
            var found = new List<T>();
            if (typeof(ScriptableObject).IsAssignableFrom(typeof(T)))
            {
                foreach (ScriptableObject so in s_scriptables)
                    if (so is T t && !so.IsDestroyed) found.Add(t);
            }
            else
            {
                foreach (GameObject go in s_gameObjects)
                {
                    if (!go.activeInHierarchy) continue;
                    if (go is T g) found.Add(g);
                    foreach (Component c in go.Components)
                        if (c is T t && !c.IsDestroyed) found.Add(t);
                }
            }
            if (sortMode == FindObjectsSortMode.InstanceID) found.Sort((a, b) => a.GetInstanceID().CompareTo(b.GetInstanceID()));
            return found.ToArray();
        }

        // ---- messages ----

        /// <summary>Calls the script's message method (any access, declared on its class or a base class) if it has one; logs what it throws.</summary>
        internal static void Send(Object target, string message, params object[] args)
        {
            MethodInfo m = Message(target.GetType(), message, args.Length);
            if (m == null) return;
            try
            {
                m.Invoke(target, args);
            }
            catch (TargetInvocationException e)
            {
                Debug.LogException(e.InnerException ?? e, target);
            }
        }

        /// <summary>Sends <paramref name="message"/> to every enabled script on an active GameObject, in the order they were added (the application's messages).</summary>
        internal static void Broadcast(string message, params object[] args)
        {
            foreach (MonoBehaviour mb in s_behaviours.ToArray())
                if (!mb.IsDestroyed && mb.IsEnabledState && mb.gameObject.activeInHierarchy) Send(mb, message, args);
        }

        internal static bool Has(Object target, string message, int arity = 0) => Message(target.GetType(), message, arity) != null;

        static MethodInfo Message(Type type, string name, int arity)
        {
            var key = (type, name, arity);
            if (s_messages.TryGetValue(key, out MethodInfo cached)) return cached;
            MethodInfo found = null;
            for (Type t = type; t != null && t != typeof(MonoBehaviour) && t != typeof(ScriptableObject) && t != typeof(Object); t = t.BaseType)
            {
                foreach (MethodInfo m in t.GetMethods(BindingFlags.Instance | BindingFlags.Public | BindingFlags.NonPublic | BindingFlags.DeclaredOnly))
                    if (m.Name == name && m.GetParameters().Length == arity) { found = m; break; }
                if (found != null) break;
            }
            s_messages[key] = found;
            return found;
        }

        // ---- the player loop ----

        /// <summary>Scripts that run this phase: started (or starting), active, enabled; in execution order.</summary>
        static List<MonoBehaviour> Running()
        {
            var list = new List<MonoBehaviour>(s_behaviours.Count);
            foreach (MonoBehaviour mb in s_behaviours)
                if (mb.isActiveAndEnabled) list.Add(mb);
            // Stable: by [DefaultExecutionOrder], then by when the script was added.
            var ordered = new List<MonoBehaviour>(list);
            ordered.Sort((a, b) =>
            {
                int c = Order(a.GetType()).CompareTo(Order(b.GetType()));
                return c != 0 ? c : list.IndexOf(a).CompareTo(list.IndexOf(b));
            });
            return ordered;
        }

        static int Order(Type t)
        {
            var attr = (DefaultExecutionOrder)Attribute.GetCustomAttribute(t, typeof(DefaultExecutionOrder), true);
            return attr != null ? attr.order : 0;
        }

        static void RunPendingStarts()
        {
            foreach (MonoBehaviour mb in Running())
            {
                if (mb.StartCalled || !mb.isActiveAndEnabled) continue;
                mb.StartCalled = true;
                Send(mb, "Start");
            }
        }

        static void Phase(string message)
        {
            foreach (MonoBehaviour mb in Running())
                if (mb.StartCalled && mb.isActiveAndEnabled && !mb.IsDestroyed) Send(mb, message);
        }

        /// <summary>A frame's duration when a test does not set Time.captureDeltaTime: 90 Hz, the Quest 2's default refresh rate.</summary>
        internal const float DefaultFrameTime = 1f / 90f;

        /// <summary>One frame of <paramref name="dt"/> seconds (Time.captureDeltaTime, when set, wins, as in Unity).</summary>
        internal static void Frame(float dt)
        {
            Time.BeginFrame(Time.captureDeltaTime > 0 ? Time.captureDeltaTime : dt);
            RunPendingStarts();
            while (Time.fixedTimeAsDouble + Time.fixedDeltaTime <= Time.timeAsDouble + 1e-9)
            {
                Time.BeginFixedStep();
                RunPendingStarts();
                Phase("FixedUpdate");
                PhysicsScene.Step();
                Time.EndFixedStep();
            }
            RunPendingStarts();
            Phase("Update");
            RunPendingStarts();
            Phase("LateUpdate");
            Application.BeforeRender();
            FlushDestroy();
        }

        internal static void FlushDestroy()
        {
            while (s_pendingDestroy.Count > 0)
            {
                Object obj = s_pendingDestroy[0];
                s_pendingDestroy.RemoveAt(0);
                if (!obj.IsDestroyed) DestroyNow(obj);
            }
        }

        /// <summary>An empty scene and clock: destroys every object (running OnDisable and OnDestroy), as leaving play mode does.</summary>
        internal static void Reset() => Reset(keepAssets: false);

        /// <summary>As <see cref="Reset()"/>; <paramref name="keepAssets"/>: a new scene in the editor, which keeps assets (prefabs, ScriptableObjects) loaded.</summary>
        internal static void Reset(bool keepAssets)
        {
            s_pendingDestroy.Clear();
            foreach (GameObject go in new List<GameObject>(s_gameObjects))
                if (!go.IsDestroyed && go.transform.parent == null && !(keepAssets && go.IsAsset)) DestroyNow(go);
            if (keepAssets)
            {
                PhysicsScene.Reset();
                return;
            }
            foreach (GameObject go in new List<GameObject>(s_gameObjects)) DestroyNow(go);
            foreach (ScriptableObject so in new List<ScriptableObject>(s_scriptables)) DestroyNow(so);
            s_gameObjects.Clear();
            s_behaviours.Clear();
            s_scriptables.Clear();
            PhysicsScene.Reset();
            Time.Reset();
            Application.Reset();
        }
    }

    public class MissingReferenceException : Exception
    {
        public MissingReferenceException(string message) : base(message) { }
    }
}
