using System;
using System.Collections.Generic;

namespace Kosmos.PseudoHaptic.Evaluation
{
    /// <summary>The answers at one comparison level: <see cref="Trials"/> trials, <see cref="Heavier"/> of them "heavier".</summary>
    public readonly struct StimulusLevel
    {
        public double Level { get; }
        public int Trials { get; }
        public int Heavier { get; }
        public double Proportion => Trials > 0 ? (double)Heavier / Trials : 0;

        public StimulusLevel(double level, int trials, int heavier)
        {
            if (double.IsNaN(level) || double.IsInfinity(level)) throw new ArgumentException("level must be finite", nameof(level));
            if (trials < 0 || heavier < 0 || heavier > trials) throw new ArgumentOutOfRangeException(nameof(heavier), heavier, "need 0 ≤ heavier ≤ trials");
            Level = level;
            Trials = trials;
            Heavier = heavier;
        }

        /// <summary>Binary answers grouped by level (exactly equal levels together), ascending.</summary>
        public static StimulusLevel[] Group(IReadOnlyList<double> levels, IReadOnlyList<int> responses)
        {
            if (levels == null) throw new ArgumentNullException(nameof(levels));
            if (responses == null) throw new ArgumentNullException(nameof(responses));
            if (levels.Count != responses.Count) throw new ArgumentException("levels and responses differ in length");
            var n = new SortedDictionary<double, int>();
            var k = new Dictionary<double, int>();
            for (int i = 0; i < levels.Count; i++)
            {
                if (responses[i] != 0 && responses[i] != 1) throw new ArgumentException("responses must be 0 or 1", nameof(responses));
                double x = levels[i] == 0 ? 0 : levels[i]; // −0 and 0 are one level
                int c;
                n.TryGetValue(x, out c);
                n[x] = c + 1;
                k.TryGetValue(x, out c);
                k[x] = c + responses[i];
            }
            var result = new StimulusLevel[n.Count];
            int j = 0;
            foreach (var pair in n) result[j++] = new StimulusLevel(pair.Key, pair.Value, k[pair.Key]);
            return result;
        }
    }

    /// <summary>
    /// The maximum-likelihood fit of a cumulative Gaussian psychometric function to binary answers,
    /// Ψ(x) = γ + (1 − γ − λ)·Φ((x − μ)/σ) with γ = λ = <c>lapse</c> fixed (0 by default). PSE = μ,
    /// JND = σ·Φ⁻¹(0.75), deviance = 2·Σ [k·ln(k/(n·Ψ)) + (n − k)·ln((n − k)/(n·(1 − Ψ)))] over the levels
    /// (the binomial deviance against the saturated model, as R's glm reports it for grouped data).
    /// The fit is on the probit scale, η = a + b·z with z the levels standardized, by Newton's method with
    /// Levenberg damping and step halving (the log-likelihood is concave in (a, b) when γ = λ = 0, so the
    /// maximum found is the unique one); μ = mean − sd·a/b, σ = sd/b. Data that have no finite maximum (no
    /// trials, a single level, all answers alike, levels perfectly separated by the answer, or with lapses a
    /// step between levels as likely as any σ) or a decreasing fit (with lapses also a falling step as likely as any
    /// curve) are <see cref="Estimable"/> = false with a <see cref="Reason"/>; their numbers are NaN and are never written.
    /// </summary>
    public sealed class PsychometricFit
    {
        /// <summary>Φ⁻¹(0.75): JND = σ·this.</summary>
        public static readonly double JndFactor = Normal.Quantile(0.75);

        public bool Estimable { get; }
        /// <summary>"yes" when estimable, else why not.</summary>
        public string Reason { get; }
        public double Lapse { get; }
        public int Trials { get; }
        public double Mu { get; }
        public double Sigma { get; }
        public double Pse => Mu;
        public double Jnd => Sigma * JndFactor;
        public double Deviance { get; }
        public double LogLikelihood { get; }
        public int Iterations { get; }
        public IReadOnlyList<StimulusLevel> Levels { get; }

