namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// Mean of the <see cref="Count"/> latest poses. It advances on new poses only, so a 30 Hz pose held over
    /// 72–120 Hz frames counts once whatever the frame rate. On a ramp sampled every T it lags by (N − 1)·T/2
    /// (33 ms for N = 3 at 30 Hz, 67 ms for N = 5); at rest it divides white jitter's standard deviation by √N.
    /// The sum is recomputed over the N slots on each new pose (N ≤ 256): no running sum to drift in long holds.
    /// </summary>
    public sealed class MovingAverage : IHandFilter
    {
        public const int MaxCount = 256;

        readonly double[] _poses;
        int _next;
        double _mean;

        /// <summary>How many of the latest poses are averaged.</summary>
        public int Count { get; }
        public string Name => "moving-average-" + Count;

        public MovingAverage(int count = 5)
        {
            Count = (int)ConfigurationGuard.InRange(count, 1, MaxCount, nameof(count));
            _poses = new double[Count];
        }

        public IHandFilter Create() => new MovingAverage(Count);

        /// <summary>The hand has been at <paramref name="handY"/> for the last N poses.</summary>
        public void Reset(double handY)
        {
            for (int i = 0; i < _poses.Length; i++) _poses[i] = handY;
            _next = 0;
            _mean = handY;
        }

        public double Filter(double poseY, bool isNewPose, double poseInterval, double dt)
        {
            if (!isNewPose) return _mean;
            _poses[_next] = poseY;
            _next = _next + 1 == _poses.Length ? 0 : _next + 1;
            double sum = 0;
            for (int i = 0; i < _poses.Length; i++) sum += _poses[i];
            _mean = sum / _poses.Length;
            return _mean;
        }
    }
}
