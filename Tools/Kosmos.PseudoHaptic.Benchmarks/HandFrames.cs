using Kosmos.PseudoHaptic.Simulation;

namespace Kosmos.PseudoHaptic.Benchmarks;

/// <summary>
/// The input every benchmark steps through: 8192 frames (91 s) of a hand lifting and lowering 0.3 m again and
/// again, as a Quest 2 delivers it (90 Hz frames, 30 Hz poses, 45 ms late, 1.5 mm jitter), made once: two frames in
/// three repeat the last one's pose.
/// </summary>
public static class HandFrames
{
    public const int Count = 8192, Mask = Count - 1;
    public const double MassKg = 1.0;

    public static readonly HandSample[] Samples;
    public static readonly double[] Dt;

    /// <summary>The same lifts with a new pose every frame (90 Hz poses): no frame repeats the last one's sample, so
    /// none is still and every frame runs the whole pipeline: the default pipeline's worst case.</summary>
    public static readonly HandSample[] EveryFramePoses;
    public static readonly double[] EveryFrameDt;

    static HandFrames()
    {
        (Samples, Dt) = Render(30);
        (EveryFramePoses, EveryFrameDt) = Render(90);
    }

    static (HandSample[], double[]) Render(double poseRate)
    {
        var path = HandPath.StartAt(0.9).Hold(0.3);
        while (path.Duration < Count / 90.0 + 1) path.MoveTo(1.2, 0.8).Hold(0.4).MoveTo(0.9, 0.8).Hold(0.5);
        var frames = new HeadsetSimulator { FrameRate = 90, PoseRate = poseRate, Latency = 0.045, JitterSd = 0.0015, Seed = 4 }.Render(path);
        var samples = new HandSample[Count];
        var dt = new double[Count];
        for (int i = 0; i < Count; i++)
        {
            samples[i] = frames[i].ToSample();
            dt[i] = i == 0 ? 1 / 90.0 : frames[i].Time - frames[i - 1].Time;
        }
        return (samples, dt);
    }

    public static WeightSolver Holding(WeightProfile profile)
    {
        var solver = new WeightSolver(WeightModel.FromMass(MassKg), profile);
        solver.BeginHold(Samples[0].Y, Samples[0].Y, Samples[0].PoseTime);
        return solver;
    }
}