        PsychometricFit(IReadOnlyList<StimulusLevel> levels, double lapse, int trials, string reason)
        {
            Levels = levels;
            Lapse = lapse;
            Trials = trials;
            Estimable = false;
            Reason = reason;
            Mu = Sigma = Deviance = LogLikelihood = double.NaN;
        }

        PsychometricFit(IReadOnlyList<StimulusLevel> levels, double lapse, int trials, double mu, double sigma, double deviance, double logLikelihood, int iterations)
        {
            Levels = levels;
            Lapse = lapse;
            Trials = trials;
            Estimable = true;
            Reason = "yes";
            Mu = mu;
            Sigma = sigma;
            Deviance = deviance;
            LogLikelihood = logLikelihood;
            Iterations = iterations;
        }

        /// <summary>Ψ(x) of this fit.</summary>
        public double Psi(double x) => Lapse + (1 - 2 * Lapse) * Normal.Cdf((x - Mu) / Sigma);

        public static PsychometricFit Fit(IReadOnlyList<double> levels, IReadOnlyList<int> responses, double lapse = 0)
            => Fit(StimulusLevel.Group(levels, responses), lapse);

        /// <summary>Fits <paramref name="levels"/> (any order; equal levels are merged).</summary>
        public static PsychometricFit Fit(IReadOnlyList<StimulusLevel> levels, double lapse = 0)
            => Fit(levels, lapse, null, null);

