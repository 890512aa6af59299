namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// One rendered frame's view of one tracked hand in three dimensions, in the held object's parent space
    /// (y up), for <see cref="WeightSolver3D"/>. Any field may be garbage: the solver absorbs it.
    /// </summary>
    public readonly struct HandPose
    {
        public readonly double X;
        public readonly double Y;
        public readonly double Z;
        public readonly bool IsTracked;
        public readonly bool IsHighConfidence;

        /// <summary>When the pose was sampled, s, on the frames' clock; NaN when unknown.</summary>
        public readonly double PoseTime;

        public HandPose(double x, double y, double z, bool isTracked = true, bool isHighConfidence = true, double poseTime = double.NaN)
        {
            X = x;
            Y = y;
            Z = z;
            IsTracked = isTracked;
            IsHighConfidence = isHighConfidence;
            PoseTime = poseTime;
        }

        /// <summary>No hand: not tracked, no confidence, no position.</summary>
        public static HandPose Lost => new HandPose(double.NaN, double.NaN, double.NaN, false, false);

        /// <summary>Tracked, with every coordinate finite and strictly within ±<see cref="WeightSolver.MaxCoordinate"/>.</summary>
        public bool IsUsable => IsTracked && HandSample.IsUsableHeight(X) && HandSample.IsUsableHeight(Y) && HandSample.IsUsableHeight(Z);
    }
}
