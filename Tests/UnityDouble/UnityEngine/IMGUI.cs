// Test double: no GUI is drawn; the event is a Repaint unless a driver says otherwise. Transcribed from Unity-Technologies/UnityCsReference, branch 2022.3:
//   Modules/IMGUI/Event.cs + Event.bindings.cs (Event), Modules/IMGUI/EventEnums.cs (EventType),
//   Modules/IMGUI/GUI.cs (GUI), Modules/IMGUI/GUIStyle.cs (GUIStyle), Modules/IMGUI/GUILayout.cs (GUILayout),
//   Modules/IMGUI/GUILayoutOption.cs (GUILayoutOption), Modules/IMGUI/GUIContent.cs (GUIContent)
namespace UnityEngine
{
    public sealed class Event
    {
        public static Event current { get; internal set; } = new Event();
        public EventType type { get; internal set; } = EventType.Repaint;
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
        public static void Label(Rect position, string text, GUIStyle style) => Drawn.Add(text);
        internal static readonly System.Collections.Generic.List<string> Drawn = new System.Collections.Generic.List<string>();
    }

    public sealed class GUIStyle
    {
    }

    /// <summary>Real (Modules/IMGUI/GUIUtility.cs): ExitGUI throws ExitGUIException, which the editor's GUI loop catches
    /// without a message: the rest of this event's GUI is skipped and the next event lays it out anew.</summary>
    public class GUIUtility
    {
        public static void ExitGUI() => throw new ExitGUIException();
    }

    public sealed class ExitGUIException : System.Exception
    {
    }

    public class GUILayout
    {
        /// <summary>True for the label a driver "clicks" (GUILayout.Clicked), once.</summary>
        public static bool Button(string text, params GUILayoutOption[] options)
        {
            if (Clicked != text) return false;
            Clicked = null;
            return true;
        }

        internal static string Clicked;
    }

    public class GUIContent
    {
        public GUIContent(string text, string tooltip)
        {
            this.text = text;
            this.tooltip = tooltip;
        }

        public string text { get; set; }
        public string tooltip { get; set; }
    }

    public sealed class GUILayoutOption
    {
    }
}