        /// <summary>As <see cref="Fit(IReadOnlyList{StimulusLevel}, double)"/> from a start (a bootstrap's original fit), and with
        /// the ascents' iterations capped at <paramref name="iterationCap"/> (below 500 only in the tests, which make every
        /// ascent fail that way).</summary>
        internal static PsychometricFit Fit(IReadOnlyList<StimulusLevel> levels, double lapse, double? startMu, double? startSigma, int iterationCap = MaxIterations)
        {
            if (levels == null) throw new ArgumentNullException(nameof(levels));
            if (!(lapse >= 0 && lapse < 0.5)) throw new ArgumentOutOfRangeException(nameof(lapse), lapse, "lapse must be in [0, 0.5)");
            var merged = Merge(levels);
            int trials = 0, heavier = 0, used = 0;
            foreach (var l in merged) { trials += l.Trials; heavier += l.Heavier; if (l.Trials > 0) used++; }
            string why = Degenerate(merged, trials, heavier, used);
            if (why != null) return new PsychometricFit(merged, lapse, trials, why);

            // Standardize the levels (trial-weighted) so that the optimisation does not depend on the unit.
            double sum = 0;
            foreach (var l in merged) sum += l.Level * l.Trials;
            double mean = sum / trials;
            double ss = 0;
            foreach (var l in merged) ss += l.Trials * (l.Level - mean) * (l.Level - mean);
            double sd = Math.Sqrt(ss / trials);
            if (!IsFinite(mean) || !IsFinite(sd) || !(sd > 0))
                return new PsychometricFit(merged, lapse, trials, "levels out of range: their spread cannot be computed in double precision");
            int m = merged.Length;
            var z = new double[m];
            var n = new int[m];
            var k = new int[m];
            for (int i = 0; i < m; i++) { z[i] = (merged[i].Level - mean) / sd; n[i] = merged[i].Trials; k[i] = merged[i].Heavier; }

            // Starts: the caller's (a bootstrap's original fit); with lapses the likeliest point of a grid, the likeliest
            // shallow curve and the likeliest peaks of a finer grid; and the plain (0, 1). The highest converged maximum
            // wins (with γ = λ = 0 there is only one).
            var starts = new List<double[]>();
            if (startMu.HasValue && startSigma.HasValue && startSigma.Value > 0 && IsFinite(startMu.Value))
                starts.Add(new[] { -(startMu.Value - mean) / startSigma.Value, sd / startSigma.Value });
            if (lapse > 0)
            {
                var grid = LikelihoodGrid(z, n, k, lapse);
                starts.Add(GridStart(z, grid));
                starts.Add(ShallowStart(z, n, k, lapse));
                foreach (var peak in PeakStarts(z, grid))
                    if (!Contains(starts, peak)) starts.Add(peak); // the coarse grid's likeliest point is often one of the peaks
            }
            starts.Add(new[] { 0.0, 1.0 });
            double a = 0, b = 1, best = double.NegativeInfinity, failed = double.NegativeInfinity;
            bool converged = false;
            int iterations = 0;
            for (int s = 0; s < starts.Count; s++)
            {
                double sa = starts[s][0], sb = starts[s][1];
                int it;
                if (!Maximize(z, n, k, lapse, ref sa, ref sb, out it, iterationCap)) { failed = Math.Max(failed, LogLik(z, n, k, lapse, sa, sb)); continue; }
                double ll = LogLik(z, n, k, lapse, sa, sb);
                // Likelier by more than the log-likelihood's rounding: two ascents that end on one maximum keep the first's.
                if (!converged || ll > best + 1e-12 * Math.Abs(best)) { a = sa; b = sb; best = ll; iterations = it; converged = true; }
                if (lapse == 0) break; // concave: the first maximum is the maximum
            }
            // With lapses the likelihood can be highest as σ → 0, at a step between two levels (Ψ = γ on one side of it,
            // 1 − γ on the other): the ascents then stop where the gradient vanishes, at a σ that says nothing, or give up
            // climbing towards it (b past 1e8). Without lapses such answers are separated, found above. The likeliest
            // explanation wins: a step, rising ("a step") or falling ("decreasing"), when one is as likely as the best point
            // found, else that point. A point where μ or σ would overflow has every η beyond ±40 (|a/b| < 4e10 otherwise,
            // and sd < 1.4e154): Ψ is γ or 1 − γ at every level, a step, never likelier than the best one. Without lapses
            // both steps are −∞ (every level but the step's own adds k·ln 0 or 0·ln 0, −∞ or NaN).
            double rise = BestStepLogLik(merged, lapse, true);
            double fall = BestStepLogLik(merged, lapse, false);
            string stepReason = rise >= fall ? StepReason : DecreasingReason;
            double step = Math.Max(rise, fall);
            if (!converged)
                return new PsychometricFit(merged, lapse, trials, lapse > 0 && step >= failed - StepTolerance ? stepReason : "the fit did not converge");
            double logLik = LogLik(z, n, k, lapse, a, b);
            if (step >= logLik - StepTolerance) return new PsychometricFit(merged, lapse, trials, stepReason);
            // b is in units of the standardized levels, so 1e-9 means a σ a billion times their spread.
            if (Math.Abs(b) < 1e-9) return new PsychometricFit(merged, lapse, trials, "flat: the answers do not change with the comparison (σ infinite)");
            if (!(b > 0)) return new PsychometricFit(merged, lapse, trials, DecreasingReason);
            double mu = mean - sd * a / b;
            double sigma = sd / b;

            double deviance = 0;
            for (int i = 0; i < m; i++)
            {
                double eta = a + b * z[i];
                double p = lapse + (1 - 2 * lapse) * Normal.Cdf(eta);
                double q = lapse + (1 - 2 * lapse) * Normal.UpperTail(eta);
                if (k[i] > 0) deviance += k[i] * Math.Log(k[i] / (n[i] * p));
                if (n[i] - k[i] > 0) deviance += (n[i] - k[i]) * Math.Log((n[i] - k[i]) / (n[i] * q));
            }
            deviance = Math.Max(0, 2 * deviance);
            return new PsychometricFit(merged, lapse, trials, mu, sigma, deviance, logLik, iterations);
        }

        static bool IsFinite(double v) => !double.IsNaN(v) && !double.IsInfinity(v);

        static bool Contains(List<double[]> starts, double[] start)
        {
            foreach (var s in starts) if (s[0] == start[0] && s[1] == start[1]) return true;
            return false;
        }

