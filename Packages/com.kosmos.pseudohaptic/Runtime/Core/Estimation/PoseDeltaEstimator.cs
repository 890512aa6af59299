using System;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// The default estimator of the hand's vertical motion: it follows each new pose in the frame the pose arrives
    /// and measures speed against the pose's own timestamps (design note §6). Repeated poses (30 Hz tracking under
    /// 72–120 Hz frames) move nothing and never read as a stop followed by a spike. Across a loss, a hitch or a pose
    /// clock that steps back the hand's motion is followed in full (bridged): it is the hand's real motion, and the
    /// weight is a function of where the hand is, so nothing the gap hid is lost. Only a pose no hand could have
    /// reached in the time since the last one is refused (treated as lost, P8; <see cref="Reach"/>); once enough time has
    /// passed for a hand to get there, it is followed.
    /// </summary>
    public struct PoseDeltaEstimator
    {
        double _poseY;
        double _poseTime;       // NaN when the source gives no pose timestamps
        double _sincePose;      // frame time since the last accepted pose, s
        double _speed;          // the last pose-to-pose speed, m/s
        Reach _reach;           // whether a hand could have got to a pose
        bool _hasPose;
        bool _lost;

        /// <summary>A hand that has shown no new pose for longer than this is taken as still, s.</summary>
        const double StillAfter = 0.1;

        /// <summary>The shortest pose period assumed when poses carry no timestamp: Quest tracks hands at 60 Hz at most.</summary>
        const double MinPosePeriod = 1.0 / 60;

        /// <summary>The hand's height as followed, m.</summary>
        public double HandY => _poseY;

        public bool HasPose => _hasPose;

        /// <summary>The hand's last pose-to-pose speed, m/s, kept over repeated poses; 0 once more than 0.1 s passed without a new pose.</summary>
        public double Speed => _sincePose > StillAfter || _lost ? 0 : _speed;

        /// <summary>Starts over at the pose <paramref name="handY"/> taken at <paramref name="poseTime"/>. When the hand is
        /// not tracked (<paramref name="handY"/> not finite), the hand is taken to be at <paramref name="untrackedHandY"/>
        /// until a pose comes (the solver passes the object's height: nothing pulls the object toward a hand never seen),
        /// and the first pose anchors the hold.</summary>
        public void Reset(double handY, double poseTime, double untrackedHandY = 0)
        {
            _hasPose = double.IsFinite(handY);
            _poseY = _hasPose ? handY : untrackedHandY;
            _poseTime = poseTime;
            _sincePose = _speed = 0;
            _lost = false;
            _reach.Reset();
            if (_hasPose) _reach.TryAccept(0, handY, 0, double.PositiveInfinity);
        }

        /// <summary>Fills HandBefore/After, HandDelta, HandSpeed, MotionInterval, NewPose, Bridged, AcrossGap and Reanchored; clears
        /// Usable for a pose no hand could have reached (<see cref="Screen"/>, then <see cref="Follow"/>).</summary>
        public void Update(ref MotionFrame f, SolverLimits limits)
        {
            Screen(ref f, limits);
            Follow(ref f);
        }

        /// <summary>The frame's time passes, and a new pose no hand could have reached is refused: Usable is cleared, so
        /// that everything after (the input effects, then <see cref="Follow"/>) treats it as not tracked. The solver calls
        /// this before its input effects.</summary>
        public void Screen(ref MotionFrame f, SolverLimits limits)
        {
            Advance(f.Dt, limits.MaxFrameTime);
            if (!f.Usable || !_hasPose || !IsNewPose(in f)) return;
            if (!_reach.TryAccept(0, f.PoseY, 0, limits.MaxHandSpeed)) f.Usable = false;
        }

        /// <summary>A new timestamp or a new value is a new pose: a source whose timestamps stick must not freeze the object.</summary>
        bool IsNewPose(in MotionFrame f)
        {
            bool hasTime = double.IsFinite(f.PoseTime);
            return f.PoseY != _poseY || (hasTime && !(double.IsFinite(_poseTime) && f.PoseTime == _poseTime));
        }

        /// <summary>Follows the frame <see cref="Screen"/> has screened: fills HandBefore/After, HandDelta, HandSpeed,
        /// MotionInterval, NewPose, Bridged, AcrossGap and Reanchored.</summary>
        public void Follow(ref MotionFrame f)
        {
            f.HandBefore = f.HandAfter = _poseY;
            f.HandDelta = f.HandSpeed = f.MotionInterval = 0;

            if (!f.Usable)
            {
                Lose();
                return;
            }
            if (!_hasPose)
            {
                _reach.TryAccept(0, f.PoseY, 0, double.PositiveInfinity);
                f.Reanchored = true;
                Accept(ref f);
                return;
            }
            if (!IsNewPose(in f)) return;

            // Speed is measured against the poses' own clock; without it (or when it steps back), against the frames'
            // time since the last pose, but never less than a 60 Hz pose period: two poses can land in one short frame.
            bool hasTime = double.IsFinite(f.PoseTime), hadTime = double.IsFinite(_poseTime);
            // Comparisons, not Math.Max (a call where nothing inlines it): the time since the pose is a sum of sanitized frame
            // times and the pose interval a positive difference, never NaN, and both bounds are positive, so no signed zero.
            double interval = hasTime && hadTime && f.PoseTime > _poseTime ? f.PoseTime - _poseTime
                : (_sincePose > MinPosePeriod ? _sincePose : MinPosePeriod);
            if (interval < 1e-4) interval = 1e-4;
            double delta = f.PoseY - _poseY;

            f.Bridged = _lost;
            f.AcrossGap = _lost || _sincePose > SolverLimits.GapTime;
            f.HandDelta = delta;
            f.HandSpeed = _speed = delta / interval;
            f.MotionInterval = interval;
            Accept(ref f);
        }

        /// <summary>A frame of <paramref name="dt"/> s passed: all that a frame repeating the last one's pose changes here
        /// (the solver calls it alone for a still frame).</summary>
        public void Advance(double dt, double longestFrame)
        {
            _sincePose += dt;
            _reach.Tick(dt, longestFrame);
        }

        void Lose()
        {
            _lost = true;
            _reach.Miss();
        }

        void Accept(ref MotionFrame f)
        {
            _poseY = f.PoseY;
            _poseTime = f.PoseTime;
            _sincePose = 0;
            _hasPose = true;
            _lost = false;
            f.NewPose = true;
            f.HandAfter = _poseY;
        }
    }
}
