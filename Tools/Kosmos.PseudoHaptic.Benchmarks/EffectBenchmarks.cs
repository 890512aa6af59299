using BenchmarkDotNet.Attributes;
using Kosmos.PseudoHaptic.Cli.Accuracy;

namespace Kosmos.PseudoHaptic.Benchmarks;

/// <summary>
/// Each effect switched on alone (a profile with just that effect; "none": no effect at all, only the estimator,
/// the gain and the safety limits every profile keeps). The difference from "none" is what the effect costs;
/// an effect a profile leaves out is never called.
/// </summary>
public class EffectBenchmarks : UpdateBenchmark
{
    public static IEnumerable<string> Effects => new[] { "none" }.Concat(EstimatorCatalog.AllEffects.Select(e => e.Name));

    [ParamsSource(nameof(Effects))]
    public string Effect { get; set; } = "none";

    protected override WeightProfile Profile() => EstimatorCatalog.EffectAlone(Effect);
}
