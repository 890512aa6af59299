// Compile-only. Transcribed from Unity-Technologies/UnityCsReference, branch 2022.3:
//   Editor/Mono/Inspector/Editor.cs (Editor, CanEditMultipleObjects), Editor/Mono/Inspector/CustomEditor.cs,
//   Editor/Mono/EditorGUILayout.cs, Editor/Mono/EditorGUI.cs (DrawRect), Editor/Mono/GUI/EditorStyles.cs,
//   Editor/Mono/EditorGUIUtility.bindings.cs (MessageType), Editor/Mono/Handles.cs, Editor/Mono/DrawGizmo.cs,
//   Editor/Mono/Undo/Undo.bindings.cs, Editor/Mono/EditorUtility.bindings.cs, Editor/Mono/MenuItem.cs,
//   Editor/Mono/SerializedObject.bindings.cs, Editor/Mono/SerializedProperty.bindings.cs
using System;
using UnityEngine;
using Object = UnityEngine.Object;

namespace UnityEditor
{
    public class Editor : ScriptableObject
    {
        public Object target { get => throw null; set => throw null; }
        public Object[] targets => throw null;
        public virtual void OnInspectorGUI() => throw null;
        public bool DrawDefaultInspector() => throw null;
        public virtual bool RequiresConstantRepaint() => throw null;
    }

    public class CustomEditor : Attribute
    {
        public CustomEditor(Type inspectedType) => throw null;
    }

    public sealed class CanEditMultipleObjects : Attribute
    {
    }

    public sealed class EditorGUILayout
    {
        public static void LabelField(string label, params GUILayoutOption[] options) => throw null;
        public static void LabelField(string label, GUIStyle style, params GUILayoutOption[] options) => throw null;
        public static void LabelField(string label, string label2, params GUILayoutOption[] options) => throw null;
        public static void LabelField(string label, string label2, GUIStyle style, params GUILayoutOption[] options) => throw null;
        public static void HelpBox(string message, MessageType type) => throw null;
        public static void Space() => throw null;
        public static Rect GetControlRect(bool hasLabel, float height, params GUILayoutOption[] options) => throw null;
        public static Rect BeginHorizontal(params GUILayoutOption[] options) => throw null;
        public static void EndHorizontal() => throw null;
    }

    public sealed class EditorGUI
    {
        public static void DrawRect(Rect rect, Color color) => throw null;
    }

    public sealed class EditorStyles
    {
        public static GUIStyle miniLabel => throw null;
        public static GUIStyle boldLabel => throw null;
        public static GUIStyle miniBoldLabel => throw null;
        public static GUIStyle wordWrappedMiniLabel => throw null;
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
        public static Color color { get => throw null; set => throw null; }
        public static void DrawAAPolyLine(float width, params Vector3[] points) => throw null;
        public static void Label(Vector3 position, string text) => throw null;
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
        public DrawGizmo(GizmoType gizmo) => throw null;
    }

    public partial class Undo
    {
        public static void RecordObject(Object objectToUndo, string name) => throw null;
    }

    public sealed partial class EditorUtility
    {
        public static void SetDirty(Object target) => throw null;
    }

    [AttributeUsage(AttributeTargets.Method, AllowMultiple = true)]
    public sealed class MenuItem : Attribute
    {
        public MenuItem(string itemName) => throw null;
        public string menuItem;
        public bool validate;
        public int priority;
    }

    public class SerializedObject : IDisposable
    {
        public SerializedObject(Object obj) => throw null;
        public SerializedProperty FindProperty(string propertyPath) => throw null;
        public bool ApplyModifiedPropertiesWithoutUndo() => throw null;
        public void Dispose() => throw null;
    }

    public class SerializedProperty : IDisposable
    {
        public int intValue { get => throw null; set => throw null; }
        public void Dispose() => throw null;
    }
}
