using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>
    /// The hand filters' edges that FilterTests' smooth inputs do not reach, written for the mutants Stryker left
    /// alive in the estimation piece (quality.md, "In pieces"): the clamps of the pose interval (a clamped interval
    /// filters exactly as the bound does), the window's open end, time that never runs backwards, and the names
    /// the CLI and reports print.
    /// </summary>
    public class FilterEdgeTests
    {
        /// <summary>
        /// Resets a fresh copy at 0 and feeds two poses, 0.1 after 1/30 s and 0.3 after <paramref name="interval"/>
        /// (with a steady interval the alpha-beta filter's T cancels out, so the second one differs).
        /// </summary>
        static double TwoPoses(IHandFilter prototype, double interval)
        {
            var f = prototype.Create();
            f.Reset(0);
            f.Filter(0.1, true, 1 / 30.0, 1 / 90.0);
            return f.Filter(0.3, true, interval, 1 / 90.0);
        }

        [TestCase(0.5)]
        [TestCase(3600.0)]
        [TestCase(double.PositiveInfinity)]
        public void AlphaBetaTakesALongerIntervalThanTheLongestAsTheLongest(double interval)
        {
            var f = new AlphaBetaFilter();
            Assert.That(TwoPoses(f, interval), Is.EqualTo(TwoPoses(f, 0.1)), "T is clamped to 100 ms");
            Assert.That(TwoPoses(f, 0.1), Is.Not.EqualTo(TwoPoses(f, 0.05)), "and 100 ms is not 50 ms");
        }

        [TestCase(0.0)]
        [TestCase(1e-6)]
        [TestCase(-1.0)]
        [TestCase(double.NaN)]
        public void AlphaBetaTakesAShorterOrUnknownIntervalAsTheShortest(double interval)
        {
            var f = new AlphaBetaFilter();
            Assert.That(TwoPoses(f, interval), Is.EqualTo(TwoPoses(f, 0.001)), "T is clamped to 1 ms");
            Assert.That(TwoPoses(f, 0.001), Is.Not.EqualTo(TwoPoses(f, 0.002)), "and 1 ms is not 2 ms");
        }

        [TestCase(5.0, 1.0, 0.5)]
        [TestCase(double.PositiveInfinity, 1.0, 0.5)]
        [TestCase(0.0, 1e-4, 2e-4)]
        [TestCase(1e-7, 1e-4, 2e-4)]
        [TestCase(-1.0, 1e-4, 2e-4)]
        [TestCase(double.NaN, 1e-4, 2e-4)]
        public void OneEuroClampsItsSamplingPeriod(double interval, double bound, double inside)
        {
            var f = new OneEuroFilter();
            Assert.That(TwoPoses(f, interval), Is.EqualTo(TwoPoses(f, bound)));
            Assert.That(TwoPoses(f, bound), Is.Not.EqualTo(TwoPoses(f, inside)), "a period inside the bounds is used as it is");
        }

        [Test]
        public void OneEuroSmoothsMoreAtRestThanWhenFast()
        {
            // The cutoff grows with |speed|, downwards as upwards: a fast fall is followed as closely as a fast rise.
            var f = new OneEuroFilter();
            double up = TwoPoses(f, 1 / 30.0);
            var g = f.Create();
            g.Reset(0);
            g.Filter(-0.1, true, 1 / 30.0, 1 / 90.0);
            double down = g.Filter(-0.3, true, 1 / 30.0, 1 / 90.0);
            Assert.That(down, Is.EqualTo(-up).Within(1e-15), "the filter is odd in the hand's motion");
            var slow = new OneEuroFilter(1.0, 0.0, 1.0);
            Assert.That(TwoPoses(slow, 1 / 30.0), Is.LessThan(up), "without the speed term it lags more");
        }

        [Test]
        public void OneSecondAveragesWindowIsOpenAtItsOldEnd()
        {
            // A pose exactly one window old has left (the window is (now − W, now]); times are exact in binary.
            var f = new OneSecondAverage(1.0).Create();
            f.Reset(0);
            Assert.That(f.Filter(2, true, 0.5, 0.5), Is.EqualTo(1), "0 at t = 0 and 2 at t = 0.5");
            Assert.That(f.Filter(2, false, 0, 0.25), Is.EqualTo(1), "at 0.75 s both are in");
            Assert.That(f.Filter(2, false, 0, 0.25), Is.EqualTo(2), "at 1 s the pose of t = 0 has left");
        }

        [Test]
        public void OneSecondAveragesClockNeverRunsBackwards()
        {
            var f = new OneSecondAverage(1.0).Create();
            f.Reset(0);
            f.Filter(2, true, 0.5, 0.5);
            // A negative frame time is ignored: the pose of t = 0 leaves after 0.5 s more of positive time, not 1.5 s.
            Assert.That(f.Filter(2, false, 0, -1), Is.EqualTo(1));
            Assert.That(f.Filter(2, false, 0, 0.5), Is.EqualTo(2));
        }

        [Test]
        public void TheWindowAveragesRunningSumIsRecomputedEveryCapacityPoses()
        {
            // Four slots, a long window: 10¹⁶ three times, then 0.1 … 0.5. Adding 0.1–0.3 to a sum of order 10¹⁶ loses them,
            // so once the large poses have left, the running sum is wrong; the sum is recomputed from the slots when the
            // capacity's count of poses has come in since the last time (here at 0.1 and again at 0.5), so at 0.5 the
            // average is the slots' own.
            var f = new OneSecondAverage(10, 4);
            f.Reset(0);
            for (int i = 0; i < 3; i++) f.Filter(1e16, true, 0.01, 0.01);
            double y = 0;
            foreach (var pose in new[] { 0.1, 0.2, 0.3, 0.4, 0.5 }) y = f.Filter(pose, true, 0.01, 0.01);
            Assert.That(y, Is.EqualTo((0.2 + 0.3 + 0.4 + 0.5) / 4), "the four poses in the window, summed afresh");
        }

        [Test]
        public void TheWindowAveragesRunningSumKeepsAPoseCheapHoweverFullTheWindow()
        {
            // The running sum is why a pose costs the same with 65,536 poses in the window as with 1: it is recomputed
            // from the slots only once per capacity's count of poses. 200,000 poses of a 10 kHz source into a 10 s
            // window, full at 65,536 from the 65,536th on: a few milliseconds with the running sum; summed afresh at
            // every pose, about 10¹⁰ additions, seconds on any machine. The bound leaves two orders of magnitude for a
            // loaded one.
            const int poses = 200000, capacity = OneSecondAverage.MaxCapacity;
            var f = new OneSecondAverage(10, capacity);
            f.Reset(0);
            double y = 0;
            var watch = System.Diagnostics.Stopwatch.StartNew();
            for (int i = 1; i <= poses; i++) y = f.Filter(i % 100 * 0.001, true, 1e-4, 1e-4);
            watch.Stop();
            double sum = 0;
            for (int i = poses - capacity + 1; i <= poses; i++) sum += i % 100 * 0.001;
            Assert.That(y, Is.EqualTo(sum / capacity).Within(1e-12), "the mean of the last 65,536 poses");
            Assert.That(watch.Elapsed.TotalSeconds, Is.LessThan(2), "200,000 poses into a full window");
        }

        [Test]
        public void OneSecondAverageGivesTheLastPoseItselfWhenItIsAlone()
        {
            // 0.1 + 0.2 − 0.1 is 0.20000000000000004 in doubles: alone, the newest pose is returned, not the running sum.
            var f = new OneSecondAverage(1.0).Create();
            f.Reset(0.1);
            f.Filter(0.2, true, 0.5, 0.5);
            Assert.That(f.Filter(0.2, false, 0, 0.5), Is.EqualTo(0.2));
        }

        [Test]
        public void OneSecondAverageAtCapacityDropsTheOldestFirst()
        {
            var f = new OneSecondAverage(10, 3).Create();
            f.Reset(0);
            f.Filter(3, true, 0.1, 0.1);
            f.Filter(6, true, 0.1, 0.1);                 // holds 0, 3, 6
            Assert.That(f.Filter(9, true, 0.1, 0.1), Is.EqualTo(6), "0 dropped for 9: mean of 3, 6, 9");
            Assert.That(f.Filter(12, true, 0.1, 0.1), Is.EqualTo(9), "then 3: mean of 6, 9, 12");
            Assert.That(f.Filter(0, true, 0.1, 0.1), Is.EqualTo(7), "then 6: mean of 9, 12, 0");
        }

        [Test]
        public void MovingAverageReplacesTheOldestPose()
        {
            var f = new MovingAverage(3).Create();
            f.Reset(0);
            Assert.That(f.Filter(3, true, 0.1, 0.1), Is.EqualTo(1));
            Assert.That(f.Filter(3, false, 0, 0.1), Is.EqualTo(1), "no new pose: the mean stays");
            Assert.That(f.Filter(6, true, 0.1, 0.1), Is.EqualTo(3));
            Assert.That(f.Filter(9, true, 0.1, 0.1), Is.EqualTo(6), "0 left");
            Assert.That(f.Filter(12, true, 0.1, 0.1), Is.EqualTo(9), "3 left: the ring wrapped");
        }

        [Test]
        public void ExponentialSmoothingMovesByDtOverTauPlusDt()
        {
            var f = new ExponentialSmoothing(0.03).Create();
            f.Reset(1);
            Assert.That(f.Filter(2, true, 0.01, 0.01), Is.EqualTo(1.25).Within(1e-15), "1 + (2 − 1) · 0.01 / 0.04");
            Assert.That(f.Filter(2, false, 0, 0.03), Is.EqualTo(1.625).Within(1e-15), "half the rest with dt = τ");
        }

        [Test]
        public void NamesAreWhatReportsPrint()
        {
            Assert.That(new AlphaBetaFilter().Name, Is.EqualTo("alpha-beta"));
            Assert.That(new ExponentialSmoothing().Name, Is.EqualTo("exponential"));
            Assert.That(new MovingAverage(7).Name, Is.EqualTo("moving-average-7"));
            Assert.That(new OneEuroFilter().Name, Is.EqualTo("one-euro"));
            Assert.That(new OneSecondAverage().Name, Is.EqualTo("one-second-average"));
            Assert.That(new OneSecondAverage(0.5).Name, Is.EqualTo("window-average-0.5s"));
        }

        [Test]
        public void CreateKeepsEverySetting()
        {
            var ab = (AlphaBetaFilter)new AlphaBetaFilter(0.4, 0.2).Create();
            Assert.That((ab.Alpha, ab.Beta), Is.EqualTo((0.4, 0.2)));
            var oe = (OneEuroFilter)new OneEuroFilter(2, 30, 3).Create();
            Assert.That((oe.MinCutoff, oe.Beta, oe.DerivativeCutoff), Is.EqualTo((2.0, 30.0, 3.0)));
            var es = (ExponentialSmoothing)new ExponentialSmoothing(0.2).Create();
            Assert.That(es.TimeConstant, Is.EqualTo(0.2));
            var wa = (OneSecondAverage)new OneSecondAverage(0.5, 16).Create();
            Assert.That((wa.Window, wa.Capacity), Is.EqualTo((0.5, 16)));
            Assert.That(((MovingAverage)new MovingAverage(9).Create()).Count, Is.EqualTo(9));
        }
    }
}
