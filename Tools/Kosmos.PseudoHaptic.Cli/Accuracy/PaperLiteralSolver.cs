using System;
using System.Collections.Generic;

namespace Kosmos.PseudoHaptic.Cli.Accuracy;

/// <summary>
/// The weight algorithm written the way the paper describes it, as the baseline of the speed-up ratio and a
/// row of the accuracy table: every frame the hand's speed is measured over the frame (Δy / dt), kept in a
/// <see cref="List{T}"/> of the last second of samples, and averaged ("the unit time for measuring the average
/// speed is 1 s"); W = m·g, Eq. 4's ratio and Eq. 5's exponential are recomputed every frame; the object moves
/// by v_final · dt (Eq. 6, in the package's relative reading so that its gain equals the package's). No
/// precomputation, no cap on the gain, no effects. Linked into the benchmark project: keep it core-only.
/// </summary>
public sealed class PaperLiteralSolver
{
    const double Gravity = 9.80665, StandardMassKg = 0.045, CurveA = 1.6793, CurveB = 0.24, UnitTime = 1.0;

    readonly List<double> _times = new();
    readonly List<double> _speeds = new();
    readonly double _massKg;
    double _clock;
    double _handY;

    public PaperLiteralSolver(double massKg)
    {
        if (!(massKg > 0) || double.IsInfinity(massKg)) throw new ArgumentOutOfRangeException(nameof(massKg), massKg, "massKg must be a finite number greater than 0.");
        _massKg = massKg;
    }

    public double ObjectY { get; private set; }

    public void BeginHold(double handY, double objectY)
    {
        _times.Clear();
        _speeds.Clear();
        _clock = 0;
        _handY = handY;
        ObjectY = objectY;
    }

    /// <summary>One frame: the tracked hand height (NaN or untracked: no speed this frame) and the frame time.</summary>
    public double Step(double handY, bool tracked, double dt)
    {
        if (!(dt > 0) || double.IsInfinity(dt)) return ObjectY;
        _clock += dt;
        double speed = 0;
        if (tracked && double.IsFinite(handY))
        {
            speed = (handY - _handY) / dt;
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
        double vFinal = (vVirtual + vReal * vExperiment / vExperimentStandard) / 2; // Eq. 6
        ObjectY += vFinal * dt;
        return ObjectY;
    }
}
