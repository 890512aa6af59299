namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// The paper's literal reading of "the unit time for measuring the average speed is 1 s": the followed height
    /// is the mean of the poses that arrived during the last <see cref="Window"/> seconds of frame time. A
    /// time-based ring buffer of at most <see cref="Capacity"/> poses, allocated here; when more poses than that
    /// arrive within one window the oldest are dropped early. On a ramp it lags by about half the window
    /// (0.48 s for 1 s at 30 Hz poses), which is why it is not the default (accuracy-vs-time.md). After a reset
    /// only the reset height is known: the window refills over the next second. The sum is recomputed from
    /// the buffer every <see cref="Capacity"/> poses, so add/subtract rounding cannot accumulate over hours.
    /// </summary>
    public sealed class OneSecondAverage : IHandFilter
    {
        public const int MaxCapacity = 1 << 16;

        readonly double[] _y;
        readonly double[] _t;
        int _oldest;
        int _count;
        int _sinceRecompute;
        double _sum;
        double _now;

        /// <summary>Length of the averaging window, s (1 in the paper).</summary>
        public double Window { get; }

        /// <summary>Most poses held at once; 1024 covers a 1 kHz source over 1 s.</summary>
        public int Capacity { get; }

        public string Name => Window == 1 ? "one-second-average" : "window-average-" + Window.ToString("R", System.Globalization.CultureInfo.InvariantCulture) + "s";

        public OneSecondAverage(double window = 1.0, int capacity = 1024)
        {
            Window = ConfigurationGuard.InRange(window, 0.001, 10, nameof(window));
            Capacity = (int)ConfigurationGuard.InRange(capacity, 1, MaxCapacity, nameof(capacity));
            _y = new double[Capacity];
            _t = new double[Capacity];
        }

        public IHandFilter Create() => new OneSecondAverage(Window, Capacity);

        public void Reset(double handY)
        {
            _now = 0;
            _oldest = 0;
            _count = 1;
            _y[0] = handY;
            _t[0] = 0;
            _sum = handY;
            _sinceRecompute = 0;
        }

        public double Filter(double poseY, bool isNewPose, double poseInterval, double dt)
        {
            if (dt > 0) _now += dt;
            if (isNewPose)
            {
                if (_count == Capacity) Drop();
                int slot = _oldest + _count;
                if (slot >= Capacity) slot -= Capacity;
                _y[slot] = poseY;
                _t[slot] = _now;
                _count++;
                _sum += poseY;
                if (++_sinceRecompute >= Capacity) Recompute();
            }
            // Poses older than the window leave it; the newest always stays (the hand is where it last was).
            double expired = _now - Window;
            while (_count > 1 && _t[_oldest] <= expired) Drop();
            return _count == 1 ? _y[_oldest] : _sum / _count;
        }

        void Drop()
        {
            _sum -= _y[_oldest];
            _oldest = _oldest + 1 == Capacity ? 0 : _oldest + 1;
            _count--;
        }

        void Recompute()
        {
            double sum = 0;
            int i = _oldest;
            for (int k = 0; k < _count; k++)
            {
                sum += _y[i];
                i = i + 1 == Capacity ? 0 : i + 1;
            }
            _sum = sum;
            _sinceRecompute = 0;
        }
    }
}
