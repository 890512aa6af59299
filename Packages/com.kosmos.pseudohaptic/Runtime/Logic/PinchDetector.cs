using System;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// An index pinch with hysteresis, from the tracker's pinch strength (0 open … 1 closed; a source that only
    /// says yes or no gives 1 or 0). The pinch closes when the strength reaches <see cref="CloseAt"/> and opens
    /// only when it has stayed below <see cref="OpenBelow"/> for <see cref="OpenAfter"/> seconds, so that the
    /// strength's flicker around one threshold and a pinch flag dropped for a frame in fast motion do not drop
    /// a held object. While the hand is untracked the pinch keeps its state (what a lost hand does is the grab's
    /// decision). No allocation; NaN strength counts as open.
    /// </summary>
    public sealed class PinchDetector
    {
        public const double DefaultCloseAt = 0.9;
        public const double DefaultOpenBelow = 0.5;
        public const double DefaultOpenAfter = 0.05;

        /// <summary>
        /// The most one frame counts toward a timer of the grab, s: one tracker pose period (30 Hz). A hitch, or the first
        /// frame after the headset wakes, is one frame of evidence however long it lasted: one dropped pinch flag in it must
        /// not open the pinch, nor one untracked frame in it release the object (<see cref="HandGrab"/>). Longer than the
        /// solver's <see cref="SolverLimits.MaxFrameTime"/> (0.025 s, the time it moves an object over): the frames of an app
        /// running at 30 Hz must count in full toward these timers.
        /// </summary>
        public const double LongestCountedFrame = 1.0 / 30;

        double _closeAt = DefaultCloseAt, _openBelow = DefaultOpenBelow, _openAfter = DefaultOpenAfter;
        double _openFor;

        /// <summary>The pinch is closed.</summary>
        public bool IsPinching { get; private set; }

        /// <summary>The pinch closed on the last update.</summary>
        public bool Began { get; private set; }

        /// <summary>Strength at which an open pinch closes, in (0, 1].</summary>
        public double CloseAt
        {
            get => _closeAt;
            set
            {
                if (!(value > 0 && value <= 1)) throw new ArgumentOutOfRangeException(nameof(CloseAt), value, "CloseAt must be in (0, 1]");
                if (value < _openBelow) throw new ArgumentOutOfRangeException(nameof(CloseAt), value, "CloseAt must not be below OpenBelow (" + _openBelow + ")");
                _closeAt = value;
            }
        }

        /// <summary>Strength under which a closed pinch starts opening, in (0, <see cref="CloseAt"/>].</summary>
        public double OpenBelow
        {
            get => _openBelow;
            set
            {
                if (!(value > 0 && value <= _closeAt)) throw new ArgumentOutOfRangeException(nameof(OpenBelow), value, "OpenBelow must be in (0, CloseAt]");
                _openBelow = value;
            }
        }

        /// <summary>How long the strength must stay under <see cref="OpenBelow"/> before the pinch opens, s (≥ 0).</summary>
        public double OpenAfter
        {
            get => _openAfter;
            set
            {
                if (!(value >= 0) || double.IsInfinity(value)) throw new ArgumentOutOfRangeException(nameof(OpenAfter), value, "OpenAfter must be finite and >= 0");
                _openAfter = value;
            }
        }

        /// <summary>One frame: the hand's tracking, its pinch strength, the frame's duration (s).</summary>
        public void Update(bool tracked, double strength, double dt)
        {
            Began = false;
            if (!tracked) return;
            if (!IsPinching)
            {
                _openFor = 0;
                if (strength >= _closeAt) IsPinching = Began = true;
                return;
            }
            if (strength >= _openBelow) { _openFor = 0; return; }
            if (dt > 0 && !double.IsInfinity(dt)) _openFor += Math.Min(dt, LongestCountedFrame);
            if (_openFor >= _openAfter) IsPinching = false;
        }

        /// <summary>Opens the pinch at once (the hand was released elsewhere or the component disabled).</summary>
        public void Reset()
        {
            IsPinching = Began = false;
            _openFor = 0;
        }
    }
}
