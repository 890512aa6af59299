using System;
using System.Collections.Generic;

namespace Kosmos.PseudoHaptic.Simulation
{
    /// <summary>
    /// A hand's true height over time, for running the solver with no headset: holds and minimum-jerk moves
    /// (Flash &amp; Hogan 1985, the standard model of a smooth reaching movement), or a recorded trace
    /// interpolated linearly. Used by the tests, the command-line demo and editor previews; not per frame.
    /// </summary>
    public sealed class HandPath
    {
        readonly List<double> _t = new List<double>();   // segment start times
        readonly List<double> _y0 = new List<double>();  // segment start heights
        readonly List<double> _y1 = new List<double>();  // segment end heights
        readonly List<double> _d = new List<double>();   // segment durations
        readonly bool _linear;
        double _end;
        double _endY;

        HandPath(double y, bool linear) { _endY = y; _linear = linear; }

        /// <summary>A path that starts at rest at height <paramref name="y"/>.</summary>
        public static HandPath StartAt(double y) => new HandPath(y, false);

        public double Duration => _end;
        public double EndHeight => _endY;

        /// <summary>Stays where it is for <paramref name="seconds"/>.</summary>
        public HandPath Hold(double seconds) => MoveTo(_endY, seconds);

        /// <summary>A minimum-jerk move to <paramref name="y"/> taking <paramref name="seconds"/>; peak speed is 1.875 × the mean.</summary>
        public HandPath MoveTo(double y, double seconds)
        {
            if (!(seconds > 0)) throw new ArgumentOutOfRangeException(nameof(seconds), seconds, "seconds must be > 0.");
            _t.Add(_end); _y0.Add(_endY); _y1.Add(y); _d.Add(seconds);
            _end += seconds;
            _endY = y;
            return this;
        }

        /// <summary>A recorded trace, linearly interpolated between samples; times must increase.</summary>
        public static HandPath FromSamples(IReadOnlyList<double> times, IReadOnlyList<double> heights)
        {
            if (times.Count != heights.Count || times.Count < 2) throw new ArgumentException("need at least two samples of equal-length times and heights.");
            var p = new HandPath(heights[0], true);
            double t0 = times[0];
            for (int i = 1; i < times.Count; i++)
            {
                double d = times[i] - times[i - 1];
                if (!(d > 0)) throw new ArgumentException("times must increase (index " + i + ").");
                p._t.Add(times[i - 1] - t0); p._y0.Add(heights[i - 1]); p._y1.Add(heights[i]); p._d.Add(d);
            }
            p._end = times[times.Count - 1] - t0;
            p._endY = heights[heights.Count - 1];
            return p;
        }

        /// <summary>Height at time <paramref name="t"/>; before 0 the start, after the end the end.</summary>
        public double HeightAt(double t)
        {
            if (_t.Count == 0 || t >= _end) return _endY;
            if (t <= 0) return _y0.Count > 0 ? _y0[0] : _endY;
            int i = _t.BinarySearch(t);
            if (i < 0) i = ~i - 1;
            double s = (t - _t[i]) / _d[i];
            if (!_linear) s = s * s * s * (10 + s * (-15 + 6 * s));
            return _y0[i] + (_y1[i] - _y0[i]) * s;
        }
    }
}
