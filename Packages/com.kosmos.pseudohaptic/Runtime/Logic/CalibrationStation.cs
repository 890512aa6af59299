using System;
using System.Collections.Generic;
using System.Globalization;

namespace Kosmos.PseudoHaptic
{
    /// <summary>The calibration station's phases.</summary>
    public enum CalibrationPhase
    {
        Idle,
        /// <summary>Waiting for the hand to hold the ball still before a lift.</summary>
        Rest,
        /// <summary>Recording a lift.</summary>
        Lift,
        /// <summary>Waiting for the ball lowered half the smallest lift from its top, after a lift that rose at least that much (a smaller one goes back to Rest).</summary>
        Lower,
        Accepted,
        Rejected,
    }

    /// <summary>Stores an accepted calibration (the Unity layer's user store); returns a sentence for the participant, throws on failure.</summary>
    public interface ICalibrationSaver
    {
        /// <summary>Stores <paramref name="result"/>; returns whose it is ("user 'p07'").</summary>
        string Save(in CalibrationResult result);
    }

    /// <summary>
    /// The calibration station's decisions (Son et al. 2022, §3, Fig. 6a), engine-free: it segments the hand's height
    /// into lifts of a real golf ball (still at rest → lift → still at the top → lowered), hands each lift's samples to
    /// the core's <see cref="StandardSpeedCalibration"/>, says what to do next or why a lift did not count, and, with
    /// enough lifts, combines them and stores an accepted result through an <see cref="ICalibrationSaver"/>. Buffers
    /// are allocated at <see cref="Begin"/>; frames allocate nothing (messages are built only when the phase changes).
    /// </summary>
    public sealed class CalibrationStation
    {
        const int SamplesPerSecond = 250; // above any tracking or frame rate; a lift that fills its buffer (MaxLiftTime at this rate) ends there

        readonly List<LiftMeasurement> _measurements = new List<LiftMeasurement>();
        double[] _t = Array.Empty<double>();
        double[] _y = Array.Empty<double>();
        int _count, _accepted;
        double _clock, _stillRef, _stillSince, _liftStartTime, _liftStartY, _top;
        double _lastY = double.NaN, _lastPoseTime = double.NaN;
        int _lifts = 5;

        /// <summary>Accepted lifts wanted (at least 1); at most twice as many are tried.</summary>
        public int LiftsWanted { get => _lifts; set => _lifts = Math.Max(1, value); }
        /// <summary>The hand must stay within this band to count as still, m.</summary>
        public double StillBand = 0.015;
        /// <summary>Stillness before a lift starts recording, s.</summary>
        public double RestTime = 0.5;
        /// <summary>Stillness at the top that ends a lift, s.</summary>
        public double SettleTime = 0.3;
        /// <summary>A lift still going after this long is ended, s.</summary>
        public double MaxLiftTime = 4;
        /// <summary>Where an accepted result is stored; null: not stored.</summary>
        public ICalibrationSaver Saver;

        public CalibrationPhase Phase { get; private set; }
        public string Message { get; private set; } = "";
        public CalibrationResult Result { get; private set; }
        public IReadOnlyList<LiftMeasurement> Measurements => _measurements;

        /// <summary>Raised when a calibration ends, accepted or rejected.</summary>
        public event Action<CalibrationResult> Completed;

        /// <summary>Raised with the reason when an accepted result could not be stored.</summary>
        public event Action<Exception> SaveFailed;

        /// <summary>Starts (or restarts) a calibration; without a hand it says so and stays idle.</summary>
        public void Begin(bool hasHand)
        {
            int capacity = (int)Math.Ceiling(Math.Max(0.5, MaxLiftTime) * SamplesPerSecond) + 2;
            if (_t.Length != capacity)
            {
                _t = new double[capacity];
                _y = new double[capacity];
            }
            _measurements.Clear();
            _accepted = 0;
            _clock = 0;
            Result = default;
            if (!hasHand)
            {
                Phase = CalibrationPhase.Idle;
                Message = "No hand: assign an IHandPoseSource to the calibrator.";
                return;
            }
            EnterRest(double.NaN, "Hold the golf ball still, resting on the table.");
        }

