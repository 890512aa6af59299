using System;
using NUnit.Framework;
using Kosmos.PseudoHaptic.Simulation;

namespace Kosmos.PseudoHaptic.Tests.Stability
{
    /// <summary>P9: hours of use do not drift. Ten hours at 120 Hz is 4.32 million steps; it runs in about a second.</summary>
    public class LongSessionTests
    {
        const double FrameRate = 120, Hours = 10;

        // One 8 s cycle of realistic use: rest, lift 0.3 m in 1 s, hold, lower in 1 s, rest.
        static readonly HandPath Cycle = HandPath.StartAt(0.8).Hold(2).MoveTo(1.1, 1).Hold(2).MoveTo(0.8, 1).Hold(2);

        static double Jitter(long pose, int seed)
        {
            ulong x = (ulong)pose * 0x9E3779B97F4A7C15UL + (ulong)seed;
            x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9UL;
            x = (x ^ (x >> 27)) * 0x94D049BB133111EBUL;
            return ((x ^ (x >> 31)) >> 11) * (1.0 / (1UL << 53)) - 0.5;
        }

        /// <summary>Runs ten hours; returns the offset at the top hold and the object height at rest, per hour.</summary>
        static (double[] top, double[] rest, long steps) TenHours(string profile, double massKg, double jitter)
        {
            var solver = new WeightSolver(WeightModel.FromMass(massKg), NamedProfiles.Get(profile), 0.5);
            long frames = (long)(Hours * 3600 * FrameRate), perHour = (long)(3600 * FrameRate);
            var top = new double[(int)Hours];
            var rest = new double[(int)Hours];
            solver.BeginHold(0.8, 0.8, 0);
            long lastPose = 0;
            double hand = 0.8;
            for (long i = 1; i <= frames; i++)
            {
                double t = i / FrameRate;
                long pose = (long)Math.Floor(t * 30);
                if (pose != lastPose)
                {
                    lastPose = pose;
                    double poseT = pose / 30.0;
                    hand = Cycle.HeightAt(poseT % Cycle.Duration) + jitter * Jitter(pose, 17);
                }
                solver.Step(new HandSample(hand, true, true, pose / 30.0), 1 / FrameRate);
                long inHour = i % perHour;
                int hour = (int)(i / perHour);
                if (hour >= (int)Hours) hour = (int)Hours - 1;
                if (inHour == (long)(3.5 * FrameRate)) top[hour] = solver.Offset;       // second 3.5: holding at the top
                if (inHour == (long)(7.5 * FrameRate)) rest[hour] = solver.ObjectY;     // second 7.5: back at rest
            }
            Assert.That(solver.State.Time, Is.EqualTo(Hours * 3600).Within(1e-6), "the hold's clock after ten hours");
            return (top, rest, frames);
        }

        [Category("Soak")] // ten hours at 120 Hz (Support/Soak.cs)
        [TestCase("paper", 2.0), TestCase("paper-experiment", 0.3), TestCase("gain", 0.045)]
        public void TenHoursOfLiftsDoNotDrift(string profile, double massKg)
        {
            Soak.SkipIfAsked();
            var (top, rest, steps) = TenHours(profile, massKg, 0);
            Assert.That(steps, Is.EqualTo(4320000));
            // A hold settles into its cycle (the deadband, the lowering guard and the offset correction leave a trace
            // of each lift in the next, shrinking geometrically), then repeats it: the hour-to-hour change never
            // grows (settling, not drift), the last hours agree to 10 nm, and settling moves nothing by 5 mm.
            for (int h = 1; h < top.Length; h++)
            {
                Assert.That(Math.Abs(top[h] - top[0]), Is.LessThan(0.005), "offset at the top, hour " + (h + 1) + " vs hour 1");
                Assert.That(Math.Abs(rest[h] - rest[0]), Is.LessThan(0.005), "height at rest, hour " + (h + 1) + " vs hour 1");
                if (h >= 2)
                {
                    Assert.That(Math.Abs(top[h] - top[h - 1]), Is.LessThanOrEqualTo(Math.Abs(top[h - 1] - top[h - 2]) + 1e-12), "offset at the top, hour " + (h + 1) + ": settling, not drifting");
                    Assert.That(Math.Abs(rest[h] - rest[h - 1]), Is.LessThanOrEqualTo(Math.Abs(rest[h - 1] - rest[h - 2]) + 1e-12), "height at rest, hour " + (h + 1) + ": settling, not drifting");
                }
            }
            Assert.That(top[top.Length - 1], Is.EqualTo(top[top.Length - 2]).Within(1e-8), "offset at the top, the last two hours");
            Assert.That(rest[rest.Length - 1], Is.EqualTo(rest[rest.Length - 2]).Within(1e-8), "height at rest, the last two hours");
        }

        [Category("Soak")] // ten hours at 120 Hz (Support/Soak.cs)
        [Test]
        public void TenHoursWithTrackingJitterStayBounded()
        {
            Soak.SkipIfAsked();
            var (top, rest, _) = TenHours("paper", 2.0, 0.003);
            for (int h = 0; h < top.Length; h++)
            {
                Assert.That(top[h], Is.EqualTo(top[0]).Within(0.01), "offset at the top, hour " + (h + 1));
                Assert.That(rest[h], Is.EqualTo(0.8).Within(0.01), "height at rest, hour " + (h + 1));
            }
        }
    }
}
