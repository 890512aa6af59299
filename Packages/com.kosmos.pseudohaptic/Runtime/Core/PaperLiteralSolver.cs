using System;
using System.Collections.Generic;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// The named profile <c>paper-literal</c> (<see cref="NamedProfiles.PaperLiteral"/>): the weight algorithm written the
    /// way the paper describes it. The hand's speed is averaged over the paper's unit time of 1 s ("the unit time for
    /// measuring the average speed of a virtual object is defined as 1 s"): at every instant the average speed over the
    /// last second, (y(t) − y(t − 1 s)) / 1 s, of the hand's path (straight between the heights of successive frames, the
    /// object at rest before the grab, so the hand counts as resting where it was grabbed), taken over each frame; W = m·g,
    /// Eq. 4's ratio and Eq. 5's exponential are recomputed every frame; the object moves by v_final · dt (Eq. 6, in the
    /// package's relative reading so that its gain equals the package's), and never below y = 0 (the paper's only bound).
    /// Integrated so, the object moves G times the change of the hand's mean height over the last second: a second after
    /// the hand stops the object has moved G times the hand, whatever the frame times (the golf ball, G = 1, ends at the
    /// hand). Added to the paper: the gain cap of every profile (<see cref="MaxGain"/>, P3; the paper's Eq. 4 alone moves a
    /// 1 g object 45 times the hand). No precomputation, no offset correction, no other effect. It is the accuracy page's
    /// baseline (accuracy-results.md, row <c>paper-literal</c>) and the benchmarks' naive implementation, and what
    /// <c>pseudohaptic replay --profile paper-literal</c> runs. It allocates while its window grows and walks the window
    /// every frame: a reference, not a pipeline for a headset.
    /// </summary>
    public sealed class PaperLiteralSolver
    {
        const double Gravity = 9.80665, StandardMassKg = 0.045, CurveA = 1.6793, CurveB = 0.24, UnitTime = 1.0;

        /// <summary>The paper's floor: the object's height never goes below this, m (§3.1, "y ≥ 0").</summary>
        public const double Floor = 0.0;

        // The hand's path over (at least) the last second, oldest first: each frame a straight piece from its start height
        // to its end height over its duration; the first piece is the rest before the grab.
        readonly List<double> _durations = new List<double>();
        readonly List<double> _from = new List<double>();
        readonly List<double> _to = new List<double>();
        readonly double _massKg;
        double _cueStrength = WeightSolver.DefaultCueStrength;
        double _maxGain = SolverLimits.Default.MaxGain;
        double _handY;
        double _mean; // the hand's mean height over the last second, after the last frame

        public PaperLiteralSolver(double massKg)
        {
            if (!(massKg > 0) || double.IsInfinity(massKg)) throw new ArgumentOutOfRangeException(nameof(massKg), massKg, "massKg must be a finite number greater than 0.");
            _massKg = massKg;
        }

        public double MassKg => _massKg;

        public double ObjectY { get; private set; }

        /// <summary>The cue strength s (<see cref="WeightSolver.CueStrength"/>): v_final = v_real · G^s. At s = 1 (the
        /// default) Eq. 6 is computed exactly as printed in its relative reading; bounds and validation as the solver's.</summary>
        public double CueStrength
        {
            get => _cueStrength;
            set => _cueStrength = ConfigurationGuard.InRange(value, WeightSolver.MinCueStrength, WeightSolver.MaxCueStrength, nameof(CueStrength));
        }

        /// <summary>The largest gain on the hand's motion (P3), the profile's <see cref="SolverLimits.MaxGain"/>: default 3;
        /// within [1, 100] as the limits' setting. Eq. 6 is computed as printed below it.</summary>
        public double MaxGain
        {
            get => _maxGain;
            set => _maxGain = ConfigurationGuard.InRange(value, 1.0, 100.0, nameof(MaxGain));
        }

        public void BeginHold(double handY, double objectY)
        {
            _durations.Clear();
            _from.Clear();
            _to.Clear();
            _handY = handY;
            if (HandSample.IsUsableHeight(handY)) Rest(handY);
            ObjectY = Math.Max(objectY, Floor);
        }

        /// <summary>The hand at rest at <paramref name="y"/> for the last second: the path before the grab.</summary>
        void Rest(double y)
        {
            _durations.Add(UnitTime);
            _from.Add(y);
            _to.Add(y);
            _mean = y;
        }

        /// <summary>A frame time shorter than this, s, is not a frame: Δy / dt over it would be absurd (a new pose under a
        /// frame of a nanosecond reads as 10⁸ m/s), so nothing happens and the next frame measures the hand's move.</summary>
        public const double ShortestFrame = 1e-4;

        /// <summary>One frame: the tracked hand height (not finite, beyond ±10⁵ m or untracked: no speed this frame) and
        /// the frame time (shorter than <see cref="ShortestFrame"/> or not finite: nothing happens). The height returned is
        /// always finite and within ±<see cref="WeightSolver.MaxCoordinate"/>.</summary>
        public double Step(double handY, bool tracked, double dt)
        {
            if (!(dt >= ShortestFrame) || double.IsInfinity(dt)) return ObjectY;
            bool usable = tracked && HandSample.IsUsableHeight(handY);
            if (_durations.Count == 0)
            {
                // A hold begun before the hand was seen takes its first usable height as where it was: this frame is still.
                if (usable) { _handY = handY; Rest(handY); }
                return ObjectY;
            }
            double y = usable ? handY : _handY; // no usable hand: it stays where it was last seen
            _durations.Add(dt);
            _from.Add(_handY);
            _to.Add(y);
            _handY = y;

            // The mean height over the last second, from the newest piece back (measured from the hand's height now, so that
            // a resting hand gives exactly its height and moves nothing); pieces wholly older than that go.
            double remaining = UnitTime, area = 0;
            int i = _durations.Count - 1;
            for (; i >= 0 && remaining > 0; i--)
            {
                double d = _durations[i], take = Math.Min(d, remaining);
                area += take * ((_to[i] - y) - (_to[i] - _from[i]) * (take / d) / 2); // the piece's last `take` seconds
                remaining -= take;
            }
            if (i >= 0)
            {
                _durations.RemoveRange(0, i + 1);
                _from.RemoveRange(0, i + 1);
                _to.RemoveRange(0, i + 1);
            }
            double mean = y + area / UnitTime;
            double vReal = (mean - _mean) / dt;                                    // average speed over the unit time
            _mean = mean;

            double weight = _massKg * Gravity;                                     // Eq. 1
            double standardWeight = StandardMassKg * Gravity;                      // Eq. 2
            double vVirtual = vReal * standardWeight / weight;                     // Eq. 4
            double vExperiment = CurveA * Math.Exp(-CurveB * _massKg);             // Eq. 5
            double vExperimentStandard = CurveA * Math.Exp(-CurveB * StandardMassKg);
            double gain = (standardWeight / weight + vExperiment / vExperimentStandard) / 2;
            double vFinal = _cueStrength == 1.0 && gain <= _maxGain
                ? (vVirtual + vReal * vExperiment / vExperimentStandard) / 2        // Eq. 6
                : vReal * WeightSolver.StrengthenedGain(Math.Min(gain, _maxGain), _cueStrength, _maxGain); // the pipeline's cap: G capped, then G^s capped
            double next = ObjectY + vFinal * dt;
            // y ≥ 0; and only a height a pose could have (finite, within ±10⁵ m, as the pipeline keeps it): hands that jump
            // tens of kilometres make v_final absurd, and the object stays where it is instead.
            if (Math.Abs(next) <= WeightSolver.MaxCoordinate) ObjectY = Math.Max(next, Floor);
            return ObjectY;
        }
    }
}
