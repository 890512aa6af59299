using FsCheck;
using FsCheck.Fluent;
using Microsoft.FSharp.Core;

namespace Kosmos.PseudoHaptic.Properties.Tests;

/// <summary>
/// Runs a property with FsCheck from an NUnit test: <paramref name="cases"/> generated cases from a fixed seed, so CI sees
/// the same cases every run; a failure is shrunk to the smallest case that still fails and thrown with it (the
/// case's <c>ToString</c>) and the seed that replays it. <c>PSEUDOHAPTIC_PROPERTY_SEED=N</c> runs the properties from
/// another seed, to look for cases the fixed one never makes, and <c>PSEUDOHAPTIC_PROPERTY_SCALE=K</c> runs K times as many.
/// </summary>
static class Checks
{
    const ulong FixedSeed = 20261128;

    public static void Hold<T>(Arbitrary<T> cases, Action<T> property, int count)
    {
        if (int.TryParse(Environment.GetEnvironmentVariable("PSEUDOHAPTIC_PROPERTY_SCALE"), out var scale) && scale > 0) count *= scale;
        ulong seed = ulong.TryParse(Environment.GetEnvironmentVariable("PSEUDOHAPTIC_PROPERTY_SEED"), out var s) ? s : FixedSeed;
        var config = Config.QuickThrowOnFailure.WithMaxTest(count).WithQuietOnSuccess(true)
            .WithReplay(FSharpOption<Replay>.Some(new Replay(new Rnd(seed, 0x9E3779B97F4A7C15UL), FSharpOption<int>.None)));
        try { Check.One(config, Prop.ForAll(cases, property)); }
        catch (Exception e) when (e is not NUnit.Framework.AssertionException) { NUnit.Framework.Assert.Fail(e.Message); }
    }
}
