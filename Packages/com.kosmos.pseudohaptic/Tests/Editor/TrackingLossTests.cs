using System;
using NUnit.Framework;
using Kosmos.PseudoHaptic.Simulation;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>
    /// Short tracking losses mid-lift, as a Quest produces them: low-confidence poses in fast motion and frames
    /// without a pose. Motion during a short loss is caught up, not thrown away (P1 through short losses).
    /// </summary>
    public class TrackingLossTests
    {
        /// <summary>Replays <paramref name="frames"/>, treating frames whose time lies in [from, from + seconds) as
        /// low-confidence (tracked, with their pose) or lost (untracked, no pose).</summary>
        static double[] ReplayWithLoss(WeightSolver solver, TraceFrame[] frames, double from, double seconds, bool lowConfidence)
        {
            var y = new double[frames.Length];
            solver.BeginHold(frames[0].HandY, frames[0].HandY, frames[0].PoseTime);
            y[0] = solver.ObjectY;
            for (int i = 1; i < frames.Length; i++)
            {
                var f = frames[i];
                bool inLoss = f.Time >= from && f.Time < from + seconds;
                var sample = !inLoss ? new HandSample(f.HandY, true, true, f.PoseTime)
                    : lowConfidence ? new HandSample(f.HandY, true, false, f.PoseTime) : HandSample.Lost;
                y[i] = solver.Step(sample, f.Time - frames[i - 1].Time);
            }
            return y;
        }

        // One frame, 50 ms and 150 ms of low confidence (or of lost tracking) in the middle of a golf-ball lift: the
        // golf ball was left 10, 16 and 22 cm below the hand for good. It must be back within 5 mm of the hand within
        // 0.1 s of the loss, and within 1 mm once the hand has rested 0.5 s.
        [Test]
        public void AShortLossMidLiftIsCaughtUp([Values("paper", "paper-experiment", "gain")] string profile,
            [Values(0.0, 0.05, 0.15)] double seconds, [Values(true, false)] bool lowConfidence, [Values(72.0, 90, 120)] double frameRate)
        {
            var path = HandPath.StartAt(0.8).Hold(0.3).MoveTo(1.2, 0.6).Hold(1.0);
            var frames = Run.Headset(frameRate: frameRate).Render(path);
            double from = 0.6, length = seconds > 0 ? seconds : 0.5 / frameRate; // 0: exactly one frame
            var y = ReplayWithLoss(Run.Solver(PhysicalConstants.StandardMassKg, NamedProfiles.Get(profile)), frames, from, length, lowConfidence);
            string at = profile + ", " + (seconds > 0 ? seconds * 1000 + " ms" : "one frame") + (lowConfidence ? " low-confidence" : " lost") + ", " + frameRate + " Hz";
            for (int i = 0; i < frames.Length; i++)
            {
                double t = frames[i].Time;
                if (t >= from + length + 0.1 && t < 1.0)
                    Assert.That(Math.Abs(frames[i].HandY - y[i]), Is.LessThanOrEqualTo(0.005), at + ": frame " + i + " at " + t.ToString("0.000") + " s");
            }
            Assert.That(Math.Abs(frames[frames.Length - 1].HandY - Run.Last(y)), Is.LessThanOrEqualTo(0.001), at + ": at rest");
        }

        // Heavier objects keep their weight through the loss: the lift ends where it ends without the loss.
        [Test]
        public void AShortLossDoesNotChangeWhereAHeavyObjectEnds([Values(0.5, 2, 5)] double massKg, [Values(0.05, 0.15)] double seconds)
        {
            var path = HandPath.StartAt(0.8).Hold(0.3).MoveTo(1.2, 0.6).Hold(1.5);
            var frames = Run.Headset(frameRate: 90).Render(path);
            var clean = Run.Replay(Run.Solver(massKg, NamedProfiles.Paper), frames);
            var lost = ReplayWithLoss(Run.Solver(massKg, NamedProfiles.Paper), frames, 0.6, seconds, true);
            Assert.That(Run.Last(lost), Is.EqualTo(Run.Last(clean)).Within(0.01), massKg + " kg");
        }
    }
}
