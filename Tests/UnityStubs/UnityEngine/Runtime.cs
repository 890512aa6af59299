// Compile-only. Transcribed from Unity-Technologies/UnityCsReference, branch 2022.3:
//   Runtime/Export/Debug/Debug.bindings.cs (Debug), Runtime/Export/BaseClass.cs (LogType),
//   Runtime/Export/Application/Application.bindings.cs (Application), Runtime/Export/Time/Time.bindings.cs (Time),
//   Modules/JSONSerialize/Public/JsonUtility.bindings.cs (JsonUtility), Runtime/Export/Resources/Resources.bindings.cs
//   (Resources), Runtime/Export/SceneManager/Scene.cs (Scene)
using System;

namespace UnityEngine
{
    public class Debug
    {
        public static void Log(object message) => throw null;
        public static void LogWarning(object message) => throw null;
        public static void LogError(object message) => throw null;
        public static void LogError(object message, Object context) => throw null;
        public static void LogException(Exception exception) => throw null;
        public static void LogException(Exception exception, Object context) => throw null;
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
        public static string persistentDataPath => throw null;
        public static bool isPlaying => throw null;
        public static bool isBatchMode => throw null;
    }

    public class Time
    {
        public static float deltaTime => throw null;
        public static double timeAsDouble => throw null;
        public static float captureDeltaTime { get => throw null; set => throw null; }
    }

    public static class JsonUtility
    {
        public static string ToJson(object obj, bool prettyPrint) => throw null;
        public static T FromJson<T>(string json) => throw null;
    }

    public sealed class Resources
    {
        public static T GetBuiltinResource<T>(string path) where T : Object => throw null;
    }
}

namespace UnityEngine.SceneManagement
{
    public struct Scene
    {
    }
}
