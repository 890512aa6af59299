using System;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// Whether a hand could have got to a pose (P8): within <see cref="SolverLimits.MaxHandSpeed"/> over the time since the
    /// last accepted pose, judged over at least one 30 Hz pose period (a step under 10 m/s × 33 ms = 33 cm is always
    /// reachable) and at most 50 ms plus the time the hand was lost, refused or hitched (a long still spell without pose
    /// timestamps does not license a teleport, but a hand that moved while unseen is followed once a hand could have got
    /// there). A pose that is out of reach of the last accepted one but within reach of the one before it is accepted too:
    /// the last one was the glitch (a glitched pose accepted right after a loss must not lock the real hand out). And a pose
    /// within reach of the last refused one is accepted: a hand seen twice in a row at its new place is there.
    /// Plain values: it lives inside the solvers' state and allocates nothing.
    /// </summary>
    public struct Reach
    {
        bool _has, _hasPrior;
        double _x, _y, _z, _since, _lost;            // the last accepted pose, the time since, the time lost since
        double _px, _py, _pz, _sincePrior, _lostPrior; // the one before it
        bool _hasRefused;
        double _rx, _ry, _rz, _sinceRefused;          // the last refused pose
        double _frame;                                // the part of this frame's time not yet counted as unseen

        public bool HasPose => _has;

        /// <summary>Forgets every pose: the next one is accepted.</summary>
        public void Reset() => this = default;

        /// <summary>A frame of <paramref name="dt"/> s passed. It counts as time the hand was unseen when it was lost (or its
        /// pose refused: call <see cref="Miss"/>), and beyond <paramref name="longestFrame"/> anyway (a hitch).</summary>
        public void Tick(double dt, double longestFrame)
        {
            _since += dt;
            _sincePrior += dt;
            _sinceRefused += dt;
            if (dt > longestFrame) Unseen(dt - longestFrame);
            _frame = dt < longestFrame ? dt : longestFrame;
        }

        /// <summary>This frame the hand was lost, or its pose refused: all of the frame's time was unseen.</summary>
        public void Miss() => Unseen(_frame);

        void Unseen(double dt)
        {
            _lost += dt;
            _lostPrior += dt;
        }

        /// <summary>Accepts the pose when a hand moving at most <paramref name="maxSpeed"/> m/s could have got there.</summary>
        public bool TryAccept(double x, double y, double z, double maxSpeed)
        {
            // The same pose again (a 30 Hz pose over faster frames) is within any reach: Within would say so.
            if (!_has || (x == _x && y == _y && z == _z) || Within(x, y, z, _x, _y, _z, _since, _lost, maxSpeed))
            {
                _px = _x; _py = _y; _pz = _z; _sincePrior = _since; _lostPrior = _lost; _hasPrior = _has;
                Take(x, y, z);
                return true;
            }
            if (_hasPrior && Within(x, y, z, _px, _py, _pz, _sincePrior, _lostPrior, maxSpeed))
            {
                Take(x, y, z); // the last accepted pose was the outlier; the one before it stays the prior
                return true;
            }
            bool seenThere = _hasRefused && (x != _rx || y != _ry || z != _rz) && Within(x, y, z, _rx, _ry, _rz, _sinceRefused, 0, maxSpeed);
            if (seenThere)
            {
                _hasPrior = false;
                Take(x, y, z);
                return true;
            }
            if (!_hasRefused || x != _rx || y != _ry || z != _rz) { _rx = x; _ry = y; _rz = z; _sinceRefused = 0; }
            _hasRefused = true;
            return false;
        }

        void Take(double x, double y, double z)
        {
            _x = x; _y = y; _z = z;
            _since = _lost = 0;
            _has = true;
            _hasRefused = false;
        }

        static bool Within(double x, double y, double z, double fx, double fy, double fz, double since, double lost, double maxSpeed)
        {
            double dx = x - fx, dy = y - fy, dz = z - fz, d2 = dx * dx + dy * dy + dz * dz;
            // Within the shortest window's reach is within every window's (the products are monotone): almost every pose,
            // decided without the window.
            double least = maxSpeed * SolverLimits.MinJumpWindow;
            if (d2 <= least * least) return true;
            double window = Math.Max(SolverLimits.MinJumpWindow, Math.Min(since, SolverLimits.JumpWindow + lost));
            double reach = maxSpeed * window;
            return d2 <= reach * reach;
        }
    }
}
