namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// A constant-velocity alpha-beta tracker of the hand height: per new pose z after interval T,
    /// predict x ← x + v·T, then correct with the residual r = z − x: x ← x + α·r, v ← v + (β/T)·r.
    /// It is the steady-state form of the two-state (height, speed) Kalman filter with white-acceleration
    /// noise (Kalata 1984): with poses at a steady 30 Hz the Kalman gains converge to constant α, β within a
    /// few poses, so a full Kalman filter would spend a 2×2 covariance update per pose to arrive at the same
    /// two numbers. Chosen for that, and because α and β are easy to state: β follows Benedict–Bordner,
    /// β = α²/(2 − α), a good lag/overshoot compromise, and α = 0.6 came out of the sweep in
    /// accuracy-vs-time.md (0.5 added more than 40 ms of lag on fast lifts). Tracks a ramp with no steady-state
    /// lag, smooths white jitter (σ × 0.71 at the defaults) and overshoots briefly when the hand stops.
    /// Runs on new poses only; T is clamped to [1 ms, 100 ms] so a stalled or sub-millisecond pose clock
    /// cannot throw the speed estimate.
    /// </summary>
    public sealed class AlphaBetaFilter : IHandFilter
    {
        const double MinInterval = 0.001, MaxInterval = 0.1;

        double _x;   // height, m
        double _v;   // speed, m/s

        /// <summary>Position gain, in (0, 1]: 1 follows each pose exactly.</summary>
        public double Alpha { get; }

        /// <summary>Speed gain, in [0, 2 − α] (stricter than the stability bound 4 − 2α: no ringing).</summary>
        public double Beta { get; }

        public string Name => "alpha-beta";

        public AlphaBetaFilter(double alpha = 0.6, double beta = 0.6 * 0.6 / (2 - 0.6))
        {
            Alpha = ConfigurationGuard.InRange(alpha, 1e-3, 1, nameof(alpha));
            Beta = ConfigurationGuard.InRange(beta, 0, 2 - Alpha, nameof(beta));
        }

        public IHandFilter Create() => new AlphaBetaFilter(Alpha, Beta);

        public void Reset(double handY)
        {
            _x = handY;
            _v = 0;
        }

        public double Filter(double poseY, bool isNewPose, double poseInterval, double dt)
        {
            if (!isNewPose) return _x;
            double t = !(poseInterval >= MinInterval) ? MinInterval : (poseInterval > MaxInterval ? MaxInterval : poseInterval);
            double predicted = _x + _v * t;
            double residual = poseY - predicted;
            _x = predicted + Alpha * residual;
            _v += Beta / t * residual;
            return _x;
        }
    }
}
