using System;
using System.Collections.Generic;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>A hand's true position over time, m.</summary>
    internal delegate void HandPath3D(double t, out double x, out double y, out double z);

    /// <summary>Frames of one or two hands as a Quest delivers them: poses at <see cref="PoseRate"/>, late by
    /// <see cref="Latency"/>, with jitter per pose and axis (a function of seed, pose and axis only), over frames
    /// whose times may wobble, with stretches of lost tracking per hand.</summary>
    internal sealed class Headset3D
    {
        public double FrameRate = 90, PoseRate = 30, Latency = 0.045, JitterSd, Wobble;
        public int Seed = 1;
        readonly List<(int hand, double start, double end)> _drops = new List<(int, double, double)>();

        public Headset3D Drop(int hand, double start, double seconds)
        {
            _drops.Add((hand, start, start + seconds));
            return this;
        }

        public sealed class Frames
        {
            public double[] T, Dt;
            public HandPose[] A, B;
            public int Count => T.Length;
        }

        public Frames Render(HandPath3D first, HandPath3D second, double duration)
        {
            var rng = new Random(Seed);
            var t = new List<double>();
            var a = new List<HandPose>();
            var b = new List<HandPose>();
            double time = 0;
            while (time <= duration + 1e-12)
            {
                t.Add(time);
                long k = (long)Math.Floor((time - Latency) * PoseRate + 1e-9);
                double poseT = k / PoseRate;
                a.Add(Pose(first, 1, k, poseT, time));
                b.Add(second == null ? HandPose.Lost : Pose(second, 2, k, poseT, time));
                double w = Wobble > 0 ? 1 + Wobble * (2 * rng.NextDouble() - 1) : 1;
                time += w / FrameRate;
            }
            var dt = new double[t.Count];
            for (int i = 1; i < t.Count; i++) dt[i] = t[i] - t[i - 1];
            return new Frames { T = t.ToArray(), Dt = dt, A = a.ToArray(), B = b.ToArray() };
        }

        HandPose Pose(HandPath3D path, int hand, long k, double poseT, double time)
        {
            foreach (var d in _drops)
                if (d.hand == hand && time >= d.start && time < d.end) return HandPose.Lost;
            path(poseT, out double x, out double y, out double z);
            if (JitterSd > 0)
            {
                x += JitterSd * Noise(hand * 3 + 0, k);
                y += JitterSd * Noise(hand * 3 + 1, k);
                z += JitterSd * Noise(hand * 3 + 2, k);
            }
            return new HandPose(x, y, z, true, true, poseT);
        }

        double Noise(int axis, long k)
        {
            ulong x = (ulong)Seed * 0x9E3779B97F4A7C15UL + (ulong)axis * 0xD1B54A32D192ED03UL + (ulong)k;
            x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9UL;
            x = (x ^ (x >> 27)) * 0x94D049BB133111EBUL;
            double u = ((x ^ (x >> 31)) >> 11) * (1.0 / (1UL << 53));
            return 2 * u - 1; // uniform in [−1, 1)
        }

        /// <summary>Minimum-jerk blend from a to b between t0 and t0 + duration.</summary>
        public static double MinJerk(double t, double t0, double duration, double a, double b)
        {
            double s = duration > 0 ? Math.Max(0, Math.Min(1, (t - t0) / duration)) : 1;
            return a + (b - a) * s * s * s * (10 + s * (-15 + 6 * s));
        }
    }

    /// <summary>What a 3D hold produced, frame by frame.</summary>
    internal sealed class Run3D
    {
        /// <summary>A tracked, high-confidence pose at (x, y, z) with pose time t.</summary>
        public static HandPose At(double x, double y, double z, double t) => new HandPose(x, y, z, true, true, t);

        public double[] X, Y, Z, FollowedX, FollowedY, FollowedZ;
        public bool[] Holding;

        public static Run3D Of(WeightSolver3D solver, Headset3D.Frames f, double objectX = double.NaN, double objectY = double.NaN, double objectZ = double.NaN)
        {
            int n = f.Count;
            var r = new Run3D { X = new double[n], Y = new double[n], Z = new double[n], FollowedX = new double[n], FollowedY = new double[n], FollowedZ = new double[n], Holding = new bool[n] };
            int start = 0;
            while (start < n && !f.A[start].IsUsable && !f.B[start].IsUsable) start++;
            if (start == n) start = 0;
            var a = f.A[start];
            var b = f.B[start];
            double mx = a.IsUsable && b.IsUsable && solver.Profile.Has<TwoHands>() ? 0.5 * (a.X + b.X) : (a.IsUsable ? a.X : b.X);
            double my = a.IsUsable && b.IsUsable && solver.Profile.Has<TwoHands>() ? 0.5 * (a.Y + b.Y) : (a.IsUsable ? a.Y : b.Y);
            double mz = a.IsUsable && b.IsUsable && solver.Profile.Has<TwoHands>() ? 0.5 * (a.Z + b.Z) : (a.IsUsable ? a.Z : b.Z);
            solver.BeginHold(a, b, double.IsNaN(objectX) ? mx : objectX, double.IsNaN(objectY) ? my : objectY, double.IsNaN(objectZ) ? mz : objectZ);
            for (int i = 0; i < n; i++)
            {
                if (i > start) solver.Step(f.A[i], f.B[i], f.Dt[i]);
                r.X[i] = solver.ObjectX;
                r.Y[i] = solver.ObjectY;
                r.Z[i] = solver.ObjectZ;
                r.FollowedX[i] = solver.FollowedX;
                r.FollowedY[i] = solver.FollowedY;
                r.FollowedZ[i] = solver.FollowedZ;
                r.Holding[i] = solver.IsHolding;
            }
            return r;
        }

        public static double MaxStep3D(Run3D r)
        {
            double m = 0;
            for (int i = 1; i < r.X.Length; i++)
            {
                double dx = r.X[i] - r.X[i - 1], dy = r.Y[i] - r.Y[i - 1], dz = r.Z[i] - r.Z[i - 1];
                m = Math.Max(m, Math.Sqrt(dx * dx + dy * dy + dz * dz));
            }
            return m;
        }
    }
}
