using System;
using System.Collections.Generic;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>
    /// The hand filters of issue 4 (MovingAverage, OneSecondAverage, OneEuroFilter, AlphaBetaFilter): each settles
    /// on a still hand, lags a ramp by what its design says, smooths jitter, rejects bad settings by name,
    /// allocates nothing per call and is deterministic. accuracy-vs-time.md measures them on Quest-like input.
    /// </summary>
    public class FilterTests
    {
        const double FrameRate = 90, PoseRate = 30, PosePeriod = 1 / PoseRate;

        static IEnumerable<TestCaseData> Filters()
        {
            yield return new TestCaseData(new MovingAverage(3)).SetName("MovingAverage3");
            yield return new TestCaseData(new MovingAverage(5)).SetName("MovingAverage5");
            yield return new TestCaseData(new OneSecondAverage()).SetName("OneSecondAverage");
            yield return new TestCaseData(new OneEuroFilter()).SetName("OneEuroFilter");
            yield return new TestCaseData(new AlphaBetaFilter()).SetName("AlphaBetaFilter");
        }

        /// <summary>
        /// Feeds 90 Hz frames carrying 30 Hz poses of <paramref name="hand"/> (pose k sampled at k/30 s) to a fresh
        /// instance reset at hand(0); returns the output at every frame that brought a new pose, and those poses.
        /// </summary>
        static (double[] Output, double[] Pose, double[] Time) Feed(IHandFilter prototype, Func<int, double> hand, double seconds)
        {
            var filter = prototype.Create();
            filter.Reset(hand(0));
            int frames = (int)(seconds * FrameRate);
            var output = new List<double>();
            var pose = new List<double>();
            var time = new List<double>();
            int lastPose = 0;
            for (int i = 1; i <= frames; i++)
            {
                int k = i / 3; // 90 Hz frames, 30 Hz poses
                bool isNew = k != lastPose;
                double y = hand(k);
                double r = filter.Filter(y, isNew, isNew ? PosePeriod : 0, 1 / FrameRate);
                if (isNew)
                {
                    output.Add(r);
                    pose.Add(y);
                    time.Add(k * PosePeriod);
                }
                lastPose = k;
            }
            return (output.ToArray(), pose.ToArray(), time.ToArray());
        }

        static double Gaussian(Random rng)
        {
            double u1 = 1.0 - rng.NextDouble(), u2 = rng.NextDouble();
            return Math.Sqrt(-2.0 * Math.Log(u1)) * Math.Cos(2 * Math.PI * u2);
        }

        [TestCaseSource(nameof(Filters))]
        public void ConvergesOnAStillHand(IHandFilter filter)
        {
            var run = Feed(filter, k => k == 0 ? 0.8 : 1.1, 6);
            Assert.That(run.Output[run.Output.Length - 1], Is.EqualTo(1.1).Within(1e-9), "settled on the hand after 6 s");
            foreach (var y in run.Output) Assert.That(y, Is.InRange(0.8 - 0.15, 1.1 + 0.15), "overshoot of a 0.3 m step stays under half of it");
        }

        [TestCaseSource(nameof(Filters))]
        public void SmoothsJitterAtRest(IHandFilter filter)
        {
            var rng = new Random(7);
            var jitter = new double[20 * 30 + 1];
            for (int k = 1; k < jitter.Length; k++) jitter[k] = 1.0 + 0.002 * Gaussian(rng);
            jitter[0] = 1.0;
            var run = Feed(filter, k => jitter[k], 20);
            double inSs = 0, outSs = 0;
            int n = 0;
            for (int i = 60; i < run.Output.Length; i++)
            {
                inSs += (run.Pose[i] - 1) * (run.Pose[i] - 1);
                outSs += (run.Output[i] - 1) * (run.Output[i] - 1);
                n++;
            }
            Assert.That(Math.Sqrt(outSs / n), Is.LessThan(0.8 * Math.Sqrt(inSs / n)), "RMS of the output about the still hand vs. the input's");
        }

        static IEnumerable<TestCaseData> RampLags()
        {
            const double v = 0.3;
            yield return new TestCaseData(new MovingAverage(3), v, 1 * PosePeriod, 1e-9).SetName("MovingAverage3LagsOnePose");
            yield return new TestCaseData(new MovingAverage(5), v, 2 * PosePeriod, 1e-9).SetName("MovingAverage5LagsTwoPoses");
            yield return new TestCaseData(new OneSecondAverage(), v, 29 / 2.0 * PosePeriod, PosePeriod / 2).SetName("OneSecondAverageLagsHalfASecond");
            yield return new TestCaseData(new OneEuroFilter(), v, 1 / (2 * Math.PI * (1 + 80 * v)), 1e-4).SetName("OneEuroLagsItsCutoffsTimeConstant");
            yield return new TestCaseData(new OneEuroFilter(2, 0), v, 1 / (2 * Math.PI * 2), 1e-4).SetName("OneEuroWithoutBetaIsALowPassAtMinCutoff");
            yield return new TestCaseData(new AlphaBetaFilter(), v, 0.0, 1e-4).SetName("AlphaBetaTracksARampWithoutLag");
        }

        [TestCaseSource(nameof(RampLags))]
        public void LagsARampByWhatItsDesignSays(IHandFilter filter, double speed, double expectedLag, double tolerance)
        {
            var run = Feed(filter, k => 1 + speed * k * PosePeriod, 12);
            int last = run.Output.Length - 1;
            double lag = (run.Pose[last] - run.Output[last]) / speed;
            Assert.That(lag, Is.EqualTo(expectedLag).Within(tolerance), "lag behind the latest pose after 12 s of a 0.3 m/s ramp, s");
        }

        [Test]
        public void OneSecondAverageIsTheMeanOfTheLastSecondsPoses()
        {
            var f = new OneSecondAverage().Create();
            f.Reset(0);
            // Four poses 0.4 s apart: at 1.3 s the pose of 0.1 s has left the window, the rest remain.
            double r = 0;
            for (int i = 1; i <= 13; i++)
            {
                bool isNew = i % 4 == 1;
                r = f.Filter(isNew ? i : 0, isNew, isNew ? 0.4 : 0, 0.1);
            }
            Assert.That(r, Is.EqualTo((5 + 9 + 13) / 3.0).Within(1e-12));
            // No new pose for longer than the window: the newest pose alone remains.
            for (int i = 0; i < 20; i++) r = f.Filter(13, false, 0, 0.1);
            Assert.That(r, Is.EqualTo(13));
        }

        [Test]
        public void OneSecondAverageKeepsItsNewestCapacityPosesAndNoRoundingDrift()
        {
            var f = new OneSecondAverage(1.0, 8).Create();
            f.Reset(0);
            double r = 0;
            // A thousand poses per second, far more than the 8 it can hold, around a large offset, for 100 s.
            for (int i = 1; i <= 100000; i++) r = f.Filter(1e4 + (i % 8), true, 0.001, 0.001);
            Assert.That(r, Is.EqualTo(1e4 + 3.5).Within(1e-9), "the mean of the newest 8 poses (0..7 around 1e4)");
        }

        static IEnumerable<TestCaseData> BadSettings()
        {
            yield return new TestCaseData((TestDelegate)(() => new MovingAverage(0)), "count");
            yield return new TestCaseData((TestDelegate)(() => new MovingAverage(MovingAverage.MaxCount + 1)), "count");
            yield return new TestCaseData((TestDelegate)(() => new OneSecondAverage(0)), "window");
            yield return new TestCaseData((TestDelegate)(() => new OneSecondAverage(double.NaN)), "window");
            yield return new TestCaseData((TestDelegate)(() => new OneSecondAverage(1, 0)), "capacity");
            yield return new TestCaseData((TestDelegate)(() => new OneEuroFilter(0)), "minCutoff");
            yield return new TestCaseData((TestDelegate)(() => new OneEuroFilter(double.PositiveInfinity)), "minCutoff");
            yield return new TestCaseData((TestDelegate)(() => new OneEuroFilter(1, -1)), "beta");
            yield return new TestCaseData((TestDelegate)(() => new OneEuroFilter(1, double.NaN)), "beta");
            yield return new TestCaseData((TestDelegate)(() => new OneEuroFilter(1, 10, 0)), "derivativeCutoff");
            yield return new TestCaseData((TestDelegate)(() => new AlphaBetaFilter(0)), "alpha");
            yield return new TestCaseData((TestDelegate)(() => new AlphaBetaFilter(1.5)), "alpha");
            yield return new TestCaseData((TestDelegate)(() => new AlphaBetaFilter(0.5, -0.1)), "beta");
            yield return new TestCaseData((TestDelegate)(() => new AlphaBetaFilter(0.5, 1.6)), "beta");
            yield return new TestCaseData((TestDelegate)(() => new AlphaBetaFilter(0.5, double.NaN)), "beta");
        }

        [TestCaseSource(nameof(BadSettings))]
        public void RejectsBadSettingsNamingTheField(TestDelegate create, string field)
        {
            var e = Assert.Throws<ArgumentOutOfRangeException>(create);
            Assert.That(e.ParamName, Is.EqualTo(field));
            Assert.That(e.Message, Does.StartWith(field + " must"));
        }

        [TestCaseSource(nameof(Filters))]
        public void OutputIsFiniteForOddButFiniteInput(IHandFilter filter)
        {
            var f = filter.Create();
            f.Reset(0);
            double[] ys = { 1e5 - 1, -1e5 + 1, 0, 1e-300, 3, 3, -7 };
            double[] intervals = { 0, 1e-9, double.NaN, 1e-4, 3600, 0.25, double.PositiveInfinity };
            double[] dts = { 0, 1e-9, 3600, 0.011, 0, 0.25, 0.001 };
            for (int rep = 0; rep < 50; rep++)
                for (int i = 0; i < ys.Length; i++)
                {
                    double r = f.Filter(ys[i], (rep + i) % 2 == 0, intervals[i], dts[i]);
                    Assert.That(!double.IsNaN(r) && !double.IsInfinity(r), Is.True, "finite output at " + rep + "/" + i);
                }
        }

        [TestCaseSource(nameof(Filters))]
        public void IsDeterministicAndCreateGivesIndependentState(IHandFilter prototype)
        {
            var a = prototype.Create();
            var b = prototype.Create();
            a.Reset(1);
            b.Reset(1);
            var rng = new Random(3);
            for (int i = 0; i < 3000; i++)
            {
                bool isNew = i % 3 == 0;
                double y = 1 + 0.1 * Math.Sin(i / 50.0) + 0.002 * Gaussian(rng);
                double ra = a.Filter(y, isNew, isNew ? PosePeriod : 0, 1 / FrameRate);
                double rb = b.Filter(y, isNew, isNew ? PosePeriod : 0, 1 / FrameRate);
                Assert.That(BitConverter.DoubleToInt64Bits(ra), Is.EqualTo(BitConverter.DoubleToInt64Bits(rb)), "same input, same bits, at " + i);
            }
            // A fresh instance carries none of that history.
            var c = prototype.Create();
            c.Reset(5);
            Assert.That(c.Filter(5, false, 0, 1 / FrameRate), Is.EqualTo(5));
            Assert.That(c.Name, Is.EqualTo(prototype.Name));
        }

        [TestCaseSource(nameof(Filters))]
        public void InTheSolverTheObjectEndsWhereTheGainPutsIt(IHandFilter filter)
        {
            var profile = NamedProfiles.Paper.Without<MotionDeadband>().Without<FasterMovesFurther>().WithHandFilter(filter);
            var solver = Run.Solver(1.0, profile);
            var frames = Run.Headset(jitterSd: 0).Render(Run.Lift().Hold(2.0));
            var y = Run.Replay(solver, frames);
            Assert.That(Run.AllFinite(y), Is.True);
            Assert.That(Run.Last(y) - y[0], Is.EqualTo(0.3 * solver.Gain).Within(1e-6), "after the hand rests, the filter has caught up");
        }

        static void Calls(IHandFilter f, int count)
        {
            for (int i = 0; i < count; i++)
            {
                bool isNew = i % 3 == 0;
                f.Filter(1 + 0.001 * (i % 17), isNew, isNew ? PosePeriod : 0, 1 / FrameRate);
            }
        }

        [TestCaseSource(nameof(Filters))]
        public void FilterAllocatesNothing(IHandFilter prototype)
        {
            var f = prototype.Create();
            f.Reset(1);
            Allocation.AssertNone(n => Calls(f, n), "calls");
        }

        [TestCaseSource(nameof(Filters))]
        public void SolverWithTheFilterAllocatesNothingPerStep(IHandFilter filter)
        {
            var solver = Run.Solver(0.7, NamedProfiles.Paper.WithHandFilter(filter));
            solver.BeginHold(1, 1, 0);
            Allocation.AssertNone(n => Steps(solver, n), "steps");
        }

        static void Steps(WeightSolver solver, int count)
        {
            for (int i = 0; i < count; i++)
            {
                double t = i / FrameRate, poseT = Math.Floor(t * PoseRate) / PoseRate;
                var sample = i % 97 == 0 ? HandSample.Lost : new HandSample(1 + 0.2 * Math.Sin(poseT), true, true, poseT);
                solver.Step(sample, 1 / FrameRate);
            }
        }
    }
}