        /// <summary>
        /// The likeliest (a, b) of a coarse grid: μ at each level and halfway between neighbours, b = ±(0.5, 1, 2, … 32), σ
        /// from 2 to 1/32 of the levels' spread (rising, then falling; the first of equals). Its points are the finer grid's
        /// (<paramref name="grid"/>, from <see cref="LikelihoodGrid"/>) at every other centre and every other slope, read
        /// from it rather than computed again.
        /// With lapses the likelihood can have several maxima (an outlying level that the lapse explains, a steep rise a
        /// shallow curve smooths over, a fall against a rise in answers that barely change), and the ascent from (0, 1)
        /// can end at a lesser one.
        /// </summary>
        internal static double[] GridStart(double[] z, double[,,] grid)
        {
            double bestA = 0, bestB = 1, best = double.NegativeInfinity;
            for (int c = 0; c < 2 * z.Length - 1; c++)
                for (int s = 0; s < 2; s++)
                    for (int j = 0; j < PeakSlopes.Length; j += 2)
                    {
                        double ll = grid[s, 2 * c, j];
                        if (ll > best) { best = ll; bestB = (s == 0 ? 1 : -1) * PeakSlopes[j]; bestA = -bestB * PeakCentre(z, 2 * c); }
                    }
            return new[] { bestA, bestB };
        }

        /// <summary>The finer grid's slopes |b|: σ from 2 to 1/32 of the levels' spread in steps of √2 (every other one a
        /// power of two: the coarse grid's).</summary>
        static readonly double[] PeakSlopes = { 0.5, 0.5 * Math.Sqrt(2), 1, Math.Sqrt(2), 2, 2 * Math.Sqrt(2), 4, 4 * Math.Sqrt(2), 8, 8 * Math.Sqrt(2), 16, 16 * Math.Sqrt(2), 32 };

        /// <summary>How many of the finer grid's peaks start an ascent.</summary>
        internal const int PeakStartCount = 4;

        /// <summary>The log-likelihood on the finer grid, [rising 0 or falling 1, centre, slope]: μ at each level and a
        /// quarter, half and three quarters of the way to the next (<see cref="PeakCentre"/>), b = ±<see cref="PeakSlopes"/>.
        /// Computed once for both the coarse grid's start and the peaks.</summary>
        internal static double[,,] LikelihoodGrid(double[] z, int[] n, int[] k, double lapse)
        {
            int centres = 4 * (z.Length - 1) + 1, slopes = PeakSlopes.Length;
            var ll = new double[2, centres, slopes];
            for (int s = 0; s < 2; s++)
                for (int c = 0; c < centres; c++)
                    for (int j = 0; j < slopes; j++)
                    {
                        double b = (s == 0 ? 1 : -1) * PeakSlopes[j];
                        ll[s, c, j] = LogLik(z, n, k, lapse, -b * PeakCentre(z, c), b);
                    }
            return ll;
        }

        /// <summary>
        /// The <see cref="PeakStartCount"/> likeliest peaks of the finer grid (<paramref name="ll"/>, from
        /// <see cref="LikelihoodGrid"/>; the steepest slope only as a neighbour): points likelier
        /// by <see cref="PeakMargin"/> than each neighbour one step away in μ, in slope or both, likeliest first (the first
        /// of equals). Each peak is the top of a hill of the likelihood the grid saw, and its ascent climbs that hill: the
        /// likeliest point of a grid can lie on the flank of a broad hill whose top is lower than a narrow one's (a steep
        /// rise between two levels that a shallow curve also explains).
        /// </summary>
        internal static List<double[]> PeakStarts(double[] z, double[,,] ll)
        {
            int centres = ll.GetLength(1), slopes = ll.GetLength(2);
            var best = new double[PeakStartCount];
            var found = new double[PeakStartCount][];
            int count = 0;
            for (int s = 0; s < 2; s++)
                for (int c = 0; c < centres; c++)
                    for (int j = 0; j < slopes - 1; j++) // a peak at the steepest slope is a step's hill (BestStepLogLik)
                    {
                        double v = ll[s, c, j];
                        if (double.IsNegativeInfinity(v) || !IsPeak(ll, s, c, j)) continue;
                        // Insert into the likeliest so far, after its equals.
                        int at = count;
                        while (at > 0 && v > best[at - 1]) at--;
                        if (at >= PeakStartCount) continue;
                        for (int i = Math.Min(count, PeakStartCount - 1); i > at; i--) { best[i] = best[i - 1]; found[i] = found[i - 1]; }
                        double b = (s == 0 ? 1 : -1) * PeakSlopes[j];
                        best[at] = v;
                        found[at] = new[] { -b * PeakCentre(z, c), b };
                        if (count < PeakStartCount) count++;
                    }
            var result = new List<double[]>(count);
            for (int i = 0; i < count; i++) result.Add(found[i]);
            return result;
        }

