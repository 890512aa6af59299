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
