using System;

namespace Kosmos.PseudoHaptic.Evaluation
{
    /// <summary>How the comparisons of a discrimination task are chosen.</summary>
    public enum DiscriminationProcedure
    {
        /// <summary>The method of constant stimuli: the levels, in a seeded order.</summary>
        ConstantStimuli,
        /// <summary>A 1-up-2-down staircase (converges on 70.7 % "heavier").</summary>
        Staircase1Up2Down,
        /// <summary>A 1-up-3-down staircase (converges on 79.4 % "heavier").</summary>
        Staircase1Up3Down,
    }

    /// <summary>
    /// The settings of the in-headset discrimination task (the component's inspector fields, engine-free) and
    /// what they give: a <see cref="ConstantStimuliPlan"/> or a <see cref="Staircase"/>, and the
    /// <see cref="DiscriminationSession"/> that runs it. The same settings and seed give the same trials.
    /// </summary>
    public sealed class DiscriminationSettings
    {
        /// <summary>The smallest comparison a staircase may reach, kg.</summary>
        public const double StaircaseMinLevel = 0.001;

        public DiscriminationProcedure Procedure;
        public double StandardKg;
        public double[] ComparisonKg;
        public int Repetitions;
        public double[] CatchKg;
        public int CatchRepetitions;
        public int Seed;
        public double StaircaseStartKg, StaircaseStepKg, MinStepKg;
        public int HalvingReversals, StopAfterReversals, LastReversals, MaxTrials;

        /// <summary>The constant-stimuli plan these settings give (null level arrays are empty).</summary>
        public ConstantStimuliPlan Plan() => new ConstantStimuliPlan
        {
            Standard = StandardKg,
            Levels = ComparisonKg ?? new double[0],
            Repetitions = Repetitions,
            CatchLevels = CatchKg ?? new double[0],
            CatchRepetitions = CatchRepetitions,
            Seed = Seed,
        };

        /// <summary>The staircase these settings give for a participant and condition: 1-up-3-down for <see cref="DiscriminationProcedure.Staircase1Up3Down"/>, else 1-up-2-down.</summary>
        public Staircase MakeStaircase(string participant, string condition) => new Staircase(
            participant, condition, StandardKg, StaircaseStartKg, StaircaseStepKg,
            Procedure == DiscriminationProcedure.Staircase1Up3Down ? 3 : 2, StopAfterReversals, LastReversals, Seed,
            HalvingReversals, MinStepKg, MaxTrials, minLevel: StaircaseMinLevel);

        /// <summary>A session of <paramref name="participant"/> in <paramref name="condition"/> over the plan or the staircase; throws as <see cref="DiscriminationSession"/> does.</summary>
        public DiscriminationSession CreateSession(string participant, string condition, string trialsPath)
            => Procedure == DiscriminationProcedure.ConstantStimuli
                ? new DiscriminationSession(participant, condition, trialsPath, Plan())
                : new DiscriminationSession(participant, condition, trialsPath, MakeStaircase);
    }
}
