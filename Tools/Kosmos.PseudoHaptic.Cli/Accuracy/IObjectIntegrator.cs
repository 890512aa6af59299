using Kosmos.PseudoHaptic.Simulation;

namespace Kosmos.PseudoHaptic.Cli.Accuracy;

/// <summary>
/// A harness-side way of moving the held object from the tracked hand, for the rows of the study that are
/// not the solver itself (float state, velocity integration, sub-stepping, the paper-literal baseline).
/// Each applies the same gain G as the solver and no effect.
/// </summary>
public interface IObjectIntegrator
{
    /// <summary>Starts a hold with hand and object at <paramref name="handY"/>.</summary>
    void Begin(double handY, double poseTime);

    /// <summary>One rendered frame; returns the object's height.</summary>
    double Step(in TraceFrame frame, double dt);
}