        /// <summary>The finer grid's centre c: level c/4, or a quarter, half or three quarters of the way to the next (the
        /// halfway point computed as the coarse grid computes it, so that their common points are equal).</summary>
        static double PeakCentre(double[] z, int c)
        {
            int i = c / 4, q = c % 4;
            if (q == 0) return z[i];
            if (q == 2) return 0.5 * (z[i] + z[i + 1]);
            return z[i] + 0.25 * q * (z[i + 1] - z[i]);
        }

        /// <summary>How much likelier than each neighbour a peak is, at least: where a steep curve has saturated (Φ rounds to 0 or
        /// 1 at every level but one) neighbours are equal to rounding, a step's plateau, not a hill (BestStepLogLik).</summary>
        const double PeakMargin = 1e-9;

        static bool IsPeak(double[,,] ll, int s, int c, int j)
        {
            double v = ll[s, c, j];
            for (int dc = -1; dc <= 1; dc++)
                for (int dj = -1; dj <= 1; dj++)
                {
                    int c2 = c + dc, j2 = j + dj;
                    if ((dc == 0 && dj == 0) || c2 < 0 || c2 >= ll.GetLength(1) || j2 < 0 || j2 >= ll.GetLength(2)) continue;
                    if (ll[s, c2, j2] >= v - PeakMargin) return false;
                }
            return true;
        }

        /// <summary>The values of η = a + b·z at the lowest and the highest level the shallow grid tries.</summary>
        static readonly double[] ShallowEtas = { -4, -3, -2, -1.5, -1, -0.5, 0, 0.5, 1, 1.5, 2, 3, 4 };

        /// <summary>
        /// The likeliest (a, b) of a grid over what a curve does across the levels, η at the lowest and at the highest
        /// (each from <see cref="ShallowEtas"/>, the two different; the first of equals): it holds the shallow curves centred
        /// far outside the levels, which the grid of centres at the levels does not (answers that barely change across the
        /// levels, a lapse on one of them).
        /// </summary>
        internal static double[] ShallowStart(double[] z, int[] n, int[] k, double lapse)
        {
            double lo = z[0], hi = z[z.Length - 1], bestA = 0, bestB = 1, best = double.NegativeInfinity;
            foreach (double etaLo in ShallowEtas)
                foreach (double etaHi in ShallowEtas)
                {
                    if (etaLo == etaHi) continue;
                    double b = (etaHi - etaLo) / (hi - lo), a = etaLo - b * lo;
                    double ll = LogLik(z, n, k, lapse, a, b);
                    if (ll > best) { best = ll; bestA = a; bestB = b; }
                }
            return new[] { bestA, bestB };
        }

        /// <summary>The ascent's cap on iterations (the tests' longest take a few dozen).</summary>
        internal const int MaxIterations = 500;

        /// <summary>A log-likelihood ratio below which a step is as likely as the fit (1.000001 : 1: no evidence of a σ).</summary>
        const double StepTolerance = 1e-6;

        const string StepReason = "a step: with this lapse a step between levels explains the answers as well as any σ (σ → 0)";

        const string DecreasingReason = "decreasing: the comparison was judged heavier less often as it grew";

