using System.Numerics;
using Kosmos.PseudoHaptic.Simulation;

namespace Kosmos.PseudoHaptic.Cli.Accuracy;

/// <summary>
/// The solver's integration, object += G · Δpose on each new pose, written once for any IEEE floating type so
/// that float and double state run the very same code. All state (last pose, its time, the object, G) is of
/// type <typeparamref name="T"/>; the hand arrives as T too, as a Unity transform would hand it over for float.
/// No effects and no re-anchoring: it isolates what the precision of the state costs.
/// </summary>
public sealed class IncrementIntegrator<T>(double gain) : IObjectIntegrator where T : struct, IFloatingPointIeee754<T>
{
    readonly T _gain = T.CreateTruncating(gain);
    T _pose, _poseTime, _object;

    public double ObjectY => double.CreateTruncating(_object);

    public void Begin(double handY, double poseTime)
    {
        _pose = _object = T.CreateTruncating(handY);
        _poseTime = T.CreateTruncating(poseTime);
    }

    public double Step(in TraceFrame frame, double dt)
    {
        if (!frame.Tracked || !double.IsFinite(frame.HandY)) return ObjectY;
        T y = T.CreateTruncating(frame.HandY);
        bool newPose = double.IsFinite(frame.PoseTime) ? T.CreateTruncating(frame.PoseTime) != _poseTime : y != _pose;
        if (newPose)
        {
            _object += _gain * (y - _pose);
            _pose = y;
            _poseTime = T.CreateTruncating(frame.PoseTime);
        }
        return ObjectY;
    }
}
