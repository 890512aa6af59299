namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// The 1€ filter (Casiez, Roussel &amp; Vogel, CHI 2012): a first-order low-pass whose cutoff rises with the
    /// hand's speed, fc = <see cref="MinCutoff"/> + <see cref="Beta"/> · |v̂|, where v̂ is the pose-to-pose speed
    /// low-passed at <see cref="DerivativeCutoff"/>. Slow hands are smoothed hard (jitter), fast hands barely
    /// (lag). It runs on new poses only, with the pose interval as its sampling period, so held poses under
    /// 72–120 Hz frames neither count twice nor read as stops. The speed is taken between raw poses, as in the
    /// authors' reference code (the paper's listing differences against the filtered height, which overstates
    /// the speed by the filter's own lag), so on a steady ramp of speed v it lags by exactly
    /// 1/(2π·(MinCutoff + Beta·v)) s. Units: metres, m/s, Hz. Per pose: two divisions, no exponential.
    /// The defaults (1 Hz, 80 Hz per m/s, 1 Hz) come from the sweep in accuracy-vs-time.md: at 0.5 m/s the
    /// cutoff is 41 Hz (4 ms of lag); at rest, with 1.5 mm of jitter at 30 Hz, about 2 Hz.
    /// </summary>
    public sealed class OneEuroFilter : IHandFilter
    {
        const double TwoPi = 2 * System.Math.PI;

        double _x;     // filtered height, m
        double _dx;    // filtered speed, m/s
        double _pose;  // the previous pose, m

        /// <summary>Cutoff at rest, Hz: lower smooths jitter more and lags slow motion more.</summary>
        public double MinCutoff { get; }

        /// <summary>Cutoff added per m/s of hand speed, Hz·s/m: higher lags fast motion less.</summary>
        public double Beta { get; }

        /// <summary>Cutoff of the speed estimate, Hz.</summary>
        public double DerivativeCutoff { get; }

        public string Name => "one-euro";

        public OneEuroFilter(double minCutoff = 1.0, double beta = 80.0, double derivativeCutoff = 1.0)
        {
            MinCutoff = ConfigurationGuard.InRange(minCutoff, 0.001, 1000, nameof(minCutoff));
            Beta = ConfigurationGuard.InRange(beta, 0, 10000, nameof(beta));
            DerivativeCutoff = ConfigurationGuard.InRange(derivativeCutoff, 0.001, 1000, nameof(derivativeCutoff));
        }

        public IHandFilter Create() => new OneEuroFilter(MinCutoff, Beta, DerivativeCutoff);

        public void Reset(double handY)
        {
            _x = _pose = handY;
            _dx = 0;
        }

        public double Filter(double poseY, bool isNewPose, double poseInterval, double dt)
        {
            if (!isNewPose) return _x;
            // The sampling period, kept to [0.1 ms, 1 s]: a stalled or absurd pose clock cannot make it 0 or infinite.
            double te = poseInterval > 1e-4 ? (poseInterval < 1 ? poseInterval : 1) : 1e-4;
            double speed = (poseY - _pose) / te;
            _pose = poseY;
            _dx += (speed - _dx) * Alpha(te, DerivativeCutoff);
            double cutoff = MinCutoff + Beta * (_dx < 0 ? -_dx : _dx);
            _x += (poseY - _x) * Alpha(te, cutoff);
            return _x;
        }

        /// <summary>Smoothing factor of a first-order low-pass at <paramref name="cutoff"/> Hz sampled every <paramref name="te"/> s.</summary>
        static double Alpha(double te, double cutoff) => te / (te + 1 / (TwoPi * cutoff));
    }
}