        /// <summary>
        /// The supremum of the log-likelihood as σ → 0 from above (<paramref name="rising"/>) or below: the likeliest step of
        /// height 1 − 2γ, rising (γ at the levels below it, 1 − γ above) or falling (1 − γ below, γ above), with
        /// <paramref name="levels"/> ascending and distinct. The step sits on a level, where Ψ can be anything from γ to
        /// 1 − γ (μ and σ shrinking together hold η there), best at its k/n held within those bounds; a step between two
        /// levels is the one on the upper of them with Ψ there as above it, so never likelier.
        /// </summary>
        internal static double BestStepLogLik(StimulusLevel[] levels, double lapse, bool rising)
        {
            // Ψ below the step is γ rising, 1 − γ falling; above it the other.
            double low = Math.Log(rising ? lapse : 1 - lapse), high = Math.Log(rising ? 1 - lapse : lapse);
            double best = double.NegativeInfinity;
            for (int j = 0; j < levels.Length; j++)
            {
                double ll = 0;
                for (int i = 0; i < levels.Length; i++)
                {
                    int yes = levels[i].Heavier, no = levels[i].Trials - levels[i].Heavier;
                    if (i < j) ll += yes * low + no * high;
                    else if (i > j) ll += yes * high + no * low;
                    else
                    {
                        double p = Math.Min(Math.Max(levels[i].Proportion, lapse), 1 - lapse); // γ ≤ Ψ ≤ 1 − γ: both logs finite
                        ll += yes * Math.Log(p) + no * Math.Log(1 - p);
                    }
                }
                if (ll > best) best = ll;
            }
            return best;
        }

        static StimulusLevel[] Merge(IReadOnlyList<StimulusLevel> levels)
        {
            var byLevel = new SortedDictionary<double, int[]>();
            foreach (var l in levels)
            {
                double x = l.Level == 0 ? 0 : l.Level;
                int[] c;
                if (!byLevel.TryGetValue(x, out c)) byLevel.Add(x, c = new int[2]);
                c[0] += l.Trials;
                c[1] += l.Heavier;
            }
            var result = new StimulusLevel[byLevel.Count];
            int j = 0;
            foreach (var pair in byLevel) result[j++] = new StimulusLevel(pair.Key, pair.Value[0], pair.Value[1]);
            return result;
        }

        /// <summary>Why the likelihood has no finite maximum, or null if it has one.</summary>
        internal static string Degenerate(StimulusLevel[] levels, int trials, int heavier, int used)
        {
            if (trials == 0) return "no trials";
            if (used < 2) return "a single level";
            if (heavier == 0) return "all answers the same (0)";
            if (heavier == trials) return "all answers the same (1)";
            // Separation: every "not heavier" at or below every "heavier" (or the reverse).
            double maxNo = double.NegativeInfinity, minYes = double.PositiveInfinity;
            double maxYes = double.NegativeInfinity, minNo = double.PositiveInfinity;
            foreach (var l in levels)
            {
                if (l.Heavier > 0) { minYes = Math.Min(minYes, l.Level); maxYes = Math.Max(maxYes, l.Level); }
                if (l.Trials - l.Heavier > 0) { maxNo = Math.Max(maxNo, l.Level); minNo = Math.Min(minNo, l.Level); }
            }
            if (maxNo <= minYes) return "perfect separation: every 'heavier' answer lies at or above every 'not heavier' one";
            if (maxYes <= minNo) return "perfect separation: every 'heavier' answer lies at or below every 'not heavier' one";
            return null;
        }

        static double LogLik(double[] z, int[] n, int[] k, double lapse, double a, double b)
        {
            double ll = 0;
            for (int i = 0; i < z.Length; i++)
            {
                double lower, upper; // Φ(η) and its complement from one evaluation: the grids' starts evaluate this a thousand times
                Normal.Both(a + b * z[i], out lower, out upper);
                if (k[i] > 0)
                {
                    double p = lapse + (1 - 2 * lapse) * lower;
                    ll += k[i] * Math.Log(p);
                }
                if (n[i] - k[i] > 0)
                {
                    double q = lapse + (1 - 2 * lapse) * upper;
                    ll += (n[i] - k[i]) * Math.Log(q);
                }
            }
            return double.IsNaN(ll) ? double.NegativeInfinity : ll;
        }

