namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// An optional smoother of the hand height the solver follows, between the estimator (which detects new
    /// poses, gaps and glitches) and the effects. Called once per frame while the hand is usable; after a
    /// re-anchor it is reset to the new pose. It trades lag for smoothness: ALGORITHM.md and
    /// accuracy-vs-time.md say at what price. A profile holds a prototype; each solver gets its own instance
    /// from <see cref="Create"/>, so per-hold state lives in the instance and nothing is allocated per frame.
    /// </summary>
    public interface IHandFilter
    {
        /// <summary>Short, stable name used in tables and on the command line.</summary>
        string Name { get; }

        /// <summary>A fresh instance with the same settings, for one solver.</summary>
        IHandFilter Create();

        /// <summary>Forget the past: the hand is at <paramref name="handY"/>.</summary>
        void Reset(double handY);

        /// <summary>
        /// The followed height this frame, given the latest pose <paramref name="poseY"/>, whether it is new this
        /// frame, the interval it covers (s, 0 when not new) and the frame time <paramref name="dt"/> (s, ≥ 0).
        /// Must return a finite value for finite input, never allocate and never throw.
        /// </summary>
        double Filter(double poseY, bool isNewPose, double poseInterval, double dt);
    }
}
