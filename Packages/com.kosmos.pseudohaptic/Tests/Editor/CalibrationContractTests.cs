using System;
using System.Collections.Generic;
using System.Globalization;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>
    /// The standard-speed calibration to the number and the word: a straight ramp measured exactly (10–90 % of
    /// the rise), each refusal's message, and how several lifts combine (outliers only when the lifts spread at
    /// all; inconsistent lifts refused with their spread).
    /// </summary>
    public class CalibrationContractTests
    {
        /// <summary>Rest at 1 m, a straight ramp of <paramref name="rise"/> m over <paramref name="seconds"/>, rest; sampled at <paramref name="hz"/>.</summary>
        static (double[] T, double[] Y) Ramp(double rise, double seconds, double hz = 100, double rest = 0.5)
        {
            var t = new List<double>();
            var y = new List<double>();
            int n = (int)Math.Round((2 * rest + seconds) * hz);
            for (int i = 0; i <= n; i++)
            {
                double ti = i / hz;
                double u = Math.Min(1, Math.Max(0, (ti - rest) / seconds));
                t.Add(ti);
                y.Add(1.0 + rise * u);
            }
            return (t.ToArray(), y.ToArray());
        }

        /// <summary>A hand path <paramref name="height"/>(t) sampled at 100 Hz from 0 to <paramref name="seconds"/> inclusive.</summary>
        static (double[] T, double[] Y) Sampled(double seconds, Func<double, double> height)
        {
            int n = (int)Math.Round(seconds * 100);
            var t = new double[n + 1];
            var y = new double[n + 1];
            for (int i = 0; i <= n; i++)
            {
                t[i] = i / 100.0;
                y[i] = height(t[i]);
            }
            return (t, y);
        }

        static LiftMeasurement Accepted(double speed) => new LiftMeasurement(true, speed, 0.3, 0.5, null);

        static LiftMeasurement Rejected(string reason) => new LiftMeasurement(false, double.NaN, 0.05, 0.5, reason);

        [Test]
        public void AStraightRampIsMeasuredExactly()
        {
            var (t, y) = Ramp(0.3, 0.6);
            var lift = StandardSpeedCalibration.MeasureLift(t, y);
            Assert.That(lift.IsAccepted, Is.True, lift.Reason);
            Assert.That(lift.Rise, Is.EqualTo(0.3).Within(1e-9));
            Assert.That(lift.Duration, Is.EqualTo(0.8 * 0.6).Within(1e-9), "from 10 % to 90 % of the rise");
            Assert.That(lift.Speed, Is.EqualTo(0.5).Within(1e-9));
            Assert.That(lift.Reason, Is.Null);
            Assert.That(lift.ToString(), Is.EqualTo("lift of 0.300 m at 0.500 m/s"));
        }

        [Test]
        public void ACoarselyOrUnevenlySampledRampIsMeasuredExactly()
        {
            // Samples farther apart than the ±25 ms smoothing leave the heights as they are; linear interpolation between
            // samples is exact on a straight ramp: 0.3 m in 0.6 s from t = 0.5 s, 10–90 % from 0.56 s to 1.04 s.
            var (t, y) = Ramp(0.3, 0.6, 10);
            var coarse = StandardSpeedCalibration.MeasureLift(t, y);
            Assert.That(coarse.IsAccepted, Is.True, coarse.Reason);
            Assert.That(coarse.Duration, Is.EqualTo(0.48).Within(1e-9), "at 10 Hz: 90 % is crossed in the last rising sample's interval");
            Assert.That(coarse.Speed, Is.EqualTo(0.5).Within(1e-9));

            var times = new[] { 0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.55, 0.58, 0.7, 0.76, 0.9, 1.03, 1.06, 1.1, 1.2, 1.3, 1.4, 1.5, 1.6 };
            var heights = new double[times.Length];
            for (int i = 0; i < times.Length; i++) heights[i] = 1.0 + 0.3 * Math.Min(1, Math.Max(0, (times[i] - 0.5) / 0.6));
            var uneven = StandardSpeedCalibration.MeasureLift(times, heights);
            Assert.That(uneven.IsAccepted, Is.True, uneven.Reason);
            Assert.That(uneven.Duration, Is.EqualTo(0.48).Within(1e-9), "uneven frame times");
            Assert.That(uneven.Speed, Is.EqualTo(0.5).Within(1e-9));
        }

        [Test]
        public void ARiseOfExactly10CmCounts()
        {
            // "A rise under 0.10 m" is refused, 0.10 m is not. Samples 0.25 s apart (beyond the ±25 ms smoothing) and a single
            // rising interval keep the heights exact: the rise is 0.10 m to the last bit.
            var lift = StandardSpeedCalibration.MeasureLift(new[] { -0.25, 0, 0.25, 0.5 }, new[] { 0, 0, 0.1, 0.1 });
            Assert.That(lift.Rise, Is.EqualTo(StandardSpeedCalibration.MinRise));
            Assert.That(lift.IsAccepted, Is.True, lift.Reason);
            Assert.That(lift.Duration, Is.EqualTo(0.2).Within(1e-12), "10–90 % of a straight interval of 0.25 s");
        }

        [Test]
        public void ALiftOfExactlyTheShortestDurationCounts()
        {
            // "Too short" is a lift under 0.1 s: 0.25 m over one straight interval of 0.125 s (samples beyond the ±25 ms
            // smoothing) takes 0.8 × 0.125 = 0.1 s from 10 % to 90 %, to the last bit, at 2 m/s.
            var lift = StandardSpeedCalibration.MeasureLift(new[] { -0.25, 0, 0.125, 0.375 }, new[] { 0, 0, 0.25, 0.25 });
            Assert.That(lift.Duration, Is.EqualTo(StandardSpeedCalibration.MinDuration));
            Assert.That(lift.IsAccepted, Is.True, lift.Reason);
            Assert.That(lift.Speed, Is.EqualTo(2.0).Within(1e-12));
        }

        // Speeds under 0.05 m/s or over 5 m/s are refused. Slowest: 0.125 m over 2.5 s is 0.1 m in 2 s from 10 % to 90 %,
        // 0.05 m/s to the last bit; fastest: 1.25 m over 0.25 s is 1 m in 0.2 s, 5 m/s to the last bit.
        [TestCase(2.5, 0.125, 2.0, StandardSpeedCalibration.MinSpeed, TestName = "ALiftAtExactlyTheSlowestSpeedCounts")]
        [TestCase(0.25, 1.25, 0.2, StandardSpeedCalibration.MaxSpeed, TestName = "ALiftAtExactlyTheFastestSpeedCounts")]
        public void ALiftAtExactlyASpeedBoundCounts(double riseTime, double rise, double duration, double speed)
        {
            var lift = StandardSpeedCalibration.MeasureLift(new[] { -0.25, 0, riseTime, riseTime + 0.25 }, new[] { 0, 0, rise, rise });
            Assert.That(lift.Duration, Is.EqualTo(duration).Within(1e-12));
            Assert.That(lift.IsAccepted, Is.True, lift.Reason);
            Assert.That(lift.Speed, Is.EqualTo(speed));
        }

        [Test]
        public void AHandThatPausesExactlyAtNinetyPercentReachedItWhenThePauseBegan()
        {
            // A rise of 0.5 m that pauses at exactly 0.45 m (90 %) from 0.25 s to 0.5 s: "the first time it reached 90 %" is
            // 0.25 s, not when it next went above. 10 % (0.05 m) is crossed at 0.25 / 9 s on the way up.
            var lift = StandardSpeedCalibration.MeasureLift(new[] { -0.25, 0, 0.25, 0.5, 0.75, 1.0 }, new[] { 0, 0, 0.45, 0.45, 0.5, 0.5 });
            Assert.That(lift.IsAccepted, Is.True, lift.Reason);
            Assert.That(lift.Rise, Is.EqualTo(0.5));
            Assert.That(lift.Duration, Is.EqualTo(0.25 - 0.25 / 9).Within(1e-12));
        }

        [Test]
        public void AHandThatPausesExactlyAtTenPercentWasLastBelowItWhenThePauseBegan()
        {
            // A rise of 0.5 m that pauses at exactly 0.05 m (10 %) from 0.25 s to 0.5 s: at 10 % is not below it, so "the last
            // time the hand was below 10 %" ends at 0.25 s, not at 0.5 s. 90 % (0.45 m) is crossed at 0.5 + 0.25 × 0.4 / 0.45 s.
            var lift = StandardSpeedCalibration.MeasureLift(new[] { -0.25, 0, 0.25, 0.5, 0.75, 1.0 }, new[] { 0, 0, 0.05, 0.05, 0.5, 0.5 });
            Assert.That(lift.IsAccepted, Is.True, lift.Reason);
            Assert.That(lift.Rise, Is.EqualTo(0.5));
            Assert.That(lift.Duration, Is.EqualTo(0.5 + 0.25 * 0.4 / 0.45 - 0.25).Within(1e-12));
        }

        [Test]
        public void SamplesExactly25MsApartAreInsideEachOthersSmoothingWindow()
        {
            // The moving average is over ±25 ms, both ends included: at 0, 25 and 50 ms (exactly 25 ms apart) the hand is at
            // 0, 0.3 and 0.6 m, so the smoothed heights there are 0.15 (0 and 25 ms), 0.3 (all three) and 0.45 m (25 and 50 ms);
            // the other samples are 0.25 s from any. Rise 0.6 m: 10 % (0.06 m) is crossed at −0.25 + 0.25 × 0.06 / 0.15 = −0.15 s,
            // 90 % (0.54 m) at 0.05 + 0.25 × 0.09 / 0.15 = 0.2 s.
            var lift = StandardSpeedCalibration.MeasureLift(new[] { -0.5, -0.25, 0, 0.025, 0.05, 0.3, 0.55 }, new[] { 0, 0, 0, 0.3, 0.6, 0.6, 0.6 });
            Assert.That(lift.IsAccepted, Is.True, lift.Reason);
            Assert.That(lift.Rise, Is.EqualTo(0.6).Within(1e-12));
            Assert.That(lift.Duration, Is.EqualTo(0.35).Within(1e-12));
        }

        [Test]
        public void OnlyTheLargestRiseCounts()
        {
            // A small lift (0.12 m) first, down again, then the real one (0.3 m) from a lower start.
            var (t, y) = Sampled(4, ti => ti < 0.5 ? 1.0 : ti < 0.8 ? 1.0 + 0.4 * (ti - 0.5) : ti < 1.1 ? 1.12 - 0.5 * (ti - 0.8)
                : ti < 1.5 ? 0.97 : ti < 2.1 ? 0.97 + 0.5 * (ti - 1.5) : 1.27);
            var lift = StandardSpeedCalibration.MeasureLift(t, y);
            Assert.That(lift.IsAccepted, Is.True, lift.Reason);
            Assert.That(lift.Rise, Is.EqualTo(0.3).Within(1e-9));
            Assert.That(lift.Speed, Is.EqualTo(0.5).Within(1e-9));
        }

        [Test]
        public void ABumpBeforeTheLiftThatComesBackDownIsNotTimed()
        {
            // At rest at 1.0 m, the hand bumps up 3 cm (above 10 % of the coming rise) and settles back at 1.005 m for half a
            // second, then lifts 0.2 m at 0.5 m/s. The rise is measured from the lowest point (1.0 m: 0.205 m), but the timed
            // 10–90 % is the lift's own: from the last time the hand was below 10 %, not the bump's crossing.
            var (t, y) = Sampled(2, ti => ti < 0.2 ? 1.0 : ti < 0.3 ? 1.0 + 0.3 * (ti - 0.2) : ti < 0.4 ? 1.03 - 0.25 * (ti - 0.3)
                : ti < 0.9 ? 1.005 : ti < 1.3 ? 1.005 + 0.5 * (ti - 0.9) : 1.205);
            var lift = StandardSpeedCalibration.MeasureLift(t, y);
            Assert.That(lift.IsAccepted, Is.True, lift.Reason);
            Assert.That(lift.Rise, Is.EqualTo(0.205).Within(1e-9));
            Assert.That(lift.Speed, Is.EqualTo(0.5).Within(1e-9), "the lift's own speed, not slowed by the rest after the bump");
            Assert.That(lift.Duration, Is.EqualTo(0.8 * 0.205 / 0.5).Within(1e-9));
        }

        [Test]
        public void AHandThatDipsBelowTenPercentDuringTheLiftIsTimedFromItsLastDip()
        {
            // A lift of 0.3 m from 1.0 m that pauses and sinks back below 10 % (1.03 m) once, then rises straight through:
            // the rise that reaches 90 % starts from the dip; the speed is that straight rise's, 0.5 m/s.
            var times = new[] { 0.0, 0.25, 0.5, 0.75, 1.0, 1.25, 1.5, 2.1, 2.35 };
            var heights = new[] { 1.0, 1.0, 1.05, 1.02, 1.02, 1.02, 1.0, 1.3, 1.3 };
            var lift = StandardSpeedCalibration.MeasureLift(times, heights);
            Assert.That(lift.IsAccepted, Is.True, lift.Reason);
            Assert.That(lift.Duration, Is.EqualTo(0.48).Within(1e-9), "10–90 % of the straight rise from 1.5 s to 2.1 s");
            Assert.That(lift.Speed, Is.EqualTo(0.5).Within(1e-9));
        }

        [Test]
        public void ARefusalJustShortOfItsBoundShowsTheDigitsThatMakeItShort()
        {
            // 0.09999 m rounds to the bound's own "0.1": the message must not read "rose 0.1 m, at least 0.1 m needed".
            var lift = StandardSpeedCalibration.MeasureLift(new[] { -0.25, 0, 0.25, 0.5 }, new[] { 0, 0, 0.09999, 0.09999 });
            Assert.That(lift.IsAccepted, Is.False);
            Assert.That(lift.Reason, Is.EqualTo("too short: the hand rose 0.09999 m, at least 0.1 m needed"));
            var clear = StandardSpeedCalibration.MeasureLift(new[] { -0.25, 0, 0.25, 0.5 }, new[] { 0, 0, 0.05, 0.05 });
            Assert.That(clear.Reason, Is.EqualTo("too short: the hand rose 0.05 m, at least 0.1 m needed"), "to the millimetre otherwise");
        }

        [Test]
        public void EachRefusalSaysWhy()
        {
            Assert.That(StandardSpeedCalibration.MeasureLift(new[] { 0.0, 1.0 }, new[] { 1.0 }).Reason,
                Is.EqualTo("times and heights differ in length (2 vs 1)"));
            Assert.That(StandardSpeedCalibration.MeasureLift(new[] { 0.0, 1.0 }, new[] { 1.0, 1.5 }).Reason,
                Is.EqualTo("too short: 2 samples, at least 3 needed"));
            Assert.That(StandardSpeedCalibration.MeasureLift(new[] { 0.0, 1.0, 2.0 }, new[] { 1.0, 1.0, 1.0 }).Reason,
                Is.EqualTo("too short: the hand rose 0 m, at least 0.1 m needed"), "three samples are enough to be judged");
            var (t, y) = Ramp(0.05, 0.5);
            Assert.That(StandardSpeedCalibration.MeasureLift(t, y).Reason, Is.EqualTo("too short: the hand rose 0.05 m, at least 0.1 m needed"));
        }

        [Test]
        public void TooSlowAndTooFastLiftsAreRefusedWithTheirSpeed()
        {
            var (ts, ys) = Ramp(0.3, 8.0);
            var slow = StandardSpeedCalibration.MeasureLift(ts, ys);
            Assert.That(slow.IsAccepted, Is.False);
            Assert.That(slow.Speed, Is.NaN);
            Assert.That(slow.Reason, Is.EqualTo("too slow: 0.038 m/s, at least 0.05 m/s expected"), "0.3 m at 0.0375 m/s");
            Assert.That(slow.ToString(), Is.EqualTo("rejected: " + slow.Reason));

            var (tf, yf) = Ramp(1.0, 0.15, 1000);
            var fast = StandardSpeedCalibration.MeasureLift(tf, yf);
            Assert.That(fast.IsAccepted, Is.False);
            string speed = (0.8 * fast.Rise / fast.Duration).ToString("0.###", CultureInfo.InvariantCulture);
            Assert.That(0.8 * fast.Rise / fast.Duration, Is.GreaterThan(5));
            Assert.That(fast.Reason, Is.EqualTo("too fast: " + speed + " m/s, at most 5 m/s expected"));
        }

        [Test]
        public void ALiftOverTooQuicklyIsRefusedWithItsDuration()
        {
            // 0.3 m in 0.1 s: 10–90 % of the rise takes about 0.08 s (3 m/s, within the speed bounds).
            var (t, y) = Ramp(0.3, 0.1, 1000);
            var lift = StandardSpeedCalibration.MeasureLift(t, y);
            Assert.That(lift.IsAccepted, Is.False);
            Assert.That(lift.Speed, Is.NaN);
            Assert.That(lift.Duration, Is.LessThan(0.1).And.GreaterThan(0.05));
            Assert.That(lift.Rise, Is.EqualTo(0.3).Within(1e-9));
            Assert.That(lift.Reason, Is.EqualTo("too short: the lift took " + lift.Duration.ToString("0.###", CultureInfo.InvariantCulture) + " s, at least 0.1 s needed"));
        }

        [Test]
        public void CombiningNothingOrOnlyRefusedLiftsSaysSo()
        {
            var none = StandardSpeedCalibration.Combine(new LiftMeasurement[0]);
            Assert.That((none.IsAccepted, none.LiftsUsed, none.LiftsOffered, none.Reason), Is.EqualTo((false, 0, 0, "no lifts recorded")));
            Assert.That(none.StandardSpeed, Is.NaN);
            var refused = StandardSpeedCalibration.Combine(new[] { Rejected("too slow: first"), Rejected("too fast: second") });
            Assert.That(refused.Reason, Is.EqualTo("no usable lift (first: too slow: first)"));
            Assert.That(refused.LiftsOffered, Is.EqualTo(2));
            Assert.That(refused.ToString(), Is.EqualTo("rejected: no usable lift (first: too slow: first)"));
            Assert.That(() => StandardSpeedCalibration.Combine(null), Throws.ArgumentNullException);
        }

        [Test]
        public void AnOutlierIsDroppedOnlyWhenTheOtherLiftsSpread()
        {
            var spread = StandardSpeedCalibration.Combine(new[] { Accepted(0.5), Accepted(0.52), Accepted(0.48), Accepted(0.5), Accepted(1.5), Rejected("x") });
            Assert.That(spread.IsAccepted, Is.True);
            Assert.That((spread.LiftsUsed, spread.LiftsOffered), Is.EqualTo((4, 6)), "1.5 m/s is 50 MADs out");
            Assert.That(spread.StandardSpeed, Is.EqualTo(0.5).Within(1e-12));
            Assert.That(spread.ToString(), Is.EqualTo("v_std = 0.500 m/s from 4 of 6 lifts"));

            // Three identical lifts: the MAD is 0, nothing is an outlier, the fourth stays in (the median is 0.5).
            var same = StandardSpeedCalibration.Combine(new[] { Accepted(0.5), Accepted(0.5), Accepted(0.5), Accepted(0.9) });
            Assert.That(same.IsAccepted, Is.True);
            Assert.That(same.LiftsUsed, Is.EqualTo(4));
            Assert.That(same.StandardSpeed, Is.EqualTo(0.5));
            Assert.That(same.RelativeSpread, Is.EqualTo(0));
        }

        [Test]
        public void ALiftExactlyThreeScaledMadsFromTheMedianIsNotAnOutlier()
        {
            // Outliers lie *beyond* 3 scaled MADs (1.4826 × MAD). Median 0.75, MAD 0.25 (deviations 0.25, 0.125, 0, 0.25 and
            // the fifth's): a fifth lift at 0.75 + 3 × 1.4826 × 0.25 m/s is exactly at the limit and stays in.
            double atLimit = 0.75 + 3 * 1.4826 * 0.25;
            Assert.That(atLimit - 0.75, Is.EqualTo(3 * 1.4826 * 0.25), "binary-exact: the limit to the last bit");
            var r = StandardSpeedCalibration.Combine(new[] { Accepted(0.5), Accepted(0.625), Accepted(0.75), Accepted(1.0), Accepted(atLimit) });
            Assert.That(r.IsAccepted, Is.True, r.Reason);
            Assert.That(r.LiftsUsed, Is.EqualTo(5));
            Assert.That(r.StandardSpeed, Is.EqualTo(0.75));
            Assert.That(r.RelativeSpread, Is.EqualTo(0.25 / 0.75).Within(1e-12));
        }

        [Test]
        public void InconsistentLiftsAreRefusedWithTheirSpread()
        {
            // Median 0.5, MAD 0.2 (no outlier within 3 × 1.4826 × 0.2): spread 40 % > 35 %.
            var r = StandardSpeedCalibration.Combine(new[] { Accepted(0.3), Accepted(0.5), Accepted(0.8) });
            Assert.That(r.IsAccepted, Is.False);
            Assert.That(r.StandardSpeed, Is.NaN);
            Assert.That(r.RelativeSpread, Is.EqualTo(0.4).Within(1e-12));
            Assert.That(r.LiftsUsed, Is.EqualTo(3));
            Assert.That(r.Reason, Is.EqualTo("inconsistent lifts: speeds spread 40 % around their median, at most 35 % allowed"));
        }

        [Test]
        public void LiftsSpreadExactly35PercentAreStillConsistent()
        {
            // Median 1.25, MAD 0.4375 (binary-exact): spread 0.4375 / 1.25 = 0.35, "more than 35 %" refused, 35 % not.
            var r = StandardSpeedCalibration.Combine(new[] { Accepted(0.8125), Accepted(1.25), Accepted(1.6875) });
            Assert.That(r.RelativeSpread, Is.EqualTo(0.35));
            Assert.That(r.IsAccepted, Is.True, r.Reason);
            Assert.That(r.StandardSpeed, Is.EqualTo(1.25));
        }

        [Test]
        public void FromLiftsRefusesMismatchedLists()
        {
            var (t, y) = Ramp(0.3, 0.6);
            Assert.That(() => StandardSpeedCalibration.FromLifts(null, new[] { y }), Throws.ArgumentNullException);
            Assert.That(() => StandardSpeedCalibration.FromLifts(new[] { t }, null), Throws.ArgumentNullException);
            var mismatch = Assert.Throws<ArgumentException>(() => StandardSpeedCalibration.FromLifts(new[] { t, t }, new[] { y }));
            Assert.That(mismatch.ParamName, Is.EqualTo("heights"));
            Assert.That(mismatch.Message, Does.Contain("same number of lifts"), "says what does not match");
            var one = StandardSpeedCalibration.FromLifts(new[] { t }, new[] { y });
            Assert.That(one.IsAccepted, Is.True);
            Assert.That(one.StandardSpeed, Is.EqualTo(0.5).Within(1e-9));
        }
    }
}
