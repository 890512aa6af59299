using System;

namespace Kosmos.PseudoHaptic.Evaluation
{
    /// <summary>One row of fits.csv: the fit of one participant × condition × standard, with its bootstrap.</summary>
    public sealed class PsychometricRow
    {
        public string Participant { get; }
        public string Condition { get; }
        public double Standard { get; }
        public PsychometricFit Fit { get; }
        public PsychometricBootstrap Bootstrap { get; }
        public double Weber => Fit.Jnd / Standard;

        public PsychometricRow(string participant, string condition, double standard, PsychometricFit fit, PsychometricBootstrap bootstrap)
        {
            Participant = participant;
            Condition = condition;
            Standard = standard;
            Fit = fit;
            Bootstrap = bootstrap;
        }
    }
}