        /// <summary>Newton–Levenberg ascent of the log-likelihood in (a, b); true when it converged. Internal for the
        /// tests, which start it far from the maximum where the likelihood with lapses is not concave.</summary>
        internal static bool Maximize(double[] z, int[] n, int[] k, double lapse, ref double a, ref double b, out int iterations, int iterationCap = MaxIterations)
        {
            double ll = LogLik(z, n, k, lapse, a, b);
            if (double.IsNegativeInfinity(ll)) { a = 0; b = 1; ll = LogLik(z, n, k, lapse, a, b); }
            double damping = 0;
            // Where rounding stops the ascent, the gradient left is of the order of the log-likelihood's rounding times the
            // curvature, which grows with the trials: the tolerance for "at the maximum to rounding" grows with them too
            // (a fixed 1e-6 refused reasonable fits of 360 trials, issue 31's simulated observers).
            int total = 0;
            for (int i = 0; i < n.Length; i++) total += n[i];
            double atRounding = 1e-6 * Math.Max(1, total);
            for (iterations = 1; iterations <= iterationCap; iterations++)
            {
                // Gradient and Hessian through η: ℓ_i(p) with p = γ + (1 − 2γ)Φ(η).
                double ga = 0, gb = 0, haa = 0, hab = 0, hbb = 0;
                double c = 1 - 2 * lapse;
                for (int i = 0; i < z.Length; i++)
                {
                    double eta = a + b * z[i];
                    double lower, upper;
                    Normal.Both(eta, out lower, out upper);
                    double p = lapse + c * lower;
                    double q = lapse + c * upper;
                    double d1 = c * Normal.Pdf(eta);           // dp/dη
                    double d2 = -eta * d1;                      // d²p/dη²
                    double yes = k[i], no = n[i] - k[i];
                    double lp = yes / p - no / q;
                    double lpp = -yes / (p * p) - no / (q * q);
                    double g = lp * d1;
                    double h = lpp * d1 * d1 + lp * d2;
                    // Only where Φ(η) or its complement has underflowed (|η| > 38, a level far outside or a far start): 0/0 at a
                    // level without such answers, whose term is no·φ(η) < 1e-320, or k/Ψ overflowed against φ(η) → 0.
                    if (double.IsNaN(g) || double.IsNaN(h)) { g = 0; h = 0; }
                    ga += g; gb += g * z[i];
                    haa += h; hab += h * z[i]; hbb += h * z[i] * z[i];
                }
                double gradNorm = Math.Sqrt(ga * ga + gb * gb);
                if (gradNorm < 1e-11) return true;

                // Solve (−H + τ·I) δ = g; raise τ until the matrix is positive definite.
                double A = -haa, B = -hab, C = -hbb;
                double tau = damping;
                double da = 0, db = 0;
                for (int attempt = 0; attempt < 60; attempt++)
                {
                    double aa = A + tau, cc = C + tau;
                    double det = aa * cc - B * B;
                    if (aa > 0 && det > 1e-300 * Math.Max(1, aa * cc))
                    {
                        da = (cc * ga - B * gb) / det;
                        db = (aa * gb - B * ga) / det;
                        break;
                    }
                    tau = tau == 0 ? 1e-6 * (Math.Abs(A) + Math.Abs(C) + 1) : tau * 10;
                }
                // Halve the step until it does not descend; at 2⁻⁶⁰ a finite step is below the last bit (an equal
                // log-likelihood, accepted), so all sixty fail only for a step that is not a number, and the damping grows.
                double scale = 1;
                for (int half = 0; half < 60; half++, scale *= 0.5)
                {
                    double na = a + scale * da, nb = b + scale * db;
                    double nll = LogLik(z, n, k, lapse, na, nb);
                    if (nll >= ll)
                    {
                        double moved = Math.Abs(na - a) + Math.Abs(nb - b);
                        a = na; b = nb;
                        double gain = nll - ll;
                        ll = nll;
                        if (moved < 1e-14 * (1 + Math.Abs(a) + Math.Abs(b)) && gain <= 1e-15 * (1 + Math.Abs(ll))) return gradNorm < atRounding;
                        break;
                    }
                }
                damping = scale == 1 ? tau * 0.1 : Math.Max(tau * 10, 1e-6);
                if (damping < 1e-12) damping = 0;
                if (Math.Abs(a) > 1e8 || Math.Abs(b) > 1e8) return false;
            }
            return false;
        }
    }
}
