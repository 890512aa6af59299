// Test double of UnityEngine's runtime services, with Unity's documented semantics: Debug's messages reach
// Application.logMessageReceived (the Test Framework's LogAssert listens there); Time advances per frame and reads the
// fixed step inside FixedUpdate; Application.onBeforeRender runs after LateUpdate, its callbacks by their method's
// [BeforeRenderOrder] (0 without it), in subscription order within one order (Runtime/Export/Application/BeforeRenderHelper.cs); JsonUtility writes and reads the
// public and [SerializeField] fields of a [Serializable] class and throws ArgumentException on malformed JSON. Public
// members are those of UnityCsReference 2022.3 (Runtime/Export/Debug/Debug.bindings.cs, Runtime/Export/BaseClass.cs,
// Runtime/Export/Application/Application.bindings.cs, Runtime/Export/Time/Time.bindings.cs,
// Modules/JSONSerialize/Public/JsonUtility.bindings.cs, Runtime/Export/Resources/Resources.bindings.cs) that are used.
using System;
using System.Collections;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Reflection;
using System.Text;

namespace UnityEngine
{
    public class Debug
    {
        public static void Log(object message) => Emit(LogType.Log, message, null);
        public static void Log(object message, Object context) => Emit(LogType.Log, message, context);
        public static void LogWarning(object message) => Emit(LogType.Warning, message, null);
        public static void LogWarning(object message, Object context) => Emit(LogType.Warning, message, context);
        public static void LogError(object message) => Emit(LogType.Error, message, null);
        public static void LogError(object message, Object context) => Emit(LogType.Error, message, context);
        public static void LogException(Exception exception) => LogException(exception, null);

        public static void LogException(Exception exception, Object context) =>
            Application.Log(exception.GetType().Name + ": " + exception.Message, exception.StackTrace ?? "", LogType.Exception);

        static void Emit(LogType type, object message, Object context) =>
            Application.Log(message == null ? "Null" : message.ToString(), Environment.StackTrace, type);
    }

    public enum LogType
    {
        Error = 0,
        Assert = 1,
        Warning = 2,
        Log = 3,
        Exception = 4,
    }

    public class Application
    {
        public delegate void LogCallback(string condition, string stackTrace, LogType type);

        static string s_persistentDataPath;

        public static event LogCallback logMessageReceived;
        public static event LogCallback logMessageReceivedThreaded;

        /// <summary>
        /// Called after LateUpdate, before the frame renders (where XR rigs late-latch their poses). As Unity's
        /// BeforeRenderHelper: a callback's order is its method's [BeforeRenderOrder] (0 without), lower orders run
        /// first, callbacks of one order in the order they subscribed.
        /// </summary>
        public static event UnityEngine.Events.UnityAction onBeforeRender
        {
            add => BeforeRenderBlocks.Register(value);
            remove => BeforeRenderBlocks.Unregister(value);
        }

        /// <summary>A folder of its own per test run (under the system's temporary folder) until a driver sets another.</summary>
        public static string persistentDataPath => s_persistentDataPath ??= Path.Combine(Path.GetTempPath(), "unity-double-" + Guid.NewGuid().ToString("N"));

        public static bool isPlaying => IsPlayingState;
        public static bool isBatchMode => IsBatchModeState;
        public static bool isEditor => true;
        public static string unityVersion => "2022.3.50f1";

        internal static bool IsPlayingState = true, IsBatchModeState;
        internal static string PersistentDataPathOverride { set => s_persistentDataPath = value; }

        internal static void Log(string message, string stack, LogType type)
        {
            Console.WriteLine("[" + type + "] " + message);
            logMessageReceivedThreaded?.Invoke(message, stack, type);
            logMessageReceived?.Invoke(message, stack, type);
        }

        internal static void BeforeRender()
        {
            try
            {
                BeforeRenderBlocks.Invoke();
            }
            catch (Exception e)
            {
                Debug.LogException(e);
            }
        }

        internal static void Reset()
        {
            BeforeRenderBlocks.Clear();
            IsPlayingState = true;
        }
    }

    /// <summary>Unity's BeforeRenderHelper: one multicast delegate per order, the orders sorted.</summary>
    static class BeforeRenderBlocks
    {
        static readonly List<KeyValuePair<int, UnityEngine.Events.UnityAction>> s_blocks = new List<KeyValuePair<int, UnityEngine.Events.UnityAction>>();

