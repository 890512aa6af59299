using System;
using System.Collections.Generic;
using System.IO;
using UnityEngine;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// The calibration station (Son et al. 2022, §3, Fig. 6a): guides the user through several lifts of a
    /// real golf ball, records the hand's (t, y) during each, and hands them to the core's
    /// <see cref="StandardSpeedCalibration"/>. It shows each lift's speed or the reason it did not count,
    /// then the user's standard speed or why the calibration was rejected, and stores an accepted one
    /// through <see cref="UserCalibrationStore"/>. Buffers are allocated when a calibration begins; frames
    /// in between allocate nothing (messages are built only when the phase changes).
    /// </summary>
    [AddComponentMenu("Kosmos/Pseudo-Haptic/Standard Speed Calibrator")]
    public sealed class StandardSpeedCalibrator : MonoBehaviour
    {
        public enum Phase
        {
            Idle,
            /// <summary>Waiting for the hand to hold the ball still before a lift.</summary>
            Rest,
            /// <summary>Recording a lift.</summary>
            Lift,
            /// <summary>Waiting for the hand to lower the ball after a lift.</summary>
            Lower,
            Accepted,
            Rejected,
        }

        [Tooltip("The hand holding the golf ball: an IHandPoseSource (tracked is enough; a ball in the hand often lowers confidence).")]
        [SerializeField] MonoBehaviour _hand;
        [Tooltip("Accepted lifts wanted.")]
        [SerializeField] int _lifts = 5;
        [Tooltip("The hand must stay within this band to count as still, m.")]
        [SerializeField] float _stillBand = 0.015f;
        [Tooltip("Stillness before a lift starts recording, s.")]
        [SerializeField] float _restTime = 0.5f;
        [Tooltip("Stillness at the top that ends a lift, s.")]
        [SerializeField] float _settleTime = 0.3f;
        [Tooltip("A lift still going after this long is ended, s.")]
        [SerializeField] float _maxLiftTime = 4f;
        [SerializeField] bool _beginOnStart = true;
        [Tooltip("Store an accepted calibration as the user's profile.")]
        [SerializeField] bool _store = true;
        [Tooltip("Whose profile; the store's current user when empty.")]
        [SerializeField] string _userId = "";
        [Tooltip("Optional: where the instructions and the result are shown.")]
        [SerializeField] TextMesh _display;

        const int SamplesPerSecond = 250; // above any tracking or frame rate

        IHandPoseSource _source;
        readonly List<LiftMeasurement> _measurements = new List<LiftMeasurement>();
        double[] _t = Array.Empty<double>();
        double[] _y = Array.Empty<double>();
        int _count;
        int _accepted;
        Phase _phase;
        string _message = "";
        CalibrationResult _result;

        double _clock;
        double _stillRef, _stillSince;
        double _liftStartTime, _liftStartY, _top;
        double _lastY = double.NaN, _lastPoseTime = double.NaN;

        /// <summary>Raised when a calibration ends, accepted or rejected.</summary>
        public event Action<CalibrationResult> Completed;

        public Phase CurrentPhase => _phase;
        public string Message => _message;
        public CalibrationResult Result => _result;
        public IReadOnlyList<LiftMeasurement> Measurements => _measurements;
        /// <summary>Accepted lifts wanted (at least 1); at most twice as many are tried.</summary>
        public int LiftsWanted
        {
            get => _lifts;
            set => _lifts = Math.Max(1, value);
        }
        public IHandPoseSource Hand => _source ?? (_source = HandSourceField.Resolve<IHandPoseSource>(_hand));

        public void InjectHand(IHandPoseSource hand)
        {
            _source = hand;
            _hand = hand as MonoBehaviour;
        }

        public void InjectDisplay(TextMesh display) => _display = display;

        void OnValidate()
        {
            MonoBehaviour source = HandSourceField.Normalize<IHandPoseSource>(_hand);
            if (source != null) _hand = source;
            _source = null;
            if (_lifts < 1) _lifts = 1;
        }

        void Start()
        {
            if (_beginOnStart) Begin();
        }

        void Update() => Tick(Time.deltaTime);

        /// <summary>Starts (or restarts) a calibration.</summary>
        [ContextMenu("Begin calibration")]
        public void Begin()
        {
            int capacity = (int)Math.Ceiling(Math.Max(0.5, _maxLiftTime) * SamplesPerSecond) + 2;
            if (_t.Length != capacity)
            {
                _t = new double[capacity];
                _y = new double[capacity];
            }
            _measurements.Clear();
            _accepted = 0;
            _clock = 0;
            _result = default;
            if (Hand == null)
            {
                _phase = Phase.Idle;
                Show("No hand: assign an IHandPoseSource to the calibrator.");
                return;
            }
            EnterRest(double.NaN, "Hold the golf ball still, resting on the table.");
        }

        /// <summary>One frame of the calibration; Update calls it, tests may too.</summary>
        public void Tick(float dt)
        {
            if (_phase == Phase.Idle || _phase == Phase.Accepted || _phase == Phase.Rejected) return;
            if (!(dt > 0) || float.IsInfinity(dt)) return; // no time passed: nothing to record
            _clock += dt;
            IHandPoseSource hand = Hand;
            if (hand == null || !hand.IsTracked) return;
            double y = hand.Position.y;
            if (double.IsNaN(y) || double.IsInfinity(y)) return;
            double poseTime = hand.PoseTime;
            bool newPose = !double.IsNaN(poseTime) ? poseTime != _lastPoseTime : y != _lastY;
            _lastPoseTime = poseTime;
            _lastY = y;

            if (Math.Abs(y - _stillRef) > _stillBand || double.IsNaN(_stillRef))
            {
                _stillRef = y;
                _stillSince = _clock;
            }
            double stillFor = _clock - _stillSince;

            switch (_phase)
            {
                case Phase.Rest:
                    if (stillFor >= _restTime) StartLift(y);
                    break;
                case Phase.Lift:
                    if (newPose && _count < _t.Length) Record(y);
                    if (y > _top) _top = y;
                    bool risen = _top - _liftStartY >= StandardSpeedCalibration.MinRise;
                    bool atTop = y >= _top - _stillBand;
                    if ((risen && atTop && stillFor >= _settleTime) || _clock - _liftStartTime > _maxLiftTime || _count >= _t.Length)
                        FinishLift();
                    break;
                case Phase.Lower:
                    if (y <= _top - 0.5 * StandardSpeedCalibration.MinRise)
                        EnterRest(y, "Hold the ball still for lift " + (_accepted + 1) + " of " + _lifts + ".");
                    break;
            }
        }

        void EnterRest(double y, string message)
        {
            _phase = Phase.Rest;
            _stillRef = y;
            _stillSince = _clock;
            Show(message);
        }

        void StartLift(double y)
        {
            _phase = Phase.Lift;
            _count = 0;
            _liftStartTime = _clock;
            _liftStartY = y;
            _top = y;
            Record(y);
            Show("Lift " + (_accepted + 1) + " of " + _lifts + ": lift the ball up to your shoulder at your natural pace, and hold it there.");
        }

        void Record(double y)
        {
            _t[_count] = _clock;
            _y[_count] = y;
            _count++;
        }

        void FinishLift()
        {
            LiftMeasurement m = StandardSpeedCalibration.MeasureLift(
                new ReadOnlySpan<double>(_t, 0, _count), new ReadOnlySpan<double>(_y, 0, _count));
            _measurements.Add(m);
            if (m.IsAccepted) _accepted++;

            if (_accepted >= _lifts || _measurements.Count >= 2 * _lifts)
            {
                Complete();
                return;
            }
            string outcome = m.IsAccepted
                ? "Lift " + _accepted + ": " + m.Speed.ToString("0.00", System.Globalization.CultureInfo.InvariantCulture) + " m/s."
                : "That lift did not count: " + m.Reason + ".";
            if (_top - _liftStartY >= 0.5 * StandardSpeedCalibration.MinRise)
            {
                _phase = Phase.Lower;
                Show(outcome + " Lower the ball to the table.");
            }
            else
            {
                EnterRest(double.NaN, outcome + " Hold the ball still to try again.");
            }
        }

        void Complete()
        {
            _result = StandardSpeedCalibration.Combine(_measurements);
            if (!_result.IsAccepted)
            {
                _phase = Phase.Rejected;
                Show("Calibration rejected: " + _result.Reason + ". Begin again.");
            }
            else
            {
                _phase = Phase.Accepted;
                string saved = "";
                if (_store)
                {
                    string id = string.IsNullOrWhiteSpace(_userId) ? UserCalibrationStore.CurrentUserId : _userId;
                    try
                    {
                        UserCalibrationStore.Save(UserCalibration.From(id, _result));
                        saved = " Saved for user '" + id + "'.";
                    }
                    catch (Exception e) when (e is IOException || e is UnauthorizedAccessException || e is ArgumentException)
                    {
                        saved = " Not saved: " + e.Message;
                        Debug.LogError("Standard speed calibration not saved: " + e, this);
                    }
                }
                Show("Your standard speed: " + _result + "." + saved);
            }
            Completed?.Invoke(_result);
        }

        void Show(string message)
        {
            _message = message;
            if (_display != null) _display.text = message;
        }
    }
}
