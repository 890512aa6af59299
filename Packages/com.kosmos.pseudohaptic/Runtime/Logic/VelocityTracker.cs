namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// Velocity of a tracked point for the release velocity. Hand poses arrive at 30 Hz while frames run at
    /// 72–120 Hz, so a repeated position carries no information: the velocity is measured between position
    /// changes at least <see cref="Window"/> seconds apart, and reads as zero once the point has not moved for
    /// <see cref="StillAfter"/> seconds. Always finite; no allocation.
    /// </summary>
    public struct VelocityTracker
    {
        public const double Window = 0.05;
        public const double StillAfter = 0.1;

        Vector3d _anchor, _last;
        double _anchorTime, _lastTime;
        Vector3d _velocity;
        bool _hasAnchor;

        /// <summary>The velocity at time <paramref name="now"/> (same clock as <see cref="Add"/>): zero from
        /// <see cref="StillAfter"/> seconds after the last change of position on.</summary>
        public Vector3d VelocityAt(double now) =>
            _hasAnchor && now - _lastTime < StillAfter ? _velocity : Vector3d.Zero;

        public void Reset(Vector3d position, double time)
        {
            _velocity = Vector3d.Zero;
            _hasAnchor = position.IsFinite && double.IsFinite(time);
            _anchor = _last = position;
            _anchorTime = _lastTime = time;
        }

        public void Add(Vector3d position, double time)
        {
            if (!position.IsFinite || !double.IsFinite(time)) return;
            if (!_hasAnchor || time < _lastTime) { Reset(position, time); return; }
            if (position.Equals(_last)) return; // a repeated pose
            _last = position;
            _lastTime = time;
            double elapsed = time - _anchorTime;
            if (elapsed < Window) return;
            Vector3d v = (position - _anchor) / elapsed;
            if (v.IsFinite) _velocity = v;
            _anchor = position;
            _anchorTime = time;
        }
    }
}
