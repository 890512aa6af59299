namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// What a solver derives once, at configuration, from the object, the user and the profile, so that no
    /// step recomputes an exponential or a ratio.
    /// </summary>
    public readonly struct SolverConstants
    {
        /// <summary>G: the object's displacement per metre of hand displacement.</summary>
        public readonly double Gain;

        /// <summary>The user's standard speed v_std, m/s.</summary>
        public readonly double StandardSpeed;

        /// <summary>Largest object speed <see cref="SpeedCap"/> allows, m/s (infinity without it).</summary>
        public readonly double CapSpeed;

        /// <summary>Half-width of <see cref="MotionDeadband"/>, m (0 without it).</summary>
        public readonly double DeadbandWidth;

        public readonly SolverLimits Limits;

        public SolverConstants(double gain, double standardSpeed, double capSpeed, double deadbandWidth, SolverLimits limits)
        {
            Gain = gain;
            StandardSpeed = standardSpeed;
            CapSpeed = capSpeed;
            DeadbandWidth = deadbandWidth;
            Limits = limits;
        }
    }
}
