using System;
using System.Collections.Generic;

namespace Kosmos.PseudoHaptic.Evaluation
{
    /// <summary>One row of comparisons.csv: a pair of conditions of one questionnaire, or (<see cref="Friedman"/> set) the omnibus test.</summary>
    public sealed class ComparisonRow
    {
        public string Questionnaire { get; }
        public string ConditionA { get; }
        public string ConditionB { get; }
        public PairedComparison Pair { get; }
        public FriedmanTest Friedman { get; }
        public double PHolm { get; internal set; } = double.NaN;
        /// <summary>The participants of the pair, aligned with <see cref="A"/> and <see cref="B"/>.</summary>
        public IReadOnlyList<string> Participants { get; }
        public IReadOnlyList<double> A { get; }
        public IReadOnlyList<double> B { get; }

        internal ComparisonRow(string questionnaire, string a, string b, PairedComparison pair, FriedmanTest friedman, IReadOnlyList<string> participants, IReadOnlyList<double> va, IReadOnlyList<double> vb)
        {
            Questionnaire = questionnaire;
            ConditionA = a;
            ConditionB = b;
            Pair = pair;
            Friedman = friedman;
            Participants = participants;
            A = va;
            B = vb;
        }

        /// <summary>The method column: friedman; t+wilcoxon-exact; t+wilcoxon-normal; or what could be computed.</summary>
        public string Method
        {
            get
            {
                if (Friedman != null) return double.IsNaN(Friedman.Statistic) ? "friedman-undefined" : "friedman";
                bool t = !double.IsNaN(Pair.T), w = !double.IsNaN(Pair.WP);
                string wilcoxon = Pair.WilcoxonExact ? "wilcoxon-exact" : "wilcoxon-normal";
                if (t && w) return "t+" + wilcoxon;
                if (t) return "t";
                if (w) return wilcoxon;
                return "none";
            }
        }
    }
}
