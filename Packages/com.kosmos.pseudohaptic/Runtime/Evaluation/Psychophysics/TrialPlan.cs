using System;
using System.Collections.Generic;
using System.Globalization;

namespace Kosmos.PseudoHaptic.Evaluation
{
    /// <summary>
    /// One two-alternative forced-choice trial: a standard and a comparison (masses in kg, or gains: one unit
    /// per file), which of the two is presented first (on the left), whether it is a catch trial, and the
    /// answer once given (1 = the comparison was judged heavier, 0 = not, −1 = not yet answered).
    /// One row of the trials file (<see cref="TrialsCsv"/>).
    /// </summary>
    public sealed class Trial
    {
        public int Index { get; }
        public string Participant { get; }
        public string Condition { get; }
        public double Standard { get; }
        public double Comparison { get; }
        /// <summary>True when the comparison is presented first (on the left), false when the standard is.</summary>
        public bool ComparisonFirst { get; }
        public bool Catch { get; }
        public int Response { get; set; } = -1;

        public Trial(int index, string participant, string condition, double standard, double comparison, bool comparisonFirst, bool isCatch)
        {
            if (!IsFinite(standard)) throw new ArgumentException("standard must be finite", nameof(standard));
            if (!IsFinite(comparison)) throw new ArgumentException("comparison must be finite", nameof(comparison));
            Index = index;
            Participant = participant ?? "";
            Condition = condition ?? "";
            Standard = standard;
            Comparison = comparison;
            ComparisonFirst = comparisonFirst;
            Catch = isCatch;
        }

        static bool IsFinite(double v) => !double.IsNaN(v) && !double.IsInfinity(v);
    }

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

    /// <summary>
    /// A transformed up-down staircase (Levitt 1971) on the comparison level: after <see cref="Down"/>
    /// consecutive "heavier" answers the comparison steps down, after one "not heavier" it steps up. With
    /// Down = 2 (1-up-2-down) it converges on the level judged heavier 70.7 % of the time (p² = ½), with
    /// Down = 3 (1-up-3-down) on 79.4 % (p³ = ½). The step is <see cref="Step"/> at first and halves at each
    /// of the first <see cref="HalvingReversals"/> reversals (never below <see cref="MinStep"/>); the run stops
    /// after <see cref="StopAfterReversals"/> reversals (or <see cref="MaxTrials"/> trials), and the threshold
    /// is the mean of the levels at the last <see cref="LastReversals"/> reversals. The order of standard and
    /// comparison is drawn from the seed for each trial. A run is reproducible from its settings, seed and
    /// answers: <see cref="Record"/> the answers again to resume one.
    /// </summary>
    public sealed class Staircase
    {
        readonly SeededRandom rng;
        readonly List<double> reversalLevels = new List<double>();
        readonly List<Trial> trials = new List<Trial>();
        int run;          // consecutive "heavier" answers at the current level
        int direction;    // +1 last step up, −1 last step down, 0 none yet
        double level, step;
        Trial pending;

        public string Participant { get; }
        public string Condition { get; }
        public double Standard { get; }
        public double Start { get; }
        public double Step => step;
        public double InitialStep { get; }
        public double MinStep { get; }
        public int Down { get; }
        public int HalvingReversals { get; }
        public int StopAfterReversals { get; }
        public int LastReversals { get; }
        public int MaxTrials { get; }
        public double MinLevel { get; }
        public double MaxLevel { get; }

        public double Level => level;
        public IReadOnlyList<double> ReversalLevels => reversalLevels;
        public IReadOnlyList<Trial> Trials => trials;
        public bool Finished => reversalLevels.Count >= StopAfterReversals || trials.Count >= MaxTrials && pending == null;
        /// <summary>The proportion "heavier" the staircase converges on: 0.5^(1/Down).</summary>
        public double TargetProbability => Math.Pow(0.5, 1.0 / Down);

        public Staircase(string participant, string condition, double standard, double start, double step, int down,
            int stopAfterReversals, int lastReversals, long seed, int halvingReversals = 2, double minStep = 0,
            int maxTrials = 200, double minLevel = double.NegativeInfinity, double maxLevel = double.PositiveInfinity)
        {
            if (down != 2 && down != 3) throw new ArgumentOutOfRangeException(nameof(down), down, "Down must be 2 (1-up-2-down) or 3 (1-up-3-down)");
            if (!(step > 0) || double.IsInfinity(step)) throw new ArgumentOutOfRangeException(nameof(step), step, "Step must be positive and finite");
            if (double.IsNaN(start) || double.IsInfinity(start)) throw new ArgumentOutOfRangeException(nameof(start), start, "Start must be finite");
            if (stopAfterReversals < 1) throw new ArgumentOutOfRangeException(nameof(stopAfterReversals), stopAfterReversals, "StopAfterReversals must be ≥ 1");
            if (lastReversals < 1 || lastReversals > stopAfterReversals) throw new ArgumentOutOfRangeException(nameof(lastReversals), lastReversals, "LastReversals must be in 1 … StopAfterReversals");
            if (halvingReversals < 0) throw new ArgumentOutOfRangeException(nameof(halvingReversals), halvingReversals, "HalvingReversals must be ≥ 0");
            if (!(minStep >= 0)) throw new ArgumentOutOfRangeException(nameof(minStep), minStep, "MinStep must be ≥ 0");
            if (maxTrials < 1) throw new ArgumentOutOfRangeException(nameof(maxTrials), maxTrials, "MaxTrials must be ≥ 1");
            Participant = participant ?? "";
            Condition = condition ?? "";
            Standard = standard;
            Start = start;
            InitialStep = step;
            MinStep = minStep;
            Down = down;
            StopAfterReversals = stopAfterReversals;
            LastReversals = lastReversals;
            HalvingReversals = halvingReversals;
            MaxTrials = maxTrials;
            MinLevel = minLevel;
            MaxLevel = maxLevel;
            rng = new SeededRandom(seed);
            level = start;
            this.step = step;
        }

        /// <summary>The next trial to present (the same one until it is answered), or null when finished.</summary>
        public Trial Next()
        {
            if (pending != null) return pending;
            if (Finished) return null;
            pending = new Trial(trials.Count + 1, Participant, Condition, Standard, level, rng.NextInt(2) == 1, false);
            return pending;
        }

        /// <summary>Records the answer to the pending trial (1 = comparison heavier) and moves the level.</summary>
        public void Record(int response)
        {
            if (response != 0 && response != 1) throw new ArgumentOutOfRangeException(nameof(response), response, "response must be 0 or 1");
            var trial = Next() ?? throw new InvalidOperationException("the staircase is finished");
            trial.Response = response;
            trials.Add(trial);
            pending = null;

            int move = 0;
            if (response == 1)
            {
                run++;
                if (run >= Down) { move = -1; run = 0; }
            }
            else
            {
                run = 0;
                move = +1;
            }
            if (move == 0) return;
            if (direction != 0 && move != direction)
            {
                reversalLevels.Add(level);
                if (reversalLevels.Count <= HalvingReversals) step = Math.Max(MinStep, step / 2);
            }
            direction = move;
            level = Math.Min(MaxLevel, Math.Max(MinLevel, level + move * step));
        }

        /// <summary>Mean of the levels at the last <see cref="LastReversals"/> reversals; NaN before there are that many.</summary>
        public double Threshold
        {
            get
            {
                if (reversalLevels.Count < LastReversals) return double.NaN;
                double sum = 0;
                for (int i = reversalLevels.Count - LastReversals; i < reversalLevels.Count; i++) sum += reversalLevels[i];
                return sum / LastReversals;
            }
        }
    }

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
