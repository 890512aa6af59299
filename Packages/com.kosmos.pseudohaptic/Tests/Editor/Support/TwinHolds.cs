using System;
using Kosmos.PseudoHaptic.Simulation;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>
    /// Two holds of one object under two profiles, stepped through the same Quest-like input (a lift, a heft, a reach
    /// down and up; glitches, a 0.3 s loss, low confidence at speed, a hitch every 97th frame, the mass halved mid-hold and
    /// restored): what the savings' tests compare frame by frame, where the second profile switches a saving off.
    /// </summary>
    internal static class TwinHolds
    {
        /// <param name="check">Called after every frame with its index, the two solvers and the heights they returned.</param>
        /// <param name="quantized">Poses on a 5 mm grid: new poses that repeat the last one's height.</param>
        public static void Run(WeightProfile first, WeightProfile second, double mass, int rate, bool quantized, int seed,
            Action<int, WeightSolver, WeightSolver, double, double> check)
        {
            var path = HandPath.StartAt(0.9).Hold(0.5).MoveTo(1.35, 0.7).Hold(0.4).MoveTo(1.2, 0.2).MoveTo(1.35, 0.2).Hold(0.6)
                .MoveTo(0.7, 0.9).Hold(0.5).MoveTo(1.5, 0.3).Hold(1.0).MoveTo(0.9, 1.0).Hold(0.5);
            var frames = new HeadsetSimulator
            {
                FrameRate = rate, FrameTimeWobble = 0.1, JitterSd = 0.0015, Seed = seed, GlitchChance = 0.03, LowConfidenceAboveSpeed = 0.8,
            }.Drop(2.0, 0.3).Glitch(3.1, 0.15).LowConfidence(4.0, 0.2).Render(path);

            var a = new WeightSolver(WeightModel.FromMass(mass), first);
            var b = new WeightSolver(WeightModel.FromMass(mass), second);
            a.BeginHold(frames[0].HandY, frames[0].HandY - 0.02, frames[0].PoseTime);
            b.BeginHold(frames[0].HandY, frames[0].HandY - 0.02, frames[0].PoseTime);
            for (int i = 1; i < frames.Length; i++)
            {
                double dt = i % 97 == 0 ? 0.2 : frames[i].Time - frames[i - 1].Time; // now and then a hitch
                if (i == frames.Length / 2)
                {
                    // Mid-hold: another mass (a second hand joining; the offset glides to its new value), then back.
                    a.Configure(WeightModel.FromMass(mass * 0.5), first, 0.5);
                    b.Configure(WeightModel.FromMass(mass * 0.5), second, 0.5);
                }
                if (i == frames.Length * 3 / 4)
                {
                    a.Configure(WeightModel.FromMass(mass), first, 0.5);
                    b.Configure(WeightModel.FromMass(mass), second, 0.5);
                }
                var sample = frames[i].ToSample();
                if (quantized) sample = new HandSample(Math.Round(sample.Y * 200) / 200, sample.IsTracked, sample.IsHighConfidence, sample.PoseTime);
                double ya = a.Step(sample, dt), yb = b.Step(sample, dt);
                check(i, a, b, ya, yb);
            }
        }
    }
}
