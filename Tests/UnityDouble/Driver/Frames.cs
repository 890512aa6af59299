// The tests' handle on the double (never part of the per-asmdef compile check, so package code cannot use it).
using System;
using NUnit.Framework;
using NUnit.Framework.Interfaces;
using UnityEngine;
using UnityEngine.TestTools.Logging;

namespace UnityDouble
{
    /// <summary>Runs the double's player loop.</summary>
    public static class Frames
    {
        /// <summary>90 Hz, the Quest 2's default refresh rate: a frame's duration when Time.captureDeltaTime is not set.</summary>
        public const float DefaultDuration = Engine.DefaultFrameTime;

        /// <summary><paramref name="count"/> frames of <paramref name="dt"/> seconds each (Time.captureDeltaTime wins when set).</summary>
        public static void Run(int count, float dt = Engine.DefaultFrameTime)
        {
            for (int i = 0; i < count; i++) Engine.Frame(dt);
        }

        /// <summary>The clock back at zero (frame count, time, fixed time, captureDeltaTime), within a test; the scene stays.</summary>
        public static void ResetClock() => Time.Reset();

        /// <summary>Frames until <paramref name="seconds"/> of game time have passed.</summary>
        public static void For(double seconds, float dt = Engine.DefaultFrameTime)
        {
            double until = Time.timeAsDouble + seconds;
            while (Time.timeAsDouble < until - 1e-9) Engine.Frame(dt);
        }
    }
}

namespace UnityDouble
{
    /// <summary>Entering play mode, as far as the package sees it.</summary>
    public static class PlayMode
    {
        /// <summary>
        /// Runs the static [RuntimeInitializeOnLoadMethod] methods of <paramref name="assembly"/> in Unity's order of load
        /// types (SubsystemRegistration, AfterAssembliesLoaded, BeforeSplashScreen, BeforeSceneLoad, AfterSceneLoad), as
        /// Unity does each time play mode starts (with or without a domain reload).
        /// </summary>
        public static void Enter(System.Reflection.Assembly assembly)
        {
            var order = new[] { RuntimeInitializeLoadType.SubsystemRegistration, RuntimeInitializeLoadType.AfterAssembliesLoaded, RuntimeInitializeLoadType.BeforeSplashScreen, RuntimeInitializeLoadType.BeforeSceneLoad, RuntimeInitializeLoadType.AfterSceneLoad };
            const System.Reflection.BindingFlags Static = System.Reflection.BindingFlags.Static | System.Reflection.BindingFlags.Public | System.Reflection.BindingFlags.NonPublic;
            foreach (RuntimeInitializeLoadType when in order)
                foreach (Type t in assembly.GetTypes())
                    foreach (System.Reflection.MethodInfo m in t.GetMethods(Static))
                        if (m.GetCustomAttributes(typeof(RuntimeInitializeOnLoadMethodAttribute), false) is { Length: > 0 } a && ((RuntimeInitializeOnLoadMethodAttribute)a[0]).loadType == when)
                            m.Invoke(null, null);
        }
    }
}

namespace UnityDouble
{
    /// <summary>
    /// The application's messages, which the double's frames never send: the app paused or resumed (the headset taken
    /// off, the menu button) and quitting. Sent to the enabled scripts on active GameObjects.
    /// </summary>
    public static class AppEvents
    {
        /// <summary>OnApplicationPause(<paramref name="paused"/>).</summary>
        public static void Pause(bool paused) => Engine.Broadcast("OnApplicationPause", paused);

        /// <summary>OnApplicationQuit().</summary>
        public static void Quit() => Engine.Broadcast("OnApplicationQuit");
    }
}
