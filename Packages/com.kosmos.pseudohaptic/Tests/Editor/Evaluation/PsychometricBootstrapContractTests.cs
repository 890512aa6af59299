using System;
using System.Collections.Generic;
using System.Linq;
using Kosmos.PseudoHaptic.Evaluation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests.Evaluation
{
    /// <summary>
    /// The bootstrap's, the Wilson interval's and the simulated observer's contracts, each against numbers worked out
    /// apart from the code: R's type-7 quantile by hand, the bootstrap rebuilt from its description (binomial draws per
    /// level from the fitted function, refits, percentiles), Wilson's interval computed in Python, the observer's
    /// probability from its formula. The coverage tests in PsychophysicsTests judge the intervals statistically; these
    /// pin what a statistic cannot see (an interpolation off by one order statistic, a refused argument let through).
    /// </summary>
    public class PsychometricBootstrapContractTests
    {
        static readonly double[] Primes = { 2, 3, 5, 7, 11 };

        [TestCase(0.0, 2.0)]
        [TestCase(0.3, 3.4)]   // h = 4·0.3 = 1.2: 3 + 0.2·(5 − 3)
        [TestCase(0.5, 5.0)]
        [TestCase(0.75, 7.0)]  // h = 3 exactly: the order statistic itself
        [TestCase(0.9, 9.4)]   // h = 3.6: 7 + 0.6·(11 − 7)
        [TestCase(1.0, 11.0)]
        public void APercentileIsRsTypeSeven(double p, double expected)
            => Assert.That(PsychometricBootstrap.Percentile(Primes, p), Is.EqualTo(expected).Within(1e-14));

        [Test]
        public void APercentileOfOneValueIsThatValueAndNoValuesAreRefused()
        {
            Assert.That(PsychometricBootstrap.Percentile(new[] { 4.5 }, 0.025), Is.EqualTo(4.5));
            Assert.That(PsychometricBootstrap.Percentile(new[] { 4.5 }, 0.975), Is.EqualTo(4.5));
            Assert.That(PsychometricBootstrap.Percentile(new[] { 1.0, 2.0 }, 0.5), Is.EqualTo(1.5));
            var none = Assert.Throws<ArgumentException>(() => PsychometricBootstrap.Percentile(new double[0], 0.5));
            Assert.That(none.ParamName, Is.EqualTo("sorted"));
            Assert.That(none.Message, Does.StartWith("no values"));
            Assert.That(Assert.Throws<ArgumentException>(() => PsychometricBootstrap.Percentile(null, 0.5)).ParamName, Is.EqualTo("sorted"));
        }

        static PsychometricFit SevenLevels(long seed, int repetitions = 12, double sigma = 0.1)
        {
            var trials = new ConstantStimuliPlan { Standard = 1, Seed = seed, Repetitions = repetitions }.Build("P1");
            new SimulatedObserver(1.03, sigma, seed + 100).AnswerAll(trials);
            return PsychometricFit.Fit(trials.Select(t => t.Comparison).ToArray(), trials.Select(t => t.Response).ToArray());
        }

        /// <summary>The bootstrap rebuilt from its description: <paramref name="resamples"/> draws of Binomial(n, Ψ̂(x)) answers at
        /// every level, each fitted again (from the data, not from the fit), the PSEs and JNDs of those that can be, sorted.</summary>
        static void Refits(PsychometricFit fit, int resamples, long seed, out List<double> pses, out List<double> jnds)
        {
            var rng = new SeededRandom(seed);
            pses = new List<double>();
            jnds = new List<double>();
            for (int r = 0; r < resamples; r++)
            {
                var drawn = fit.Levels.Select(l => new StimulusLevel(l.Level, l.Trials, rng.NextBinomial(l.Trials, fit.Psi(l.Level)))).ToArray();
                var refit = PsychometricFit.Fit(drawn, fit.Lapse);
                if (!refit.Estimable) continue;
                pses.Add(refit.Pse);
                jnds.Add(refit.Jnd);
            }
            pses.Sort();
            jnds.Sort();
        }

        [Test]
        public void TheIntervalsAreThePercentilesOfRefitsOfBinomialDrawsFromTheFit()
        {
            // Seeds 1–3 with twelve repetitions a level; 11–13 with three from a noisier observer, where some resamples cannot be fitted.
            int failures = 0;
            foreach (long seed in new long[] { 1, 2, 3, 11, 12, 13 })
            {
                var fit = seed > 10 ? SevenLevels(seed, 3, 0.3) : SevenLevels(seed);
                Assert.That(fit.Estimable, Is.True, "seed " + seed);
                foreach (double confidence in new[] { 0.95, 0.8 })
                {
                    const int resamples = 200;
                    Refits(fit, resamples, seed * 7, out var pses, out var jnds);
                    double a = (1 - confidence) / 2;
                    var boot = PsychometricBootstrap.Run(fit, resamples, seed * 7, confidence, BootstrapInterval.Percentile);
                    string at = "seed " + seed + ", confidence " + confidence;
                    Assert.That(boot.Interval, Is.EqualTo(BootstrapInterval.Percentile), at);
                    Assert.That(boot.Resamples, Is.EqualTo(resamples), at);
                    Assert.That(boot.Failed, Is.EqualTo(resamples - pses.Count), at);
                    failures += boot.Failed;
                    Assert.That(boot.HasIntervals, Is.True, at);
                    // The refits here start from the data, the bootstrap's from the fit: the same maxima, to the fit's precision.
                    Assert.That(boot.PseLow, Is.EqualTo(PsychometricBootstrap.Percentile(pses, a)).Within(1e-9), at);
                    Assert.That(boot.PseHigh, Is.EqualTo(PsychometricBootstrap.Percentile(pses, 1 - a)).Within(1e-9), at);
                    Assert.That(boot.JndLow, Is.EqualTo(PsychometricBootstrap.Percentile(jnds, a)).Within(1e-9), at);
                    Assert.That(boot.JndHigh, Is.EqualTo(PsychometricBootstrap.Percentile(jnds, 1 - a)).Within(1e-9), at);
                }
            }
            Assert.That(failures, Is.GreaterThan(0), "some resamples of 21 answers could not be fitted");
        }

        /// <summary>
        /// The BCa interval rebuilt from its description (Efron and Tibshirani 1993, §14.3) on the same refits: the bias
        /// correction z₀ = Φ⁻¹(share of refits below the fit), the acceleration a from the jackknife, here made the long way
        /// (the fit again without each of the trials, one by one, from the raw answers: the code groups the trials that are
        /// alike), and each end the percentile at Φ(z₀ + (z₀ + z)/(1 − a(z₀ + z))). Seeds 1–3 with twelve answers a level,
        /// 11–13 with three from a noisier observer, and fifteen answers of which two cannot be left out (the rest would be
        /// separated by the answer: both leave those out).
        /// </summary>
        [Test]
        public void TheBcaIntervalsAreThoseRefitsPercentilesMovedByTheBiasAndTheJackknifesAcceleration()
        {
            var cases = new List<(string Name, double[] X, int[] Y)>();
            foreach (long seed in new long[] { 1, 2, 3, 11, 12, 13 })
            {
                var trials = new ConstantStimuliPlan { Standard = 1, Seed = seed, Repetitions = seed > 10 ? 3 : 12 }.Build("P1");
                new SimulatedObserver(1.03, seed > 10 ? 0.3 : 0.1, seed + 100).AnswerAll(trials);
                cases.Add(("seed " + seed, trials.Select(t => t.Comparison).ToArray(), trials.Select(t => t.Response).ToArray()));
            }
            double[] five = { 0.8, 0.9, 1.0, 1.1, 1.2 };
            cases.Add(("fifteen answers", five.SelectMany(l => new[] { l, l, l }).ToArray(), new[] { 0, 0, 0, 0, 0, 1, 0, 1, 1, 1, 1, 1, 1, 1, 1 }));
            int leftOut = 0;
            foreach (var (name, x, y) in cases)
            {
                var fit = PsychometricFit.Fit(x, y);
                Assert.That(fit.Estimable, Is.True, name);
                const int resamples = 200;
                Refits(fit, resamples, 7, out var pses, out var jnds);
                var jackPse = new List<double>();
                var jackJnd = new List<double>();
                for (int i = 0; i < x.Length; i++)
                {
                    var without = PsychometricFit.Fit(x.Where((_, k) => k != i).ToArray(), y.Where((_, k) => k != i).ToArray());
                    if (!without.Estimable) { leftOut++; continue; }
                    jackPse.Add(without.Pse);
                    jackJnd.Add(without.Jnd);
                }
                foreach (double confidence in new[] { 0.95, 0.8 })
                {
                    var boot = PsychometricBootstrap.Run(fit, resamples, 7, confidence, BootstrapInterval.Bca);
                    string at = name + ", confidence " + confidence;
                    Assert.That(boot.Interval, Is.EqualTo(BootstrapInterval.Bca), at);
                    Assert.That(boot.Failed, Is.EqualTo(resamples - pses.Count), at);
                    double[] pse = Ends(pses, fit.Pse, jackPse, confidence), jnd = Ends(jnds, fit.Jnd, jackJnd, confidence);
                    Assert.That(boot.PseLow, Is.EqualTo(pse[0]).Within(1e-9), at);
                    Assert.That(boot.PseHigh, Is.EqualTo(pse[1]).Within(1e-9), at);
                    Assert.That(boot.JndLow, Is.EqualTo(jnd[0]).Within(1e-9), at);
                    Assert.That(boot.JndHigh, Is.EqualTo(jnd[1]).Within(1e-9), at);
                }
            }
            Assert.That(leftOut, Is.EqualTo(2), "the fifteen answers' two trials that cannot be left out, and no other");
        }

        /// <summary>The BCa ends from their textbook formulas.</summary>
        static double[] Ends(List<double> sorted, double estimate, List<double> jackknife, double confidence)
        {
            double below = sorted.Count(v => v < estimate) + 0.5 * sorted.Count(v => v == estimate);
            double share = Math.Min(Math.Max(below / sorted.Count, 0.5 / sorted.Count), 1 - 0.5 / sorted.Count);
            double z0 = Normal.Quantile(share);
            double mean = jackknife.Average();
            double a = jackknife.Sum(v => Math.Pow(mean - v, 3)) / (6 * Math.Pow(jackknife.Sum(v => Math.Pow(mean - v, 2)), 1.5));
            return new[] { -1.0, 1.0 }.Select(side =>
            {
                double w = z0 + side * Normal.Quantile(1 - (1 - confidence) / 2);
                return PsychometricBootstrap.Percentile(sorted, Normal.Cdf(z0 + w / (1 - a * w)));
            }).ToArray();
        }

        // Φ(z₀ + (z₀ + z)/(1 − a(z₀ + z))) computed with mpmath at 40 digits; z = ∓Φ⁻¹(0.975).
        [TestCase(0.0, 0.0, -1.9599639845400543, 0.025)]
        [TestCase(0.0, 0.0, 1.9599639845400543, 0.975)]
        [TestCase(0.3, 0.0, -1.9599639845400543, 0.086920660625246215)]
        [TestCase(0.3, 0.0, 1.9599639845400543, 0.99476584943243136)]
        [TestCase(0.25, 0.05, -1.9599639845400543, 0.092539091736906026)]
        [TestCase(0.25, 0.05, 1.9599639845400543, 0.99687621067518305)]
        [TestCase(-0.4, -0.1, -1.9599639845400543, 0.00024246678794579582)]
        [TestCase(-0.4, -0.1, 1.9599639845400543, 0.82880512601436196)]
        public void TheBcaLevelIsItsFormula(double z0, double a, double z, double expected)
            => Assert.That(PsychometricBootstrap.BcaLevel(z0, a, z), Is.EqualTo(expected).Within(1e-13));

        [Test]
        public void ABcaLevelPastItsPoleIsTheExtremeRefit()
        {
            // 1 − a(z₀ + z) ≤ 0: the formula has run off its end (on its way there the level tends to 1 for a > 0, to 0 for a < 0).
            Assert.That(PsychometricBootstrap.BcaLevel(0, 0.6, 1.96), Is.EqualTo(1));
            Assert.That(PsychometricBootstrap.BcaLevel(0, -0.6, -1.96), Is.EqualTo(0));
            Assert.That(PsychometricBootstrap.BcaLevel(0.5, 0.5, 1.5), Is.EqualTo(1), "exactly at the pole");
            Assert.That(PsychometricBootstrap.BcaLevel(0, 0.5, 1.9), Is.GreaterThan(0.9999), "just before it");
        }

        // Φ⁻¹ of the share below (ties half), mpmath at 40 digits; the share kept within half a value of 0 and 1.
        [TestCase(7.5, 0.52440051270804078)]   // 7 of 10 below
        [TestCase(4.0, -0.38532046640756762)]  // 3 below, one tie: 3.5 of 10
        [TestCase(0.0, -1.6448536269514727)]   // none below: 0.5 of 10
        [TestCase(11.0, 1.6448536269514727)]   // all below: 9.5 of 10
        public void TheBiasCorrectionIsTheNormalQuantileOfTheShareBelow(double estimate, double expected)
        {
            var sorted = Enumerable.Range(1, 10).Select(i => (double)i).ToArray();
            Assert.That(PsychometricBootstrap.BiasCorrection(sorted, estimate), Is.EqualTo(expected).Within(1e-13));
        }

        [Test]
        public void ANarrowerConfidenceGivesANestedInterval()
        {
            var fit = SevenLevels(4);
            var wide = PsychometricBootstrap.Run(fit, 300, 9, 0.95);
            var narrow = PsychometricBootstrap.Run(fit, 300, 9, 0.5);
            Assert.That(narrow.PseLow, Is.GreaterThan(wide.PseLow));
            Assert.That(narrow.PseHigh, Is.LessThan(wide.PseHigh));
            Assert.That(narrow.JndLow, Is.GreaterThan(wide.JndLow));
            Assert.That(narrow.JndHigh, Is.LessThan(wide.JndHigh));
        }

        [Test]
        public void FewerThanTwoRefitsGiveNoIntervals()
        {
            var fit = SevenLevels(5);
            var none = PsychometricBootstrap.Run(fit, 0, 1);
            Assert.That(none.HasIntervals, Is.False);
            Assert.That(none.Failed, Is.EqualTo(0));
            Assert.That(double.IsNaN(none.PseLow) && double.IsNaN(none.PseHigh) && double.IsNaN(none.JndLow) && double.IsNaN(none.JndHigh));
            var one = PsychometricBootstrap.Run(fit, 1, 1);
            Assert.That(one.HasIntervals, Is.False, "one refit is no interval");
            Assert.That(one.Resamples, Is.EqualTo(1));
            var two = PsychometricBootstrap.Run(fit, 2, 1);
            Assert.That(two.Failed, Is.EqualTo(0));
            Assert.That(two.HasIntervals, Is.True, "two refits are");
            Assert.That(two.PseLow, Is.LessThanOrEqualTo(two.PseHigh));
        }

        [Test]
        public void AFitThatIsNotEstimableFailsEveryResample()
        {
            var flat = PsychometricFit.Fit(new[] { 0.9, 1.0, 1.1 }, new[] { 1, 1, 1 });
            Assert.That(flat.Estimable, Is.False);
            var boot = PsychometricBootstrap.Run(flat, 50, 1);
            Assert.That(boot.Resamples, Is.EqualTo(50));
            Assert.That(boot.Failed, Is.EqualTo(50));
            Assert.That(boot.HasIntervals, Is.False);
        }

        [Test]
        public void BadArgumentsAreRefusedNamingThem()
        {
            var fit = SevenLevels(6);
            Assert.That(Assert.Throws<ArgumentNullException>(() => PsychometricBootstrap.Run(null, 10, 1)).ParamName, Is.EqualTo("fit"));
            var negative = Assert.Throws<ArgumentOutOfRangeException>(() => PsychometricBootstrap.Run(fit, -1, 1));
            Assert.That(negative.ParamName, Is.EqualTo("resamples"));
            Assert.That(negative.Message, Does.StartWith("must be ≥ 0"));
            foreach (double c in new[] { 0.0, 1.0, -0.5, 1.5, double.NaN })
            {
                var e = Assert.Throws<ArgumentOutOfRangeException>(() => PsychometricBootstrap.Run(fit, 10, 1, c));
                Assert.That(e.ParamName, Is.EqualTo("confidence"), "confidence " + c);
                Assert.That(e.Message, Does.StartWith("must be in (0, 1)"), "confidence " + c);
            }
            var kind = Assert.Throws<ArgumentOutOfRangeException>(() => PsychometricBootstrap.Run(fit, 10, 1, 0.95, (BootstrapInterval)7));
            Assert.That(kind.ParamName, Is.EqualTo("interval"));
            Assert.That(kind.Message, Does.StartWith("must be Bca or Percentile"));
            Assert.That(PsychometricBootstrap.Run(fit, 10, 1).Interval, Is.EqualTo(BootstrapInterval.Bca), "the default");
        }

        [TestCase(7, 12, 0.95, 0.3195113125495498, 0.8067396863412434)]
        [TestCase(1, 3, 0.8, 0.10577563612172286, 0.6788173521696517)]
        [TestCase(50, 100, 0.99, 0.37527962504483986, 0.6247203749551602)]
        [TestCase(10, 10, 0.95, 0.7224672001371109, 1.0)]
        [TestCase(0, 10, 0.95, 0.0, 0.27753279986288915)]
        public void WilsonsIntervalIsItsFormula(int successes, int trials, double confidence, double low, double high)
        {
            double lo, hi;
            WilsonInterval.Compute(successes, trials, confidence, out lo, out hi);
            Assert.That(lo, Is.EqualTo(low).Within(1e-13));
            Assert.That(hi, Is.EqualTo(high).Within(1e-13));
        }

        [Test]
        public void WilsonsIntervalEndsAtZeroAndOneExactlyForNoneAndAll()
        {
            double lo, hi;
            for (int n = 1; n <= 60; n++)
            {
                WilsonInterval.Compute(0, n, 0.95, out lo, out hi);
                Assert.That(lo, Is.EqualTo(0), "0 of " + n);
                WilsonInterval.Compute(n, n, 0.95, out lo, out hi);
                Assert.That(hi, Is.EqualTo(1), n + " of " + n);
            }
        }

        [TestCase(0, 0)]
        [TestCase(-1, 5)]
        [TestCase(6, 5)]
        public void WilsonsIntervalRefusesImpossibleCounts(int successes, int trials)
        {
            double lo, hi;
            var e = Assert.Throws<ArgumentOutOfRangeException>(() => WilsonInterval.Compute(successes, trials, 0.95, out lo, out hi));
            Assert.That(e.ParamName, Is.EqualTo("trials"));
            Assert.That(e.Message, Does.StartWith("need 0 ≤ successes ≤ trials, trials > 0"));
        }

        [Test]
        public void TheObserversProbabilityIsTheLapsedCumulativeGaussian()
        {
            var o = new SimulatedObserver(1.0, 0.1, 1, 0.05);
            Assert.That(o.Pse, Is.EqualTo(1.0));
            Assert.That(o.Sigma, Is.EqualTo(0.1));
            Assert.That(o.Lapse, Is.EqualTo(0.05));
            Assert.That(o.Probability(1.0), Is.EqualTo(0.5).Within(1e-15));
            // Φ(1) = 0.8413447460685429: 0.05 + 0.9·Φ(1).
            Assert.That(o.Probability(1.1), Is.EqualTo(0.05 + 0.9 * 0.8413447460685429).Within(1e-15));
            Assert.That(o.Probability(0.9), Is.EqualTo(0.05 + 0.9 * (1 - 0.8413447460685429)).Within(1e-15));
            Assert.That(o.Probability(-100), Is.EqualTo(0.05).Within(1e-15), "a lapse below");
            Assert.That(o.Probability(100), Is.EqualTo(0.95).Within(1e-15), "and above");
            Assert.That(new SimulatedObserver(1.0, 0.1, 1).Probability(1.1), Is.EqualTo(0.8413447460685429).Within(1e-15));
        }

        [Test]
        public void TheObserverSaysHeavierWhenItsDrawIsBelowTheProbability()
        {
            var o = new SimulatedObserver(1.0, 0.1, 31, 0.02);
            var draws = new SeededRandom(31);
            for (int i = 0; i < 500; i++)
            {
                double x = 0.7 + 0.0012 * i;
                Assert.That(o.Answer(x), Is.EqualTo(draws.NextDouble() < o.Probability(x) ? 1 : 0), "x = " + x);
            }
        }

        [Test]
        public void TheObserverAnswersEveryTrialInOrder()
        {
            var trials = new ConstantStimuliPlan { Seed = 3, Repetitions = 4 }.Build("P1");
            var o = new SimulatedObserver(1.0, 0.1, 8);
            var twin = new SimulatedObserver(1.0, 0.1, 8);
            o.AnswerAll(trials);
            Assert.That(trials.Select(t => t.Response), Is.EqualTo(trials.Select(t => twin.Answer(t.Comparison))));
        }

        [Test]
        public void AnObserverWithoutSpreadOrWithTooMuchLapseIsRefused()
        {
            foreach (double sigma in new[] { 0.0, -0.1, double.NaN })
                Assert.That(() => new SimulatedObserver(1, sigma, 1), Throws.TypeOf<ArgumentOutOfRangeException>()
                    .With.Property("ParamName").EqualTo("sigma").And.Message.StartsWith("sigma must be positive"), "sigma " + sigma);
            foreach (double lapse in new[] { -0.01, 0.5, double.NaN })
                Assert.That(() => new SimulatedObserver(1, 0.1, 1, lapse), Throws.TypeOf<ArgumentOutOfRangeException>()
                    .With.Property("ParamName").EqualTo("lapse").And.Message.StartsWith("lapse must be in [0, 0.5)"), "lapse " + lapse);
            Assert.That(new SimulatedObserver(1, 0.1, 1, 0.0).Lapse, Is.EqualTo(0));
            Assert.That(new SimulatedObserver(1, 0.1, 1, 0.49).Lapse, Is.EqualTo(0.49));
        }
    }
}
