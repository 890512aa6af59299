using System;
using System.Collections.Generic;
using Kosmos.PseudoHaptic.Simulation;

namespace Kosmos.PseudoHaptic.Tests.Stability
{
    /// <summary>
    /// Seeded generator of hard cases: minimum-jerk lifts and lowerings of several heights and durations with
    /// holds between them, rendered on 60/72/90/120 Hz or irregular frame clocks, poses sampled at 30 or 60 Hz,
    /// 45 ms late, with millimetre jitter; optionally tracking dropouts (short, or seconds long and returning
    /// far away), clock glitches (dt 0, negative, 10 s) and NaN/±Infinity bursts; masses from 1 g to 10⁶ kg;
    /// standard speeds from 0.05 to 5 m/s; every profile. The same seed gives the same scenario.
    /// </summary>
    internal static class ScenarioGenerator
    {
        public static readonly double[] FrameRates = { 60, 72, 90, 120 };
        public static readonly string[] Profiles = { "paper", "paper-experiment", "gain" };

        /// <summary>Random lifts and lowerings between 0.1 and 1.6 m, mean speeds 0.1–1.2 m/s, with holds.</summary>
        public static HandPath RandomMotion(Random rng, double seconds, double start = 0.8)
        {
            var path = HandPath.StartAt(start).Hold(0.2 + rng.NextDouble() * 0.5);
            double y = start;
            while (path.Duration < seconds)
            {
                double target = 0.1 + rng.NextDouble() * 1.5;
                double speed = 0.1 + rng.NextDouble() * 1.1;
                double duration = Math.Max(0.15, Math.Abs(target - y) / speed);
                path.MoveTo(target, duration);
                y = target;
                if (rng.Next(2) == 0) path.Hold(0.1 + rng.NextDouble() * 1.0);
            }
            return path;
        }

        public static double LogUniform(Random rng, double min, double max) => Math.Exp(Math.Log(min) + rng.NextDouble() * (Math.Log(max) - Math.Log(min)));

        public static HeadsetSimulator RandomHeadset(Random rng, int seed)
        {
            bool irregular = rng.Next(4) == 0;
            return new HeadsetSimulator
            {
                FrameRate = FrameRates[rng.Next(FrameRates.Length)],
                FrameTimeWobble = irregular ? 0.4 : 0,
                PoseRate = rng.Next(3) == 0 ? 60 : 30,
                Latency = 0.045,
                JitterSd = 0.001 + rng.NextDouble() * 0.001,
                WritePoseTime = rng.Next(3) != 0,
                Seed = seed,
            };
        }

        /// <summary>A realistic scenario: degradation a Quest 2 produces every second, nothing broken.</summary>
        public static Scenario Clean(int seed)
        {
            var rng = new Random(seed);
            var path = RandomMotion(rng, 6 + rng.NextDouble() * 6);
            var headset = RandomHeadset(rng, seed);
            return new Scenario
            {
                Seed = seed,
                Path = path,
                Frames = headset.Render(path, extra: 0.5),
                MassKg = LogUniform(rng, 0.001, 1e6),
                StandardSpeed = LogUniform(rng, 0.05, 5),
                Profile = Profiles[rng.Next(Profiles.Length)],
                IsClean = true,
                Description = "clean, " + headset.FrameRate + " Hz frames" + (headset.FrameTimeWobble > 0 ? " (irregular)" : "") + ", " + headset.PoseRate + " Hz poses" + (headset.WritePoseTime ? "" : " without timestamps"),
            };
        }

        /// <summary>A clean scenario, then broken: dropouts, clock glitches, garbage bursts.</summary>
        public static Scenario Adversarial(int seed)
        {
            var s = Clean(seed);
            var rng = new Random(seed * 7919 + 1);
            var frames = new List<TraceFrame>(s.Frames);
            var notes = new List<string>();

            // Dropouts: short ones, and long ones after which the hand comes back far away.
            for (int k = rng.Next(4); k > 0; k--)
            {
                int at = rng.Next(frames.Count);
                bool longOne = rng.Next(2) == 0;
                double seconds = longOne ? 1 + rng.NextDouble() * 3 : 0.03 + rng.NextDouble() * 0.2;
                double farAway = longOne && rng.Next(2) == 0 ? (rng.Next(2) == 0 ? 1 : -1) * (0.3 + rng.NextDouble()) : 0;
                double end = frames[at].Time + seconds;
                for (int i = at; i < frames.Count; i++)
                {
                    var f = frames[i];
                    if (f.Time < end) { f.Tracked = false; f.HandY = double.NaN; }
                    else if (farAway != 0) f.HandY += farAway; // everything after the loss is displaced
                    frames[i] = f;
                }
                notes.Add((longOne ? "long" : "short") + " dropout" + (farAway != 0 ? " returning " + farAway.ToString("0.00") + " m away" : ""));
            }
            // Garbage bursts while "tracked".
            double[] garbage = { double.NaN, double.PositiveInfinity, double.NegativeInfinity, 1e12 };
            for (int k = rng.Next(4); k > 0; k--)
            {
                int at = rng.Next(frames.Count), n = 1 + rng.Next(20);
                for (int i = at; i < Math.Min(frames.Count, at + n); i++)
                {
                    var f = frames[i];
                    f.HandY = garbage[rng.Next(garbage.Length)];
                    if (rng.Next(2) == 0) f.PoseTime = garbage[rng.Next(3)];
                    frames[i] = f;
                }
                notes.Add("garbage burst of " + n);
            }
            // Clock glitches: a repeated time (dt 0), a step back, a 10 s pause.
            for (int k = rng.Next(4); k > 0; k--)
            {
                int at = 1 + rng.Next(frames.Count - 1);
                int kind = rng.Next(3);
                double shift = kind == 0 ? frames[at - 1].Time - frames[at].Time : kind == 1 ? -0.05 - rng.NextDouble() * 0.2 : 10;
                for (int i = at; i < frames.Count; i++) { var f = frames[i]; f.Time += shift; frames[i] = f; if (kind == 0) break; }
                notes.Add(kind == 0 ? "dt 0" : kind == 1 ? "clock steps back" : "10 s pause");
            }
            s.Frames = frames.ToArray();
            s.IsClean = false;
            s.Description = s.Description.Replace("clean", "adversarial") + "; " + string.Join(", ", notes);
            return s;
        }

        public static WeightSolver Solver(Scenario s)
            => new WeightSolver(WeightModel.FromMass(s.MassKg), NamedProfiles.Get(s.Profile), s.StandardSpeed);
    }
}
