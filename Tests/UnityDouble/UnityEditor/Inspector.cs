// Test double: nothing is drawn; what an inspector shows (labels, help boxes) is recorded for tests (EditorGUILayout.Shown).
// Transcribed from Unity-Technologies/UnityCsReference, branch 2022.3:
//   Editor/Mono/Inspector/Editor.cs (Editor, CanEditMultipleObjects), Editor/Mono/Inspector/CustomEditor.cs,
//   Editor/Mono/EditorGUILayout.cs, Editor/Mono/EditorGUI.cs (DrawRect), Editor/Mono/GUI/EditorStyles.cs,
//   Editor/Mono/EditorGUIUtility.bindings.cs (MessageType), Editor/Mono/Handles.cs, Editor/Mono/DrawGizmo.cs,
//   Editor/Mono/Undo/Undo.bindings.cs, Editor/Mono/EditorUtility.bindings.cs, Editor/Mono/MenuItem.cs,
//   Editor/Mono/SerializedObject.bindings.cs, Editor/Mono/SerializedProperty.bindings.cs, Editor/Mono/GUI/GenericMenu.cs
using System;
using UnityEngine;
using Object = UnityEngine.Object;

namespace UnityEditor
{
    public class Editor : ScriptableObject
    {
        Object _target;

        public Object target { get => _target; set { _target = value; Targets = new[] { value }; } }
        public Object[] targets => Targets ?? new Object[0];
        internal Object[] Targets;
        public virtual void OnInspectorGUI() => DrawDefaultInspector();
        public bool DrawDefaultInspector() => true;
        public virtual bool RequiresConstantRepaint() => false;
    }

    public class CustomEditor : Attribute
    {
        public CustomEditor(Type inspectedType) => InspectedType = inspectedType;
        internal readonly Type InspectedType;
    }

    public sealed class CanEditMultipleObjects : Attribute
    {
    }

    public sealed class EditorGUILayout
    {
        internal static readonly System.Collections.Generic.List<string> Shown = new System.Collections.Generic.List<string>();

        public static void LabelField(string label, params GUILayoutOption[] options) => Shown.Add(label);
        public static void LabelField(string label, GUIStyle style, params GUILayoutOption[] options) => Shown.Add(label);
        public static void LabelField(string label, string label2, params GUILayoutOption[] options) => Shown.Add(label + ": " + label2);
        public static void LabelField(string label, string label2, GUIStyle style, params GUILayoutOption[] options) => Shown.Add(label + ": " + label2);
        public static void HelpBox(string message, MessageType type) => Shown.Add(type + ": " + message);
        public static void Space() { }
        public static Rect GetControlRect(bool hasLabel, float height, params GUILayoutOption[] options) => new Rect(0, 0, 300, height);
        public static Rect BeginHorizontal(params GUILayoutOption[] options) => new Rect(0, 0, 300, 20);
        public static void EndHorizontal() { }

        /// <summary>The foldout as it was (a driver does not click it): recorded as "Foldout: label".</summary>
        public static bool Foldout(bool foldout, string content, bool toggleOnLabelClick)
        {
            Shown.Add("Foldout: " + content);
            return foldout;
        }

        /// <summary>The value as it was, unless a driver typed one for this label (UnityDouble.Editor.Type); recorded "label: value".</summary>
        public static double DoubleField(string label, double value, params GUILayoutOption[] options)
        {
            if (Typed.TryGetValue(label, out double typed)) { Typed.Remove(label); value = typed; }
            Shown.Add(label + ": " + value.ToString("R", System.Globalization.CultureInfo.InvariantCulture));
            return value;
        }

        public static bool Toggle(string label, bool value, params GUILayoutOption[] options)
        {
            if (Typed.TryGetValue(label, out double typed)) { Typed.Remove(label); value = typed != 0; }
            Shown.Add(label + ": " + (value ? "on" : "off"));
            return value;
        }

        public static string TextField(string label, string text, params GUILayoutOption[] options)
        {
            Shown.Add(label + ": " + text);
            return text;
        }

        public static System.Enum EnumPopup(string label, System.Enum selected, params GUILayoutOption[] options)
        {
            Shown.Add(label + ": " + selected);
            return selected;
        }

        internal static readonly System.Collections.Generic.Dictionary<string, double> Typed = new System.Collections.Generic.Dictionary<string, double>();
    }

