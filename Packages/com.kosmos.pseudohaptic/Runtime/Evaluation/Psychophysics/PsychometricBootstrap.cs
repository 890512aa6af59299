using System;
using System.Collections.Generic;

namespace Kosmos.PseudoHaptic.Evaluation
{
    /// <summary>
    /// 95 % (or other) intervals of the PSE and JND by a seeded parametric bootstrap (Efron and Tibshirani
    /// 1993; Wichmann and Hill 2001b): each resample draws, at every level, Binomial(n, Ψ̂(x)) answers from the
    /// fitted function and is fitted again the same way. The intervals are, by default, the bias-corrected and accelerated
    /// (BCa) percentiles of the refitted PSEs and JNDs (<see cref="BootstrapInterval.Bca"/>), or their plain percentiles
    /// (<see cref="BootstrapInterval.Percentile"/>); either way R's quantile type 7, linear between order statistics.
    /// Resamples that cannot be fitted (all answers alike, perfect separation) are left out and counted in
    /// <see cref="Failed"/>. The same seed gives the same numbers on every runtime (<see cref="SeededRandom"/>).
    /// </summary>
    public sealed class PsychometricBootstrap
    {
        public int Resamples { get; }
        /// <summary>Resamples left out because they could not be fitted.</summary>
        public int Failed { get; }
        public double PseLow { get; }
        public double PseHigh { get; }
        public double JndLow { get; }
        public double JndHigh { get; }
        /// <summary>True when at least two resamples could be fitted, so that the intervals are numbers.</summary>
        public bool HasIntervals { get; }
        /// <summary>How the intervals were made from the refitted values.</summary>
        public BootstrapInterval Interval { get; }

        PsychometricBootstrap(BootstrapInterval interval, int resamples, int failed, double pl, double ph, double jl, double jh)
        {
            Interval = interval;
            Resamples = resamples;
            Failed = failed;
            PseLow = pl; PseHigh = ph; JndLow = jl; JndHigh = jh;
            HasIntervals = !double.IsNaN(pl);
        }

        /// <summary>The bootstrap with BCa intervals (<see cref="BootstrapInterval.Bca"/>).</summary>
        public static PsychometricBootstrap Run(PsychometricFit fit, int resamples, long seed, double confidence = 0.95)
            => Run(fit, resamples, seed, confidence, BootstrapInterval.Bca);

        /// <summary>The bootstrap with intervals made as <paramref name="interval"/> says. The resamples, and so
        /// <see cref="Failed"/>, are the same for both kinds of interval at one seed.</summary>
        public static PsychometricBootstrap Run(PsychometricFit fit, int resamples, long seed, double confidence, BootstrapInterval interval)
        {
            if (fit == null) throw new ArgumentNullException(nameof(fit));
            if (resamples < 0) throw new ArgumentOutOfRangeException(nameof(resamples), resamples, "must be ≥ 0");
            if (!(confidence > 0 && confidence < 1)) throw new ArgumentOutOfRangeException(nameof(confidence), confidence, "must be in (0, 1)");
            if (interval != BootstrapInterval.Bca && interval != BootstrapInterval.Percentile)
                throw new ArgumentOutOfRangeException(nameof(interval), interval, "must be Bca or Percentile");
            if (!fit.Estimable) return new PsychometricBootstrap(interval, resamples, resamples, double.NaN, double.NaN, double.NaN, double.NaN);

            var rng = new SeededRandom(seed);
            var levels = fit.Levels;
            var p = new double[levels.Count];
            for (int i = 0; i < p.Length; i++) p[i] = fit.Psi(levels[i].Level);
            var resample = new StimulusLevel[levels.Count];
            var pses = new List<double>(resamples);
            var jnds = new List<double>(resamples);
            for (int r = 0; r < resamples; r++)
            {
                for (int i = 0; i < p.Length; i++)
                    resample[i] = new StimulusLevel(levels[i].Level, levels[i].Trials, rng.NextBinomial(levels[i].Trials, p[i]));
                var refit = PsychometricFit.Fit(resample, fit.Lapse, fit.Mu, fit.Sigma);
                if (!refit.Estimable) continue;
                pses.Add(refit.Pse);
                jnds.Add(refit.Jnd);
            }
            int failed = resamples - pses.Count;
            if (pses.Count < 2) return new PsychometricBootstrap(interval, resamples, failed, double.NaN, double.NaN, double.NaN, double.NaN);
            pses.Sort();
            jnds.Sort();
            double alpha = (1 - confidence) / 2;
            if (interval == BootstrapInterval.Percentile)
                return new PsychometricBootstrap(interval, resamples, failed,
                    Percentile(pses, alpha), Percentile(pses, 1 - alpha), Percentile(jnds, alpha), Percentile(jnds, 1 - alpha));
            double aPse, aJnd;
            Acceleration(fit, out aPse, out aJnd);
            double zPse = BiasCorrection(pses, fit.Pse), zJnd = BiasCorrection(jnds, fit.Jnd);
            double zLow = Normal.Quantile(alpha), zHigh = Normal.Quantile(1 - alpha);
            return new PsychometricBootstrap(interval, resamples, failed,
                Percentile(pses, BcaLevel(zPse, aPse, zLow)), Percentile(pses, BcaLevel(zPse, aPse, zHigh)),
                Percentile(jnds, BcaLevel(zJnd, aJnd, zLow)), Percentile(jnds, BcaLevel(zJnd, aJnd, zHigh)));
        }

