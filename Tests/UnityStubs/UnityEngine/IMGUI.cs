// Compile-only. Transcribed from Unity-Technologies/UnityCsReference, branch 2022.3:
//   Modules/IMGUI/Event.cs + Event.bindings.cs (Event), Modules/IMGUI/EventEnums.cs (EventType),
//   Modules/IMGUI/GUI.cs (GUI), Modules/IMGUI/GUIStyle.cs (GUIStyle), Modules/IMGUI/GUILayout.cs (GUILayout),
//   Modules/IMGUI/GUILayoutOption.cs (GUILayoutOption)
namespace UnityEngine
{
    public sealed class Event
    {
        public static Event current => throw null;
        public EventType type => throw null;
    }

    public enum EventType
    {
        MouseDown = 0,
        MouseUp = 1,
        MouseMove = 2,
        MouseDrag = 3,
        KeyDown = 4,
        KeyUp = 5,
        ScrollWheel = 6,
        Repaint = 7,
        Layout = 8,
    }

    public class GUI
    {
        public static void Label(Rect position, string text, GUIStyle style) => throw null;
    }

    public sealed class GUIStyle
    {
    }

    public class GUILayout
    {
        public static bool Button(string text, params GUILayoutOption[] options) => throw null;
    }

    public sealed class GUILayoutOption
    {
    }
}