        /// <summary>One frame: its duration, whether the hand is tracked, its height (m), its pose time (NaN if unknown).</summary>
        public void Tick(double dt, bool tracked, double y, double poseTime)
        {
            if (Phase == CalibrationPhase.Idle || Phase == CalibrationPhase.Accepted || Phase == CalibrationPhase.Rejected) return;
            if (!(dt > 0) || double.IsInfinity(dt)) return; // no time passed: nothing to record
            _clock += dt;
            if (!tracked || !double.IsFinite(y)) return;
            bool newPose = !double.IsNaN(poseTime) ? poseTime != _lastPoseTime : y != _lastY;
            _lastPoseTime = poseTime;
            _lastY = y;

            if (Math.Abs(y - _stillRef) > StillBand || double.IsNaN(_stillRef))
            {
                _stillRef = y;
                _stillSince = _clock;
            }
            double stillFor = _clock - _stillSince;

            switch (Phase)
            {
                case CalibrationPhase.Rest:
                    if (stillFor >= RestTime) StartLift(y);
                    break;
                case CalibrationPhase.Lift:
                    if (newPose && _count < _t.Length) Record(y);
                    if (y > _top) _top = y;
                    bool risen = _top - _liftStartY >= StandardSpeedCalibration.MinRise;
                    bool atTop = y >= _top - StillBand;
                    if ((risen && atTop && stillFor >= SettleTime) || _clock - _liftStartTime > MaxLiftTime || _count >= _t.Length)
                        FinishLift();
                    break;
                case CalibrationPhase.Lower:
                    if (y <= _top - 0.5 * StandardSpeedCalibration.MinRise)
                        EnterRest(y, "Hold the ball still for lift " + (_accepted + 1) + " of " + _lifts + ".");
                    break;
            }
        }

        void EnterRest(double y, string message)
        {
            Phase = CalibrationPhase.Rest;
            _stillRef = y;
            _stillSince = _clock;
            Message = message;
        }

        void StartLift(double y)
        {
            Phase = CalibrationPhase.Lift;
            _count = 0;
            _liftStartTime = _clock;
            _liftStartY = y;
            _top = y;
            Record(y);
            Message = "Lift " + (_accepted + 1) + " of " + _lifts + ": lift the ball up to your shoulder at your natural pace, and hold it there.";
        }

        void Record(double y)
        {
            _t[_count] = _clock;
            _y[_count] = y;
            _count++;
        }

        void FinishLift()
        {
            LiftMeasurement m = StandardSpeedCalibration.MeasureLift(new ReadOnlySpan<double>(_t, 0, _count), new ReadOnlySpan<double>(_y, 0, _count));
            // A lift ends with the ball held up; one that ran out of time back near its start (a wrong pose, a
            // hand that went up and straight down) is not one, whatever its samples say.
            if (m.IsAccepted && !(_lastY - _liftStartY >= StandardSpeedCalibration.MinRise))
                m = new LiftMeasurement(false, double.NaN, m.Rise, m.Duration, "the ball was not held up at the top: lift it and hold it still there");
            _measurements.Add(m);
            if (m.IsAccepted) _accepted++;
            if (_accepted >= _lifts || _measurements.Count >= 2 * _lifts)
            {
                Complete();
                return;
            }
            string outcome = m.IsAccepted
                ? "Lift " + _accepted + ": " + m.Speed.ToString("0.00", CultureInfo.InvariantCulture) + " m/s."
                : "That lift did not count: " + m.Reason + ".";
            if (_top - _liftStartY >= 0.5 * StandardSpeedCalibration.MinRise)
            {
                Phase = CalibrationPhase.Lower;
                Message = outcome + " Lower the ball to the table.";
            }
            else
            {
                EnterRest(double.NaN, outcome + " Hold the ball still to try again.");
            }
        }

        void Complete()
        {
            CalibrationResult result = StandardSpeedCalibration.Combine(_measurements);
            Result = result;
            if (!result.IsAccepted)
            {
                Phase = CalibrationPhase.Rejected;
                Message = "Calibration rejected: " + result.Reason + ". Begin again.";
            }
            else
            {
                Phase = CalibrationPhase.Accepted;
                string saved = "";
                if (Saver != null)
                {
                    try
                    {
                        saved = " Saved for " + Saver.Save(in result) + ".";
                    }
                    catch (Exception e) when (e is System.IO.IOException || e is UnauthorizedAccessException || e is ArgumentException)
                    {
                        saved = " Not saved: " + e.Message;
                        SaveFailed?.Invoke(e);
                    }
                }
                Message = "Your standard speed: " + result + "." + saved;
            }
            Completed?.Invoke(result);
        }
    }
}
