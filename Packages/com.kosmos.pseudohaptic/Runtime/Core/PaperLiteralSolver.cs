using System;
using System.Collections.Generic;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// The named profile <c>paper-literal</c> (<see cref="NamedProfiles.PaperLiteral"/>): the weight algorithm written the
    /// way the paper describes it. Every frame the hand's speed is measured over the frame (Δy / dt), kept in a
    /// <see cref="List{T}"/> of the last second of samples, and averaged ("the unit time for measuring the average speed
    /// is 1 s"); W = m·g, Eq. 4's ratio and Eq. 5's exponential are recomputed every frame; the object moves by
    /// v_final · dt (Eq. 6, in the package's relative reading so that its gain equals the package's), and never below
    /// y = 0 (the paper's only bound). No precomputation, no cap on the gain, no offset correction, no other effect.
    /// It is the accuracy page's baseline (accuracy-results.md, row <c>paper-literal</c>) and the benchmarks' naive
    /// implementation, and what <c>pseudohaptic replay --profile paper-literal</c> runs. It allocates while its window
    /// grows and does a list scan per frame: a reference, not a pipeline for a headset.
    /// </summary>
    public sealed class PaperLiteralSolver
    {
        const double Gravity = 9.80665, StandardMassKg = 0.045, CurveA = 1.6793, CurveB = 0.24, UnitTime = 1.0;

        /// <summary>The paper's floor: the object's height never goes below this, m (§3.1, "y ≥ 0").</summary>
        public const double Floor = 0.0;

        readonly List<double> _times = new List<double>();
        readonly List<double> _speeds = new List<double>();
        readonly double _massKg;
        double _cueStrength = WeightSolver.DefaultCueStrength;
        double _clock;
        double _handY;

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

        public void BeginHold(double handY, double objectY)
        {
            _times.Clear();
            _speeds.Clear();
            _clock = 0;
            _handY = handY;
            ObjectY = Math.Max(objectY, Floor);
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
            _clock += dt;
            double speed = 0;
            if (tracked && HandSample.IsUsableHeight(handY))
            {
                // A hold begun before the hand was seen (a NaN start) takes its first usable height as where it was.
                speed = HandSample.IsUsableHeight(_handY) ? (handY - _handY) / dt : 0;
                _handY = handY;
            }
            _times.Add(_clock);
            _speeds.Add(speed);
            while (_times.Count > 1 && _times[0] <= _clock - UnitTime)
            {
                _times.RemoveAt(0);
                _speeds.RemoveAt(0);
            }
            double sum = 0;
            for (int i = 0; i < _speeds.Count; i++) sum += _speeds[i];
            double vReal = sum / _speeds.Count;                                    // average speed over the unit time

            double weight = _massKg * Gravity;                                     // Eq. 1
            double standardWeight = StandardMassKg * Gravity;                      // Eq. 2
            double vVirtual = vReal * standardWeight / weight;                     // Eq. 4
            double vExperiment = CurveA * Math.Exp(-CurveB * _massKg);             // Eq. 5
            double vExperimentStandard = CurveA * Math.Exp(-CurveB * StandardMassKg);
            double vFinal = _cueStrength == 1.0
                ? (vVirtual + vReal * vExperiment / vExperimentStandard) / 2        // Eq. 6
                : vReal * Math.Pow((standardWeight / weight + vExperiment / vExperimentStandard) / 2, _cueStrength);
            double y = ObjectY + vFinal * dt;
            // y ≥ 0; and only a height a pose could have (finite, within ±10⁵ m, as the pipeline keeps it): hands that jump
            // tens of kilometres make v_final absurd, and the object stays where it is instead.
            if (Math.Abs(y) <= WeightSolver.MaxCoordinate) ObjectY = Math.Max(y, Floor);
            return ObjectY;
        }
    }
}
