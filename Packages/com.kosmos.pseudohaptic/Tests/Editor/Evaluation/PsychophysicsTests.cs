using System;
using System.Collections.Generic;
using System.Linq;
using Kosmos.PseudoHaptic.Evaluation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests.Evaluation
{
    /// <summary>
    /// Distributions, the psychometric fit and its bootstrap, against values known independently of the
    /// code: closed forms (χ² with even ν, t with ν = 1 and 2), published tables and a textbook probit fit
    /// (Bliss's beetles, Dobson and Barnett), a brute-force Nelder–Mead maximisation, and simulated observers.
    /// </summary>
    public class PsychophysicsTests
    {
        [TestCase(0.0, 0.5)]
        [TestCase(1.0, 0.8413447460685429)]
        [TestCase(-1.959963984540054, 0.025)]
        [TestCase(-3.0, 0.0013498980316300946)]
        [TestCase(-5.0, 2.866515718791939e-07)]
        [TestCase(-10.0, 7.619853024160527e-24)]
        [TestCase(-20.0, 2.7536241186062337e-89)]
        public void NormalCdfMatchesTables(double z, double expected)
        {
            Assert.That(Normal.Cdf(z), Is.EqualTo(expected).Within(1e-13 * expected + 1e-16));
            Assert.That(Normal.UpperTail(-z), Is.EqualTo(expected).Within(1e-13 * expected + 1e-16));
        }

        [Test]
        public void TwoIndependentNormalMethodsAgree()
        {
            // Cody's rational approximations against Q(½, z²/2) by series and continued fraction.
            for (double z = -35; z <= 8; z += 0.0137)
            {
                double a = Normal.Cdf(z), b = Normal.CdfByGamma(z);
                Assert.That(a, Is.EqualTo(b).Within(1e-12 * b), "z = " + z);
            }
        }

        [TestCase(0.75, 0.6744897501960817)]
        [TestCase(0.975, 1.959963984540054)]
        [TestCase(0.5, 0.0)]
        [TestCase(1e-10, -6.361340902404056)]
        [TestCase(0.999, 3.090232306167813)]
        public void NormalQuantileMatchesTables(double p, double expected)
        {
            Assert.That(Normal.Quantile(p), Is.EqualTo(expected).Within(1e-12 * Math.Max(1, Math.Abs(expected))));
        }

        [Test]
        public void ChiSquareTailMatchesClosedForms()
        {
            foreach (double x in new[] { 0.01, 0.5, 1, 3, 7.5, 20, 60, 200 })
            {
                Assert.That(ChiSquare.UpperTail(x, 2), Is.EqualTo(Math.Exp(-x / 2)).Within(1e-14 * Math.Exp(-x / 2)), "ν = 2 at " + x);
                double four = Math.Exp(-x / 2) * (1 + x / 2);
                Assert.That(ChiSquare.UpperTail(x, 4), Is.EqualTo(four).Within(1e-13 * four), "ν = 4 at " + x);
                double six = Math.Exp(-x / 2) * (1 + x / 2 + x * x / 8);
                Assert.That(ChiSquare.UpperTail(x, 6), Is.EqualTo(six).Within(1e-13 * six), "ν = 6 at " + x);
                // ν = 1: P(χ² > x) = 2·(1 − Φ(√x)).
                Assert.That(ChiSquare.UpperTail(x, 1), Is.EqualTo(2 * Normal.UpperTail(Math.Sqrt(x))).Within(1e-13 * ChiSquare.UpperTail(x, 1)));
            }
            Assert.That(ChiSquare.UpperTail(3.841458820694124, 1), Is.EqualTo(0.05).Within(1e-14));
            Assert.That(ChiSquare.UpperTail(0, 3), Is.EqualTo(1));
        }

        [Test]
        public void TTailsMatchClosedForms()
        {
            foreach (double t in new[] { 0.1, 1, 2.5, 10, 100, 1e4 })
            {
                double cauchy = 0.5 - Math.Atan(t) / Math.PI; // ν = 1
                Assert.That(StudentT.Cdf(-t, 1), Is.EqualTo(cauchy).Within(1e-12 * cauchy));
                double two = 0.5 - t / (2 * Math.Sqrt(2 + t * t)); // ν = 2
                Assert.That(StudentT.Cdf(-t, 2), Is.EqualTo(two).Within(1e-9 * two + 1e-15));
            }
        }

        // Bliss (1935) beetle mortality, the probit fit in Dobson and Barnett, An Introduction to Generalized
        // Linear Models (3rd ed., Table 7.3): β1 = −34.935, β2 = 19.728 on log10 dose, deviance 10.12.
        [Test]
        public void BlissBeetlesMatchTheTextbookProbit()
        {
            double[] dose = { 1.6907, 1.7242, 1.7552, 1.7842, 1.8113, 1.8369, 1.8610, 1.8839 };
            int[] n = { 59, 60, 62, 56, 63, 59, 62, 60 };
            int[] killed = { 6, 13, 18, 28, 52, 53, 61, 60 };
            var levels = dose.Select((d, i) => new StimulusLevel(d, n[i], killed[i])).ToArray();
            var fit = PsychometricFit.Fit(levels);
            Assert.That(fit.Estimable, Is.True, fit.Reason);
            Assert.That(1 / fit.Sigma, Is.EqualTo(19.728).Within(0.001));
            Assert.That(-fit.Mu / fit.Sigma, Is.EqualTo(-34.935).Within(0.001));
            Assert.That(fit.Deviance, Is.EqualTo(10.12).Within(0.005));
        }

        /// <summary>An independent maximisation: Nelder–Mead on (μ, ln σ) of the binary log-likelihood.</summary>
        static double[] NelderMead(Func<double[], double> f, double[] start, double scale)
        {
            int d = start.Length;
            var simplex = new double[d + 1][];
            simplex[0] = (double[])start.Clone();
            for (int i = 0; i < d; i++) { simplex[i + 1] = (double[])start.Clone(); simplex[i + 1][i] += scale; }
            var values = simplex.Select(f).ToArray();
            for (int iter = 0; iter < 20000; iter++)
            {
                var order = Enumerable.Range(0, d + 1).OrderBy(i => values[i]).ToArray();
                simplex = order.Select(i => simplex[i]).ToArray();
                values = order.Select(i => values[i]).ToArray();
                double size = 0;
                for (int i = 1; i <= d; i++) for (int j = 0; j < d; j++) size = Math.Max(size, Math.Abs(simplex[i][j] - simplex[0][j]));
                if (size < 1e-10) break;
                var centroid = new double[d];
                for (int i = 0; i < d; i++) for (int j = 0; j < d; j++) centroid[j] += simplex[i][j] / d;
                Func<double, double[]> along = t => centroid.Select((c, j) => c + t * (simplex[d][j] - c)).ToArray();
                var reflected = along(-1); double fr = f(reflected);
                if (fr < values[0])
                {
                    var expanded = along(-2); double fe = f(expanded);
                    if (fe < fr) { simplex[d] = expanded; values[d] = fe; } else { simplex[d] = reflected; values[d] = fr; }
                }
                else if (fr < values[d - 1]) { simplex[d] = reflected; values[d] = fr; }
                else
                {
                    var contracted = along(0.5); double fc = f(contracted);
                    if (fc < values[d]) { simplex[d] = contracted; values[d] = fc; }
                    else
                        for (int i = 1; i <= d; i++)
                        {
                            simplex[i] = simplex[i].Select((v, j) => simplex[0][j] + 0.5 * (v - simplex[0][j])).ToArray();
                            values[i] = f(simplex[i]);
                        }
                }
            }
            return simplex[0];
        }

        [TestCase(0.0)]
        [TestCase(0.04)]
        public void FitAgreesWithNelderMeadOnSimulatedObservers(double lapse)
        {
            for (int seed = 1; seed <= 20; seed++)
            {
                var observer = new SimulatedObserver(1.0 + 0.02 * (seed % 5), 0.08 + 0.01 * (seed % 4), seed, lapse);
                var plan = new ConstantStimuliPlan { Standard = 1, Seed = seed, Repetitions = 10 };
                var trials = plan.Build("P" + seed);
                observer.AnswerAll(trials);
                var x = trials.Select(t => t.Comparison).ToArray();
                var y = trials.Select(t => t.Response).ToArray();
                var fit = PsychometricFit.Fit(x, y, lapse);
                if (!fit.Estimable) continue;
                Func<double[], double> negLogLik = th =>
                {
                    double s = Math.Exp(th[1]), ll = 0;
                    for (int i = 0; i < x.Length; i++)
                    {
                        double p = lapse + (1 - 2 * lapse) * Normal.Cdf((x[i] - th[0]) / s);
                        ll += y[i] == 1 ? Math.Log(p) : Math.Log(1 - p);
                    }
                    return -ll;
                };
                var best = NelderMead(negLogLik, new[] { 1.0, Math.Log(0.1) }, 0.05);
                Assert.That(-fit.LogLikelihood, Is.LessThanOrEqualTo(negLogLik(best) + 1e-9), "the fit is at least as good, seed " + seed + ": " + fit.Mu + " " + fit.Sigma + " vs " + best[0] + " " + Math.Exp(best[1]));
                // With lapses a step between two levels leaves μ on a flat ridge: compare where it is determined.
                if (lapse > 0 && fit.Sigma < 0.03) continue;
                Assert.That(fit.Mu, Is.EqualTo(best[0]).Within(1e-6 * Math.Abs(best[0])), "μ, seed " + seed);
                Assert.That(fit.Sigma, Is.EqualTo(Math.Exp(best[1])).Within(1e-5 * Math.Exp(best[1])), "σ, seed " + seed);
                Assert.That(-fit.LogLikelihood, Is.LessThanOrEqualTo(negLogLik(best) + 1e-9), "the fit is at least as good, seed " + seed);
                Assert.That(fit.Jnd, Is.EqualTo(0.6744897501960817 * fit.Sigma).Within(1e-15));
            }
        }

        [Test]
        public void DegenerateDataAreNotEstimableNeverNaNOrCrash()
        {
            Assert.That(PsychometricFit.Fit(new double[0], new int[0]).Reason, Is.EqualTo("no trials"));
            Assert.That(PsychometricFit.Fit(new[] { 1.0, 1.0, 1.0 }, new[] { 0, 1, 1 }).Reason, Is.EqualTo("a single level"));
            Assert.That(PsychometricFit.Fit(new[] { 0.8, 1.0, 1.2 }, new[] { 1, 1, 1 }).Reason, Does.StartWith("all answers the same (1)"));
            Assert.That(PsychometricFit.Fit(new[] { 0.8, 1.0, 1.2 }, new[] { 0, 0, 0 }).Reason, Does.StartWith("all answers the same (0)"));
            Assert.That(PsychometricFit.Fit(new[] { 0.8, 0.9, 1.1, 1.2 }, new[] { 0, 0, 1, 1 }).Reason, Does.StartWith("perfect separation"));
            Assert.That(PsychometricFit.Fit(new[] { 0.8, 1.0, 1.0, 1.2 }, new[] { 0, 0, 1, 1 }).Reason, Does.StartWith("perfect separation"), "quasi-complete");
            Assert.That(PsychometricFit.Fit(new[] { 0.8, 0.9, 1.1, 1.2 }, new[] { 1, 1, 0, 0 }).Reason, Does.StartWith("perfect separation"));
            var decreasing = PsychometricFit.Fit(new[] { 0.8, 0.8, 0.8, 1.0, 1.0, 1.2, 1.2, 1.2 }, new[] { 1, 1, 0, 1, 0, 0, 0, 1 });
            Assert.That(decreasing.Estimable, Is.False);
            Assert.That(decreasing.Reason, Does.StartWith("decreasing"));
            Assert.That(PsychometricFit.Fit(new[] { 1.0, 1.0, 1.0000000000000002, 1.0000000000000002 }, new[] { 1, 0, 1, 0 }).Reason, Does.StartWith("flat"));
            Assert.That(PsychometricFit.Fit(new[] { -0.1, -0.1, 0, 0.1, 0.1 }, new[] { 1, 0, 1, 1, 0 }).Reason, Does.StartWith("flat"));
            Assert.That(PsychometricFit.Fit(new[] { 1e300, -1e300, 1e300, -1e300 }, new[] { 1, 0, 0, 1 }).Estimable, Is.False);
            var boot = PsychometricBootstrap.Run(decreasing, 100, 1);
            Assert.That(boot.HasIntervals, Is.False);
        }

        [Test]
        public void BootstrapIsReproducibleFromItsSeed()
        {
            var observer = new SimulatedObserver(1.05, 0.1, 7);
            var trials = new ConstantStimuliPlan { Seed = 7 }.Build("P1");
            observer.AnswerAll(trials);
            var fit = PsychometricFit.Fit(trials.Select(t => t.Comparison).ToArray(), trials.Select(t => t.Response).ToArray());
            var a = PsychometricBootstrap.Run(fit, 300, 42);
            var b = PsychometricBootstrap.Run(fit, 300, 42);
            var c = PsychometricBootstrap.Run(fit, 300, 43);
            Assert.That(new[] { a.PseLow, a.PseHigh, a.JndLow, a.JndHigh }, Is.EqualTo(new[] { b.PseLow, b.PseHigh, b.JndLow, b.JndHigh }));
            Assert.That(a.PseLow, Is.Not.EqualTo(c.PseLow));
            Assert.That(a.PseLow, Is.LessThan(fit.Pse));
            Assert.That(a.PseHigh, Is.GreaterThan(fit.Pse));
            Assert.That(a.JndLow, Is.LessThan(fit.Jnd));
            Assert.That(a.JndHigh, Is.GreaterThan(fit.Jnd));
        }

        /// <summary>
        /// Issue 11 item 5: over 200 seeded simulated participants (7 levels × 12 repetitions, as Samad et al.),
        /// the 95 % bootstrap interval of the PSE contains the true PSE for 92–98 % of them. Measured then, and here, on the
        /// percentile interval; the BCa interval, the default since, covers the PSE as often
        /// (<see cref="TheBcaIntervalCoversThePseAsOftenAndTheJndMoreOftenThanThePercentileInterval"/>).
        /// </summary>
        [Test]
        public void BootstrapIntervalCoversTheTruePseFor92To98PercentOf200Participants()
        {
            var population = new SeededRandom(2024);
            int covered = 0, estimable = 0;
            for (int p = 0; p < 200; p++)
            {
                double pse = 1.0 + 0.05 * population.NextGaussian();
                double sigma = 0.08 + 0.06 * population.NextDouble();
                var observer = new SimulatedObserver(pse, sigma, 1000 + p);
                var trials = new ConstantStimuliPlan { Standard = 1, Seed = p, Repetitions = 12 }.Build("P" + p);
                observer.AnswerAll(trials);
                var fit = PsychometricFit.Fit(trials.Select(t => t.Comparison).ToArray(), trials.Select(t => t.Response).ToArray());
                if (!fit.Estimable) continue; // counted as not covering
                estimable++;
                var boot = PsychometricBootstrap.Run(fit, 1000, 5000 + p, 0.95, BootstrapInterval.Percentile);
                if (boot.PseLow <= pse && pse <= boot.PseHigh) covered++;
            }
            Assert.That(estimable, Is.GreaterThanOrEqualTo(195));
            double coverage = covered / 200.0;
            TestContext.WriteLine("coverage " + coverage + ", estimable " + estimable);
            Assert.That(coverage, Is.InRange(0.92, 0.98));
        }

        [Test]
        public void BootstrapJndIntervalCoversTheTrueJndLessOftenWith12RepetitionsThanWith24AndMissesBelowIt()
        {
            // The same population as above. With 12 repetitions per level (84 trials) the maximum-likelihood σ is too small
            // (the slope too steep: Wichmann and Hill 2001a), and the percentile interval carries that bias with it: the true
            // JND lies above the interval for most misses (what the BCa interval, the default since, corrects: below). Leaving the unfittable resamples out is not the cause: they are
            // separations, σ → 0, and counting them as JND 0 could only lower the interval's ends. With 24 repetitions the
            // coverage nears the nominal 95 %. evaluation.md §8.3 quotes the numbers printed here.
            foreach (int repetitions in new[] { 12, 24 })
            {
                var population = new SeededRandom(2024);
                int covered = 0, above = 0, below = 0, estimable = 0, failed = 0;
                for (int p = 0; p < 200; p++)
                {
                    double pse = 1.0 + 0.05 * population.NextGaussian();
                    double sigma = 0.08 + 0.06 * population.NextDouble();
                    double jnd = sigma * Normal.Quantile(0.75);
                    var observer = new SimulatedObserver(pse, sigma, 1000 + p);
                    var trials = new ConstantStimuliPlan { Standard = 1, Seed = p, Repetitions = repetitions }.Build("P" + p);
                    observer.AnswerAll(trials);
                    var fit = PsychometricFit.Fit(trials.Select(t => t.Comparison).ToArray(), trials.Select(t => t.Response).ToArray());
                    if (!fit.Estimable) continue; // counted as not covering
                    estimable++;
                    var boot = PsychometricBootstrap.Run(fit, 1000, 5000 + p, 0.95, BootstrapInterval.Percentile);
                    failed += boot.Failed;
                    if (jnd > boot.JndHigh) above++;
                    else if (jnd < boot.JndLow) below++;
                    else covered++;
                }
                TestContext.WriteLine($"{repetitions} repetitions: JND covered {covered} of 200 ({covered / 2.0} %), true JND above the interval {above}, below {below}; estimable {estimable}; unfittable resamples {failed} of {estimable * 1000}");
                if (repetitions == 12)
                {
                    Assert.That(covered, Is.InRange(168, 180), "84 to 90 %");
                    Assert.That(above, Is.GreaterThanOrEqualTo(4 * below + 10), "the misses are the interval's being too low");
                }
                else Assert.That(covered, Is.InRange(184, 194), "92 to 97 %");
            }
        }

        /// <summary>The test population above: participant <paramref name="p"/> of <paramref name="population"/>'s draws, with the
        /// fit of their answers (null when it cannot be fitted) and their true PSE and JND.</summary>
        static PsychometricFit Participant(SeededRandom population, int p, int repetitions, out double pse, out double jnd)
        {
            pse = 1.0 + 0.05 * population.NextGaussian();
            double sigma = 0.08 + 0.06 * population.NextDouble();
            jnd = sigma * Normal.Quantile(0.75);
            var trials = new ConstantStimuliPlan { Standard = 1, Seed = p, Repetitions = repetitions }.Build("P" + p);
            new SimulatedObserver(pse, sigma, 1000 + p).AnswerAll(trials);
            var fit = PsychometricFit.Fit(trials.Select(t => t.Comparison).ToArray(), trials.Select(t => t.Response).ToArray());
            return fit.Estimable ? fit : null;
        }

        /// <summary>How often each interval holds the truth over a population: [method, PSE or JND, covered / truth above / below].</summary>
        static int[,,] Coverage(long populationSeed, int participants, int repetitions)
        {
            var counts = new int[2, 2, 3];
            var population = new SeededRandom(populationSeed);
            for (int p = 0; p < participants; p++)
            {
                var fit = Participant(population, p, repetitions, out double pse, out double jnd);
                if (fit == null) continue; // counted as not covering
                var methods = new[] { BootstrapInterval.Percentile, BootstrapInterval.Bca };
                for (int m = 0; m < 2; m++)
                {
                    var boot = PsychometricBootstrap.Run(fit, 1000, 5000 + p, 0.95, methods[m]);
                    counts[m, 0, pse > boot.PseHigh ? 1 : pse < boot.PseLow ? 2 : 0]++;
                    counts[m, 1, jnd > boot.JndHigh ? 1 : jnd < boot.JndLow ? 2 : 0]++;
                }
            }
            return counts;
        }

        static string Describe(int[,,] c, int participants, int repetitions)
        {
            var text = new System.Text.StringBuilder();
            string[] methods = { "percentile", "BCa" }, what = { "PSE", "JND" };
            for (int m = 0; m < 2; m++)
                for (int q = 0; q < 2; q++)
                    text.Append($"{repetitions} repetitions, {methods[m]}: {what[q]} covered {c[m, q, 0]} of {participants} ({100.0 * c[m, q, 0] / participants:F1} %), true {what[q]} above {c[m, q, 1]}, below {c[m, q, 2]}\n");
            return text.ToString();
        }

        /// <summary>
        /// The BCa interval (Efron 1987), the default: on the population above (7 levels × 12 repetitions), it holds the
        /// true PSE as often as the percentile interval (within three participants of 200: the PSE's fit has next to no bias
        /// for it to correct), and the true JND far more often, its misses no longer nearly all on one side. Measured: PSE
        /// 183 and 185 of 200, JND 185 against 174, the true JND above the interval for 12 against 24 (printed). A BCa
        /// level with the bias correction's sign turned, or without it, covers the JND less often than this asks.
        /// </summary>
        [Test]
        public void TheBcaIntervalCoversThePseAsOftenAndTheJndMoreOftenThanThePercentileInterval()
        {
            var c = Coverage(2024, 200, 12);
            TestContext.WriteLine(Describe(c, 200, 12));
            Assert.That(Math.Abs(c[1, 0, 0] - c[0, 0, 0]), Is.LessThanOrEqualTo(3), "the PSE: as often");
            Assert.That(c[1, 1, 0], Is.GreaterThanOrEqualTo(c[0, 1, 0] + 8), "the JND: more often");
            Assert.That(c[1, 1, 0], Is.InRange(180, 194), "the JND: 90 to 97 %");
            Assert.That(c[1, 1, 1], Is.LessThanOrEqualTo(16), "the true JND above the interval: at most 8 %");
        }

        /// <summary>evaluation.md §8.3's coverage over two populations of 1000 participants each, both intervals, 12 and 24
        /// repetitions a level (about a minute): <c>dotnet test Tests/Kosmos.PseudoHaptic.Tests -c Release --filter
        /// Name~CoverageOverTwoThousandParticipants --logger "console;verbosity=detailed"</c>.</summary>
        [Test, Explicit("about a minute; prints evaluation.md's coverage figures")]
        public void CoverageOverTwoThousandParticipants()
        {
            foreach (long seed in new long[] { 77, 4242 })
                foreach (int repetitions in new[] { 12, 24 })
                {
                    var c = Coverage(seed, 1000, repetitions);
                    TestContext.WriteLine($"population seed {seed}:\n" + Describe(c, 1000, repetitions));
                    Assert.That(Math.Abs(c[1, 0, 0] - c[0, 0, 0]), Is.LessThanOrEqualTo(10), "the PSE: as often");
                    Assert.That(c[1, 1, 0], Is.GreaterThan(c[0, 1, 0]), "the JND: more often");
                }
        }

        [Test]
        public void WilsonIntervalMatchesHandComputation()
        {
            // 7 of 12, z = 1.959964: centre (0.58333 + 0.16006)/(1.32011) = 0.56313, half 0.25035.
            double lo, hi;
            WilsonInterval.Compute(7, 12, 0.95, out lo, out hi);
            Assert.That(lo, Is.EqualTo(0.31947).Within(1e-4));
            Assert.That(hi, Is.EqualTo(0.80668).Within(1e-4));
            WilsonInterval.Compute(0, 10, 0.95, out lo, out hi);
            Assert.That(lo, Is.EqualTo(0));
            Assert.That(hi, Is.EqualTo(0.27753).Within(1e-4));
        }
    }
}
