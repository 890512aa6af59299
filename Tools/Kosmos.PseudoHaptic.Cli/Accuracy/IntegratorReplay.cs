using Kosmos.PseudoHaptic.Simulation;

namespace Kosmos.PseudoHaptic.Cli.Accuracy;

/// <summary>Runs frames through a harness-side integrator with the replay contract's start: the hold begins at the first usable frame.</summary>
public static class IntegratorReplay
{
    public static double[] Run(IObjectIntegrator integrator, IReadOnlyList<TraceFrame> frames)
    {
        var y = new double[frames.Count];
        int first = TraceReplay.FirstUsable(frames);
        if (first < 0) return y;
        double start = frames[first].HandY;
        integrator.Begin(start, frames[first].PoseTime);
        for (int i = 0; i <= first; i++) y[i] = start;
        for (int i = first + 1; i < frames.Count; i++)
            y[i] = integrator.Step(frames[i], frames[i].Time - frames[i - 1].Time);
        return y;
    }

    /// <summary>The paper-literal baseline as an integrator.</summary>
    public sealed class PaperLiteral(double massKg, double cueStrength = WeightSolver.DefaultCueStrength) : IObjectIntegrator
    {
        readonly PaperLiteralSolver _solver = new(massKg) { CueStrength = cueStrength };

        public void Begin(double handY, double poseTime) => _solver.BeginHold(handY, handY);

        public double Step(in TraceFrame frame, double dt) => _solver.Step(frame.HandY, frame.Tracked, dt);
    }
}