        static int Order(UnityEngine.Events.UnityAction callback)
        {
            object[] attributes = callback.Method.GetCustomAttributes(typeof(BeforeRenderOrderAttribute), true);
            return attributes.Length > 0 ? ((BeforeRenderOrderAttribute)attributes[0]).order : 0;
        }

        internal static void Register(UnityEngine.Events.UnityAction callback)
        {
            if (callback == null) return;
            int order = Order(callback);
            int i = 0;
            for (; i < s_blocks.Count && s_blocks[i].Key <= order; i++)
            {
                if (s_blocks[i].Key != order) continue;
                s_blocks[i] = new KeyValuePair<int, UnityEngine.Events.UnityAction>(order, s_blocks[i].Value + callback);
                return;
            }
            s_blocks.Insert(i, new KeyValuePair<int, UnityEngine.Events.UnityAction>(order, callback));
        }

        internal static void Unregister(UnityEngine.Events.UnityAction callback)
        {
            if (callback == null) return;
            int order = Order(callback);
            for (int i = 0; i < s_blocks.Count && s_blocks[i].Key <= order; i++)
            {
                if (s_blocks[i].Key != order) continue;
                UnityEngine.Events.UnityAction rest = s_blocks[i].Value - callback;
                if (rest == null) s_blocks.RemoveAt(i);
                else s_blocks[i] = new KeyValuePair<int, UnityEngine.Events.UnityAction>(order, rest);
                return;
            }
        }

        internal static void Invoke()
        {
            for (int i = 0; i < s_blocks.Count; i++) s_blocks[i].Value?.Invoke();
        }

        internal static void Clear() => s_blocks.Clear();
    }

    public class Time
    {
        static double s_time, s_fixedTime, s_unscaledTime;
        static float s_deltaTime, s_unscaledDeltaTime, s_fixedDeltaTime = 0.02f, s_timeScale = 1;
        static bool s_inFixedStep;

        /// <summary>The frame's duration in game time (the real one × <see cref="timeScale"/>); inside FixedUpdate, the fixed step (as Unity).</summary>
        public static float deltaTime => s_inFixedStep ? s_fixedDeltaTime : s_deltaTime;
        /// <summary>The frame's real duration, whatever <see cref="timeScale"/> is.</summary>
        public static float unscaledDeltaTime => s_unscaledDeltaTime;
        /// <summary>Real time since the start (the sum of <see cref="unscaledDeltaTime"/>).</summary>
        public static double unscaledTimeAsDouble => s_unscaledTime;
        public static float unscaledTime => (float)s_unscaledTime;
        /// <summary>How fast game time runs against real time (Unity: 0 pauses it; deltaTime, time and the fixed steps follow it, the unscaled ones do not).</summary>
        public static float timeScale { get => s_timeScale; set => s_timeScale = value; }
        public static float time => (float)(s_inFixedStep ? s_fixedTime : s_time);
        public static double timeAsDouble => s_inFixedStep ? s_fixedTime : s_time;
        public static float fixedTime => (float)s_fixedTime;
        public static double fixedTimeAsDouble => s_fixedTime;
        public static float fixedDeltaTime { get => s_fixedDeltaTime; set => s_fixedDeltaTime = value; }
        public static int frameCount { get; private set; }
        public static float captureDeltaTime { get; set; }

        internal static void BeginFrame(float dt)
        {
            s_unscaledDeltaTime = dt;
            s_unscaledTime += dt;
            s_deltaTime = dt * s_timeScale;
            s_time += s_deltaTime;
            frameCount++;
        }

        internal static void BeginFixedStep()
        {
            s_fixedTime += s_fixedDeltaTime;
            s_inFixedStep = true;
        }

        internal static void EndFixedStep() => s_inFixedStep = false;

        internal static void Reset()
        {
            s_time = s_fixedTime = s_unscaledTime = 0;
            s_deltaTime = s_unscaledDeltaTime = 0;
            s_timeScale = 1;
            s_fixedDeltaTime = 0.02f;
            s_inFixedStep = false;
            frameCount = 0;
            captureDeltaTime = 0;
        }
    }

    public static class JsonUtility
    {
        public static string ToJson(object obj) => ToJson(obj, false);

        public static string ToJson(object obj, bool prettyPrint)
        {
            if (obj == null) return "";
            var sb = new StringBuilder();
            Json.WriteObject(sb, obj, prettyPrint, 0);
            return sb.ToString();
        }

        public static T FromJson<T>(string json) => (T)FromJson(json, typeof(T));

