using System;
using System.Collections.Generic;
using UnityEngine;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// The calibration station (Son et al. 2022, §3, Fig. 6a): guides the user through several lifts of a real golf
    /// ball and stores their standard speed. Glue over the engine-free <see cref="CalibrationStation"/> (lift
    /// segmentation, messages, combining, when to store): this reads the hand's height each frame, shows the
    /// station's message, and stores an accepted result through <see cref="UserCalibrationStore"/>.
    /// </summary>
    [AddComponentMenu("Kosmos/Pseudo-Haptic/Standard Speed Calibrator")]
    public sealed class StandardSpeedCalibrator : MonoBehaviour, ICalibrationSaver
    {
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

        IHandPoseSource _source;
        CalibrationStation _station;
        string _shown;

        /// <summary>Raised when a calibration ends, accepted or rejected.</summary>
        public event Action<CalibrationResult> Completed;

        public CalibrationStation Station => _station ?? (_station = CreateStation());
        public CalibrationPhase CurrentPhase => Station.Phase;
        public string Message => Station.Message;
        public CalibrationResult Result => Station.Result;
        public IReadOnlyList<LiftMeasurement> Measurements => Station.Measurements;
        public int LiftsWanted { get => Station.LiftsWanted; set { Station.LiftsWanted = value; _lifts = Station.LiftsWanted; } }
        public IHandPoseSource Hand => _source ?? (_source = HandSourceField.Resolve<IHandPoseSource>(_hand));

        public void InjectHand(IHandPoseSource hand)
        {
            _source = hand;
            _hand = hand as MonoBehaviour;
        }

        public void InjectDisplay(TextMesh display) => _display = display;

        CalibrationStation CreateStation()
        {
            var station = new CalibrationStation { LiftsWanted = _lifts, StillBand = _stillBand, RestTime = _restTime, SettleTime = _settleTime, MaxLiftTime = _maxLiftTime };
            station.Completed += r => Completed?.Invoke(r);
            station.SaveFailed += e => Debug.LogError("Standard speed calibration not saved: " + e, this);
            return station;
        }

        void OnValidate()
        {
            MonoBehaviour source = HandSourceField.Normalize<IHandPoseSource>(_hand);
            if (source != null) _hand = source;
            _source = null;
            _lifts = Math.Max(1, _lifts);
            _station = null;
        }

        void Start()
        {
            if (_beginOnStart) Begin();
        }

        void Update() => Tick(Time.unscaledDeltaTime);

        /// <summary>Starts (or restarts) a calibration.</summary>
        [ContextMenu("Begin calibration")]
        public void Begin()
        {
            Station.Saver = _store ? this : null;
            Station.Begin(Hand != null);
            Show();
        }

        /// <summary>One frame of the calibration; Update calls it, tests may too.</summary>
        public void Tick(float dt)
        {
            IHandPoseSource hand = Hand;
            if (hand == null) return;
            Station.Tick(dt, hand.IsTracked, hand.Position.y, hand.PoseTime);
            Show();
        }

        string ICalibrationSaver.Save(in CalibrationResult result)
        {
            string id = string.IsNullOrWhiteSpace(_userId) ? UserCalibrationStore.CurrentUserId : _userId;
            UserCalibrationStore.Save(UserCalibration.From(id, result));
            return "user '" + id + "'";
        }

        void Show()
        {
            // The message changes only with the phase: the text is written then, not every frame.
            if (_display != null && !ReferenceEquals(_shown, Station.Message)) _display.text = _shown = Station.Message;
        }
    }
}
