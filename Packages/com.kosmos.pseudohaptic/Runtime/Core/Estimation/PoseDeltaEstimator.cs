using System;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// The default estimator of the hand's vertical motion: it follows each new pose's exact displacement in
    /// the frame the pose arrives and measures speed against the pose's own timestamps (design note §6).
    /// Repeated poses (30 Hz tracking under 72–120 Hz frames) move nothing and never read as a stop
    /// followed by a spike. Total displacement is conserved, so any frame clock ends in the same place (P7).
    /// It re-anchors (follows the hand from where it is now, without moving the object) after a loss or a
    /// hitch longer than <see cref="SolverLimits.MaxCatchUpGap"/>, on a pose clock that steps back, and on a
    /// pose that would need an impossible hand speed (P8).
    /// </summary>
    public struct PoseDeltaEstimator
    {
        double _poseY;
        double _poseTime;       // NaN when the source gives no pose timestamps
        double _sincePose;      // frame time since the last new pose, s
        double _lostFor;        // frame time since tracking was lost, s
        double _speed;          // the last pose-to-pose speed, m/s
        bool _hasPose;
        bool _lost;

        /// <summary>A hand that has shown no new pose for this long is taken as still, s.</summary>
        const double StillAfter = 0.1;

        /// <summary>The shortest pose period assumed when poses carry no timestamp: Quest tracks hands at 60 Hz at most.</summary>
        const double MinPosePeriod = 1.0 / 60;

        /// <summary>The hand's height as followed, m.</summary>
        public double HandY => _poseY;

        public bool HasPose => _hasPose;

        /// <summary>The hand's last pose-to-pose speed, m/s, kept over repeated poses; 0 once no new pose came for 0.1 s.</summary>
        public double Speed => _sincePose > StillAfter || _lost ? 0 : _speed;

        /// <summary>Starts over at the pose <paramref name="handY"/> taken at <paramref name="poseTime"/>. When the hand is
        /// not tracked (<paramref name="handY"/> not finite), the hand is taken to be at <paramref name="untrackedHandY"/>
        /// until a pose comes (the solver passes the object's height: nothing pulls the object toward a hand never seen),
        /// and the first pose re-anchors.</summary>
        public void Reset(double handY, double poseTime, double untrackedHandY = 0)
        {
            _hasPose = double.IsFinite(handY);
            _poseY = _hasPose ? handY : untrackedHandY;
            _poseTime = poseTime;
            _sincePose = _lostFor = _speed = 0;
            // Stryker disable once all : no path reads _lost before a frame sets it (its loss time is 0, its speed 0)
            _lost = !_hasPose;
        }

        /// <summary>Fills HandBefore/After, HandDelta, HandSpeed, MotionInterval and Reanchored.</summary>
        public void Update(ref MotionFrame f, SolverLimits limits)
        {
            _sincePose += f.Dt;
            f.HandBefore = _poseY;
            f.HandDelta = f.HandSpeed = f.MotionInterval = 0;

            if (!f.Usable)
            {
                _lost = true;
                _lostFor += f.Dt;
                f.HandAfter = _poseY;
                return;
            }

            bool hasTime = double.IsFinite(f.PoseTime);
            bool hadTime = double.IsFinite(_poseTime);
            // A new timestamp or a new value is a new pose: a source whose timestamps stick must not freeze the object.
            bool newPose = f.PoseY != _poseY || (hasTime && !(hadTime && f.PoseTime == _poseTime));
            bool clockBack = hasTime && hadTime && f.PoseTime < _poseTime;
            bool gap = f.Dt > limits.MaxCatchUpGap || (_lost && _lostFor > limits.MaxCatchUpGap);

            if (!_hasPose || f.ForceReanchor || clockBack || gap)
            {
                Reanchor(ref f);
                return;
            }
            if (!newPose)
            {
                _lost = false;
                _lostFor = 0;
                f.HandAfter = _poseY;
                return;
            }

            // Speed is measured against the poses' own clock; without it, against the frames' time since the last
            // new pose, but never less than a 60 Hz pose period: two poses can land in one short frame.
            double interval = hasTime && hadTime && f.PoseTime > _poseTime ? f.PoseTime - _poseTime
                : Math.Max(_sincePose, MinPosePeriod);
            interval = Math.Max(interval, 1e-4);
            double delta = f.PoseY - _poseY;
            // Judged over at least one 30 Hz pose period: without timestamps two poses can land in one short frame;
            // and over at most 50 ms, so a long still spell does not license a teleport, plus the time tracking was
            // lost, so a hand that moved during a short loss is caught up, not rejected (only a pose no hand could
            // have reached is).
            double longest = SolverLimits.JumpWindow + _lostFor; // _lostFor is 0 unless tracking was lost
            double window = Math.Max(SolverLimits.MinJumpWindow, Math.Min(interval, longest));
            if (Math.Abs(delta) > limits.MaxHandSpeed * window)
            {
                Reanchor(ref f);
                return;
            }

            f.HandDelta = delta;
            f.HandSpeed = _speed = delta / interval;
            f.MotionInterval = interval;
            Accept(ref f);
        }

        void Reanchor(ref MotionFrame f)
        {
            f.Reanchored = true;
            _speed = 0;
            Accept(ref f);
        }

        void Accept(ref MotionFrame f)
        {
            _poseY = f.PoseY;
            _poseTime = f.PoseTime;
            _sincePose = _lostFor = 0;
            _hasPose = true;
            _lost = false;
            f.HandAfter = _poseY;
        }
    }
}
