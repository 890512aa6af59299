using System;
using NUnit.Framework;
using Kosmos.PseudoHaptic.Simulation;

namespace Kosmos.PseudoHaptic.Tests.Stability
{
    /// <summary>
    /// A real human hand: 60 s of optical motion capture at 100 Hz (../shared/data/mocap-hand-100hz.csv),
    /// degraded as a Quest 2 would deliver it. Ignored, with the reason, where ../shared is absent.
    /// </summary>
    public class MotionCaptureTests
    {
        static HandPath RealHand()
        {
            var (t, y) = SharedData.ReadHand(SharedData.RequireFile("mocap-hand-100hz.csv"));
            return HandPath.FromSamples(t, y);
        }

        [Test]
        public void DegradedRealMotionStaysFiniteSmoothAndClockIndependent([Values("paper", "paper-experiment", "gain")] string profile)
        {
            var hand = RealHand();
            foreach (var mass in new[] { 0.01, 0.045, 0.5, 2, 20 })
            {
                double? reference = null;
                foreach (var rate in new[] { 72.0, 90, 120 })
                {
                    var headset = new HeadsetSimulator { FrameRate = rate, PoseRate = 30, Latency = 0.045, JitterSd = 0.0015, Seed = 9 };
                    // With dropouts: finite, no step beyond the hand's own (times a light object's gain) plus 1 cm.
                    var dropped = headset.Drop(20, 0.15).Drop(40, 2.0).Render(hand);
                    var solver = new WeightSolver(WeightModel.FromMass(mass), NamedProfiles.Get(profile));
                    var d = TraceReplay.Run(solver, dropped);
                    Assert.That(Run.AllFinite(d), Is.True);
                    Assert.That(QuestLikeInput.StepBeyondHand(dropped, d, solver.Gain, 0, double.PositiveInfinity), Is.LessThanOrEqualTo(0.01), mass + " kg at " + rate + " Hz");

                    var frames = new HeadsetSimulator { FrameRate = rate, PoseRate = 30, Latency = 0.045, JitterSd = 0.0015, Seed = 9 }.Render(hand);
                    var y = TraceReplay.Run(new WeightSolver(WeightModel.FromMass(mass), NamedProfiles.Get(profile)), frames);
                    reference = reference ?? y[y.Length - 1];
                    Assert.That(y[y.Length - 1], Is.EqualTo(reference.Value).Within(0.01), mass + " kg at " + rate + " Hz vs 72 Hz");
                }
            }
        }

        [Test]
        public void TheGolfBallFollowsTheRealHand()
        {
            var hand = RealHand();
            var frames = new HeadsetSimulator { FrameRate = 90, PoseRate = 30, JitterSd = 0.0015, Seed = 4 }.Render(hand);
            var y = TraceReplay.Run(new WeightSolver(WeightModel.FromMass(PhysicalConstants.StandardMassKg), NamedProfiles.Paper), frames);
            Assert.That(Run.MaxOffset(frames, y), Is.LessThan(0.006), "within the deadband and a little jitter");
        }
    }
}
