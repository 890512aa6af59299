using System;
using System.Collections.Generic;
using Kosmos.PseudoHaptic.Simulation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>A hand path's documented contract: moves need positive durations; a recorded trace needs two or more
    /// samples of equal-length times and heights, times increasing, and is interpolated linearly on its own clock (0 at
    /// its first sample); before 0 the start, from the end on the end.</summary>
    public class HandPathTests
    {
        [TestCase(0.0)]
        [TestCase(-1.0)]
        [TestCase(double.NaN)]
        public void AMoveNeedsAPositiveDuration(double seconds)
        {
            var e = Assert.Throws<ArgumentOutOfRangeException>(() => HandPath.StartAt(1).MoveTo(2, seconds));
            Assert.That(e.ParamName, Is.EqualTo("seconds"));
            Assert.That(e.Message, Does.Contain("> 0"));
        }

        [Test]
        public void ATraceNeedsTwoSamplesOfEqualLengthTimesAndHeights()
        {
            Assert.Throws<ArgumentException>(() => HandPath.FromSamples(new[] { 0.0 }, new[] { 1.0 }));
            var e = Assert.Throws<ArgumentException>(() => HandPath.FromSamples(new[] { 0.0, 1, 2 }, new[] { 1.0, 2 }));
            Assert.That(e.Message, Does.Contain("two samples"));
            Assert.That(HandPath.FromSamples(new[] { 0.0, 1 }, new[] { 1.0, 3 }).HeightAt(0.5), Is.EqualTo(2.0));
        }

        [TestCase(1.0)]
        [TestCase(0.5)]
        public void ATraceNeedsIncreasingTimesAndNamesTheFirstThatIsNot(double third)
        {
            var e = Assert.Throws<ArgumentException>(() => HandPath.FromSamples(new[] { 0.0, 1, third, 2 }, new[] { 1.0, 2, 3, 4 }));
            Assert.That(e.Message, Is.EqualTo("times must increase (index 2)."));
        }

        [Test]
        public void ATraceIsInterpolatedLinearlyOnItsOwnClock()
        {
            var p = HandPath.FromSamples(new[] { 10.0, 11, 13 }, new[] { 1.0, 2, 0 });
            Assert.That(p.Duration, Is.EqualTo(3.0));
            Assert.That(p.EndHeight, Is.EqualTo(0.0));
            Assert.That(p.HeightAt(-1), Is.EqualTo(1.0));
            Assert.That(p.HeightAt(0.25), Is.EqualTo(1.25).Within(1e-12));
            Assert.That(p.HeightAt(1.0), Is.EqualTo(2.0).Within(1e-12));
            Assert.That(p.HeightAt(2.0), Is.EqualTo(1.0).Within(1e-12));
            Assert.That(p.HeightAt(2.5), Is.EqualTo(0.5).Within(1e-12));
            Assert.That(p.HeightAt(3.0), Is.EqualTo(0.0));
            Assert.That(p.HeightAt(4.0), Is.EqualTo(0.0));
        }

        [Test]
        public void AtItsEndAPathIsExactlyAtItsEndHeight()
        {
            for (int i = 1; i < 50; i++)
            {
                double a = i * 0.1, b = i * 0.07;
                var p = HandPath.StartAt(0.3).Hold(a).MoveTo(0.7 + i * 0.01, b);
                Assert.That(p.HeightAt(p.Duration), Is.EqualTo(p.EndHeight), "hold " + a + " move " + b);
                var q = HandPath.FromSamples(new[] { 0.0, a, a + b }, new[] { 0.3, 0.1, 0.7 + i * 0.01 });
                Assert.That(q.HeightAt(q.Duration), Is.EqualTo(q.EndHeight), "trace " + a + " " + b);
            }
        }
    }

    /// <summary>Trace frames and recorded frames: usable means tracked and finite; confidence only when tracked.</summary>
    public class TraceFrameTests
    {
        [Test]
        public void ANewFrameIsConfidentAndUsableWhenTrackedAtAFiniteHeight()
        {
            var f = new TraceFrame(0.1, 1.0, true, 0.05);
            Assert.That(f.LowConfidence, Is.False);
            Assert.That(f.IsUsable, Is.True);
            var s = f.ToSample();
            Assert.That(s.IsTracked && s.IsHighConfidence, Is.True);
            Assert.That(s.Y, Is.EqualTo(1.0));
            Assert.That(s.PoseTime, Is.EqualTo(0.05));
        }

        [Test]
        public void AnUntrackedFrameIsNeitherUsableNorConfidentWhateverItsHeight()
        {
            var f = new TraceFrame(0.1, 1.0, false);
            Assert.That(f.IsUsable, Is.False);
            Assert.That(f.ToSample().IsHighConfidence, Is.False);
            Assert.That(new TraceFrame(0.1, double.NaN, true).IsUsable, Is.False);
        }

        [Test]
        public void ARecordedFrameWithoutHighConfidenceReplaysAsLowConfidence()
        {
            var r = new RecordedFrame { Time = 1, HandY = 0.9, Tracked = true, HighConfidence = false, PoseTime = 0.95 };
            Assert.That(r.ToTraceFrame().LowConfidence, Is.True);
            r.HighConfidence = true;
            Assert.That(r.ToTraceFrame().LowConfidence, Is.False);
            r.Tracked = false; r.HighConfidence = false;
            Assert.That(r.ToTraceFrame().LowConfidence, Is.False);
        }
    }

    /// <summary>Trace replay's contract: one finite height per frame; the hold begins at the first usable frame.</summary>
    public class TraceReplayTests
    {
        static WeightSolver Solver() => new WeightSolver(WeightModel.FromMass(1.0), NamedProfiles.Get(NamedProfiles.PaperName), 0.5);

        static TraceFrame[] Lift(int lostFirst)
        {
            var frames = new TraceFrame[40];
            for (int i = 0; i < frames.Length; i++)
                frames[i] = i < lostFirst ? new TraceFrame(i / 90.0, double.NaN, false) : new TraceFrame(i / 90.0, 1.0 + 0.005 * i, true);
            return frames;
        }

        [Test]
        public void NullArgumentsAndAShortOutputAreRefused()
        {
            var frames = Lift(0);
            Assert.Throws<ArgumentNullException>(() => TraceReplay.Run(null, frames, new double[40]));
            Assert.Throws<ArgumentNullException>(() => TraceReplay.Run(Solver(), null, new double[40]));
            var e = Assert.Throws<ArgumentException>(() => TraceReplay.Run(Solver(), frames, new double[39]));
            Assert.That(e.ParamName, Is.EqualTo("objectY"));
            Assert.That(e.Message, Does.Contain("one value per frame"));
            e = Assert.Throws<ArgumentException>(() => TraceReplay.Run(Solver(), frames, null));
            Assert.That(e.ParamName, Is.EqualTo("objectY"));
        }

        [Test]
        public void ALongerOutputIsFine()
        {
            var y = new double[50];
            TraceReplay.Run(Solver(), Lift(0), y);
            Assert.That(y[0], Is.EqualTo(1.0));
            Assert.That(y[39], Is.GreaterThan(1.0));
        }

        [Test]
        public void WithNoUsableFrameEveryHeightIsZero()
        {
            var frames = Lift(40);
            Assert.That(TraceReplay.FirstUsable(frames), Is.EqualTo(-1));
            Assert.That(TraceReplay.FirstUsable(new TraceFrame[0]), Is.EqualTo(-1));
            var y = new double[40];
            for (int i = 0; i < y.Length; i++) y[i] = 7;
            TraceReplay.Run(Solver(), frames, y);
            foreach (double v in y) Assert.That(v, Is.EqualTo(0));
        }

        [Test]
        public void TheHoldBeginsAtTheFirstUsableFrameAndEndsAfterTheLast()
        {
            var frames = Lift(5);
            Assert.That(TraceReplay.FirstUsable(frames), Is.EqualTo(5));
            var solver = Solver();
            var y = TraceReplay.Run(solver, frames);
            for (int i = 0; i <= 5; i++) Assert.That(y[i], Is.EqualTo(frames[5].HandY), "frame " + i);
            Assert.That(y[39], Is.GreaterThan(frames[5].HandY));
            Assert.That(solver.IsHolding, Is.False);
        }
    }
}
