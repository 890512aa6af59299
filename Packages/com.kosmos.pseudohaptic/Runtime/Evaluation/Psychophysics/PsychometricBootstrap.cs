using System;
using System.Collections.Generic;

namespace Kosmos.PseudoHaptic.Evaluation
{
    /// <summary>
    /// 95 % (or other) intervals of the PSE and JND by a seeded parametric bootstrap (Efron and Tibshirani
    /// 1993; Wichmann and Hill 2001b): each resample draws, at every level, Binomial(n, Ψ̂(x)) answers from the
    /// fitted function, is fitted again the same way, and the intervals are the percentiles of the refitted
    /// PSEs and JNDs (R's quantile type 7, linear between order statistics). Resamples that cannot be fitted
    /// (all answers alike, perfect separation) are left out and counted in <see cref="Failed"/>. The same
    /// seed gives the same numbers on every runtime (<see cref="SeededRandom"/>).
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

        PsychometricBootstrap(int resamples, int failed, double pl, double ph, double jl, double jh)
        {
            Resamples = resamples;
            Failed = failed;
            PseLow = pl; PseHigh = ph; JndLow = jl; JndHigh = jh;
            HasIntervals = !double.IsNaN(pl);
        }

        public static PsychometricBootstrap Run(PsychometricFit fit, int resamples, long seed, double confidence = 0.95)
        {
            if (fit == null) throw new ArgumentNullException(nameof(fit));
            if (resamples < 0) throw new ArgumentOutOfRangeException(nameof(resamples), resamples, "must be ≥ 0");
            if (!(confidence > 0 && confidence < 1)) throw new ArgumentOutOfRangeException(nameof(confidence), confidence, "must be in (0, 1)");
            if (!fit.Estimable) return new PsychometricBootstrap(resamples, resamples, double.NaN, double.NaN, double.NaN, double.NaN);

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
            if (pses.Count < 2) return new PsychometricBootstrap(resamples, failed, double.NaN, double.NaN, double.NaN, double.NaN);
            pses.Sort();
            jnds.Sort();
            double alpha = (1 - confidence) / 2;
            return new PsychometricBootstrap(resamples, failed,
                Percentile(pses, alpha), Percentile(pses, 1 - alpha), Percentile(jnds, alpha), Percentile(jnds, 1 - alpha));
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
