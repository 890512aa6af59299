using Kosmos.PseudoHaptic.Simulation;

namespace Kosmos.PseudoHaptic.Cli.Accuracy;

/// <summary>
/// Velocity integration, the way an engine script often moves an object: the object's speed is G times the
/// hand's speed, integrated over the frame time, object += G · v_hand · dt. v_hand is the core estimator's
/// pose-to-pose speed (<see cref="PoseDeltaEstimator.Speed"/>: measured against pose timestamps, held over
/// repeated poses, 0 after 0.1 s without a new one or on a re-anchor). With <c>subSteps</c> &gt; 1 each frame
/// is integrated in that many sub-steps with the speed ramped linearly from the previous frame's estimate to
/// this frame's, the usual cure for a rectangle rule. Either way a pose's displacement is integrated over the
/// frames it is held for, not over its own interval, so the sum drifts from the hand's true displacement.
/// </summary>
public sealed class VelocityIntegrator(double gain, int subSteps = 1) : IObjectIntegrator
{
    PoseDeltaEstimator _estimator;
    double _object, _lastSpeed;

    public void Begin(double handY, double poseTime)
    {
        _estimator.Reset(handY, poseTime);
        _object = handY;
        _lastSpeed = 0;
    }

    public double Step(in TraceFrame frame, double dt)
    {
        if (!(dt > 0) || double.IsInfinity(dt)) dt = 0;
        var f = new MotionFrame
        {
            Dt = dt,
            PoseY = frame.HandY,
            PoseTime = double.IsFinite(frame.PoseTime) ? frame.PoseTime : double.NaN,
            IsHighConfidence = frame.Tracked,
            Usable = frame.IsUsable,
            ObjectY = _object,
        };
        _estimator.Update(ref f, SolverLimits.Default);
        double speed = f.Reanchored ? 0 : _estimator.Speed;
        if (subSteps <= 1) _object += gain * speed * dt;
        else
        {
            double h = dt / subSteps;
            for (int s = 1; s <= subSteps; s++)
                _object += gain * (_lastSpeed + (speed - _lastSpeed) * s / subSteps) * h;
        }
        _lastSpeed = speed;
        return _object;
    }
}