        /// <summary>Overwrites the serialized fields the JSON names (others keep their values), then, as Unity does for an
        /// object that implements it, calls ISerializationCallbackReceiver.OnAfterDeserialize. Works on a ScriptableObject.</summary>
        public static void FromJsonOverwrite(string json, object objectToOverwrite)
        {
            if (objectToOverwrite == null) throw new ArgumentNullException(nameof(objectToOverwrite));
            if (string.IsNullOrEmpty(json)) return;
            if (!(Json.Parse(json) is Dictionary<string, object> fields)) throw new ArgumentException("JSON must represent an object type.");
            Json.Fill(objectToOverwrite, fields);
            if (objectToOverwrite is ISerializationCallbackReceiver receiver) receiver.OnAfterDeserialize();
        }

        public static object FromJson(string json, Type type)
        {
            if (string.IsNullOrEmpty(json)) return null;
            object parsed = Json.Parse(json);
            if (!(parsed is Dictionary<string, object> fields)) throw new ArgumentException("JSON must represent an object type.");
            object target = Activator.CreateInstance(type, true);
            Json.Fill(target, fields);
            return target;
        }
    }

    /// <summary>The small JSON reader and writer behind the double's JsonUtility.</summary>
    static class Json
    {
        static IEnumerable<FieldInfo> SerializedFields(Type t)
        {
            foreach (FieldInfo f in t.GetFields(BindingFlags.Instance | BindingFlags.Public | BindingFlags.NonPublic))
                if (!f.IsNotSerialized && !f.IsInitOnly && (f.IsPublic || f.IsDefined(typeof(SerializeField), true))) yield return f;
        }

        internal static void WriteObject(StringBuilder sb, object obj, bool pretty, int depth)
        {
            sb.Append('{');
            bool first = true;
            foreach (FieldInfo f in SerializedFields(obj.GetType()))
            {
                if (!first) sb.Append(',');
                first = false;
                if (pretty) sb.Append('\n').Append(' ', 4 * (depth + 1));
                WriteString(sb, f.Name);
                sb.Append(pretty ? ": " : ":");
                WriteValue(sb, f.GetValue(obj), pretty, depth + 1);
            }
            if (pretty && !first) sb.Append('\n').Append(' ', 4 * depth);
            sb.Append('}');
        }

        static void WriteValue(StringBuilder sb, object v, bool pretty, int depth)
        {
            switch (v)
            {
                case null: sb.Append("\"\""); break;
                case string s: WriteString(sb, s); break;
                case bool b: sb.Append(b ? "true" : "false"); break;
                case float f: sb.Append(f.ToString("R", CultureInfo.InvariantCulture)); break;
                case double d: sb.Append(d.ToString("R", CultureInfo.InvariantCulture)); break;
                case Enum e: sb.Append(System.Convert.ToInt64(e, CultureInfo.InvariantCulture)); break;
                case IFormattable n when v.GetType().IsPrimitive: sb.Append(n.ToString(null, CultureInfo.InvariantCulture)); break;
                case IList list:
                    sb.Append('[');
                    for (int i = 0; i < list.Count; i++)
                    {
                        if (i > 0) sb.Append(',');
                        WriteValue(sb, list[i], pretty, depth);
                    }
                    sb.Append(']');
                    break;
                default: WriteObject(sb, v, pretty, depth); break;
            }
        }

        static void WriteString(StringBuilder sb, string s)
        {
            sb.Append('"');
            foreach (char c in s)
            {
                if (c == '"' || c == '\\') sb.Append('\\').Append(c);
                else if (c < ' ') sb.Append("\\u").Append(((int)c).ToString("x4", CultureInfo.InvariantCulture));
                else sb.Append(c);
            }
            sb.Append('"');
        }

        internal static void Fill(object target, Dictionary<string, object> fields)
        {
            foreach (FieldInfo f in SerializedFields(target.GetType()))
                if (fields.TryGetValue(f.Name, out object v)) f.SetValue(target, Convert(v, f.FieldType));
        }

        static object Convert(object v, Type type)
        {
            if (type == typeof(string)) return v as string ?? (v == null ? null : System.Convert.ToString(v, CultureInfo.InvariantCulture));
            if (type == typeof(bool)) return v is bool b && b;
            if (type.IsEnum) return Enum.ToObject(type, System.Convert.ToInt64(v ?? 0.0, CultureInfo.InvariantCulture));
            if (type.IsPrimitive) return System.Convert.ChangeType(v ?? 0.0, type, CultureInfo.InvariantCulture);
            if (type.IsArray && v is List<object> items)
            {
                Array a = Array.CreateInstance(type.GetElementType(), items.Count);
                for (int i = 0; i < items.Count; i++) a.SetValue(Convert(items[i], type.GetElementType()), i);
                return a;
            }
            if (v is Dictionary<string, object> nested)
            {
                object o = Activator.CreateInstance(type, true);
                Fill(o, nested);
                return o;
            }
            return type.IsValueType ? Activator.CreateInstance(type) : null;
        }

