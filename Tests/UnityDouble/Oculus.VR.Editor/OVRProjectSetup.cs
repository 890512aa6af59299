// Test double of Meta's Project Setup Tool registry (the tasks live in memory; nothing is drawn). Transcribed from the Meta XR
// Core SDK (com.meta.xr.sdk.core 68.0.2), as mirrored in icosa-mirror/com.meta.xr.sdk.core at tag 68.0.2:
// Editor/OVRProjectSetup/OVRProjectSetup.cs (global namespace, assembly Oculus.VR.Editor): TaskLevel, TaskGroup and the
// public AddTask with its parameters in their order and defaults. As there: a task needs isDone and a message (or a
// conditional one), "All" is not a group, and a second task with the same message is refused (the message is hashed into
// the task's id).
using System;
using System.Collections.Generic;
using UnityEditor;

public static class OVRProjectSetup
{
    public enum TaskLevel
    {
        Optional = 0,
        Recommended = 1,
        Required = 2
    }

    public enum TaskGroup
    {
        All = 0,
        Compatibility = 1,
        Rendering = 2,
        Quality = 3,
        Physics = 4,
        Packages = 5,
        Features = 6,
        Miscellaneous = 7
    }

    /// <summary>A registered task, as the tool keeps it (the double's record of AddTask's arguments).</summary>
    internal sealed class Task
    {
        public TaskGroup Group;
        public Func<BuildTargetGroup, bool> IsDone;
        public BuildTargetGroup Platform;
        public Action<BuildTargetGroup> Fix;
        public TaskLevel Level;
        public string Message;
        public string FixMessage;
    }

    internal static readonly List<Task> Tasks = new List<Task>();

    public static void AddTask(
        OVRProjectSetup.TaskGroup group,
        Func<BuildTargetGroup, bool> isDone,
        BuildTargetGroup platform = BuildTargetGroup.Unknown,
        Action<BuildTargetGroup> fix = null,
        OVRProjectSetup.TaskLevel level = OVRProjectSetup.TaskLevel.Recommended,
        Func<BuildTargetGroup, OVRProjectSetup.TaskLevel> conditionalLevel = null,
        string message = null,
        Func<BuildTargetGroup, string> conditionalMessage = null,
        string fixMessage = null,
        Func<BuildTargetGroup, string> conditionalFixMessage = null,
        string url = null,
        Func<BuildTargetGroup, string> conditionalUrl = null,
        bool validity = true,
        Func<BuildTargetGroup, bool> conditionalValidity = null
    )
    {
        if (isDone == null) throw new ArgumentNullException(nameof(isDone));
        if (message == null && conditionalMessage == null) throw new ArgumentNullException(nameof(message));
        if (group == TaskGroup.All) throw new ArgumentException("All is not a task group", nameof(group));
        foreach (Task t in Tasks)
            if (message != null && t.Message == message) throw new ArgumentException("a task with this message is already registered: " + message);
        Tasks.Add(new Task { Group = group, IsDone = isDone, Platform = platform, Fix = fix, Level = level, Message = message, FixMessage = fixMessage });
    }
}
