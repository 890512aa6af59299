using System;
using System.Collections.Generic;

namespace Kosmos.PseudoHaptic.Evaluation
{
    /// <summary>
    /// Two conditions compared within participants, on the differences d = b − a (Student 1908; Wilcoxon
    /// 1945; the formulas as R's t.test(paired = TRUE) and wilcox.test(paired = TRUE, correct = TRUE) compute
    /// them). Undefined figures are NaN (the CLI writes them empty): the t test needs n ≥ 2 differences that
    /// vary; the Wilcoxon test needs at least one non-zero difference.
    /// <list type="bullet">
    /// <item>Paired t: t = d̄ / (s_d/√n), ν = n − 1, two-sided p = 2·P(T_ν &gt; |t|); 95 % interval d̄ ± t(0.975, ν)·s_d/√n;
    /// d_z = d̄ / s_d.</item>
    /// <item>Wilcoxon signed-rank: zero differences dropped (N non-zero left), |d| ranked with average ranks for ties
    /// (|d| within <see cref="TieResolution"/> of each other tied, within it of 0 zero: equal up to the subtraction's rounding),
    /// W = the sum of the ranks of the positive differences. Exact two-sided p (the distribution of W over the
    /// 2^N sign patterns) when N ≤ 25 and no |d| are tied: p = min(1, 2·min(P(W ≤ w), P(W ≥ w))). Otherwise the
    /// normal approximation Z = (W − N(N+1)/4 − ½·sign(W − N(N+1)/4)) / √(N(N+1)(2N+1)/24 − Σ(t³ − t)/48)
    /// (t the sizes of the tie groups), p = 2·min(Φ(Z), 1 − Φ(Z)). r = Z/√N with that Z in both cases.</item>
    /// </list>
    /// </summary>
    public sealed class PairedComparison
    {
        public const int ExactUpTo = 25;

        /// <summary>Pairs used (participants with both values).</summary>
        public int N { get; }
        public double MeanDifference { get; }
        public double DifferenceLow { get; }
        public double DifferenceHigh { get; }
        public double T { get; }
        public double TP { get; }
        public double Dz { get; }
        /// <summary>Sum of the ranks of the positive differences.</summary>
        public double W { get; }
        public double WP { get; }
        /// <summary>The normal approximation's statistic with tie and continuity correction.</summary>
        public double Z { get; }
        public double R { get; }
        /// <summary>Non-zero differences.</summary>
        public int NonZero { get; }
        public bool HasTies { get; }
        public bool WilcoxonExact { get; }

        PairedComparison(int n, double mean, double lo, double hi, double t, double tp, double dz, double w, double wp, double z, double r, int nonZero, bool ties, bool exact)
        {
            N = n; MeanDifference = mean; DifferenceLow = lo; DifferenceHigh = hi; T = t; TP = tp; Dz = dz;
            W = w; WP = wp; Z = z; R = r; NonZero = nonZero; HasTies = ties; WilcoxonExact = exact;
        }