        internal static object Parse(string json)
        {
            int i = 0;
            object v = Value(json, ref i);
            Skip(json, ref i);
            if (i != json.Length) throw Error(json, i);
            return v;
        }

        static ArgumentException Error(string json, int at) => new ArgumentException("JSON parse error: Invalid value. (at character " + at + ")");

        static void Skip(string s, ref int i)
        {
            while (i < s.Length && char.IsWhiteSpace(s[i])) i++;
        }

        static object Value(string s, ref int i)
        {
            Skip(s, ref i);
            if (i >= s.Length) throw Error(s, i);
            char c = s[i];
            if (c == '{')
            {
                var d = new Dictionary<string, object>();
                i++;
                Skip(s, ref i);
                if (i < s.Length && s[i] == '}') { i++; return d; }
                while (true)
                {
                    Skip(s, ref i);
                    if (i >= s.Length || s[i] != '"') throw Error(s, i);
                    string key = String(s, ref i);
                    Skip(s, ref i);
                    if (i >= s.Length || s[i] != ':') throw Error(s, i);
                    i++;
                    d[key] = Value(s, ref i);
                    Skip(s, ref i);
                    if (i < s.Length && s[i] == ',') { i++; continue; }
                    if (i < s.Length && s[i] == '}') { i++; return d; }
                    throw Error(s, i);
                }
            }
            if (c == '[')
            {
                var list = new List<object>();
                i++;
                Skip(s, ref i);
                if (i < s.Length && s[i] == ']') { i++; return list; }
                while (true)
                {
                    list.Add(Value(s, ref i));
                    Skip(s, ref i);
                    if (i < s.Length && s[i] == ',') { i++; continue; }
                    if (i < s.Length && s[i] == ']') { i++; return list; }
                    throw Error(s, i);
                }
            }
            if (c == '"') return String(s, ref i);
            if (Word(s, ref i, "true")) return true;
            if (Word(s, ref i, "false")) return false;
            if (Word(s, ref i, "null")) return null;
            int start = i;
            while (i < s.Length && "+-0123456789.eE".IndexOf(s[i]) >= 0) i++;
            if (i == start || !double.TryParse(s.Substring(start, i - start), NumberStyles.Float, CultureInfo.InvariantCulture, out double n)) throw Error(s, start);
            return n;
        }

        static bool Word(string s, ref int i, string word)
        {
            if (string.CompareOrdinal(s, i, word, 0, word.Length) != 0) return false;
            i += word.Length;
            return true;
        }

        static string String(string s, ref int i)
        {
            var sb = new StringBuilder();
            i++;
            while (i < s.Length && s[i] != '"')
            {
                if (s[i] == '\\' && i + 1 < s.Length)
                {
                    char e = s[++i];
                    if (e == 'u' && i + 4 < s.Length) { sb.Append((char)int.Parse(s.Substring(i + 1, 4), NumberStyles.HexNumber, CultureInfo.InvariantCulture)); i += 4; }
                    else sb.Append(e == 'n' ? '\n' : e == 't' ? '\t' : e == 'r' ? '\r' : e == 'b' ? '\b' : e == 'f' ? '\f' : e);
                }
                else sb.Append(s[i]);
                i++;
            }
            if (i >= s.Length) throw Error(s, i);
            i++;
            return sb.ToString();
        }
    }

    public sealed class Resources
    {
        static readonly Dictionary<string, Object> s_builtin = new Dictionary<string, Object>();

        /// <summary>The editor's built-in resources; the double knows the legacy font (LegacyRuntime.ttf since 2022.2).</summary>
        public static T GetBuiltinResource<T>(string path) where T : Object
        {
            if (path != "LegacyRuntime.ttf" || typeof(T) != typeof(Font)) return null;
            if (!s_builtin.TryGetValue(path, out Object o) || o.IsDestroyed)
                s_builtin[path] = o = new Font { name = "LegacyRuntime", material = new Material { name = "Font Material" } };
            return (T)o;
        }
    }
}

namespace UnityEngine.Events
{
    public delegate void UnityAction();
}

namespace UnityEngine.SceneManagement
{
    public struct Scene
    {
        public string name { get; internal set; }
        public string path { get; internal set; }
        public bool IsValid() => name != null;
    }
}
