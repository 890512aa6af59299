using System;
using System.Collections.Generic;

namespace Kosmos.PseudoHaptic.Evaluation
{
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
}
