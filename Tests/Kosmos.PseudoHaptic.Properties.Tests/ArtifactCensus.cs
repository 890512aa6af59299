using FsCheck.Fluent;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Properties.Tests;

/// <summary>
/// How often issue 22's rule 1 fails over generated holds, and how badly: 20,000 cases of each family of
/// <see cref="ArtifactCase"/> (FsCheck's generator from <see cref="Checks"/>' fixed seed, so the same cases every run), each replayed clean and with
/// its artifact as <see cref="SolverProperties"/> does, counted by the artifact's kind and the profile. Explicit (about a
/// minute): the figures in ALGORITHM.md §2 and quality.md ("Generated properties") come from it; the settle time is the
/// tracking-loss hold's (<see cref="TrackingLossHold.DefaultSettleTime"/>, or the one given, to compare).
/// dotnet test Tests/Kosmos.PseudoHaptic.Properties.Tests --filter Name~CountHoldsBeyondRuleOne --logger "console;verbosity=detailed"
/// </summary>
[TestFixture]
public class ArtifactCensus
{
    [Explicit("a census of about a minute, for the documentation's figures")]
    [TestCase(0.0)]
    [TestCase(0.11)]
    public void CountHoldsBeyondRuleOne(double settleTime)
    {
        if (settleTime == 0) settleTime = TrackingLossHold.DefaultSettleTime;
        foreach (var (family, arbitrary) in new[] { ("one lift", ArtifactCase.OneLift()), ("paths of several moves", ArtifactCase.AnyPath()) })
        {
            int count = 0, beyond = 0;
            double worst = 0;
            string worstCase = "";
            var byKind = new SortedDictionary<string, int>();
            // Through Checks, for its fixed seed: the same 20,000 cases every run (a property that always holds and counts).
            Checks.Hold(arbitrary, c =>
            {
                var path = c.Path(out double at, out double artifactEnd);
                if (ArtifactCase.HidesALowestPoint(path, at, artifactEnd)) return;
                count++;
                double off = c.Difference(path, at, artifactEnd, out double bound, WithSettleTime(NamedProfiles.Get(c.Profile), settleTime));
                if (off > bound) { beyond++; string k = c.Kind + ", " + c.Profile; byKind[k] = byKind.GetValueOrDefault(k) + 1; }
                if (off / bound > worst) { worst = off / bound; worstCase = c + $": {off * 1000:F1} mm"; }
            }, 20000);
            TestContext.Out.WriteLine($"settle time {settleTime} s, {family}: {beyond} of {count} holds beyond the rule; the worst {worst:F2} × its bound ({worstCase})");
            foreach (var kv in byKind) TestContext.Out.WriteLine($"  {kv.Key}: {kv.Value}");
        }
    }

    static WeightProfile WithSettleTime(WeightProfile profile, double settleTime)
        => !profile.Has<TrackingLossHold>() ? profile
            : new WeightProfile(profile.Name, profile.Effects.Select(e => e is TrackingLossHold t ? new TrackingLossHold(settleTime, t.RequireHighConfidence) : e), profile.Limits, profile.HandFilter);
}
