using BenchmarkDotNet.Attributes;

namespace Kosmos.PseudoHaptic.Benchmarks;

/// <summary>Each named profile (paper is the default pipeline).</summary>
public class ProfileBenchmarks : UpdateBenchmark
{
    [Params(NamedProfiles.PaperName, NamedProfiles.PaperExperimentName, NamedProfiles.GainName)]
    public string ProfileName { get; set; } = NamedProfiles.PaperName;

    protected override WeightProfile Profile() => NamedProfiles.Get(ProfileName);
}
