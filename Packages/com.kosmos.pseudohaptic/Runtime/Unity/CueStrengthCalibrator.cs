using System;
using UnityEngine;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// The calibration's second step (issue 31): after the golf-ball lifts, a short 1-up-2-down staircase on mass at the
    /// default cue strength, run by a <see cref="DiscriminationTask"/> (two objects, two "heavier" buttons), then the cue
    /// strength tuned from the threshold it finds, stored beside the user's standard speed (<see cref="UserCalibrationStore"/>);
    /// every <see cref="PseudoHapticWeight"/> of that user then applies it. Glue only: the procedure and the tuning are
    /// <see cref="CueStrengthStep"/>'s (engine-free, tested).
    /// </summary>
    [AddComponentMenu("Kosmos/Pseudo-Haptic/Cue Strength Calibrator")]
    public sealed class CueStrengthCalibrator : MonoBehaviour
    {
        [Tooltip("The task that runs the staircase (its objects' Mass Source must be Explicit).")]
        [SerializeField] DiscriminationTask _task;
        [Tooltip("Optional: begins the staircase when this calibrator's golf-ball calibration is accepted.")]
        [SerializeField] StandardSpeedCalibrator _after;
        [Tooltip("Whose calibration to store the strength in; the store's current user when empty.")]
        [SerializeField] string _userId = "";
        [Tooltip("Optional: where the result is shown (the task shows the trials).")]
        [SerializeField] TextMesh _display;

        bool _running;
        StandardSpeedCalibrator _subscribed;

        /// <summary>The last tuning stored, or null.</summary>
        public CueStrengthTuning Result { get; private set; }

        /// <summary>What went wrong in the last run, or null.</summary>
        public string Error { get; private set; }

        public bool IsRunning => _running;

        /// <summary>Raised when a strength was stored.</summary>
        public event Action<CueStrengthTuning> Stored;

        public DiscriminationTask Task => _task;

        public void Inject(DiscriminationTask task, StandardSpeedCalibrator after, TextMesh display)
        {
            _task = task;
            _display = display;
            Follow(after);
        }

        void OnEnable() => Follow(_after);

        void OnDisable() => Follow(null, keep: true);

        void Follow(StandardSpeedCalibrator after, bool keep = false)
        {
            if (_subscribed != null) _subscribed.Completed -= OnSpeedCalibrated;
            _subscribed = null;
            if (!keep) _after = after;
            if (after != null && isActiveAndEnabled)
            {
                after.Completed += OnSpeedCalibrated;
                _subscribed = after;
            }
        }

        void OnSpeedCalibrated(CalibrationResult result)
        {
            if (result.IsAccepted) Begin();
        }

        string UserId => string.IsNullOrWhiteSpace(_userId) ? UserCalibrationStore.CurrentUserId : _userId;

        /// <summary>Begins the staircase (at the default strength); false with <see cref="Error"/> when the task cannot begin.</summary>
        [ContextMenu("Begin cue strength staircase")]
        public bool Begin()
        {
            Error = null;
            if (_task == null) { Error = "no discrimination task"; Show(Error); return false; }
            _task.Use(CueStrengthStep.Settings());
            // A file per run: every run's answers are kept, and a new run never resumes a finished one.
            _task.TrialsFile = "cue-strength-" + DateTime.UtcNow.ToString("yyyyMMdd-HHmmss-fff", System.Globalization.CultureInfo.InvariantCulture) + ".csv";
            _task.Participant = UserId;
            _task.Condition = CueStrengthStep.Condition;
            _running = _task.Begin();
            if (!_running) Error = _task.Error;
            return _running;
        }

        void Update() => Tick();

        /// <summary>Checks whether the staircase has finished and, if so, tunes and stores; Update calls it, tests may too.</summary>
        public void Tick()
        {
            if (!_running || _task == null || _task.Session == null || !_task.Session.IsFinished) return;
            _running = false;
            CueStrengthTuning t = CueStrengthStep.Tune(_task.Session.Staircase, CueStrengthTuning.ExperimentOneBoxes, UserCalibrationStore.StandardSpeedOrDefault, out string reason);
            if (t == null) { Error = reason; Show("Cue strength not set: " + reason + "."); return; }
            try
            {
                UserCalibrationStore.SaveCueStrength(UserId, t.CueStrength, t.JndKg / t.StandardKg);
            }
            catch (Exception e) when (e is System.IO.IOException || e is UnauthorizedAccessException || e is ArgumentException)
            {
                Error = e.Message;
                Debug.LogError("Cue strength not saved: " + e, this);
                Show("Cue strength not saved: " + e.Message);
                return;
            }
            Result = t;
            Show(CueStrengthStep.Message(t));
            Stored?.Invoke(t);
        }

        void Show(string text)
        {
            if (_display != null) _display.text = text;
        }
    }
}
