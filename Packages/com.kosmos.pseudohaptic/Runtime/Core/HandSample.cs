namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// One rendered frame's view of the tracked hand: its height in the held object's parent space, whether
    /// it is tracked and with high confidence, and, if known, when the pose was sampled. At 72–120 Hz
    /// rendering the same 30 Hz pose repeats over several frames; <see cref="PoseTime"/> tells repeats apart.
    /// Any field may be garbage (NaN, infinite): the solver absorbs it.
    /// </summary>
    public readonly struct HandSample
    {
        /// <summary>Hand height, metres, in the held object's parent space.</summary>
        public readonly double Y;
        public readonly bool IsTracked;
        public readonly bool IsHighConfidence;

        /// <summary>When the pose was sampled, seconds, on the same clock as the frames; NaN when unknown.</summary>
        public readonly double PoseTime;

        public HandSample(double y, bool isTracked = true, bool isHighConfidence = true, double poseTime = double.NaN)
        {
            Y = y;
            IsTracked = isTracked;
            IsHighConfidence = isHighConfidence;
            PoseTime = poseTime;
        }

        /// <summary>No hand: not tracked, no confidence, no height.</summary>
        public static HandSample Lost => new HandSample(double.NaN, false, false);

        /// <summary>A height the solver can follow: finite and strictly within ±<see cref="WeightSolver.MaxCoordinate"/> (10⁵ m itself is not).</summary>
        public static bool IsUsableHeight(double y) => System.Math.Abs(y) < WeightSolver.MaxCoordinate; // NaN compares false: not usable

        /// <summary>The solver can follow this pose: tracked, with a usable height (confidence is an effect's call).</summary>
        public bool IsUsable => IsTracked && IsUsableHeight(Y);
    }
}
