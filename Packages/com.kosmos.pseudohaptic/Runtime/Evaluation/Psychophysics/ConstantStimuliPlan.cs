using System;
using System.Collections.Generic;

namespace Kosmos.PseudoHaptic.Evaluation
{
    /// <summary>
    /// The method of constant stimuli: every comparison level presented <see cref="Repetitions"/> times against
    /// the standard, plus optional catch trials (comparisons far enough from the standard that an attentive
    /// participant cannot miss, e.g. 0.5× and 2×, used to check attention), in a seeded random order. Within
    /// each level the order of standard and comparison is counterbalanced: half the repetitions present the
    /// comparison first, half the standard (with an odd count the extra one is drawn from the seed). The same
    /// settings and seed give the same plan on every runtime.
    /// </summary>
    public sealed class ConstantStimuliPlan
    {
        public double Standard { get; set; } = 1;
        public double[] Levels { get; set; } = { 0.7, 0.8, 0.9, 1.0, 1.1, 1.2, 1.3 };
        public int Repetitions { get; set; } = 12;
        public double[] CatchLevels { get; set; } = new double[0];
        /// <summary>Repetitions of each catch level.</summary>
        public int CatchRepetitions { get; set; }
        public long Seed { get; set; }

        public IReadOnlyList<Trial> Build(string participant, string condition = "")
        {
            if (double.IsNaN(Standard) || double.IsInfinity(Standard)) throw new ArgumentException("Standard must be finite");
            if (Levels == null || Levels.Length == 0) throw new ArgumentException("Levels must not be empty");
            if (Repetitions < 1) throw new ArgumentException("Repetitions must be at least 1");
            if (CatchRepetitions < 0) throw new ArgumentException("CatchRepetitions must be ≥ 0");
            var rng = new SeededRandom(Seed);
            var items = new List<KeyValuePair<double, bool>>(); // (comparison, first) before shuffling
            var catches = new List<bool>();
            AddLevels(rng, Levels, Repetitions, false, items, catches);
            if (CatchLevels != null && CatchRepetitions > 0) AddLevels(rng, CatchLevels, CatchRepetitions, true, items, catches);

            var order = new int[items.Count];
            for (int i = 0; i < order.Length; i++) order[i] = i;
            rng.Shuffle(order);
            var trials = new List<Trial>(order.Length);
            for (int i = 0; i < order.Length; i++)
            {
                var item = items[order[i]];
                trials.Add(new Trial(i + 1, participant, condition, Standard, item.Key, item.Value, catches[order[i]]));
            }
            return trials;
        }

        static void AddLevels(SeededRandom rng, double[] levels, int repetitions, bool isCatch, List<KeyValuePair<double, bool>> items, List<bool> catches)
        {
            foreach (double level in levels)
            {
                if (double.IsNaN(level) || double.IsInfinity(level)) throw new ArgumentException("levels must be finite");
                int comparisonFirst = repetitions / 2;
                if (repetitions % 2 == 1 && rng.NextInt(2) == 1) comparisonFirst++;
                for (int r = 0; r < repetitions; r++)
                {
                    items.Add(new KeyValuePair<double, bool>(level, r < comparisonFirst));
                    catches.Add(isCatch);
                }
            }
        }
    }
}
