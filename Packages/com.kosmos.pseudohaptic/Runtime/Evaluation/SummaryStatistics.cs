using System;
using System.Collections.Generic;

namespace Kosmos.PseudoHaptic.Evaluation
{
    /// <summary>
    /// Describes one part's scores across participants: n, mean, sample standard deviation (n − 1),
    /// median, min, max and the confidence interval of the mean, mean ± t(1 − α/2, n − 1)·SD/√n with
    /// Student's t (<see cref="StudentT"/>). Undefined figures are NaN: everything when n = 0; SD and the
    /// interval when n = 1.
    /// </summary>
    public sealed class SummaryStatistics
    {
        public int N { get; }
        public double Mean { get; }
        /// <summary>Sample standard deviation, divisor n − 1.</summary>
        public double StandardDeviation { get; }
        /// <summary>SD/√n.</summary>
        public double StandardError { get; }
        public double Median { get; }
        public double Min { get; }
        public double Max { get; }
        /// <summary>0.95 for a 95 % interval.</summary>
        public double ConfidenceLevel { get; }
        /// <summary>The t quantile used: t(1 − α/2, n − 1).</summary>
        public double TCritical { get; }
        public double ConfidenceLow { get; }
        public double ConfidenceHigh { get; }

        SummaryStatistics(int n, double mean, double sd, double median, double min, double max, double confidence, double tCritical)
        {
            N = n;
            Mean = mean;
            StandardDeviation = sd;
            StandardError = n > 1 ? sd / Math.Sqrt(n) : double.NaN;
            Median = median;
            Min = min;
            Max = max;
            ConfidenceLevel = confidence;
            TCritical = tCritical;
            ConfidenceLow = mean - tCritical * StandardError;
            ConfidenceHigh = mean + tCritical * StandardError;
        }

        /// <summary>Statistics of <paramref name="values"/> (all finite) with a <paramref name="confidence"/> interval.</summary>
        public static SummaryStatistics Compute(IEnumerable<double> values, double confidence = 0.95)
        {
            if (values == null) throw new ArgumentNullException(nameof(values));
            if (!(confidence > 0 && confidence < 1)) throw new ArgumentOutOfRangeException(nameof(confidence), confidence, "confidence must be in (0, 1)");
            var sorted = new List<double>(values);
            foreach (double v in sorted)
                if (double.IsNaN(v) || double.IsInfinity(v)) throw new ArgumentException("values must be finite", nameof(values));
            sorted.Sort();
            int n = sorted.Count;
            if (n == 0) return new SummaryStatistics(0, double.NaN, double.NaN, double.NaN, double.NaN, double.NaN, confidence, double.NaN);

            double sum = 0;
            foreach (double v in sorted) sum += v;
            double mean = sum / n;

            double median = n % 2 == 1 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
            if (n == 1) return new SummaryStatistics(1, mean, double.NaN, median, sorted[0], sorted[0], confidence, double.NaN);

            double squares = 0; // two passes: no cancellation from Σx² − n·mean²
            foreach (double v in sorted) squares += (v - mean) * (v - mean);
            double sd = Math.Sqrt(squares / (n - 1));
            double t = StudentT.TwoSidedCritical(confidence, n - 1);
            return new SummaryStatistics(n, mean, sd, median, sorted[0], sorted[n - 1], confidence, t);
        }

        /// <summary>The statistics of the complete scores among <paramref name="scores"/>; incomplete parts are left out.</summary>
        public static SummaryStatistics OfScores(IEnumerable<ParticipantScore> scores, double confidence = 0.95)
        {
            if (scores == null) throw new ArgumentNullException(nameof(scores));
            var values = new List<double>();
            foreach (var s in scores)
                if (s.Score.HasValue) values.Add(s.Score.Value);
            return Compute(values, confidence);
        }
    }
}