        /// <summary>
        /// The bias correction z₀ = Φ⁻¹(share of <paramref name="sorted"/> below <paramref name="estimate"/>, ties counting
        /// half) (Efron and Tibshirani 1993, eq. 14.14). The share is kept within half a value of 0 and 1, so that z₀ is finite
        /// even when every refitted value lies on one side of the fit.
        /// </summary>
        public static double BiasCorrection(IReadOnlyList<double> sorted, double estimate)
        {
            if (sorted == null || sorted.Count == 0) throw new ArgumentException("no values", nameof(sorted));
            double below = 0;
            for (int i = 0; i < sorted.Count; i++)
            {
                if (sorted[i] < estimate) below++;
                else if (sorted[i] == estimate) below += 0.5;
            }
            double n = sorted.Count, share = below / n;
            if (share < 0.5 / n) share = 0.5 / n;
            if (share > 1 - 0.5 / n) share = 1 - 0.5 / n;
            return Normal.Quantile(share);
        }

        /// <summary>
        /// The BCa level for the normal quantile <paramref name="z"/>: Φ(z₀ + (z₀ + z) / (1 − a(z₀ + z))) (Efron and Tibshirani
        /// 1993, eq. 14.10). Where 1 − a(z₀ + z) ≤ 0 the level has run off its end: 1 above, 0 below (the extreme refitted value).
        /// z₀ = a = 0 gives Φ(z), the plain percentile.
        /// </summary>
        public static double BcaLevel(double z0, double a, double z)
        {
            double w = z0 + z, d = 1 - a * w;
            if (!(d > 0)) return w > 0 ? 1 : 0;
            return Normal.Cdf(z0 + w / d);
        }

        /// <summary>
        /// The acceleration a = Σ (θ̄ − θ₍ᵢ₎)³ / (6 [Σ (θ̄ − θ₍ᵢ₎)²]^{3/2}) of PSE and JND from the jackknife over trials (Efron and
        /// Tibshirani 1993, eq. 14.15): the fit again without one trial, for each trial. Trials at one level with one answer
        /// are alike, so each level needs two fits (without one "heavier" answer, without one "lighter"), weighted by how
        /// many trials each stands for. A fit that cannot be made without the trial (a separation) is left out; with fewer
        /// than two left, or no spread, a is 0.
        /// </summary>
        internal static void Acceleration(PsychometricFit fit, out double aPse, out double aJnd)
        {
            var levels = fit.Levels;
            var without = new StimulusLevel[levels.Count];
            var weight = new List<double>(2 * levels.Count);
            var pse = new List<double>(2 * levels.Count);
            var jnd = new List<double>(2 * levels.Count);
            for (int i = 0; i < levels.Count; i++)
            {
                for (int heavier = 0; heavier <= 1; heavier++)
                {
                    int count = heavier == 1 ? levels[i].Heavier : levels[i].Trials - levels[i].Heavier;
                    if (count == 0) continue;
                    for (int j = 0; j < levels.Count; j++)
                        without[j] = j != i ? levels[j] : new StimulusLevel(levels[j].Level, levels[j].Trials - 1, levels[j].Heavier - heavier);
                    var refit = PsychometricFit.Fit(without, fit.Lapse, fit.Mu, fit.Sigma);
                    if (!refit.Estimable) continue;
                    weight.Add(count);
                    pse.Add(refit.Pse);
                    jnd.Add(refit.Jnd);
                }
            }
            aPse = JackknifeSkew(weight, pse);
            aJnd = JackknifeSkew(weight, jnd);
        }

        static double JackknifeSkew(List<double> weight, List<double> values)
        {
            if (values.Count < 2) return 0;
            double total = 0, sum = 0;
            for (int i = 0; i < values.Count; i++) { total += weight[i]; sum += weight[i] * values[i]; }
            double mean = sum / total, squares = 0, cubes = 0;
            for (int i = 0; i < values.Count; i++)
            {
                double d = mean - values[i];
                squares += weight[i] * d * d;
                cubes += weight[i] * d * d * d;
            }
            double a = cubes / (6 * Math.Pow(squares, 1.5));
            return squares > 0 && !double.IsNaN(a) && !double.IsInfinity(a) ? a : 0;
        }

        /// <summary>Quantile of sorted values, type 7: h = (n − 1)p, linear between the neighbours.</summary>
        public static double Percentile(IReadOnlyList<double> sorted, double p)
        {
            if (sorted == null || sorted.Count == 0) throw new ArgumentException("no values", nameof(sorted));
            double h = (sorted.Count - 1) * p;
            int lo = (int)Math.Floor(h);
            if (lo >= sorted.Count - 1) return sorted[sorted.Count - 1];
            return sorted[lo] + (h - lo) * (sorted[lo + 1] - sorted[lo]);
        }
    }

    /// <summary>The Wilson score interval of a binomial proportion (Wilson 1927; Brown, Cai and DasGupta 2001).</summary>
    public static class WilsonInterval
    {
        /// <summary>(low, high) for <paramref name="successes"/> of <paramref name="trials"/> at <paramref name="confidence"/>.</summary>
        public static void Compute(int successes, int trials, double confidence, out double low, out double high)
        {
            if (trials <= 0 || successes < 0 || successes > trials) throw new ArgumentOutOfRangeException(nameof(trials), trials, "need 0 ≤ successes ≤ trials, trials > 0");
            double z = Normal.Quantile(1 - (1 - confidence) / 2);
            double n = trials, phat = successes / n, z2 = z * z;
            double denominator = 1 + z2 / n;
            double centre = (phat + z2 / (2 * n)) / denominator;
            double half = z / denominator * Math.Sqrt(phat * (1 - phat) / n + z2 / (4 * n * n));
            low = successes == 0 ? 0 : Math.Max(0, centre - half);
            high = successes == trials ? 1 : Math.Min(1, centre + half);
        }
    }
}
