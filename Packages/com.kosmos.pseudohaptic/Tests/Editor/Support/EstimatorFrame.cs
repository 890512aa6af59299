namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>One frame through a <see cref="PoseDeltaEstimator"/> as the solver feeds it, with the default limits (a hand
    /// moves at most 10 m/s): the estimator's fixtures share it (<c>using static</c>).</summary>
    internal static class EstimatorFrame
    {
        public static MotionFrame Frame(ref PoseDeltaEstimator e, double y, double poseTime, double dt, bool usable = true)
        {
            var f = new MotionFrame { Dt = dt, PoseY = y, PoseTime = poseTime, Usable = usable, IsHighConfidence = true };
            e.Update(ref f, SolverLimits.Default);
            return f;
        }
    }
}
