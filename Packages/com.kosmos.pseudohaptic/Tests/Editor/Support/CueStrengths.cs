namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>
    /// Issue 31: every rule suite (artifacts, cue rules, sideways tracking, real recordings, 3D) runs at the cue strengths
    /// s = 1/3 and 3 besides the default s = 1, on every tenth (or fifth) of its seeds: the rules hold unchanged over the
    /// whole range a user's strength may take (<see cref="WeightSolver.MinCueStrength"/> … <see cref="WeightSolver.MaxCueStrength"/>).
    /// </summary>
    internal static class CueStrengths
    {
        /// <summary>The strengths besides the default that every rule suite runs at: the bounds.</summary>
        public static readonly double[] Others = { WeightSolver.MinCueStrength, WeightSolver.MaxCueStrength };

        /// <summary>Sets the solver's cue strength and returns it.</summary>
        public static WeightSolver At(this WeightSolver solver, double cueStrength)
        {
            solver.CueStrength = cueStrength;
            return solver;
        }

        /// <summary>Sets the 3D solver's cue strength and returns it.</summary>
        public static WeightSolver3D At(this WeightSolver3D solver, double cueStrength)
        {
            solver.CueStrength = cueStrength;
            return solver;
        }
    }
}
