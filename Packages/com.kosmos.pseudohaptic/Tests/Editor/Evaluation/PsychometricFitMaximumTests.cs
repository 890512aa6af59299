using System;
using System.Collections.Generic;
using System.Linq;
using Kosmos.PseudoHaptic.Evaluation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests.Evaluation
{
    /// <summary>
    /// The psychometric fit against maxima found independently in 50-digit arithmetic (Tools/check-psychometric-fit.py,
    /// mpmath: a grid for the global maximum, Newton on the exact gradient to polish it), what it refuses and when it
    /// says a maximum is not there, and the start a bootstrap gives it.
    /// </summary>
    public class PsychometricFitMaximumTests
    {
        static readonly double[] Levels = { 0.80, 0.85, 0.90, 0.95, 1.00, 1.05, 1.10, 1.15, 1.20 };

        // The first heavier.Length levels.
        static StimulusLevel[] Data(int trials, params int[] heavier)
            => Levels.Take(heavier.Length).Select((x, i) => new StimulusLevel(x, trials, heavier[i])).ToArray();

        // ℓ of Ψ(x) = γ + (1 − 2γ)·Φ(sign·(x − μ)/σ) in the levels' own unit, independently of the fit's standardized one.
        internal static double LogLik(double[] levels, int[] n, int[] k, double lapse, double mu, double sigma, int sign)
        {
            double ll = 0;
            for (int i = 0; i < levels.Length; i++)
            {
                double psi = lapse + (1 - 2 * lapse) * Normal.Cdf(sign * (levels[i] - mu) / sigma);
                ll += k[i] * Math.Log(psi) + (n[i] - k[i]) * Math.Log(1 - psi);
            }
            return ll;
        }

        // The levels standardized as the fit standardizes equal trials: z = (x − mean)/sd, sd the population one.
        internal static double[] Standardize(double[] levels, out double mean, out double sd)
        {
            double m = levels.Average();
            mean = m;
            sd = Math.Sqrt(levels.Sum(x => (x - m) * (x - m)) / levels.Length);
            double s = sd;
            return levels.Select(x => (x - m) / s).ToArray();
        }

        static StimulusLevel[] Graded => Data(10, 0, 1, 1, 3, 5, 6, 8, 10, 9);

        static StimulusLevel[] Lapsing => Data(10, 3, 2, 1, 3, 6, 6, 8, 9, 7);

        // Tools/check-psychometric-fit.py's output: lapse, μ, σ, log-likelihood, deviance; and the relative error allowed
        // in μ and σ (1e-10, ten digits, but where the log-likelihood's rounding ends the ascent first, below).
        static IEnumerable<TestCaseData> Maxima()
        {
            yield return new TestCaseData(Graded, 0.0, 1.010958649732023, 0.10498140472835802, -36.410271655473304, 3.7670534442140512, 1e-10)
                .SetName("graded");
            yield return new TestCaseData(Graded, 0.04, 1.0088627803206924, 0.084641696319211463, -36.397026263695287, 3.7405626606580187, 1e-10)
                .SetName("graded, lapse 0.04");
            yield return new TestCaseData(Lapsing, 0.2, 0.99964416951844726, 0.052460276059148951, -50.137869289912493, 3.6839978989756752, 1e-10)
                .SetName("lapsing, lapse 0.2");
            // The same proportions a thousand times over: the same maximum, with a curvature a thousand times as steep.
            yield return new TestCaseData(Data(10000, 0, 1000, 1000, 3000, 5000, 6000, 8000, 10000, 9000), 0.0, 1.010958649732023, 0.10498140472835802, -36410.271655473304, 3767.0534442140512, 1e-10)
                .SetName("graded, a thousand times");
            // A participant who lapsed at the heaviest comparison (1 of 10 heavier): from the lapse-free maximum an ascent
            // stops at a lesser one (μ 0.98, σ 0.16, −55.3); the fit's starts find this one.
            yield return new TestCaseData(Data(10, 0, 0, 2, 7, 10, 7, 10, 8, 1), 0.1, 0.93124438337145558, 0.025306710569636963, -49.29656430922673, 47.640800126901241, 1e-10)
                .SetName("an outlier, lapse 0.1");
            // Forty trials a level, the eighth answered heavier 8 times in 40 against its neighbours' 40 and 38: under a lapse
            // of 0.02 the likeliest curve is steep and that outlier improbable. The ascents from (0, 1) and from the
            // lapse-free maximum both end at a shallow one (σ 0.24, −198.6); the grid's start finds this one.
            yield return new TestCaseData(Data(40, 0, 14, 30, 39, 40, 40, 40, 8, 38), 0.02, 0.87080228558889682, 0.034662041916901691, -191.66726152804825, 221.28601908209391, 1e-10)
                .SetName("an outlier of forty, lapse 0.02");
            // A simulated observer's 700 trials (SimulatedObserver(1.02, 0.09, seed 81), 100 repetitions of the plan's
            // seven levels). The ascent stops where a step's gain (about 1e-14) is below the rounding of a log-likelihood
            // of −164, with a gradient of 1.7e-6 left: σ is 2e-8 off, which a fixed gradient tolerance of 1e-6 would
            // call "did not converge" (issue 31).
            yield return new TestCaseData(new[] { new StimulusLevel(0.7, 100, 0), new StimulusLevel(0.8, 100, 1), new StimulusLevel(0.9, 100, 11),
                    new StimulusLevel(1.0, 100, 43), new StimulusLevel(1.1, 100, 83), new StimulusLevel(1.2, 100, 98), new StimulusLevel(1.3, 100, 100) },
                    0.0, 1.0137711191724664, 0.090764406617930104, -164.11923942490013, 0.28705661884630924, 1e-7)
                .SetName("seven levels of a hundred");
            // Four participants on whom the fit's single grid start was not enough (PsychometricFitStartsTests' seeds 4950,
            // 6831, 2169 and 823, on these levels): the likeliest point of the grid lay on the flank of a lower hill.
            // Six trials at eight levels, nearly all heavier: a shallow curve centred far below the levels (the ascents from
            // the grid's likeliest point and (0, 1) ended at μ 0.73, σ 0.10, −18.69).
            yield return new TestCaseData(Data(6, 5, 4, 6, 6, 6, 5, 5, 5), 0.04, -1.3038023666675285, 1.7134993300967359, -18.064723926178117, 6.8643398072358559, 1e-10)
                .SetName("shallow, far below, lapse 0.04");
            // 1 of 20 heavier at the lightest, then 14: a steep rise between the first two levels (the single grid start's
            // ascent ended on a shallower one, −39.99).
            yield return new TestCaseData(Data(20, 1, 14, 19, 17, 19, 20), 0.01, 0.83986637024232975, 0.026276429218284222, -39.653462025701066, 14.142159255462052, 1e-10)
                .SetName("a steep rise, lapse 0.01");
            // A jump between the fourth and the fifth level: steep, but a curve likelier than any step (it was called a step).
            yield return new TestCaseData(Data(18, 2, 2, 2, 1, 15, 16, 17, 16, 18), 0.02, 0.98177631185646936, 0.017906530834926941, -57.322260025339988, 20.186280107046102, 1e-10)
                .SetName("a jump, lapse 0.02");
            // Few heavier anywhere: a shallow rise centred above the levels, likelier than any fall (−32.44; it was called
            // decreasing).
            yield return new TestCaseData(Data(9, 2, 0, 2, 0, 2, 3, 2, 1), 0.1, 1.7964617651608108, 0.58385183515500626, -32.292363387759451, 8.7096476888865723, 1e-10)
                .SetName("few heavier, lapse 0.1");
        }

        [TestCaseSource(nameof(Maxima))]
        public void TheFitIsTheMaximum(StimulusLevel[] data, double lapse, double mu, double sigma, double logLik, double deviance, double relative)
        {
            var fit = PsychometricFit.Fit(data, lapse);
            Assert.That(fit.Estimable, Is.True, fit.Reason);
            Assert.That(fit.Reason, Is.EqualTo("yes"));
            Assert.That(fit.Mu, Is.EqualTo(mu).Within(relative * Math.Abs(mu)), "μ");
            Assert.That(fit.Sigma, Is.EqualTo(sigma).Within(relative * sigma), "σ");
            Assert.That(fit.LogLikelihood, Is.EqualTo(logLik).Within(1e-12 * -logLik), "log-likelihood");
            Assert.That(fit.Deviance, Is.EqualTo(deviance).Within(Math.Max(1e-10, relative) * deviance), "deviance");
            Assert.That(fit.Trials, Is.EqualTo(data.Sum(l => l.Trials)));
            Assert.That(fit.Lapse, Is.EqualTo(lapse));
        }

        [Test]
        public void PsiRunsFromTheLapseThroughAHalfAtThePseToOneMinusTheLapse()
        {
            var fit = PsychometricFit.Fit(Lapsing, 0.2);
            Assert.That(fit.Psi(fit.Mu), Is.EqualTo(0.5).Within(1e-15));
            Assert.That(fit.Psi(fit.Mu + fit.Sigma), Is.EqualTo(0.2 + 0.6 * 0.8413447460685429).Within(1e-15));
            Assert.That(fit.Psi(-1e6), Is.EqualTo(0.2).Within(1e-15));
            Assert.That(fit.Psi(1e6), Is.EqualTo(0.8).Within(1e-15));
        }

        [Test]
        public void MissingLevelsAndLapsesOutsideZeroToAHalfAreRefused()
        {
            Assert.That(() => PsychometricFit.Fit((IReadOnlyList<StimulusLevel>)null), Throws.ArgumentNullException.With.Property("ParamName").EqualTo("levels"));
            foreach (double lapse in new[] { -0.01, 0.5, double.NaN })
            {
                var e = Assert.Throws<ArgumentOutOfRangeException>(() => PsychometricFit.Fit(Graded, lapse));
                Assert.That(e.ParamName, Is.EqualTo("lapse"));
                Assert.That(e.Message, Does.StartWith("lapse must be in [0, 0.5)"));
            }
        }

        [Test]
        public void ALevelWithoutTrialsIsNoLevel()
        {
            var fit = PsychometricFit.Fit(new[] { new StimulusLevel(0.9, 0, 0), new StimulusLevel(1.0, 4, 2) });
            Assert.That(fit.Reason, Is.EqualTo("a single level"));
            var withEmpty = PsychometricFit.Fit(Graded.Concat(new[] { new StimulusLevel(2.0, 0, 0) }).ToArray());
            var plain = PsychometricFit.Fit(Graded);
            Assert.That(withEmpty.Mu, Is.EqualTo(plain.Mu).Within(1e-12));
            Assert.That(withEmpty.Sigma, Is.EqualTo(plain.Sigma).Within(1e-12));
            Assert.That(withEmpty.Deviance, Is.EqualTo(plain.Deviance).Within(1e-12));
        }

        // Levels whose spread overflows (±1e300: its square is infinite) or underflows (1e-200 apart: its square is 0)
        // cannot be standardized; the fit says so rather than dividing by 0 or infinity.
        [TestCase(-1e300, 1e300)]
        [TestCase(1e-200, 2e-200)]
        public void LevelsWhoseSpreadDoublesCannotHoldAreOutOfRange(double low, double high)
        {
            var fit = PsychometricFit.Fit(new[] { new StimulusLevel(low, 2, 1), new StimulusLevel(high, 2, 1) });
            Assert.That(fit.Estimable, Is.False);
            Assert.That(fit.Reason, Is.EqualTo("levels out of range: their spread cannot be computed in double precision"));
            Assert.That(double.IsNaN(fit.Mu) && double.IsNaN(fit.Sigma), Is.True);
        }

        // Answers near chance under a lapse of 0.49 (Ψ between 0.49 and 0.51), found among 200,000 random small data sets,
        // and a step between two levels a billionth apart under a lapse of 0.2: the ascents climb towards the step until b
        // passes 1e8 and give up. No maximum was found, and a step is as likely as where they stopped: a step, not "the
        // fit did not converge".
        [Test]
        public void AnAscentThatGivesUpClimbingTowardsAStepIsAStep()
        {
            var nearChance = PsychometricFit.Fit(new[] { new StimulusLevel(0.5, 1, 1), new StimulusLevel(0.1, 3, 1), new StimulusLevel(0, 4, 2) }, 0.49);
            var close = PsychometricFit.Fit(new[] { new StimulusLevel(0.0, 10, 2), new StimulusLevel(1.0, 10, 2), new StimulusLevel(1.000000001, 10, 8), new StimulusLevel(2.0, 10, 8) }, 0.2);
            foreach (var fit in new[] { nearChance, close })
            {
                Assert.That(fit.Estimable, Is.False);
                Assert.That(fit.Reason, Is.EqualTo("a step: with this lapse a step between levels explains the answers as well as any σ (σ → 0)"));
                Assert.That(double.IsNaN(fit.Mu) && double.IsNaN(fit.Sigma) && double.IsNaN(fit.LogLikelihood), Is.True);
            }
        }

        // A bootstrap refits each resample from the original fit's (μ, σ). Started at the maximum itself, Newton is
        // there at once; from the standard start (the levels' mean, their spread) it needs several steps.
        [TestCase(0.0)]
        [TestCase(0.04)]
        public void StartedAtItsMaximumTheFitStaysThereInAStep(double lapse)
        {
            var plain = PsychometricFit.Fit(Graded, lapse);
            Assert.That(plain.Iterations, Is.GreaterThanOrEqualTo(3), "from the standard start");
            var started = PsychometricFit.Fit(Graded, lapse, plain.Mu, plain.Sigma);
            Assert.That(started.Mu, Is.EqualTo(plain.Mu).Within(1e-12));
            Assert.That(started.Sigma, Is.EqualTo(plain.Sigma).Within(1e-12));
            if (lapse == 0) Assert.That(started.Iterations, Is.LessThanOrEqualTo(2));
        }

        // A start without σ, with σ ≤ 0 or a μ that is not a number is no start, nor one where the likelihood is 0 (every
        // level a hundred thousand σ below μ, and some of them answered heavier) or not a number (σ denormal): the fit is
        // the plain one, step for step.
        [TestCase(100.0, 0.001)]
        [TestCase(2.0, 1e-310)] // a = −∞, b = +∞: η = −∞ + ∞ is not a number
        [TestCase(1.0, null)]
        [TestCase(null, 0.1)]
        [TestCase(1.0, 0.0)]
        [TestCase(1.0, -0.1)]
        [TestCase(double.NaN, 0.1)]
        [TestCase(double.PositiveInfinity, 0.1)]
        public void AnIncompleteOrImpossibleStartIsIgnored(double? mu, double? sigma)
        {
            var plain = PsychometricFit.Fit(Graded, 0);
            var started = PsychometricFit.Fit(Graded, 0, mu, sigma);
            Assert.That(started.Mu, Is.EqualTo(plain.Mu));
            Assert.That(started.Sigma, Is.EqualTo(plain.Sigma));
            Assert.That(started.Iterations, Is.EqualTo(plain.Iterations));
        }
    
        // The likelihood with lapses is not concave: far from the maximum its Hessian is indefinite and the ascent damps
        // its Newton step until the matrix it solves is positive definite. From each start of a grid (σ from a fifth to
        // sixty times the maximum's) it reaches the maximum of Tools/check-psychometric-fit.py (σ to 1e-7, where the
        // rounding of the log-likelihood ends some of the ascents, as in "seven levels of a hundred" above).
        [Test]
        public void FromFarStartsTheAscentWithLapsesReachesTheMaximum()
        {
            var data = Lapsing;
            double mean, sd;
            var z = Standardize(Levels, out mean, out sd);
            var n = data.Select(l => l.Trials).ToArray();
            var k = data.Select(l => l.Heavier).ToArray();
            foreach (double mu in new[] { 0.7, 0.85, 1.0, 1.15, 1.3 })
                foreach (double sigma in new[] { 0.01, 0.03, 0.1, 0.3, 1, 3 })
                {
                    if ((mu == 0.7 || mu == 1.3) && sigma == 0.01) continue; // every level on one flat side of the step
                    double a = -(mu - mean) / sigma, b = sd / sigma;
                    int iterations;
                    Assert.That(PsychometricFit.Maximize(z, n, k, 0.2, ref a, ref b, out iterations), Is.True, "from " + mu + ", " + sigma);
                    Assert.That(mean - sd * a / b, Is.EqualTo(0.99964416951844726).Within(1e-9), "μ from " + mu + ", " + sigma);
                    Assert.That(sd / b, Is.EqualTo(0.052460276059148951).Within(1e-7 * 0.052460276059148951), "σ from " + mu + ", " + sigma);
                }
        }

        // Started (as a bootstrap may start it) at a lesser maximum, a step between 0.85 and 0.90, the fit still returns
        // the highest of its starts.
        [Test]
        public void StartedAtALesserMaximumTheFitReturnsTheHighest()
        {
            var fit = PsychometricFit.Fit(Lapsing, 0.2, 0.85, 0.003);
            Assert.That(fit.Mu, Is.EqualTo(0.99964416951844726).Within(1e-9));
            Assert.That(fit.LogLikelihood, Is.EqualTo(-50.137869289912493).Within(1e-12 * 50.14));
        }

        // Answers that a lapse of 0.2 explains best as a step between 1.00 and 1.05: below it every level at Ψ = 0.2, above
        // it at 0.8 (13 of 50 heavier below, 29 of 40 above). The likelihood climbs towards it as σ → 0 and has no
        // maximum; the ascent stops where its gradient vanishes (σ 0.0035 here before steps were looked for), a σ that
        // says nothing. So too three levels at 20 %, 50 % and 80 % with a lapse of 0.2: a step on the middle one.
        [Test]
        public void WithLapsesAStepBetweenLevelsIsNotEstimable()
        {
            var between = PsychometricFit.Fit(Data(10, 9, 3, 0, 0, 1, 9, 8, 7, 5), 0.2);
            var on = PsychometricFit.Fit(new[] { new StimulusLevel(0.8, 10, 2), new StimulusLevel(1.0, 10, 5), new StimulusLevel(1.2, 10, 8) }, 0.2);
            foreach (var fit in new[] { between, on })
            {
                Assert.That(fit.Estimable, Is.False);
                Assert.That(fit.Reason, Is.EqualTo("a step: with this lapse a step between levels explains the answers as well as any σ (σ → 0)"));
                Assert.That(double.IsNaN(fit.Mu) && double.IsNaN(fit.Sigma), Is.True);
            }
            // Without the lapse the same answers have a finite maximum.
            Assert.That(PsychometricFit.Fit(Data(10, 9, 3, 0, 0, 1, 9, 8, 7, 5)).Reason, Is.EqualTo("yes"));
            Assert.That(PsychometricFit.Fit(new[] { new StimulusLevel(0.8, 10, 2), new StimulusLevel(1.0, 10, 5), new StimulusLevel(1.2, 10, 8) }).Reason, Is.EqualTo("yes"));
        }

        // The likeliest step, in closed form: between levels (γ below, 1 − γ above) or on one, where Ψ is that level's
        // proportion held within [γ, 1 − γ].
        [Test]
        public void TheBestStepIsTheLikeliestPlaceBetweenOrOnALevel()
        {
            double l2 = Math.Log(0.2), l8 = Math.Log(0.8);
            // Between 1.00 and 1.05: 24 answers at 0.2's side, 66 at 0.8's.
            Assert.That(PsychometricFit.BestStepLogLik(Data(10, 9, 3, 0, 0, 1, 9, 8, 7, 5), 0.2, true), Is.EqualTo(24 * l2 + 66 * l8).Within(1e-12));
            // On 1.0, at its 3 of 10: better than between 1.0 and 1.2 (7·ln 0.2 + 23·ln 0.8).
            var three = new[] { new StimulusLevel(0.8, 10, 2), new StimulusLevel(1.0, 10, 3), new StimulusLevel(1.2, 10, 8) };
            Assert.That(PsychometricFit.BestStepLogLik(three, 0.2, true), Is.EqualTo(4 * l2 + 16 * l8 + 3 * Math.Log(0.3) + 7 * Math.Log(0.7)).Within(1e-12));
            // On 1.0 at 1 of 10, below γ: held at γ, as likely as the step between 1.0 and 1.2.
            var one = new[] { new StimulusLevel(0.8, 10, 2), new StimulusLevel(1.0, 10, 1), new StimulusLevel(1.2, 10, 10) };
            Assert.That(PsychometricFit.BestStepLogLik(one, 0.2, true), Is.EqualTo(3 * l2 + 17 * l8 + 10 * l8).Within(1e-12));
            // On the last level, all heavier: held at 1 − γ; on the first, none heavier: held at γ.
            Assert.That(PsychometricFit.BestStepLogLik(new[] { new StimulusLevel(0.8, 4, 0), new StimulusLevel(1.0, 4, 4) }, 0.2, true), Is.EqualTo(8 * l8).Within(1e-12));
            // A level without trials adds nothing wherever the step is.
            Assert.That(PsychometricFit.BestStepLogLik(new[] { new StimulusLevel(0.8, 4, 1), new StimulusLevel(0.9, 0, 0), new StimulusLevel(1.0, 4, 3) }, 0.2, true),
                Is.EqualTo(PsychometricFit.BestStepLogLik(new[] { new StimulusLevel(0.8, 4, 1), new StimulusLevel(1.0, 4, 3) }, 0.2, true)));
        }

        const string Decreasing = "decreasing: the comparison was judged heavier less often as it grew";

        // Twenty trials at eight levels, 13 of 20 heavier at the lightest, few in the middle, more again at the heaviest,
        // under a lapse of 0.2 (Tools/check-psychometric-fit.py, "falling, lapse 0.2"): a rising curve has a maximum
        // (μ 1.72, σ 0.90, −100.787), where the ascent from (0, 1) ends, but a falling one is likelier (μ 0.803, σ 0.005,
        // −98.2545): the answers fall. The grid's falling slopes find it, and the falling step is nearly as likely (at
        // `eac7763`, with neither, the fit said "yes").
        [Test]
        public void WithLapsesAFallingCurveLikelierThanAnyRisingOneIsDecreasing()
        {
            var levels = Levels.Take(8).ToArray();
            int[] heavier = { 13, 3, 4, 3, 4, 7, 10, 8 };
            var n = levels.Select(x => 20).ToArray();
            var fit = PsychometricFit.Fit(levels.Select((x, i) => new StimulusLevel(x, 20, heavier[i])).ToArray(), 0.2);
            Assert.That(fit.Reason, Is.EqualTo(Decreasing));
            Assert.That(double.IsNaN(fit.Mu) && double.IsNaN(fit.Sigma), Is.True);

            double mean, sd;
            var z = Standardize(levels, out mean, out sd);
            double a = 0, b = 1;
            int iterations;
            Assert.That(PsychometricFit.Maximize(z, n, heavier, 0.2, ref a, ref b, out iterations), Is.True);
            Assert.That(mean - sd * a / b, Is.EqualTo(1.7171342359917322).Within(1e-9 * 1.72), "the rising maximum's μ");
            Assert.That(sd / b, Is.EqualTo(0.8995551639710505).Within(1e-9 * 0.9), "the rising maximum's σ");
        }

        // 4, 5, 3 and 4 of 5 heavier at 0.80 to 0.95 under a lapse of 0.1 ("shallow fall, lapse 0.1"): a shallow fall (μ 1.105,
        // σ 0.192, −9.88048) is likelier than every rise (none has a maximum; the likeliest is flat, Ψ = 0.8 everywhere,
        // −10.008) and every step; only a start that falls finds it (with rising starts alone the fit said "a step").
        [Test]
        public void WithLapsesAShallowFallLikelierThanFlatIsDecreasing()
        {
            var levels = Levels.Take(4).ToArray();
            int[] heavier = { 4, 5, 3, 4 };
            var data = levels.Select((x, i) => new StimulusLevel(x, 5, heavier[i])).ToArray();
            Assert.That(PsychometricFit.Fit(data, 0.1).Reason, Is.EqualTo(Decreasing));
            double fallMax = -9.8804815985247132, flat = 16 * Math.Log(0.8) + 4 * Math.Log(0.2);
            Assert.That(flat, Is.LessThan(fallMax - 0.1));
            Assert.That(PsychometricFit.BestStepLogLik(data, 0.1, true), Is.LessThan(fallMax - 0.1));
            Assert.That(PsychometricFit.BestStepLogLik(data, 0.1, false), Is.LessThan(fallMax - 0.1));

            double mean, sd;
            var z = Standardize(levels, out mean, out sd);
            double a = (1.1 - mean) / 0.2, b = -sd / 0.2; // falling through 1.1 with σ 0.2
            int iterations;
            Assert.That(PsychometricFit.Maximize(z, new[] { 5, 5, 5, 5 }, heavier, 0.1, ref a, ref b, out iterations), Is.True);
            Assert.That(mean - sd * a / b, Is.EqualTo(1.1053376235475145).Within(1e-9), "the falling maximum's μ");
            Assert.That(-sd / b, Is.EqualTo(0.19226203742447599).Within(1e-9 * 0.19), "the falling maximum's σ");
        }

        // The grid start is the likeliest point of its grid (μ at each level and halfway between neighbours, σ from 2 to 1/32
        // of the levels' spread, rising or falling), found here from Ψ in the levels' own unit, for answers that rise, fall
        // and zigzag at uneven levels (so that no two points of the grid mirror each other).
        [Test]
        public void TheGridStartIsTheLikeliestPointOfItsGrid()
        {
            double[] levels = { 0.70, 0.80, 0.85, 0.95, 1.00, 1.20 };
            var n = levels.Select(x => 10).ToArray();
            double mean, sd;
            var z = Standardize(levels, out mean, out sd);
            var centres = levels.Concat(levels.Skip(1).Select((x, i) => (x + levels[i]) / 2)).ToArray();
            var cases = new[] { (new[] { 1, 3, 4, 9, 8, 10 }, 0.05, 1), (new[] { 9, 10, 6, 2, 3, 1 }, 0.1, -1), (new[] { 1, 9, 2, 8, 3, 9 }, 0.2, 1),
                (new[] { 0, 0, 1, 9, 10, 10 }, 0.05, 1) }; // the last a steep rise: its likeliest point has σ well below the spread
            foreach (var (k, lapse, direction) in cases)
            {
                double best = double.NegativeInfinity, bestMu = double.NaN, bestSigma = double.NaN, bestSign = 0;
                foreach (double mu in centres)
                    foreach (int sign in new[] { 1, -1 })
                        for (double sigma = 2 * sd; sigma >= sd / 32; sigma /= 2)
                        {
                            double ll = LogLik(levels, n, k, lapse, mu, sigma, sign);
                            if (ll > best) { best = ll; bestMu = mu; bestSigma = sigma; bestSign = sign; }
                        }
                var start = PsychometricFit.GridStart(z, PsychometricFit.LikelihoodGrid(z, n, k, lapse));
                string data = string.Join(", ", k);
                Assert.That(Math.Sign(start[1]), Is.EqualTo(bestSign).And.EqualTo(direction), data);
                Assert.That(mean - sd * start[0] / start[1], Is.EqualTo(bestMu).Within(1e-12), "μ, " + data);
                Assert.That(sd / Math.Abs(start[1]), Is.EqualTo(bestSigma).Within(1e-12 * bestSigma), "σ, " + data);
            }
        }

        // 4, 1 and 2 of 20 heavier at 0.80, 0.85 and 0.90 under a lapse of 0.05: the likelihood climbs towards a falling
        // step on 0.80 (Ψ = 0.2 there, 0.05 above it) and has no maximum. Decreasing, as the lapse-free fit says too.
        [Test]
        public void WithLapsesAFallingStepIsDecreasing()
        {
            var data = new[] { new StimulusLevel(0.80, 20, 4), new StimulusLevel(0.85, 20, 1), new StimulusLevel(0.90, 20, 2) };
            Assert.That(PsychometricFit.Fit(data, 0.05).Reason, Is.EqualTo(Decreasing));
            Assert.That(PsychometricFit.Fit(data).Reason, Is.EqualTo(Decreasing));
            double fall = 4 * Math.Log(0.2) + 16 * Math.Log(0.8) + 3 * Math.Log(0.05) + 37 * Math.Log(0.95);
            Assert.That(PsychometricFit.BestStepLogLik(data, 0.05, false), Is.EqualTo(fall).Within(1e-12));
            // Rising, the best step is on 0.90 at 2 of 20, every level below it at γ: 5·ln 0.05 + 35·ln 0.95 + 2·ln 0.1 + 18·ln 0.9.
            double rise = 5 * Math.Log(0.05) + 35 * Math.Log(0.95) + 2 * Math.Log(0.1) + 18 * Math.Log(0.9);
            Assert.That(PsychometricFit.BestStepLogLik(data, 0.05, true), Is.EqualTo(rise).Within(1e-12));
        }

        // A falling step is a rising one with the answers turned over (k ↔ n − k), and with the levels mirrored: over 300
        // random data sets (3 to 9 levels, 0 to 12 trials each, a lapse from 0.01 to 0.4).
        [Test]
        public void AFallingStepIsARisingOneTurnedOverOrMirrored()
        {
            var rng = new SeededRandom(35);
            for (int t = 0; t < 300; t++)
            {
                int m = 3 + (int)(rng.NextDouble() * 7);
                double lapse = 0.01 + 0.39 * rng.NextDouble();
                var data = new StimulusLevel[m];
                for (int i = 0; i < m; i++)
                {
                    int trials = (int)(rng.NextDouble() * 13);
                    data[i] = new StimulusLevel(0.8 + 0.05 * i, trials, (int)(rng.NextDouble() * (trials + 1)));
                }
                var turned = data.Select(l => new StimulusLevel(l.Level, l.Trials, l.Trials - l.Heavier)).ToArray();
                var mirrored = data.Reverse().Select(l => new StimulusLevel(-l.Level, l.Trials, l.Heavier)).ToArray();
                double fall = PsychometricFit.BestStepLogLik(data, lapse, false);
                Assert.That(PsychometricFit.BestStepLogLik(turned, lapse, true), Is.EqualTo(fall).Within(1e-9 * (1 + Math.Abs(fall))), "turned over, set " + t);
                Assert.That(PsychometricFit.BestStepLogLik(mirrored, lapse, true), Is.EqualTo(fall).Within(1e-9 * (1 + Math.Abs(fall))), "mirrored, set " + t);
            }
        }

        // Every ascent cut to two iterations (the graded answers need five without lapses) stops short of the maximum, and
        // no step is as likely as where they stopped: the fit did not converge. The answers of a step, rising or falling,
        // stay a step: it is at least as likely as any point an ascent can reach.
        [TestCase(0.0)]
        [TestCase(0.04)]
        public void AscentsCutShortAreNoFit(double lapse)
        {
            var cut = PsychometricFit.Fit(Graded, lapse, null, null, 2);
            Assert.That(cut.Estimable, Is.False);
            Assert.That(cut.Reason, Is.EqualTo("the fit did not converge"));
            Assert.That(double.IsNaN(cut.Mu) && double.IsNaN(cut.LogLikelihood), Is.True);
            Assert.That(PsychometricFit.Fit(Graded, lapse, null, null, PsychometricFit.MaxIterations).Reason, Is.EqualTo("yes"));
        }

        [Test]
        public void StepsCutShortStaySteps()
        {
            var rising = PsychometricFit.Fit(Data(10, 9, 3, 0, 0, 1, 9, 8, 7, 5), 0.2, null, null, 2);
            Assert.That(rising.Reason, Is.EqualTo("a step: with this lapse a step between levels explains the answers as well as any σ (σ → 0)"));
            var falling = PsychometricFit.Fit(new[] { new StimulusLevel(0.80, 20, 4), new StimulusLevel(0.85, 20, 1), new StimulusLevel(0.90, 20, 2) }, 0.05, null, null, 2);
            Assert.That(falling.Reason, Is.EqualTo(Decreasing));
        }

        // Started at its maximum the ascent is done in its first iteration (cut to one, it still converges).
        [TestCase(0.0)]
        [TestCase(0.2)]
        public void AtItsMaximumTheAscentNeedsOneIteration(double lapse)
        {
            var data = Lapsing;
            double mean, sd;
            var z = Standardize(Levels, out mean, out sd);
            var n = data.Select(l => l.Trials).ToArray();
            var k = data.Select(l => l.Heavier).ToArray();
            double a = 0, b = 1;
            int iterations;
            Assert.That(PsychometricFit.Maximize(z, n, k, lapse, ref a, ref b, out iterations), Is.True);
            Assert.That(iterations, Is.GreaterThan(1));
            double a1 = a, b1 = b;
            Assert.That(PsychometricFit.Maximize(z, n, k, lapse, ref a, ref b, out iterations, 1), Is.True);
            Assert.That(iterations, Is.EqualTo(1));
            Assert.That(a, Is.EqualTo(a1).Within(1e-12));
            Assert.That(b, Is.EqualTo(b1).Within(1e-12 * b1));
        }

        // Climbing towards a step (the "close" answers above, a step between 1 and 1.000000001 under a lapse of 0.2), the
        // ascent gives up at its first step past b = 1e8 (1.8e9 here, in its 22nd iteration) rather than climbing on.
        [Test]
        public void TheAscentGivesUpPastASlopeOfAHundredMillion()
        {
            double[] levels = { 0.0, 1.0, 1.000000001, 2.0 };
            double mean, sd;
            var z = Standardize(levels, out mean, out sd);
            double a = 0, b = 1;
            int iterations;
            Assert.That(PsychometricFit.Maximize(z, new[] { 10, 10, 10, 10 }, new[] { 2, 2, 8, 8 }, 0.2, ref a, ref b, out iterations), Is.False);
            Assert.That(b, Is.GreaterThan(1e8).And.LessThan(1e10));
            Assert.That(iterations, Is.LessThan(30));
        }

        // A level far below the others never answered heavier, and one far above always answered heavier, are where the fit
        // puts Ψ = 0 and 1 (Φ underflows at 57 σ): they add nothing to the likelihood and move nothing.
        [Test]
        public void LevelsFarOutsideAnsweredAsExpectedMoveNothing()
        {
            var plain = PsychometricFit.Fit(Graded);
            var wider = PsychometricFit.Fit(Graded.Concat(new[] { new StimulusLevel(-5.0, 10, 0), new StimulusLevel(7.0, 10, 10) }).ToArray());
            Assert.That(wider.Estimable, Is.True, wider.Reason);
            Assert.That(wider.Mu, Is.EqualTo(plain.Mu).Within(1e-12));
            Assert.That(wider.Sigma, Is.EqualTo(plain.Sigma).Within(1e-12 * plain.Sigma));
            Assert.That(wider.LogLikelihood, Is.EqualTo(plain.LogLikelihood).Within(1e-12));
        }

        // −0 and 0 are one level, and it is written 0.
        [Test]
        public void MinusZeroAndZeroAreOneLevelZero()
        {
            var fit = PsychometricFit.Fit(new[] { new StimulusLevel(-0.0, 2, 1), new StimulusLevel(0.0, 2, 0), new StimulusLevel(0.1, 2, 2) });
            Assert.That(fit.Levels.Count, Is.EqualTo(2));
            Assert.That(fit.Levels[0].Trials, Is.EqualTo(4));
            Assert.That(1 / fit.Levels[0].Level, Is.EqualTo(double.PositiveInfinity), "+0, not −0");
        }
    }
}
