using System;
using System.Collections.Generic;
using Kosmos.PseudoHaptic.Simulation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>
    /// The simulated headset's documented contract: frames from 0 to the path's end, each showing the newest pose
    /// sampled at or before (frame time − latency); jitter with the stated standard deviation; glitches with the stated
    /// chance, ±size; low confidence only above the stated speed, with the stated chance; drops, offsets and
    /// low-confidence stretches over [start, start + seconds); frame times wobbling within ± the stated fraction;
    /// seeded. Rates are powers of two where a boundary is tested, so frame and pose times are exact.
    /// </summary>
    public class HeadsetSimulatorTests
    {
        // 64 Hz frames, 32 Hz poses, 1/16 s latency: every frame and pose time is exact in binary.
        static HeadsetSimulator Exact() => new HeadsetSimulator { FrameRate = 64, PoseRate = 32, Latency = 0.0625 };

        static HandPath Held(double seconds) => HandPath.StartAt(1.0).Hold(seconds);

        /// <summary>The distinct poses of a render (one per pose time).</summary>
        static List<TraceFrame> Poses(TraceFrame[] frames)
        {
            var poses = new List<TraceFrame>();
            double last = double.NaN;
            foreach (var f in frames)
            {
                if (!f.Tracked || f.PoseTime == last) continue;
                last = f.PoseTime;
                poses.Add(f);
            }
            return poses;
        }

        [Test]
        public void FramesRunFromZeroToTheEndInclusiveAtTheFrameRate()
        {
            var frames = Exact().Render(Held(1.0));
            Assert.That(frames.Length, Is.EqualTo(65));
            Assert.That(frames[0].Time, Is.EqualTo(0));
            Assert.That(frames[64].Time, Is.EqualTo(1.0));
            for (int i = 1; i < frames.Length; i++) Assert.That(frames[i].Time - frames[i - 1].Time, Is.EqualTo(1 / 64.0));
        }

        [Test]
        public void EachFrameShowsTheNewestPoseSampledAtOrBeforeFrameTimeMinusLatency()
        {
            var path = HandPath.StartAt(0.8).MoveTo(1.2, 1.0).Hold(0.5);
            var sim = Exact();
            var frames = sim.Render(path);
            foreach (var f in frames)
            {
                double age = f.Time - sim.Latency - f.PoseTime;
                Assert.That(age, Is.GreaterThanOrEqualTo(0).And.LessThan(1 / sim.PoseRate), "frame at " + f.Time);
                Assert.That(f.PoseTime * sim.PoseRate, Is.EqualTo(Math.Round(f.PoseTime * sim.PoseRate)).Within(1e-9));
                Assert.That(f.HandY, Is.EqualTo(path.HeightAt(f.PoseTime)));
                Assert.That(f.Tracked && !f.LowConfidence, Is.True);
            }
        }

        [Test]
        public void WithoutPoseTimesFramesCarryNaN()
        {
            var sim = Exact();
            sim.WritePoseTime = false;
            foreach (var f in sim.Render(Held(0.5))) Assert.That(f.PoseTime, Is.NaN);
        }

        [Test]
        public void JitterHasTheStatedStandardDeviationAndNoBias()
        {
            const double sd = 0.002;
            var sim = new HeadsetSimulator { JitterSd = sd, Seed = 7 };
            var poses = Poses(sim.Render(Held(100)));
            Assert.That(poses.Count, Is.GreaterThan(2900));
            double sum = 0, sum2 = 0;
            foreach (var p in poses) { double e = p.HandY - 1.0; sum += e; sum2 += e * e; }
            double mean = sum / poses.Count, s = Math.Sqrt(sum2 / poses.Count - mean * mean);
            Assert.That(mean, Is.EqualTo(0).Within(4 * sd / Math.Sqrt(poses.Count)));
            Assert.That(s, Is.EqualTo(sd).Within(0.1 * sd)); // sampling error of an SD over 3000 poses: ~1.3 %
        }

        [Test]
        public void GlitchesHappenWithTheStatedChanceAndGoBothWaysByTheStatedSize()
        {
            var sim = new HeadsetSimulator { GlitchChance = 0.1, GlitchSize = 0.03, Seed = 3 };
            var poses = Poses(sim.Render(Held(100)));
            int glitched = 0, up = 0;
            foreach (var p in poses)
            {
                double off = p.HandY - 1.0;
                if (Math.Abs(off) < 1e-12) continue;
                Assert.That(Math.Abs(off), Is.EqualTo(0.03).Within(1e-12));
                glitched++;
                if (off > 0) up++;
            }
            int n = poses.Count;
            Assert.That(glitched, Is.EqualTo(0.1 * n).Within(4 * Math.Sqrt(n * 0.1 * 0.9)));
            Assert.That(up, Is.EqualTo(0.5 * glitched).Within(4 * Math.Sqrt(glitched * 0.25)));
        }

        [Test]
        public void NoGlitchesWhenTheChanceIsZero()
        {
            var sim = new HeadsetSimulator { GlitchChance = 0, Seed = 3 };
            foreach (var f in sim.Render(Held(20))) Assert.That(f.HandY, Is.EqualTo(1.0));
        }

        [Test]
        public void TheSameSeedGivesTheSameFramesAndAnotherSeedOtherFrames()
        {
            TraceFrame[] Render(int seed) => new HeadsetSimulator
            {
                GlitchChance = 0.2, LowConfidenceAboveSpeed = 0.1, LowConfidenceChance = 0.5, FrameTimeWobble = 0.1, Seed = seed,
            }.Render(HandPath.StartAt(0.8).MoveTo(1.2, 1).MoveTo(0.8, 1).MoveTo(1.2, 1));
            var a = Render(1); var b = Render(1); var c = Render(2);
            Assert.That(a.Length, Is.EqualTo(b.Length));
            for (int i = 0; i < a.Length; i++)
            {
                Assert.That(a[i].Time, Is.EqualTo(b[i].Time));
                Assert.That(a[i].HandY, Is.EqualTo(b[i].HandY));
                Assert.That(a[i].LowConfidence, Is.EqualTo(b[i].LowConfidence));
            }
            // A pose's glitch and confidence depend on the seed (not only on the pose): compare pose by pose.
            var pa = Poses(a); var pc = Poses(c);
            int differ = 0, lowDiffer = 0;
            var byTime = new Dictionary<double, TraceFrame>();
            foreach (var p in pc) byTime[p.PoseTime] = p;
            foreach (var p in pa)
                if (byTime.TryGetValue(p.PoseTime, out var q))
                {
                    if (p.HandY != q.HandY) differ++;
                    if (p.LowConfidence != q.LowConfidence) lowDiffer++;
                }
            Assert.That(differ, Is.GreaterThan(5));
            Assert.That(lowDiffer, Is.GreaterThan(5));
        }

        [Test]
        public void FastPosesAreLowConfidenceWithTheStatedChanceSlowOnesNever()
        {
            var path = HandPath.StartAt(0.8);
            for (int i = 0; i < 40; i++) path.MoveTo(i % 2 == 0 ? 1.2 : 0.8, 1.0).Hold(0.5);
            foreach (double chance in new[] { 0.2, 0.7 })
            {
                var sim = new HeadsetSimulator { LowConfidenceAboveSpeed = 0.5, LowConfidenceChance = chance, Seed = 11 };
                int fast = 0, fastLow = 0;
                foreach (var p in Poses(sim.Render(path)))
                {
                    double speed = Math.Abs(path.HeightAt(p.PoseTime + 1e-4) - path.HeightAt(p.PoseTime - 1e-4)) / 2e-4;
                    if (speed < 0.45) Assert.That(p.LowConfidence, Is.False, "slow pose at " + p.PoseTime);
                    else if (speed > 0.55) { fast++; if (p.LowConfidence) fastLow++; }
                }
                Assert.That(fast, Is.GreaterThan(300));
                Assert.That(fastLow, Is.EqualTo(chance * fast).Within(4 * Math.Sqrt(fast * chance * (1 - chance))), "chance " + chance);
            }
        }

        [Test]
        public void AHeldHandNeverExceedsAZeroSpeedThreshold()
        {
            var sim = new HeadsetSimulator { LowConfidenceAboveSpeed = 0, LowConfidenceChance = 1 };
            foreach (var f in sim.Render(Held(5))) Assert.That(f.LowConfidence, Is.False);
        }

        [Test]
        public void AGlitchMovesExactlyTheFirstPoseAtOrAfterItsTime()
        {
            var sim = Exact();
            sim.Glitch(0.5, 0.05);
            var poses = Poses(sim.Render(Held(1.5)));
            foreach (var p in poses)
                Assert.That(p.HandY, Is.EqualTo(p.PoseTime == 0.5 ? 1.05 : 1.0).Within(1e-12), "pose at " + p.PoseTime);
        }

        [Test]
        public void AnOffsetMovesEveryPoseSampledInItsStretch()
        {
            var sim = Exact();
            sim.Offset(0.5, 0.25, -0.04);
            foreach (var p in Poses(sim.Render(Held(1.5))))
            {
                bool inside = p.PoseTime >= 0.5 && p.PoseTime < 0.75;
                Assert.That(p.HandY, Is.EqualTo(inside ? 0.96 : 1.0).Within(1e-12), "pose at " + p.PoseTime);
            }
        }

        [Test]
        public void ADropLosesTrackingForItsFramesOnly()
        {
            var sim = Exact();
            sim.Drop(0.5, 0.25);
            foreach (var f in sim.Render(Held(1.5)))
            {
                bool inside = f.Time >= 0.5 && f.Time < 0.75;
                Assert.That(f.Tracked, Is.EqualTo(!inside), "frame at " + f.Time);
                Assert.That(f.LowConfidence, Is.False);
                if (inside) Assert.That(f.HandY, Is.NaN);
            }
        }

        [Test]
        public void ALowConfidenceStretchFlagsItsFramesOnlyAndKeepsTheirPoses()
        {
            var sim = Exact();
            sim.LowConfidence(0.5, 0.25).LowConfidence(1.0, 0.125);
            foreach (var f in sim.Render(Held(1.5)))
            {
                bool inside = (f.Time >= 0.5 && f.Time < 0.75) || (f.Time >= 1.0 && f.Time < 1.125);
                Assert.That(f.LowConfidence, Is.EqualTo(inside), "frame at " + f.Time);
                Assert.That(f.Tracked, Is.True);
                Assert.That(f.HandY, Is.EqualTo(1.0));
            }
        }

        [Test]
        public void FrameTimesWobbleUniformlyWithinTheStatedFraction()
        {
            const double w = 0.2, period = 1 / 90.0;
            var frames = new HeadsetSimulator { FrameTimeWobble = w, Seed = 5 }.Render(Held(60));
            int n = frames.Length - 1;
            double min = double.MaxValue, max = 0, sum = 0;
            for (int i = 1; i < frames.Length; i++)
            {
                double d = (frames[i].Time - frames[i - 1].Time) / period;
                min = Math.Min(min, d); max = Math.Max(max, d); sum += d;
            }
            Assert.That(min, Is.GreaterThanOrEqualTo(1 - w - 1e-9).And.LessThan(1 - 0.9 * w));
            Assert.That(max, Is.LessThanOrEqualTo(1 + w + 1e-9).And.GreaterThan(1 + 0.9 * w));
            // uniform on ±w: mean 1, standard error w / sqrt(3 n)
            Assert.That(sum / n, Is.EqualTo(1).Within(4 * w / Math.Sqrt(3.0 * n)));
        }

        // Each setting, a value just outside its documented range, and the range's own ends (which must be accepted).
        static readonly object[] Settings =
        {
            new object[] { "FrameRate", new[] { 0.0, -1, double.NaN, double.PositiveInfinity }, new[] { 1e-3, 1000.0 } },
            new object[] { "PoseRate", new[] { 0.0, -30, double.NaN, double.PositiveInfinity }, new[] { 1e-3, 1000.0 } },
            new object[] { "FrameTimeWobble", new[] { -1e-9, 0.9 + 1e-9, 1, double.NaN }, new[] { 0.0, 0.9 } },
            new object[] { "Latency", new[] { -1e-9, double.NaN, double.PositiveInfinity }, new[] { 0.0, 0.5 } },
            new object[] { "JitterSd", new[] { -1e-9, double.NaN, double.PositiveInfinity }, new[] { 0.0, 0.01 } },
            new object[] { "LowConfidenceAboveSpeed", new[] { -1e-9, double.NaN, double.NegativeInfinity }, new[] { 0.0, double.PositiveInfinity } },
            new object[] { "LowConfidenceChance", new[] { -1e-9, 1 + 1e-9, double.NaN }, new[] { 0.0, 1.0 } },
            new object[] { "GlitchChance", new[] { -1e-9, 1 + 1e-9, double.NaN }, new[] { 0.0, 1.0 } },
            new object[] { "GlitchSize", new[] { -1e-9, double.NaN, double.PositiveInfinity }, new[] { 0.0, 0.05 } },
        };

        [TestCaseSource(nameof(Settings))]
        public void ASettingOutsideItsRangeThrowsNamingItWhenSet(string name, double[] bad, double[] good)
        {
            var property = typeof(HeadsetSimulator).GetProperty(name);
            foreach (double v in bad)
            {
                var sim = new HeadsetSimulator();
                double before = (double)property.GetValue(sim);
                var e = Assert.Throws<System.Reflection.TargetInvocationException>(() => property.SetValue(sim, v), name + " = " + v);
                var inner = e.InnerException as ArgumentOutOfRangeException;
                Assert.That(inner, Is.Not.Null, name + " = " + v);
                Assert.That(inner.ParamName, Is.EqualTo(name));
                Assert.That((double)property.GetValue(sim), Is.EqualTo(before), "a refused value is not kept");
            }
            foreach (double v in good)
            {
                var sim = new HeadsetSimulator();
                property.SetValue(sim, v);
                Assert.That((double)property.GetValue(sim), Is.EqualTo(v));
            }
        }

        [Test]
        public void TheLargestWobbleStillAdvancesTheClockEveryFrame()
        {
            var frames = new HeadsetSimulator { FrameTimeWobble = 0.9, Seed = 3 }.Render(Held(5));
            for (int i = 1; i < frames.Length; i++)
                Assert.That(frames[i].Time - frames[i - 1].Time, Is.GreaterThanOrEqualTo(0.1 / 90 - 1e-12));
        }

        [Test]
        public void BadStretchesAndPathsThrowNamingTheArgument()
        {
            var sim = new HeadsetSimulator();
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => sim.Drop(double.NaN, 1)).ParamName, Is.EqualTo("start"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => sim.Drop(1, -0.1)).ParamName, Is.EqualTo("seconds"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => sim.LowConfidence(1, double.NaN)).ParamName, Is.EqualTo("seconds"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => sim.Offset(1, 1, double.PositiveInfinity)).ParamName, Is.EqualTo("size"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => sim.Glitch(double.PositiveInfinity, 0.03)).ParamName, Is.EqualTo("start"));
            Assert.That(Assert.Throws<ArgumentNullException>(() => sim.Render(null)).ParamName, Is.EqualTo("path"));
            Assert.That(Assert.Throws<ArgumentOutOfRangeException>(() => sim.Render(Held(1), -1)).ParamName, Is.EqualTo("extra"));
            // A stretch of no time is allowed (it changes nothing).
            Assert.That(sim.Drop(0.5, 0).Render(Held(1)), Has.All.Matches<TraceFrame>(f => f.Tracked));
        }

        // A seed is a trace: the accuracy pages' generated figures and a study's synthetic runs are reproduced from seeds,
        // so the streams behind jitter, glitches, confidence and frame wobble (SplitMix64 per pose, System.Random's seeded
        // sequence per frame) must not change between versions. Known answers of this version, printed with "R"; the
        // heights are compared to 1e-15 m because Math.Log and Math.Cos may differ in the last bit between runtimes.
        [Test]
        public void ASeedRendersTheSameTraceInEveryVersion()
        {
            var frames = new HeadsetSimulator
            {
                JitterSd = 0.01, GlitchChance = 0.5, GlitchSize = 0.03, LowConfidenceAboveSpeed = 0, LowConfidenceChance = 0.5,
                FrameTimeWobble = 0.2, Seed = 11,
            }.Render(HandPath.StartAt(0.8).MoveTo(1.2, 1.0));
            double[] times =
            {
                0, 0.010990763226881875, 0.02007934168502244, 0.030998855394569418, 0.043914559518464694, 0.05356956525820236,
                0.06322183489432127, 0.0758202826253647, 0.0889789773110306, 0.09937201490079096, 0.10972742170858854,
                0.12037605322914946,
            };
            for (int i = 0; i < times.Length; i++) Assert.That(frames[i].Time, Is.EqualTo(times[i]), "frame " + i);
            // The first 16 poses (from k = −2, before the move starts), and which of them are low-confidence.
            double[] heights =
            {
                0.7799839273097269, 0.8390861095947324, 0.8166579971149303, 0.8275951370310078, 0.8411620299685549,
                0.7847943334676651, 0.781285522149886, 0.8139784321345547, 0.7826579298308729, 0.7907839820887508,
                0.8612077241333161, 0.8530518317613349, 0.837385025828127, 0.8667404363963549, 0.9535092111277116,
                0.9438190412850153,
            };
            bool[] low = { false, false, true, true, false, true, false, false, false, false, false, true, false, false, true, true };
            var poses = Poses(frames);
            for (int i = 0; i < heights.Length; i++)
            {
                Assert.That(poses[i].HandY, Is.EqualTo(heights[i]).Within(1e-15), "pose " + i);
                Assert.That(poses[i].LowConfidence, Is.EqualTo(low[i]), "pose " + i);
            }
        }
    }
}