    public sealed class EditorGUI
    {
        public static int indentLevel { get; set; }

        public static void DrawRect(Rect rect, Color color) => Rects++;
        internal static int Rects;
    }

    public sealed class EditorStyles
    {
        public static GUIStyle miniLabel { get; } = new GUIStyle();
        public static GUIStyle boldLabel { get; } = new GUIStyle();
        public static GUIStyle miniBoldLabel { get; } = new GUIStyle();
        public static GUIStyle wordWrappedMiniLabel { get; } = new GUIStyle();
    }

    public enum MessageType
    {
        None = 0,
        Info = 1,
        Warning = 2,
        Error = 3,
    }

    public sealed class Handles
    {
        public static Color color { get; set; }
        public static void DrawAAPolyLine(float width, params Vector3[] points) => Lines++;
        public static void Label(Vector3 position, string text) => Labels.Add(text);
        internal static int Lines;
        internal static readonly System.Collections.Generic.List<string> Labels = new System.Collections.Generic.List<string>();
    }

    [Flags]
    public enum GizmoType
    {
        Pickable = 1,
        NotInSelectionHierarchy = 2,
        NonSelected = 32,
        Selected = 4,
        Active = 8,
        InSelectionHierarchy = 16,
    }

    public sealed class DrawGizmo : Attribute
    {
        public DrawGizmo(GizmoType gizmo) => drawOptions = gizmo;
        public GizmoType drawOptions;
    }

    /// <summary>A context menu: the double records what was shown (UnityDouble.Editor.MenuShown) and a driver chooses an item
    /// (UnityDouble.Editor.ChooseMenuItem), which calls its function as Unity does when the user picks it.</summary>
    public sealed class GenericMenu
    {
        public delegate void MenuFunction();

        internal readonly System.Collections.Generic.List<(string Text, string Tooltip, bool Enabled, bool On, MenuFunction Function)> Items =
            new System.Collections.Generic.List<(string, string, bool, bool, MenuFunction)>();

        public void AddItem(GUIContent content, bool on, MenuFunction func) => Items.Add((content.text, content.tooltip, true, on, func));
        public void AddDisabledItem(GUIContent content) => Items.Add((content.text, content.tooltip, false, false, null));
        public void ShowAsContext() => Shown = this;

        internal static GenericMenu Shown;
    }

    public partial class Undo
    {
        public static void RecordObject(Object objectToUndo, string name) { }
    }

    public sealed partial class EditorUtility
    {
        public static void SetDirty(Object target) => Dirty.Add(target);
        internal static readonly System.Collections.Generic.HashSet<Object> Dirty = new System.Collections.Generic.HashSet<Object>();
    }

    [AttributeUsage(AttributeTargets.Method, AllowMultiple = true)]
    public sealed class MenuItem : Attribute
    {
        public MenuItem(string itemName) => menuItem = itemName;
        public string menuItem;
        public bool validate;
        public int priority;
    }

    public class SerializedObject : IDisposable
    {
        readonly Object _target;

        public SerializedObject(Object obj) => _target = obj;

        /// <summary>A serialized field of that name (public, or [SerializeField]) on the object or its base classes; null if none.</summary>
        public SerializedProperty FindProperty(string propertyPath)
        {
            for (Type t = _target.GetType(); t != null; t = t.BaseType)
            {
                var f = t.GetField(propertyPath, System.Reflection.BindingFlags.Instance | System.Reflection.BindingFlags.Public | System.Reflection.BindingFlags.NonPublic | System.Reflection.BindingFlags.DeclaredOnly);
                if (f != null && (f.IsPublic || f.IsDefined(typeof(SerializeField), true))) return new SerializedProperty(_target, f);
            }
            return null;
        }

        public bool ApplyModifiedPropertiesWithoutUndo() => true;
        public void Dispose() { }
    }

    public class SerializedProperty : IDisposable
    {
        readonly object _owner;
        readonly System.Reflection.FieldInfo _field;

        internal SerializedProperty(object owner, System.Reflection.FieldInfo field)
        {
            _owner = owner;
            _field = field;
        }

        public int intValue
        {
            get => Convert.ToInt32(_field.GetValue(_owner));
            set => _field.SetValue(_owner, _field.FieldType.IsEnum ? Enum.ToObject(_field.FieldType, value) : Convert.ChangeType(value, _field.FieldType));
        }

        public void Dispose() { }
    }
}
