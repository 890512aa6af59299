namespace Kosmos.PseudoHaptic
{
    /// <summary>How a held object follows the hand apart from its height (which is the solver's), engine-free.</summary>
    public static class GrabFollow
    {
        /// <summary>
        /// The object's new world position: x and z at hand + grab offset when <paramref name="follow"/> and the hand is
        /// tracked and finite; otherwise where it is. y is left to the solver.
        /// </summary>
        public static Vector3d Horizontal(Vector3d objectNow, Vector3d hand, Vector3d grabOffset, bool tracked, bool follow)
        {
            Vector3d target = hand + grabOffset;
            if (!follow || !tracked || !target.IsFinite) return objectNow;
            return new Vector3d(target.X, objectNow.Y, target.Z);
        }

        /// <summary>Whether a grab driver moves the held object's x/z itself: when asked to and the hold's solver does not (no lateral inertia).</summary>
        public static bool GrabMovesHorizontal(bool followHorizontal, HeldObject hold) =>
            followHorizontal && (hold == null || !hold.MovesHorizontal);

        /// <summary>The held object's lag behind a rigid grab: where it is minus hand + grab offset (NaN for a lost hand).</summary>
        public static Vector3d Lag(Vector3d objectNow, Vector3d hand, Vector3d grabOffset) => objectNow - (hand + grabOffset);

        /// <summary>
        /// A pinch strength from the thumb–index tip distance, for sources that report no strength (Unity XR Hands):
        /// 1 at or below <paramref name="closed"/> m, 0 at or beyond <paramref name="open"/> m, linear between; 0 for NaN or a
        /// negative distance. <paramref name="open"/> = <paramref name="closed"/> is a binary pinch.
        /// </summary>
        public static double PinchStrength(double tipDistance, double closed = 0.015, double open = 0.04)
        {
            if (!(tipDistance >= 0) || double.IsNaN(closed)) return 0;
            if (tipDistance <= closed) return 1;
            if (!(tipDistance < open)) return 0; // at or beyond open (or a NaN open)
            return (open - tipDistance) / (open - closed); // closed < distance < open: in (0, 1)
        }
    }

    /// <summary>
    /// The point a grab of several hands follows (the Interaction SDK transformer's), engine-free: the mean of the hands
    /// added, tracked (and high confidence) only when every one is. No allocation.
    /// </summary>
    public struct GrabCentre
    {
        Vector3d _sum;
        int _count;
        bool _untracked, _lowConfidence;

        public void Add(Vector3d point, bool tracked = true, bool highConfidence = true)
        {
            _sum += point;
            _count++;
            _untracked |= !tracked;
            _lowConfidence |= !highConfidence;
        }

        public int Count => _count;
        public Vector3d Point => _count > 0 ? _sum / _count : Vector3d.NaN;
        public bool IsTracked => _count > 0 && !_untracked;
        public bool IsHighConfidence => IsTracked && !_lowConfidence;
    }
}
