using System;
using System.Collections.Generic;
using System.Globalization;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// Son et al. 2022, §3 and Fig. 6a: the user lifts a real golf ball and the mean speed of that lift is
    /// their standard speed v_std. <see cref="MeasureLift"/> finds the lift in a recording of (t, y);
    /// <see cref="Combine"/> takes the median of several, dropping outliers. Both reject, with the reason,
    /// what cannot be a deliberate lift: too short, too slow, too fast, non-finite, or inconsistent.
    /// Runs once per calibration, not per frame; it may allocate.
    /// </summary>
    public static class StandardSpeedCalibration
    {
        /// <summary>Smallest rise that counts as a lift, m.</summary>
        public const double MinRise = 0.10;

        /// <summary>Shortest lift (10–90 % of the rise), s.</summary>
        public const double MinDuration = 0.10;

        /// <summary>Lift speeds outside these bounds are rejected, m/s (the solver's own bounds on v_std).</summary>
        public const double MinSpeed = WeightSolver.MinStandardSpeed;
        public const double MaxSpeed = WeightSolver.MaxStandardSpeed;

        /// <summary>Lifts whose speeds differ from the median by more than this many scaled MADs are outliers.</summary>
        public const double OutlierMads = 3.0;

        /// <summary>A calibration whose used lifts spread more than this (MAD / median) is rejected as inconsistent.</summary>
        public const double MaxRelativeSpread = 0.35;

        /// <summary>
        /// Finds the largest rise in the recording (lowest point, then highest point after it, on a copy smoothed
        /// over ±25 ms) and measures the mean speed between 10 % and 90 % of that rise (from the last time the hand
        /// was below 10 % to the first time it reached 90 %), which ignores the slow start and end of a lift, the
        /// jitter of a hand at rest before and after it, and a bump that reaches 10 % and comes back down before it.
        /// </summary>
        public static LiftMeasurement MeasureLift(ReadOnlySpan<double> times, ReadOnlySpan<double> heights)
        {
            if (times.Length != heights.Length)
                return Reject("times and heights differ in length (" + times.Length + " vs " + heights.Length + ")");
            if (times.Length < 3)
                return Reject("too short: " + times.Length + " samples, at least 3 needed");
            for (int i = 0; i < times.Length; i++)
            {
                if (!double.IsFinite(times[i]) || !double.IsFinite(heights[i]))
                    return Reject("non-finite sample at index " + i);
                if (i > 0 && !(times[i] > times[i - 1]))
                    return Reject("time does not increase at index " + i);
            }

            // Tracking jitter would pick the extreme samples as the rise's ends: measure a lightly smoothed copy.
            heights = Smooth(times, heights);

            // Largest rise: for each j, the lowest point before it.
            int lowIdx = 0, bestLow = 0, bestHigh = 0;
            double bestRise = 0;
            for (int j = 1; j < heights.Length; j++)
            {
                if (heights[j] < heights[lowIdx]) lowIdx = j;
                double rise = heights[j] - heights[lowIdx];
                if (rise > bestRise) { bestRise = rise; bestLow = lowIdx; bestHigh = j; }
            }
            if (bestRise < MinRise)
                return Reject("too short: the hand rose " + Fmt(bestRise, MinRise) + " m, at least " + Fmt(MinRise) + " m needed");

            // The lift: from the last time the hand was below 10 % of the rise to the first time it reached 90 %. A bump
            // after the lowest point that reaches 10 % and comes back down (the hand settling on the ball) is not lift.
            double y0 = heights[bestLow];
            int i90 = FirstAtOrAbove(heights, bestLow, bestHigh, y0 + 0.90 * bestRise);
            double t90 = CrossingTime(times, heights, i90, y0 + 0.90 * bestRise);
            double t10 = CrossingTime(times, heights, LastBelow(heights, bestLow, i90, y0 + 0.10 * bestRise) + 1, y0 + 0.10 * bestRise);
            double duration = t90 - t10;
            if (!(duration >= MinDuration))
                return new LiftMeasurement(false, double.NaN, bestRise, duration, "too short: the lift took " + Fmt(duration, MinDuration) + " s, at least " + Fmt(MinDuration) + " s needed");
            double speed = 0.8 * bestRise / duration;
            if (speed < MinSpeed)
                return new LiftMeasurement(false, double.NaN, bestRise, duration, "too slow: " + Fmt(speed, MinSpeed) + " m/s, at least " + Fmt(MinSpeed) + " m/s expected");
            if (speed > MaxSpeed)
                return new LiftMeasurement(false, double.NaN, bestRise, duration, "too fast: " + Fmt(speed, MaxSpeed) + " m/s, at most " + Fmt(MaxSpeed) + " m/s expected");
            return new LiftMeasurement(true, speed, bestRise, duration, null);
        }

        /// <summary>
        /// The median speed of the accepted lifts after dropping outliers (beyond 3 scaled MADs of the median).
        /// Rejected when no lift is usable or the used lifts disagree by more than <see cref="MaxRelativeSpread"/>.
        /// </summary>
        public static CalibrationResult Combine(IReadOnlyList<LiftMeasurement> lifts)
        {
            if (lifts == null) throw new ArgumentNullException(nameof(lifts));
            var speeds = new List<double>();
            string firstReason = null;
            foreach (var l in lifts)
            {
                if (l.IsAccepted) speeds.Add(l.Speed);
                else if (firstReason == null) firstReason = l.Reason;
            }
            if (speeds.Count == 0)
                return new CalibrationResult(false, double.NaN, 0, lifts.Count, double.NaN,
                    lifts.Count == 0 ? "no lifts recorded" : "no usable lift (first: " + firstReason + ")");

            double median = Median(speeds);
            double mad = MedianAbsoluteDeviation(speeds, median);
            if (mad > 0)
                speeds.RemoveAll(s => Math.Abs(s - median) > OutlierMads * 1.4826 * mad);
            median = Median(speeds);
            double spread = MedianAbsoluteDeviation(speeds, median) / median;
            if (spread > MaxRelativeSpread)
                return new CalibrationResult(false, double.NaN, speeds.Count, lifts.Count, spread,
                    "inconsistent lifts: speeds spread " + Fmt(spread * 100) + " % around their median, at most " + Fmt(MaxRelativeSpread * 100) + " % allowed");
            return new CalibrationResult(true, median, speeds.Count, lifts.Count, spread, null);
        }

        /// <summary>Measures each recording and combines them.</summary>
        public static CalibrationResult FromLifts(IReadOnlyList<double[]> times, IReadOnlyList<double[]> heights)
        {
            if (times == null) throw new ArgumentNullException(nameof(times));
            if (heights == null) throw new ArgumentNullException(nameof(heights));
            if (times.Count != heights.Count) throw new ArgumentException("times and heights must list the same number of lifts.", nameof(heights));
            var lifts = new List<LiftMeasurement>(times.Count);
            for (int i = 0; i < times.Count; i++) lifts.Add(MeasureLift(times[i], heights[i]));
            return Combine(lifts);
        }

        /// <summary>The first sample after <paramref name="from"/>, up to <paramref name="to"/>, at or above
        /// <paramref name="level"/> (<paramref name="to"/> if none).</summary>
        static int FirstAtOrAbove(ReadOnlySpan<double> y, int from, int to, double level)
        {
            for (int i = from + 1; i <= to; i++) if (y[i] >= level) return i;
            return to;
        }

        /// <summary>The last sample before <paramref name="before"/> below <paramref name="level"/>, not before
        /// <paramref name="from"/> (the lowest point, below every level of the rise).</summary>
        static int LastBelow(ReadOnlySpan<double> y, int from, int before, double level)
        {
            int i = before - 1;
            while (i > from && !(y[i] < level)) i--;
            return i;
        }

        /// <summary>When the height reaches <paramref name="level"/> in the interval ending at sample <paramref name="i"/>,
        /// interpolated linearly. Both callers give an interval that starts below the level and ends at or above it, so
        /// the fraction lies in (0, 1].</summary>
        static double CrossingTime(ReadOnlySpan<double> t, ReadOnlySpan<double> y, int i, double level)
            => t[i - 1] + (level - y[i - 1]) / (y[i] - y[i - 1]) * (t[i] - t[i - 1]);

        /// <summary>Half-width of the centred moving average applied before measuring, s.</summary>
        public const double SmoothingHalfWindow = 0.025;

        static double[] Smooth(ReadOnlySpan<double> t, ReadOnlySpan<double> y)
        {
            var result = new double[y.Length];
            int lo = 0, hi = 0;
            double sum = 0;
            for (int i = 0; i < y.Length; i++)
            {
                while (hi < y.Length && t[hi] <= t[i] + SmoothingHalfWindow) sum += y[hi++];
                while (t[lo] < t[i] - SmoothingHalfWindow) sum -= y[lo++];
                result[i] = sum / (hi - lo);
            }
            return result;
        }

        static double Median(List<double> values)
        {
            var v = values.ToArray();
            Array.Sort(v);
            int n = v.Length;
            return n % 2 == 1 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
        }

        static double MedianAbsoluteDeviation(List<double> values, double median)
        {
            var d = new List<double>(values.Count);
            foreach (var v in values) d.Add(Math.Abs(v - median));
            return Median(d);
        }

        static LiftMeasurement Reject(string reason) => new LiftMeasurement(false, double.NaN, double.NaN, double.NaN, reason);
        static string Fmt(double v) => v.ToString("0.###", CultureInfo.InvariantCulture);

        /// <summary>A refused value beside its bound: to the millimetre (or millisecond), unless that prints the bound itself
        /// ("rose 0.1 m, at least 0.1 m"), then every digit.</summary>
        static string Fmt(double v, double bound)
        {
            string s = Fmt(v);
            return s == Fmt(bound) ? v.ToString("R", CultureInfo.InvariantCulture) : s;
        }
    }
}