        /// <summary>Compares <paramref name="b"/> with <paramref name="a"/>, pairwise (same index = same participant).</summary>
        public static PairedComparison Compute(IReadOnlyList<double> a, IReadOnlyList<double> b, double confidence = 0.95)
        {
            if (a == null) throw new ArgumentNullException(nameof(a));
            if (b == null) throw new ArgumentNullException(nameof(b));
            if (a.Count != b.Count) throw new ArgumentException("a and b differ in length");
            int n = a.Count;
            var d = new double[n];
            for (int i = 0; i < n; i++)
            {
                d[i] = b[i] - a[i];
                if (double.IsNaN(d[i]) || double.IsInfinity(d[i])) throw new ArgumentException("values must be finite");
            }

            double mean = double.NaN, lo = double.NaN, hi = double.NaN, t = double.NaN, tp = double.NaN, dz = double.NaN;
            if (n >= 1)
            {
                double sum = 0;
                foreach (double v in d) sum += v;
                mean = sum / n;
            }
            if (n >= 2)
            {
                double ss = 0;
                foreach (double v in d) ss += (v - mean) * (v - mean);
                double sd = Math.Sqrt(ss / (n - 1));
                // Differences that are all equal (up to rounding) leave the t test undefined, as in R.
                if (sd > 1e-12 * Math.Max(1, Math.Abs(mean)))
                {
                    double se = sd / Math.Sqrt(n);
                    t = mean / se;
                    tp = Math.Min(1, 2 * StudentT.Cdf(-Math.Abs(t), n - 1));
                    double crit = StudentT.TwoSidedCritical(confidence, n - 1);
                    lo = mean - crit * se;
                    hi = mean + crit * se;
                    dz = mean / sd;
                }
            }

            // Wilcoxon signed-rank. Differences equal up to the subtraction's rounding are equal: scores given to a decimal
            // come out of b − a a few units in the last place apart (3.4 − 3.2 and 3.6 − 3.4 differ in binary), and a tie
            // or a zero is the data's, not the arithmetic's.
            double resolution = TieResolution(a, b);
            var nonZero = new List<double>();
            foreach (double v in d) if (Math.Abs(v) > resolution) nonZero.Add(v);
            int m = nonZero.Count;
            double w = double.NaN, wp = double.NaN, z = double.NaN, r = double.NaN;
            bool ties = false, exact = false;
            if (m >= 1)
            {
                var abs = new double[m];
                for (int i = 0; i < m; i++) abs[i] = Math.Abs(nonZero[i]);
                double tieSum;
                double[] ranks = Ranks.Average(abs, resolution, out tieSum);
                ties = tieSum > 0;
                w = 0;
                for (int i = 0; i < m; i++) if (nonZero[i] > 0) w += ranks[i];
                double expected = m * (m + 1) / 4.0;
                double variance = m * (m + 1) * (2.0 * m + 1) / 24.0 - tieSum / 48.0;
                if (variance > 0)
                {
                    double centred = w - expected;
                    double correction = centred > 0 ? 0.5 : centred < 0 ? -0.5 : 0;
                    z = (centred - correction) / Math.Sqrt(variance);
                    r = z / Math.Sqrt(m);
                }
                if (m <= ExactUpTo && !ties)
                {
                    exact = true;
                    wp = SignedRankExactTwoSided((int)Math.Round(w), m);
                }
                else if (!double.IsNaN(z))
                {
                    wp = Math.Min(1, 2 * Math.Min(Normal.Cdf(z), Normal.UpperTail(z)));
                }
            }
            return new PairedComparison(n, mean, lo, hi, t, tp, dz, w, wp, z, r, m, ties, exact);
        }

        /// <summary>
        /// Differences closer than this are equal, and one this small is zero: 10⁻¹² of the largest |value|, thousands of
        /// units in the last place of a difference (whose rounding is a few) and far below any difference a scale records.
        /// </summary>
        public static double TieResolution(IReadOnlyList<double> a, IReadOnlyList<double> b)
        {
            double scale = 0;
            for (int i = 0; i < a.Count; i++) scale = Math.Max(scale, Math.Max(Math.Abs(a[i]), Math.Abs(b[i])));
            return 1e-12 * scale;
        }

        /// <summary>min(1, 2·min(P(W ≤ w), P(W ≥ w))) under H0 for N = <paramref name="n"/> untied ranks.</summary>
        public static double SignedRankExactTwoSided(int w, int n)
        {
            double[] counts = SignedRankCounts(n);
            double total = Math.Pow(2, n);
            double below = 0, above = 0;
            for (int s = 0; s < counts.Length; s++)
            {
                if (s <= w) below += counts[s];
                if (s >= w) above += counts[s];
            }
            return Math.Min(1, 2 * Math.Min(below, above) / total);
        }

        /// <summary>counts[s] = the number of subsets of {1 … n} whose sum is s (exact in a double up to n = 60).</summary>
        static double[] SignedRankCounts(int n)
        {
            int max = n * (n + 1) / 2;
            var counts = new double[max + 1];
            counts[0] = 1;
            for (int rank = 1; rank <= n; rank++)
                for (int s = max; s >= rank; s--) counts[s] += counts[s - rank];
            return counts;
        }
    }

    /// <summary>Average ranks (ties share the mean of the ranks they span).</summary>
    public static class Ranks
    {
        /// <summary>Ranks 1 … n of <paramref name="values"/>; <paramref name="tieSum"/> = Σ(t³ − t) over tie groups.</summary>
        public static double[] Average(IReadOnlyList<double> values, out double tieSum) => Average(values, 0, out tieSum);

