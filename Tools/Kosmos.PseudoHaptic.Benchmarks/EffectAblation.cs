using System.Diagnostics;

namespace Kosmos.PseudoHaptic.Benchmarks;

/// <summary>
/// <c>--ablation PROFILE</c>: where a frame's time goes, effect by effect (issue 33, item 5). Times the named profile, the
/// profile with each of its effects taken out in turn, and the empty profile (the pipeline alone: estimator, steady hand,
/// glide, frame record), on both inputs of <see cref="BaselineBenchmarks"/>: a new pose every frame and Quest-like input
/// (30 Hz poses over 90 Hz frames). Cases alternate within each of 200 rounds (the first 40 discarded, while the JIT settles) so that every case
/// sees the same load, as <see cref="InterleavedTiming"/> does; medians in ns per update. "Without" a lift-stage effect
/// changes the path the others see (a different gain), so a difference is the cost of the effect as the profile runs it,
/// not an exact share.
/// </summary>
public static class EffectAblation
{
    public static void Run(string profileName, TextWriter output)
    {
        var profile = NamedProfiles.Get(profileName);
        var cases = new List<(string Name, WeightProfile Profile)> { (profileName, profile) };
        foreach (var effect in profile.Effects)
            cases.Add(("without " + effect.Name, new WeightProfile(profile.Name, profile.Effects.Where(e => !ReferenceEquals(e, effect)), profile.Limits, profile.HandFilter)));
        cases.Add(("empty", new WeightProfile("empty", Array.Empty<WeightEffect>(), profile.Limits, profile.HandFilter)));

        var inputs = new[] { (Name: "new pose every frame", Samples: HandFrames.EveryFramePoses, Dt: HandFrames.EveryFrameDt),
                             (Name: "Quest-like", Samples: HandFrames.Samples, Dt: HandFrames.Dt) };
        var solvers = inputs.Select(_ => cases.Select(c => HandFrames.Holding(c.Profile)).ToArray()).ToArray();
        var times = inputs.Select(_ => cases.Select(_ => new List<double>()).ToArray()).ToArray();
        for (int round = 0; round < 200; round++)
            for (int i = 0; i < inputs.Length; i++)
                for (int c = 0; c < cases.Count; c++)
                {
                    var solver = solvers[i][c];
                    var samples = inputs[i].Samples;
                    var dt = inputs[i].Dt;
                    var sw = Stopwatch.StartNew();
                    for (int f = 0; f < samples.Length; f++) solver.Step(samples[f], dt[f]);
                    times[i][c].Add(sw.Elapsed.TotalMilliseconds * 1e6 / samples.Length);
                }

        static double Median(List<double> l) { var o = l.Skip(40).OrderBy(v => v).ToList(); return o[o.Count / 2]; }
        output.WriteLine($"{"case",-36} {inputs[0].Name,22} {inputs[1].Name,12}   (ns per update, median of 160 interleaved rounds)");
        for (int c = 0; c < cases.Count; c++)
        {
            double a = Median(times[0][c]), b = Median(times[1][c]);
            double da = c == 0 ? 0 : Median(times[0][0]) - a, db = c == 0 ? 0 : Median(times[1][0]) - b;
            string note = c == 0 ? "" : $"   ({da:+0.0;-0.0} / {db:+0.0;-0.0} ns for what was taken out)";
            output.WriteLine($"{cases[c].Name,-36} {a,22:F2} {b,12:F2}{note}");
        }
    }
}
