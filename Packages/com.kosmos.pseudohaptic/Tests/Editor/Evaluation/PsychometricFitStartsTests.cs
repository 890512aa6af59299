using System;
using System.Collections.Generic;
using System.Linq;
using Kosmos.PseudoHaptic.Evaluation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests.Evaluation
{
    /// <summary>
    /// With lapses the likelihood can have several maxima, and the fit is only as good as its starts. Here the starts
    /// themselves (each computed again from Ψ in the levels' own unit), and the fit against ascents from 45 far starts on
    /// simulated participants: among them every data set of the first 20,000 on which the fit with a single grid start
    /// (before the eighteenth session) stopped at a lesser maximum, called a curve a step, or called a rise decreasing.
    /// </summary>
    public class PsychometricFitStartsTests
    {
        // Uneven levels, so that no two points of a grid mirror each other.
        static readonly double[] Uneven = { 0.70, 0.80, 0.85, 0.95, 1.00, 1.20 };

        // The peaks of the finer grid (μ at each level and a quarter, half and three quarters of the way to the next; σ from
        // 2 to 1/32 of the levels' spread in steps of √2, the steepest only as a neighbour; rising or falling): the four
        // likeliest points likelier by 1e-9 than every neighbour one step away in μ, σ or both, likeliest first.
        [Test]
        public void ThePeakStartsAreTheLikeliestPeaksOfTheFinerGrid()
        {
            var n = Uneven.Select(x => 10).ToArray();
            double mean, sd;
            var z = PsychometricFitMaximumTests.Standardize(Uneven, out mean, out sd);
            var centres = new List<double>();
            for (int i = 0; i < Uneven.Length; i++)
                for (int q = 0; q < (i < Uneven.Length - 1 ? 4 : 1); q++)
                    centres.Add(Uneven[i] + q * (i < Uneven.Length - 1 ? Uneven[i + 1] - Uneven[i] : 0) / 4);
            var sigmas = Enumerable.Range(0, 13).Select(j => 2 * sd / Math.Pow(Math.Sqrt(2), j)).ToArray();
            var cases = new[] { new[] { 1, 3, 4, 9, 8, 10 }, new[] { 9, 10, 6, 2, 3, 1 }, new[] { 1, 9, 2, 8, 3, 9 }, new[] { 0, 7, 1, 9, 10, 4 } };
            foreach (double lapse in new[] { 0.02, 0.1, 0.2 })
                foreach (var k in cases)
                {
                    var peaks = new List<(double Ll, double Mu, double Sigma, int Sign)>();
                    foreach (int sign in new[] { 1, -1 })
                    {
                        var grid = new double[centres.Count, sigmas.Length];
                        for (int c = 0; c < centres.Count; c++)
                            for (int j = 0; j < sigmas.Length; j++) grid[c, j] = PsychometricFitMaximumTests.LogLik(Uneven, n, k, lapse, centres[c], sigmas[j], sign);
                        for (int c = 0; c < centres.Count; c++)
                            for (int j = 0; j < sigmas.Length - 1; j++)
                            {
                                bool peak = true;
                                for (int dc = -1; dc <= 1; dc++)
                                    for (int dj = -1; dj <= 1; dj++)
                                    {
                                        int c2 = c + dc, j2 = j + dj;
                                        if ((dc != 0 || dj != 0) && c2 >= 0 && c2 < centres.Count && j2 >= 0 && j2 < sigmas.Length && grid[c2, j2] >= grid[c, j] - 1e-9) peak = false;
                                    }
                                if (peak) peaks.Add((grid[c, j], centres[c], sigmas[j], sign));
                            }
                    }
                    var expected = peaks.OrderByDescending(p => p.Ll).Take(PsychometricFit.PeakStartCount).ToList();
                    var starts = PsychometricFit.PeakStarts(z, PsychometricFit.LikelihoodGrid(z, n, k, lapse));
                    string data = "lapse " + lapse + ": " + string.Join(", ", k);
                    Assert.That(starts.Count, Is.EqualTo(expected.Count), data);
                    for (int i = 0; i < starts.Count; i++)
                    {
                        Assert.That(Math.Sign(starts[i][1]), Is.EqualTo(expected[i].Sign), "sign of peak " + i + ", " + data);
                        Assert.That(mean - sd * starts[i][0] / starts[i][1], Is.EqualTo(expected[i].Mu).Within(1e-12), "μ of peak " + i + ", " + data);
                        Assert.That(sd / Math.Abs(starts[i][1]), Is.EqualTo(expected[i].Sigma).Within(1e-12 * expected[i].Sigma), "σ of peak " + i + ", " + data);
                    }
                }
        }

        // The shallow start is the likeliest line of η across the levels with η at the lowest and at the highest level from
        // −4 to 4 (13 values, the two different): a curve centred far outside the levels is one of them.
        [Test]
        public void TheShallowStartIsTheLikeliestOfItsLines()
        {
            double[] etas = { -4, -3, -2, -1.5, -1, -0.5, 0, 0.5, 1, 1.5, 2, 3, 4 };
            var n = Uneven.Select(x => 6).ToArray();
            double mean, sd;
            var z = PsychometricFitMaximumTests.Standardize(Uneven, out mean, out sd);
            // Nearly all heavier, few heavier, a rise, a steeper rise, a fall, and the same answers everywhere (whose likeliest
            // line would be flat: the two ends must differ).
            var cases = new[] { (new[] { 5, 4, 6, 6, 6, 5 }, 0.04), (new[] { 2, 0, 2, 1, 2, 3 }, 0.1), (new[] { 1, 3, 4, 5, 5, 6 }, 0.02),
                (new[] { 0, 0, 1, 3, 6, 6 }, 0.02), (new[] { 6, 6, 5, 3, 1, 0 }, 0.02), (new[] { 3, 3, 3, 3, 3, 3 }, 0.1), (new[] { 1, 1, 2, 2, 3, 3 }, 0.05) };
            foreach (var (k, lapse) in cases)
            {
                double best = double.NegativeInfinity, bestLo = 0, bestHi = 0;
                foreach (double lo in etas)
                    foreach (double hi in etas)
                    {
                        if (lo == hi) continue;
                        // η runs linearly in the level from lo at the lowest to hi at the highest: Ψ = γ + (1 − 2γ)Φ(η).
                        double ll = 0;
                        for (int i = 0; i < Uneven.Length; i++)
                        {
                            double eta = lo + (hi - lo) * (Uneven[i] - Uneven[0]) / (Uneven[Uneven.Length - 1] - Uneven[0]);
                            double psi = lapse + (1 - 2 * lapse) * Normal.Cdf(eta);
                            ll += k[i] * Math.Log(psi) + (n[i] - k[i]) * Math.Log(1 - psi);
                        }
                        if (ll > best + 1e-9) { best = ll; bestLo = lo; bestHi = hi; }
                    }
                var start = PsychometricFit.ShallowStart(z, n, k, lapse);
                string data = "lapse " + lapse + ": " + string.Join(", ", k);
                Assert.That(start[0] + start[1] * z[0], Is.EqualTo(bestLo).Within(1e-12), "η at the lowest level, " + data);
                Assert.That(start[0] + start[1] * z[z.Length - 1], Is.EqualTo(bestHi).Within(1e-12), "η at the highest level, " + data);
            }
        }

        // Ascents that end on one maximum keep the first's: a start at the maximum itself (a bootstrap's original fit, the first
        // start) gives the fit its own ascent's point, bit for bit, though the later starts climb to the same maximum.
        [Test]
        public void AscentsEndingOnOneMaximumKeepTheFirst()
        {
            foreach (var (k, lapse) in new[] { (new[] { 0, 0, 2, 7, 10, 7, 10, 8, 1 }, 0.1), (new[] { 0, 1, 1, 3, 5, 6, 8, 10, 9 }, 0.04), (new[] { 3, 2, 1, 3, 6, 6, 8, 9, 7 }, 0.2) })
            {
                double[] levels = { 0.80, 0.85, 0.90, 0.95, 1.00, 1.05, 1.10, 1.15, 1.20 };
                var data = levels.Select((x, i) => new StimulusLevel(x, 10, k[i])).ToArray();
                var plain = PsychometricFit.Fit(data, lapse);
                double mean, sd;
                var z = PsychometricFitMaximumTests.Standardize(levels, out mean, out sd);
                int matched = 0;
                // Starts a little off the maximum: each ascent ends on it, at a point of its own to the last digits.
                foreach (double off in new[] { 0.999, 1.001, 0.99, 1.01 })
                {
                    double mu = plain.Mu * off, sigma = plain.Sigma / off;
                    double a = -(mu - mean) / sigma, b = sd / sigma;
                    int iterations;
                    Assert.That(PsychometricFit.Maximize(z, levels.Select(x => 10).ToArray(), k, lapse, ref a, ref b, out iterations), Is.True);
                    var fit = PsychometricFit.Fit(data, lapse, mu, sigma);
                    string where = "lapse " + lapse + ", start ×" + off + ": " + string.Join(", ", k);
                    Assert.That(fit.Mu, Is.EqualTo(mean - sd * a / b), "μ, " + where);
                    Assert.That(fit.Sigma, Is.EqualTo(sd / b), "σ, " + where);
                    if (fit.Mu != plain.Mu || fit.Sigma != plain.Sigma) matched++;
                }
                Assert.That(matched, Is.GreaterThan(0), "no start ended at a point of its own: the test would see nothing, " + string.Join(", ", k));
            }
        }

        // A simulated participant: 4–9 evenly spaced levels, 3–32 trials each, a true
        // cumulative Gaussian with a lapse of 0 or up to 0.2, fitted under a lapse of 0.01 to 0.2.
        static StimulusLevel[] Participant(int seed, out double lapse, out double range, out double start)
        {
            double[] lapses = { 0.01, 0.02, 0.04, 0.05, 0.1, 0.2 };
            var rng = new Random(seed);
            int m = 4 + rng.Next(6);
            double step = 0.02 + rng.NextDouble() * 0.1;
            start = 0.5 + rng.NextDouble();
            int trials = 3 + rng.Next(30);
            double mu = start + (rng.NextDouble() * 1.6 - 0.3) * step * (m - 1);
            double sigma = step * (0.1 + rng.NextDouble() * 3);
            double trueLapse = rng.NextDouble() < 0.5 ? 0 : rng.NextDouble() * 0.2;
            lapse = lapses[rng.Next(lapses.Length)];
            range = step * (m - 1);
            var levels = new StimulusLevel[m];
            for (int i = 0; i < m; i++)
            {
                double x = start + i * step;
                double p = trueLapse + (1 - 2 * trueLapse) * Normal.Cdf((x - mu) / sigma);
                int k = 0;
                for (int t = 0; t < trials; t++) if (rng.NextDouble() < p) k++;
                levels[i] = new StimulusLevel(x, trials, k);
            }
            return levels;
        }

        // The seeds of the first 20,000 where the fit with one grid start went wrong: a lesser maximum (eleven), "a step" for
        // a curve (six), "decreasing" for a rise (823). Without the peak starts fourteen of them fail, without the shallow
        // start one (15823).
        static readonly int[] HardSeeds = { 1404, 4950, 5283, 6831, 7704, 7748, 12143, 15082, 15185, 15823, 16930, 2169, 3854, 7401, 12457, 12527, 17516, 823 };

        static IEnumerable<int> Seeds() => HardSeeds.Concat(Enumerable.Range(1, 100));

        // The search behind the figures in evaluation.md (8.3): every participant of a range of seeds, with the far starts of
        // the test below; counts the fits a far start beats (an estimable fit with a likelier maximum, or "a step" or
        // "decreasing" where a curve is likelier) and prints them. Explicit: four to five minutes for 20,000 seeds.
        // dotnet test Tests/Kosmos.PseudoHaptic.Tests --filter "Name~SearchTwentyThousandParticipants" --logger "console;verbosity=detailed"
        [Explicit("a search of several minutes, for the documentation's figures")]
        [TestCase(1)]
        [TestCase(20001)]
        public void SearchTwentyThousandParticipants(int firstSeed)
        {
            int fitted = 0, lesser = 0, steps = 0, decreasing = 0;
            for (int seed = firstSeed; seed < firstSeed + 20000; seed++)
            {
                double lapse, range, start;
                var levels = Participant(seed, out lapse, out range, out start);
                var fit = PsychometricFit.Fit(levels, lapse);
                if (fit.Reason.StartsWith("all answers") || fit.Reason.StartsWith("perfect separation")) continue;
                fitted++;
                if (FarLikelier(levels, lapse, range, start, fit) == null) continue;
                if (fit.Estimable) lesser++;
                else if (fit.Reason.StartsWith("a step")) steps++;
                else if (fit.Reason.StartsWith("decreasing")) decreasing++;
                if (fit.Estimable || fit.Reason.StartsWith("a step") || fit.Reason.StartsWith("decreasing")) TestContext.Out.WriteLine("seed " + seed + ": " + fit.Reason);
            }
            TestContext.Out.WriteLine("seeds " + firstSeed + "–" + (firstSeed + 19999) + ": " + fitted + " fitted; a far start finds a likelier maximum than " + lesser +
                " estimable fits, a curve likelier than " + steps + " steps and than " + decreasing + " 'decreasing'");
            Assert.That(lesser + steps + decreasing, Is.LessThanOrEqualTo(1));
        }

        // The likeliest fit from the far starts that is not the flat answers' plateau (σ beyond a thousand spreads), if one
        // is likelier than the fit (estimable), or estimable at all (the fit a step or decreasing); otherwise null.
        static PsychometricFit FarLikelier(StimulusLevel[] levels, double lapse, double range, double start, PsychometricFit fit)
        {
            PsychometricFit best = null;
            foreach (double centre in FarCentres)
                foreach (double spread in FarSpreads)
                {
                    var far = PsychometricFit.Fit(levels, lapse, start + centre * range, spread * range);
                    if (!far.Estimable || far.Sigma > 1000 * range) continue;
                    if (best == null || far.LogLikelihood > best.LogLikelihood) best = far;
                }
            if (best == null) return null;
            if (fit.Estimable) return best.LogLikelihood > fit.LogLikelihood + 1e-6 ? best : null;
            return fit.Reason.StartsWith("a step") || fit.Reason.StartsWith("decreasing") ? best : null;
        }

        // μ at the lowest level plus these many spreads of the levels; σ these many spreads.
        static readonly double[] FarCentres = { -3.0, -1.5, -0.5, 0.0, 0.5, 1.0, 1.5, 2.5, 4.0 };
        static readonly double[] FarSpreads = { 0.01, 0.1, 0.5, 2, 8 };

        // No ascent from 45 far starts (μ from three spreads below the levels to four above, σ from 1/100 to 8 spreads; the
        // fit's own starts run too) ends likelier than the fit: an estimable fit is the likeliest maximum found, and a step is
        // as likely as any. Far ascents that drift off to σ beyond a thousand spreads are the flat answers' plateau, left out.
        [Test]
        public void WithLapsesNoFarStartFindsALikelierMaximum([ValueSource(nameof(Seeds))] int seed)
        {
            double lapse, range, start;
            var levels = Participant(seed, out lapse, out range, out start);
            var fit = PsychometricFit.Fit(levels, lapse);
            if (fit.Reason.StartsWith("all answers") || fit.Reason.StartsWith("perfect separation")) return; // no maximum to find
            var far = FarLikelier(levels, lapse, range, start, fit);
            if (far == null) return;
            Assert.Fail((fit.Estimable ? "a likelier maximum" : "a curve likelier than " + fit.Reason) + " from far starts: μ " + far.Mu + ", σ " + far.Sigma +
                ", log-likelihood " + far.LogLikelihood + " against " + fit.LogLikelihood + "; seed " + seed + ", lapse " + lapse + ": " +
                string.Join(", ", levels.Select(l => l.Heavier + "/" + l.Trials)));
        }
    }
}
