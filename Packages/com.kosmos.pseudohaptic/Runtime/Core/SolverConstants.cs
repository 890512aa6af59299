namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// What a solver derives once, at configuration, from the object, the user and the profile, so that no
    /// step recomputes an exponential or a ratio.
    /// </summary>
    public readonly struct SolverConstants
    {
        /// <summary>G: the object's displacement per metre of hand displacement (Eq. 4–6, capped).</summary>
        public readonly double Gain;

        /// <summary>The user's standard speed v_std, m/s.</summary>
        public readonly double StandardSpeed;

        /// <summary>Largest object speed <see cref="SpeedCap"/> allows, m/s (infinity without it).</summary>
        public readonly double CapSpeed;

        /// <summary>Half-width of <see cref="MotionDeadband"/>, m (0 without it).</summary>
        public readonly double DeadbandWidth;

        public readonly SolverLimits Limits;

        /// <summary>Distance from the object's pivot down to its lowest point, m (<see cref="WeightSolver.BottomBelowPivot"/>).</summary>
        public readonly double BottomBelowPivot;

        /// <summary>ln G, for effects that reshape the gain (<see cref="FasterMovesFurther"/>); −∞ when G is 0.</summary>
        public readonly double LogGain;

        /// <summary><see cref="OffsetCorrection"/>'s threshold for this object, m (<see cref="OffsetCorrection.ThresholdFor"/>; 0 without it).</summary>
        public readonly double OffsetThreshold;

        public SolverConstants(double gain, double standardSpeed, double capSpeed, double deadbandWidth, SolverLimits limits,
            double bottomBelowPivot = 0, double offsetThreshold = 0)
        {
            BottomBelowPivot = bottomBelowPivot;
            OffsetThreshold = offsetThreshold;
            LogGain = System.Math.Log(gain); // the gain is never negative: 0 gives −∞
            Gain = gain;
            StandardSpeed = standardSpeed;
            CapSpeed = capSpeed;
            DeadbandWidth = deadbandWidth;
            Limits = limits;
        }

        /// <summary>The same constants for another pivot depth.</summary>
        internal SolverConstants WithBottomBelowPivot(double bottom)
            => new SolverConstants(Gain, StandardSpeed, CapSpeed, DeadbandWidth, Limits, bottom, OffsetThreshold);
    }
}
