using System;
using UnityEngine;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>
    /// A hand pose source driven by the test: a minimum-jerk lift (the shape of a deliberate human reach),
    /// poses that change only at the tracker's rate (30 Hz) while frames run faster, tracking and pinch as set.
    /// </summary>
    public sealed class ScriptedHand : IPinchHandPoseSource
    {
        public Vector3 Position { get; set; }
        public bool IsTracked { get; set; } = true;
        public bool IsHighConfidence { get; set; } = true;
        public bool IsPinching { get; set; }
        public double PoseTime => double.NaN;

        /// <summary>Tracker rate, Hz: the pose changes only every 1/rate seconds.</summary>
        public double TrackingRate = 30;

        double _sincePose = double.PositiveInfinity;

        public ScriptedHand(Vector3 start) => Position = start;

        /// <summary>Advances the scripted clock by <paramref name="dt"/> and, when a new pose is due, moves the hand to <paramref name="target"/>.</summary>
        public void Track(Vector3 target, double dt)
        {
            _sincePose += dt;
            if (_sincePose < 1.0 / TrackingRate) return;
            _sincePose = 0;
            Position = target;
        }

        /// <summary>Minimum-jerk profile from 0 to 1 over u in [0, 1].</summary>
        public static double MinimumJerk(double u)
        {
            u = Math.Min(1, Math.Max(0, u));
            return u * u * u * (10 - 15 * u + 6 * u * u);
        }
    }
}
