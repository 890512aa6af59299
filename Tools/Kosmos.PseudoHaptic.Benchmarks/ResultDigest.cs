using System.Security.Cryptography;
using Kosmos.PseudoHaptic.Cli.Accuracy;
using Kosmos.PseudoHaptic.Simulation;

namespace Kosmos.PseudoHaptic.Benchmarks;

/// <summary>
/// <c>--digest [SEEDS]</c>: a SHA-256 of the bits of every height the solvers return over seeded, Quest-like input, one
/// line per case. A change meant to make the solver faster without changing a result (accuracy-vs-time.md) must leave
/// every line as it was: run it on the build before and after and compare. Input per seed: a hand lifting and lowering at
/// random heights and speeds, rendered at 72, 90 or 120 Hz frames with 30, 60 or 90 Hz poses, 45 ms late, 0.5–3.5 mm
/// jitter, and by seed one-pose glitches, losses of up to 2 s, a snap after one, low confidence on fast poses and spans of
/// it, poses without timestamps; run at nine masses (1 g to 8 kg) and four standard speeds. Cases: the four pipeline
/// profiles on the y solver and on the 3D solver (the hand carried sideways; every third seed with a second hand), every
/// estimator of the accuracy page on the paper profile, the gain alone and with each other effect, and the paper-literal solver. The digests are
/// of this machine's math library: compare builds on one machine.
/// </summary>
public static class ResultDigest
{
    static readonly double[] Masses = { 0.001, 0.01, 0.045, 0.2, 0.5, 1.0, 1.5, 3.0, 8.0 };

    public static void Run(int seeds, TextWriter output)
    {
        var inputs = new TraceFrame[seeds][];
        for (int seed = 1; seed <= seeds; seed++) inputs[seed - 1] = Render(seed);
        using var all = IncrementalHash.CreateHash(HashAlgorithmName.SHA256);
        long values = 0;
        void Line(string name, Action<Action<double>> run)
        {
            using var hash = IncrementalHash.CreateHash(HashAlgorithmName.SHA256);
            var bytes = new byte[8];
            run(v => { BitConverter.TryWriteBytes(bytes, v); hash.AppendData(bytes); values++; });
            var digest = hash.GetHashAndReset();
            all.AppendData(digest);
            output.WriteLine($"{name,-32} {Convert.ToHexString(digest)[..16]}");
        }

        foreach (var name in NamedProfiles.PipelineNames)
        {
            var profile = NamedProfiles.Get(name);
            Line("y " + name, add => EachRun(inputs, (frames, mass, vStd) => Vertical(profile, frames, mass, vStd, add)));
            Line("3d " + name, add => EachRun(inputs, (frames, mass, vStd) => ThreeD(profile, frames, mass, vStd, add)));
        }
        foreach (var key in EstimatorCatalog.EstimatorKeys)
        {
            var profile = EstimatorCatalog.EstimatorProfile(key);
            Line("y paper/" + key, add => EachRun(inputs, (frames, mass, vStd) => Vertical(profile, frames, mass, vStd, add)));
        }
        foreach (var effect in EstimatorCatalog.AllEffects)
        {
            if (EstimatorCatalog.GainOnly.Effects.Any(e => e.Name == effect.Name)) continue;
            var profile = EstimatorCatalog.GainOnly.With(effect);
            Line("y " + profile.Name, add => EachRun(inputs, (frames, mass, vStd) => Vertical(profile, frames, mass, vStd, add)));
        }
        Line("y " + EstimatorCatalog.GainOnly.Name, add => EachRun(inputs, (frames, mass, vStd) => Vertical(EstimatorCatalog.GainOnly, frames, mass, vStd, add)));
        Line("paper-literal", add => EachRun(inputs, (frames, mass, _) => Literal(frames, mass, add)));
        output.WriteLine($"{"all (" + values + " heights)",-32} {Convert.ToHexString(all.GetHashAndReset())[..16]}");
    }

    static void EachRun(TraceFrame[][] inputs, Action<TraceFrame[], double, double> run)
    {
        for (int i = 0; i < inputs.Length; i++)
            foreach (var mass in Masses) run(inputs[i], mass, 0.3 + (i % 4) * 0.2);
    }

    static TraceFrame[] Render(int seed)
    {
        var rng = new Random(seed);
        var path = HandPath.StartAt(0.8 + rng.NextDouble() * 0.3).Hold(0.2 + rng.NextDouble() * 0.3);
        for (int k = 0; k < 4; k++) path.MoveTo(0.7 + rng.NextDouble() * 0.7, 0.2 + rng.NextDouble() * 1.2).Hold(rng.NextDouble() * 0.6);
        double[] frameRates = { 72, 90, 120 }, poseRates = { 30, 60, 90 };
        var sim = new HeadsetSimulator
        {
            FrameRate = frameRates[seed % 3], PoseRate = poseRates[seed / 3 % 3], Latency = 0.045, JitterSd = 0.0005 + rng.NextDouble() * 0.003,
            Seed = seed, WritePoseTime = seed % 5 != 0, GlitchChance = seed % 4 == 0 ? 0.03 : 0,
            LowConfidenceAboveSpeed = seed % 3 == 0 ? 0.6 : double.PositiveInfinity,
        };
        if (seed % 2 == 0) sim.Drop(1 + rng.NextDouble(), rng.NextDouble() * (seed % 6 == 0 ? 2 : 0.3));
        if (seed % 7 == 0) sim.Offset(2.5, 0.1, 0.04);
        if (seed % 5 == 1) sim.LowConfidence(1.5, 0.3);
        return sim.Render(path, 0.5);
    }

    static void Vertical(WeightProfile profile, TraceFrame[] frames, double mass, double standardSpeed, Action<double> add)
    {
        var solver = new WeightSolver(WeightModel.FromMass(mass), profile, standardSpeed);
        foreach (var y in TraceReplay.Run(solver, frames)) add(y);
    }

    static void ThreeD(WeightProfile profile, TraceFrame[] frames, double mass, double standardSpeed, Action<double> add)
    {
        var solver = new WeightSolver3D(WeightModel.FromMass(mass), profile, standardSpeed);
        bool two = frames.Length % 3 == 1; // a second hand on about a third of the inputs (by their length: any input may have it)
        HandPose Hand(int i, double side)
        {
            var f = frames[i];
            double x = 0.1 + side + 0.3 * Math.Sin(f.Time * 1.3), z = 0.3 + 0.2 * Math.Cos(f.Time * 0.7);
            return new HandPose(x, f.HandY + side * 0.03, z, f.Tracked, !f.LowConfidence, f.PoseTime);
        }
        if (two) solver.BeginHold(Hand(0, 0), Hand(0, 0.3), 0.25, frames[0].HandY, 0.3);
        else solver.BeginHold(Hand(0, 0), 0.1, frames[0].HandY, 0.3);
        for (int i = 1; i < frames.Length; i++)
        {
            double dt = frames[i].Time - frames[i - 1].Time;
            if (two) solver.Step(Hand(i, 0), Hand(i, 0.3), dt);
            else solver.Step(Hand(i, 0), dt);
            add(solver.ObjectX);
            add(solver.ObjectY);
            add(solver.ObjectZ);
        }
    }

    static void Literal(TraceFrame[] frames, double mass, Action<double> add)
    {
        var solver = new PaperLiteralSolver(mass);
        solver.BeginHold(frames[0].HandY, frames[0].HandY);
        for (int i = 1; i < frames.Length; i++) add(solver.Step(frames[i].HandY, frames[i].Tracked, frames[i].Time - frames[i - 1].Time));
    }
}
