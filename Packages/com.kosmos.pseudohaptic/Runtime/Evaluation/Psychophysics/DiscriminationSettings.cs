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
    /// <see cref="DiscriminationSession"/> that runs it. <see cref="Seed"/> is the study's: each participant and condition
    /// runs in its own order drawn from it (<see cref="SessionSeed"/>), the same on every device and after a resume, so
    /// that order effects are not the same for everyone. The same settings, seed, participant and condition give the same trials.
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

        /// <summary>The constant-stimuli plan these settings give, at the study's <see cref="Seed"/> (null level arrays are empty).</summary>
        public ConstantStimuliPlan Plan() => Plan(Seed);

        /// <summary>The plan <paramref name="participant"/> runs in <paramref name="condition"/>: at their <see cref="SessionSeed"/>.</summary>
        public ConstantStimuliPlan PlanFor(string participant, string condition) => Plan(SessionSeed(Seed, participant, condition));

        ConstantStimuliPlan Plan(long seed) => new ConstantStimuliPlan
        {
            Standard = StandardKg,
            Levels = ComparisonKg ?? new double[0],
            Repetitions = Repetitions,
            CatchLevels = CatchKg ?? new double[0],
            CatchRepetitions = CatchRepetitions,
            Seed = seed,
        };

        /// <summary>The staircase these settings give for a participant and condition, at their <see cref="SessionSeed"/>: 1-up-3-down for <see cref="DiscriminationProcedure.Staircase1Up3Down"/>, else 1-up-2-down.</summary>
        public Staircase MakeStaircase(string participant, string condition) => new Staircase(
            participant, condition, StandardKg, StaircaseStartKg, StaircaseStepKg,
            Procedure == DiscriminationProcedure.Staircase1Up3Down ? 3 : 2, StopAfterReversals, LastReversals, SessionSeed(Seed, participant, condition),
            HalvingReversals, MinStepKg, MaxTrials, minLevel: StaircaseMinLevel);

        /// <summary>A session of <paramref name="participant"/> in <paramref name="condition"/> over their plan or staircase; throws as <see cref="DiscriminationSession"/> does.</summary>
        public DiscriminationSession CreateSession(string participant, string condition, string trialsPath)
            => Procedure == DiscriminationProcedure.ConstantStimuli
                ? new DiscriminationSession(participant, condition, trialsPath, PlanFor(participant, condition))
                : new DiscriminationSession(participant, condition, trialsPath, MakeStaircase);

        /// <summary>
        /// The seed of <paramref name="participant"/>'s session in <paramref name="condition"/>: the study's
        /// <paramref name="seed"/> mixed with both names (64-bit FNV-1a over their UTF-16 code units, each name closed by its
        /// length, so "P1"+"0" and "P"+"10" differ), stable across runtimes (unlike <see cref="string.GetHashCode()"/>).
        /// </summary>
        public static long SessionSeed(long seed, string participant, string condition)
        {
            ulong h = 14695981039346656037UL;
            h = Fnv(h, participant ?? "");
            h = Fnv(h, condition ?? "");
            return (long)(h ^ unchecked((ulong)seed * 0x9E3779B97F4A7C15UL));
        }

        static ulong Fnv(ulong h, string text)
        {
            for (int i = 0; i < text.Length; i++) h = (h ^ text[i]) * 1099511628211UL;
            return (h ^ (ulong)text.Length) * 1099511628211UL;
        }
    }
}
