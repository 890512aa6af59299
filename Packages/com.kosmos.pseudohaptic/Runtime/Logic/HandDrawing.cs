using System;

namespace Kosmos.PseudoHaptic
{
    /// <summary>Where the rendered hand is drawn while it holds a pseudo-haptic object.</summary>
    public enum HandDrawingMode
    {
        /// <summary>The paper's: the rendered hand stays where the tracked hand is and the object visibly lags it.</summary>
        HandTrue,
        /// <summary>Samad et al. 2019, Rietzler et al. 2018: the rendered hand is drawn at the object, so the grasp looks intact.</summary>
        HandOnObject,
    }

    /// <summary>
    /// Where the hand is drawn, as an offset from the tracked hand, engine-free. While a hand holds an object in
    /// <see cref="HandDrawingMode.HandOnObject"/>, the drawn hand carries the object's lag: the object's position
    /// minus where it would be if it followed the hand rigidly (hand + grab offset), so the grasp looks intact.
    /// Otherwise (released, or <see cref="HandDrawingMode.HandTrue"/>) the offset returns to zero at a steady
    /// speed chosen when the return began, |offset| / <see cref="ReturnTime"/>, and never more than
    /// <see cref="MaxStep"/> in a frame: back within 0.2 s with no step over 1 cm whenever the offset at release is
    /// at most 1 cm × 0.2 s / frame time (18 cm at 90 Hz, 14.4 cm at 72 Hz, 24 cm at 120 Hz); a larger one takes
    /// |offset| / 1 cm frames. A new grab during a return keeps what remains and adds the new lag to it, so the
    /// drawn hand never jumps. Non-finite input keeps the last offset. No allocation.
    /// </summary>
    public sealed class HandDrawing
    {
        /// <summary>How long the drawn hand takes to return to the tracked one, s.</summary>
        public const double ReturnTime = 0.2;

        /// <summary>The largest change of the offset in one frame during a return, m.</summary>
        public const double MaxStep = 0.01;

        Vector3d _lag, _residual;
        double _returnSpeed;
        bool _holding;

        /// <summary>Drawn hand − tracked hand, world space, m.</summary>
        public Vector3d Offset => _lag + _residual;

        /// <summary>The offset is returning to zero.</summary>
        public bool IsReturning => _residual.SqrLength > 0;

        /// <summary>
        /// One frame. <paramref name="holding"/>: the hand holds an object; <paramref name="lag"/>: that object's position
        /// minus hand + grab offset (ignored when not holding); <paramref name="dt"/>: the frame's duration, s.
        /// Returns the offset to draw the hand at.
        /// </summary>
        public Vector3d Update(HandDrawingMode mode, bool holding, Vector3d lag, double dt)
        {
            bool onObject = holding && mode == HandDrawingMode.HandOnObject;
            if (onObject && !_holding)
            {
                // A new hold: whatever is still returning keeps returning, the lag starts from here.
                _holding = true;
                _lag = Vector3d.Zero;
            }
            else if (!onObject && _holding)
            {
                _holding = false;
                _residual += _lag;
                _lag = Vector3d.Zero;
                _returnSpeed = _residual.Length / ReturnTime;
            }
            if (_holding && lag.IsFinite) _lag = lag;
            Return(dt);
            return Offset;
        }

        /// <summary>
        /// The same frame's offset with the lag measured again: after a rig re-posed the tracked hand before the frame
        /// renders (OVRCameraRig's before-render update), the drawn hand is placed from the new hand, so it stays on the
        /// object. No time passes: the return does not advance, a hold neither begins nor ends. Non-finite: kept.
        /// </summary>
        public Vector3d Remeasure(Vector3d lag)
        {
            if (_holding && lag.IsFinite) _lag = lag;
            return Offset;
        }

        void Return(double dt)
        {
            double left = _residual.Length;
            if (left == 0 || !(dt > 0) || double.IsInfinity(dt)) return;
            double step = Math.Min(MaxStep, Math.Max(_returnSpeed, 1e-3) * dt);
            _residual = step >= left - 1e-12 ? Vector3d.Zero : _residual * ((left - step) / left);
        }

        /// <summary>Back to the tracked hand at once (a teleport, a new scene).</summary>
        public void Reset()
        {
            _lag = _residual = Vector3d.Zero;
            _holding = false;
            _returnSpeed = 0;
        }
    }
}
