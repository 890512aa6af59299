using System;
using System.Collections.Generic;
using Kosmos.PseudoHaptic.Simulation;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>What a source does once the hand stops: new poses of the same place (Quest: a new time stamp every 1/30 s),
    /// or the last pose repeated exactly, its time stamp frozen (tracking that holds its last pose), or without time
    /// stamps at all (a simulator, a controller at rest).</summary>
    public enum AfterTheStop { NewPoses, Frozen, NoTimeStamps }

    /// <summary>
    /// Issue 32, "the sideways lag freezes when poses repeat": a motion at constant speed that stops abruptly, poses at 30 Hz
    /// taken 45 ms late over faster frames, and after the stop the pose repeated as <see cref="AfterTheStop"/> says. Whatever
    /// moves on its own must advance with time: every way of repeating must end where new poses end.
    /// </summary>
    internal static class RepeatedPoses
    {
        /// <summary>The hand's position along the motion at time t: rest at 0 until <paramref name="start"/>, then
        /// <paramref name="speed"/> m/s (signed) for <paramref name="distance"/> m, then rest.</summary>
        public static double Along(double t, double start, double speed, double distance)
        {
            double s = Math.Max(0, t - start) * Math.Abs(speed);
            return Math.Sign(speed) * Math.Min(s, distance);
        }

        /// <summary>Frame times and, per frame, the pose's place along the motion and its time stamp (NaN: none).</summary>
        public static void Render(double frameRate, double speed, double distance, double duration, AfterTheStop after,
            out double[] time, out double[] along, out double[] poseTime, double start = 0.5)
        {
            double stop = start + distance / Math.Abs(speed);
            var t = new List<double>();
            var a = new List<double>();
            var p = new List<double>();
            double lastPoseT = double.NaN, lastA = 0;
            for (int i = 0; ; i++)
            {
                double ft = i / frameRate;
                if (ft > duration + 1e-12) break;
                long k = (long)Math.Floor((ft - 0.045) * 30 + 1e-9);
                double pt = k / 30.0;
                double value = Along(pt, start, speed, distance);
                bool stopped = pt > stop + 1e-9 && !double.IsNaN(lastPoseT) && value == lastA;
                if (after == AfterTheStop.NoTimeStamps) pt = double.NaN;
                else if (after == AfterTheStop.Frozen && stopped) pt = lastPoseT;
                t.Add(ft);
                a.Add(value);
                p.Add(pt);
                lastPoseT = pt;
                lastA = value;
            }
            time = t.ToArray();
            along = a.ToArray();
            poseTime = p.ToArray();
        }

        /// <summary>A vertical motion from <paramref name="from"/> as trace frames.</summary>
        public static TraceFrame[] Vertical(double frameRate, double from, double speed, double distance, double duration, AfterTheStop after)
        {
            Render(frameRate, speed, distance, duration, after, out var time, out var along, out var poseTime);
            var frames = new TraceFrame[time.Length];
            for (int i = 0; i < frames.Length; i++) frames[i] = new TraceFrame(time[i], from + along[i], true, poseTime[i]);
            return frames;
        }

        /// <summary>A carry from (0.1, 1, 0.3) along the unit direction (<paramref name="ux"/>, <paramref name="uy"/>,
        /// <paramref name="uz"/>) as one hand's frames.</summary>
        public static Headset3D.Frames Carry(double frameRate, double ux, double uy, double uz, double speed, double distance, double duration, AfterTheStop after)
        {
            Render(frameRate, speed, distance, duration, after, out var time, out var along, out var poseTime);
            var f = new Headset3D.Frames { T = time, Dt = new double[time.Length], A = new HandPose[time.Length], B = new HandPose[time.Length] };
            for (int i = 0; i < time.Length; i++)
            {
                if (i > 0) f.Dt[i] = time[i] - time[i - 1];
                f.A[i] = new HandPose(0.1 + ux * along[i], 1.0 + uy * along[i], 0.3 + uz * along[i], true, true, poseTime[i]);
                f.B[i] = HandPose.Lost;
            }
            return f;
        }

        /// <summary>A sideways carry along x at height 1 m as one hand's frames.</summary>
        public static Headset3D.Frames Sideways(double frameRate, double speed, double distance, double duration, AfterTheStop after)
        {
            Render(frameRate, speed, distance, duration, after, out var time, out var along, out var poseTime);
            var f = new Headset3D.Frames { T = time, Dt = new double[time.Length], A = new HandPose[time.Length], B = new HandPose[time.Length] };
            for (int i = 0; i < time.Length; i++)
            {
                if (i > 0) f.Dt[i] = time[i] - time[i - 1];
                f.A[i] = new HandPose(0.1 + along[i], 1.0, 0.3, true, true, poseTime[i]);
                f.B[i] = HandPose.Lost;
            }
            return f;
        }
    }
}
