namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// First-order low-pass on the followed hand height, time constant τ, advanced by frame time:
    /// y += (pose − y) · dt/(τ + dt). Frame-rate independent to first order, no exponential per frame.
    /// Smooths jitter at the price of about τ of lag.
    /// </summary>
    public sealed class ExponentialSmoothing : IHandFilter
    {
        double _y;

        public double TimeConstant { get; }
        public string Name => "exponential";

        public ExponentialSmoothing(double timeConstant = 0.03)
        {
            TimeConstant = ConfigurationGuard.InRange(timeConstant, 0, 10, nameof(timeConstant));
        }

        public IHandFilter Create() => new ExponentialSmoothing(TimeConstant);

        public void Reset(double handY) => _y = handY;

        public double Filter(double poseY, bool isNewPose, double poseInterval, double dt)
        {
            _y += (poseY - _y) * (dt / (TimeConstant + dt));
            return _y;
        }
    }
}
