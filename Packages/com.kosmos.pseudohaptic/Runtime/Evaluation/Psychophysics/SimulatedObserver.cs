using System;
using System.Collections.Generic;

namespace Kosmos.PseudoHaptic.Evaluation
{
    /// <summary>
    /// A simulated participant for tests and worked examples: answers "heavier" with probability
    /// Ψ(x) = λ + (1 − 2λ)·Φ((x − PSE)/σ), from their own seeded generator.
    /// </summary>
    public sealed class SimulatedObserver
    {
        readonly SeededRandom rng;
        public double Pse { get; }
        public double Sigma { get; }
        public double Lapse { get; }

        public SimulatedObserver(double pse, double sigma, long seed, double lapse = 0)
        {
            if (!(sigma > 0)) throw new ArgumentOutOfRangeException(nameof(sigma), sigma, "sigma must be positive");
            if (!(lapse >= 0 && lapse < 0.5)) throw new ArgumentOutOfRangeException(nameof(lapse), lapse, "lapse must be in [0, 0.5)");
            Pse = pse;
            Sigma = sigma;
            Lapse = lapse;
            rng = new SeededRandom(seed);
        }

        public double Probability(double comparison) => Lapse + (1 - 2 * Lapse) * Normal.Cdf((comparison - Pse) / Sigma);

        /// <summary>1 when this comparison is judged heavier than the standard.</summary>
        public int Answer(double comparison) => rng.NextDouble() < Probability(comparison) ? 1 : 0;

        /// <summary>Answers every trial of a plan in place.</summary>
        public void AnswerAll(IEnumerable<Trial> trials)
        {
            foreach (var t in trials) t.Response = Answer(t.Comparison);
        }
    }
}
