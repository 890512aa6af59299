using System;
using System.Collections.Generic;
using System.Globalization;

namespace Kosmos.PseudoHaptic.Evaluation
{
    /// <summary>
    /// The fits of a trials file: one per participant × condition × standard, participants in
    /// <see cref="ParticipantOrder"/>, conditions in the order they first appear, standards ascending. Each
    /// group's bootstrap has its own seed, drawn in that order from <see cref="SeededRandom"/>(seed), so the
    /// same file and seed give the same numbers.
    /// </summary>
    public static class PsychometricAnalysis
    {
        public static IReadOnlyList<PsychometricRow> Fit(IReadOnlyList<TrialAnswer> answers, double lapse, int resamples, long seed)
            => Fit(answers, lapse, resamples, seed, null);

        /// <param name="progress">Called after each group's fit and bootstrap with (groups done, groups), for long runs.</param>
        public static IReadOnlyList<PsychometricRow> Fit(IReadOnlyList<TrialAnswer> answers, double lapse, int resamples, long seed, Action<int, int> progress)
            => Fit(answers, lapse, resamples, seed, BootstrapInterval.Bca, progress);

        /// <param name="interval">How the bootstrap's intervals are made (BCa by default).</param>
        /// <param name="progress">Called after each group's fit and bootstrap with (groups done, groups), for long runs.</param>
        public static IReadOnlyList<PsychometricRow> Fit(IReadOnlyList<TrialAnswer> answers, double lapse, int resamples, long seed, BootstrapInterval interval, Action<int, int> progress)
        {
            if (answers == null) throw new ArgumentNullException(nameof(answers));
            var conditionOrder = new Dictionary<string, int>(StringComparer.Ordinal);
            var groups = new Dictionary<string, List<TrialAnswer>>(StringComparer.Ordinal);
            var keys = new List<TrialAnswer>(); // the first answer of each group stands for it
            foreach (var a in answers)
            {
                if (!conditionOrder.ContainsKey(a.Condition)) conditionOrder.Add(a.Condition, conditionOrder.Count);
                string key = a.Participant + "\n" + a.Condition + "\n" + a.Standard.ToString("R", CultureInfo.InvariantCulture);
                List<TrialAnswer> list;
                if (!groups.TryGetValue(key, out list))
                {
                    groups.Add(key, list = new List<TrialAnswer>());
                    keys.Add(a);
                }
                list.Add(a);
            }
            keys.Sort((x, y) =>
            {
                int c = ParticipantOrder.Instance.Compare(x.Participant, y.Participant);
                if (c != 0) return c;
                c = conditionOrder[x.Condition].CompareTo(conditionOrder[y.Condition]);
                return c != 0 ? c : x.Standard.CompareTo(y.Standard);
            });
            var seeds = new SeededRandom(seed);
            var rows = new List<PsychometricRow>(keys.Count);
            foreach (var k in keys)
            {
                var list = groups[k.Participant + "\n" + k.Condition + "\n" + k.Standard.ToString("R", CultureInfo.InvariantCulture)];
                var x = new double[list.Count];
                var y = new int[list.Count];
                for (int i = 0; i < list.Count; i++) { x[i] = list[i].Comparison; y[i] = list[i].Response; }
                var fit = PsychometricFit.Fit(x, y, lapse);
                long groupSeed = unchecked((long)seeds.NextUInt64());
                var boot = PsychometricBootstrap.Run(fit, resamples, groupSeed, 0.95, interval);
                rows.Add(new PsychometricRow(k.Participant, k.Condition, k.Standard, fit, boot));
                progress?.Invoke(rows.Count, keys.Count);
            }
            return rows;
        }
    }
}