        /// <summary>
        /// As <see cref="Average(IReadOnlyList{double}, out double)"/>, values within <paramref name="resolution"/> of the
        /// smallest of their group tied (in ascending order, a group takes each next value within that distance of its first).
        /// </summary>
        public static double[] Average(IReadOnlyList<double> values, double resolution, out double tieSum)
        {
            int n = values.Count;
            var order = new int[n];
            for (int i = 0; i < n; i++) order[i] = i;
            var keys = new double[n];
            for (int i = 0; i < n; i++) keys[i] = values[i];
            Array.Sort(keys, order);
            var ranks = new double[n];
            tieSum = 0;
            int start = 0;
            while (start < n)
            {
                int end = start;
                while (end + 1 < n && (keys[end + 1] == keys[start] || keys[end + 1] - keys[start] <= resolution)) end++;
                double rank = (start + end) / 2.0 + 1;
                for (int i = start; i <= end; i++) ranks[order[i]] = rank;
                double t = end - start + 1;
                tieSum += t * t * t - t;
                start = end + 1;
            }
            return ranks;
        }
    }

    /// <summary>
    /// Friedman's test of k ≥ 2 related conditions over n complete participants (Friedman 1937), with the tie
    /// correction as R's friedman.test: each participant's values ranked 1 … k (average ranks for ties),
    /// R_j the rank sum of condition j,
    /// χ²_F = 12·Σ_j (R_j − n(k+1)/2)² / (n·k·(k+1) − Σ(t³ − t)/(k − 1)),
    /// p = P(χ²_{k−1} &gt; χ²_F). NaN when n = 0 or every participant's values are all tied.
    /// </summary>
    public sealed class FriedmanTest
    {
        public int N { get; }
        public int K { get; }
        public double Statistic { get; }
        public int DegreesOfFreedom => K - 1;
        public double P { get; }

        FriedmanTest(int n, int k, double statistic, double p)
        {
            N = n; K = k; Statistic = statistic; P = p;
        }

        /// <summary><paramref name="rows"/>[participant][condition]; every row has the same k ≥ 2 finite values.</summary>
        public static FriedmanTest Compute(IReadOnlyList<IReadOnlyList<double>> rows)
        {
            if (rows == null) throw new ArgumentNullException(nameof(rows));
            return Compute(rows, rows.Count > 0 ? rows[0].Count : 0);
        }

        /// <summary>As <see cref="Compute(IReadOnlyList{IReadOnlyList{double}})"/> for k conditions, also when there are no rows.</summary>
        public static FriedmanTest Compute(IReadOnlyList<IReadOnlyList<double>> rows, int k)
        {
            if (rows == null) throw new ArgumentNullException(nameof(rows));
            int n = rows.Count;
            if (n == 0) return new FriedmanTest(0, k, double.NaN, double.NaN);
            if (k < 2) throw new ArgumentException("need at least two conditions", nameof(rows));
            var rankSums = new double[k];
            double ties = 0;
            foreach (var row in rows)
            {
                if (row.Count != k) throw new ArgumentException("rows differ in length", nameof(rows));
                double t;
                double[] r = Ranks.Average(row, out t);
                ties += t;
                for (int j = 0; j < k; j++) rankSums[j] += r[j];
            }
            double expected = n * (k + 1) / 2.0;
            double num = 0;
            for (int j = 0; j < k; j++) num += (rankSums[j] - expected) * (rankSums[j] - expected);
            double denominator = n * k * (k + 1.0) - ties / (k - 1);
            if (!(denominator > 0)) return new FriedmanTest(n, k, double.NaN, double.NaN);
            double statistic = 12 * num / denominator;
            return new FriedmanTest(n, k, statistic, ChiSquare.UpperTail(statistic, k - 1));
        }
    }

    /// <summary>Holm's step-down correction (Holm 1979): p_(i) → max_{j ≤ i} min(1, (m − j + 1)·p_(j)); NaN stays NaN and is not counted in m.</summary>
    public static class Holm
    {
        public static double[] Adjust(IReadOnlyList<double> p)
        {
            if (p == null) throw new ArgumentNullException(nameof(p));
            var index = new List<int>();
            for (int i = 0; i < p.Count; i++) if (!double.IsNaN(p[i])) index.Add(i);
            index.Sort((x, y) => p[x] != p[y] ? p[x].CompareTo(p[y]) : x.CompareTo(y));
            var adjusted = new double[p.Count];
            for (int i = 0; i < p.Count; i++) adjusted[i] = double.NaN;
            int m = index.Count;
            double running = 0;
            for (int j = 0; j < m; j++)
            {
                double value = Math.Min(1, (m - j) * p[index[j]]);
                running = Math.Max(running, value);
                adjusted[index[j]] = running;
            }
            return adjusted;
        }
    }
}
