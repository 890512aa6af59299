using System;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests.Stability
{
    /// <summary>
    /// The step rules read, for each frame, the frames within 100 ms of it from <see cref="NearFrames.Ranges"/>; these
    /// tests hold that the run it gives holds every near frame a scan of the whole trace finds, on the frame times the
    /// suites feed: 72–120 Hz frames with jitter, hitches, repeated times, frames exactly 100 ms apart, and times out of
    /// order (a clock stepping back), where it must give the whole trace.
    /// </summary>
    [TestFixture]
    public class NearFramesTests
    {
        [Test]
        public void EveryNearFrameIsInItsFramesRun([Range(0, 299)] int seed)
        {
            var random = new Random(seed);
            int n = 50 + random.Next(400);
            var time = new double[n];
            double t = random.NextDouble();
            for (int i = 0; i < n; i++)
            {
                double r = random.NextDouble();
                t += r < 0.05 ? 0                               // the same time again
                    : r < 0.10 ? 0.1                            // exactly the window apart
                    : r < 0.13 ? 0.1 + 2 * random.NextDouble()  // a hitch
                    : 1.0 / (72 + 48 * random.NextDouble());   // a frame
                time[i] = t;
            }
            if (seed % 5 == 0) time[random.Next(n)] -= 0.5 * random.NextDouble(); // a clock stepping back
            NearFrames.Ranges(time, out var first, out var last);
            for (int i = 0; i < n; i++)
                for (int j = 0; j < n; j++)
                {
                    bool near = Math.Abs(time[j] - time[i]) <= 0.1 + 1e-9;
                    if (near) Assert.That(j >= first[i] && j <= last[i], Is.True, $"seed {seed}: frame {j} is near frame {i} but outside [{first[i]}, {last[i]}]");
                }
        }

        [Test]
        public void OnOrderedTimesTheRunIsExactlyTheNearFrames()
        {
            // Sixteenths of a second apart, exact in binary: frames 1/16 s apart are near, 1/8 s apart are not.
            var time = new[] { 0.0, 0.0625, 0.125, 0.1875, 0.3125, 0.3125 };
            NearFrames.Ranges(time, out var first, out var last);
            Assert.That(first, Is.EqualTo(new[] { 0, 0, 1, 2, 4, 4 }));
            Assert.That(last, Is.EqualTo(new[] { 1, 2, 3, 3, 5, 5 }));
        }

        [Test]
        public void TimesOutOfOrderOrNaNGiveTheWholeTrace()
        {
            foreach (var time in new[] { new[] { 0.0, 0.5, 0.2, 0.9 }, new[] { 0.0, double.NaN, 0.2, 0.9 } })
            {
                NearFrames.Ranges(time, out var first, out var last);
                Assert.That(first, Is.EqualTo(new[] { 0, 0, 0, 0 }));
                Assert.That(last, Is.EqualTo(new[] { 3, 3, 3, 3 }));
            }
        }
    }
}
