using System;
using System.Collections.Generic;

namespace Kosmos.PseudoHaptic.Cli.Accuracy;

/// <summary>
/// The named solver configurations the accuracy study and the benchmarks compare, built from the core's
/// types only: this file is compiled into the CLI and linked into Tools/Kosmos.PseudoHaptic.Benchmarks, so
/// the accuracy table and the benchmark table use the same keys for the same profiles.
/// </summary>
public static class EstimatorCatalog
{
    /// <summary>The default pipeline: the paper profile, pose-delta estimator + its motion deadband.</summary>
    public const string Default = "deadband";

    /// <summary>The paper-literal baseline (<see cref="PaperLiteralSolver"/> in the core, the named profile paper-literal).</summary>
    public const string PaperLiteral = "paper-literal";

    /// <summary>Estimator keys, in table order. Each is the paper profile with that estimator.</summary>
    public static IReadOnlyList<string> EstimatorKeys { get; } = new[]
    {
        "no-filter", Default, "ma3", "ma5", "window-1s", "exp-30ms", "one-euro", "alpha-beta", DeadbandOneEuro,
    };

    /// <summary>The One Euro filter in front of the default deadband (both: smoothed, then the band).</summary>
    public const string DeadbandOneEuro = "deadband+one-euro";

    /// <summary>One line saying what each estimator key is.</summary>
    public static string Describe(string key) => key switch
    {
        "no-filter" => "pose-delta estimator, no filter, no deadband",
        Default => "pose-delta + motion deadband (the paper profile: default)",
        "ma3" => "moving average of the 3 latest poses",
        "ma5" => "moving average of the 5 latest poses",
        "window-1s" => "mean of the poses of the last 1 s (paper-literal window)",
        "exp-30ms" => "exponential smoothing, tau 30 ms",
        "one-euro" => "One Euro filter (min cutoff 1 Hz, beta 80 Hz per m/s, speed cutoff 1 Hz)",
        "alpha-beta" => "alpha-beta tracker (alpha 0.6, beta 0.257)",
        DeadbandOneEuro => "One Euro filter, then the default deadband",
        PaperLiteral => "paper as written: mean speed over the last 1 s, exp each frame, v x dt",
        _ => throw new ArgumentException("unknown estimator '" + key + "'", nameof(key)),
    };

    /// <summary>The paper profile with the estimator <paramref name="key"/> (filters replace the deadband).</summary>
    public static WeightProfile EstimatorProfile(string key, WeightProfile? basis = null)
    {
        var paper = basis ?? NamedProfiles.Paper;
        var bare = paper.Without<MotionDeadband>(paper.Name + "/" + key);
        return key switch
        {
            "no-filter" => bare,
            Default => paper,
            DeadbandOneEuro => paper.WithHandFilter(new OneEuroFilter(), paper.Name + "/" + key),
            _ => bare.WithHandFilter(Filter(key), paper.Name + "/" + key),
        };
    }

    /// <summary>The filter prototype of a filter key.</summary>
    public static IHandFilter Filter(string key) => key switch
    {
        "ma3" => new MovingAverage(3),
        "ma5" => new MovingAverage(5),
        "window-1s" => new OneSecondAverage(1.0),
        "exp-30ms" => new ExponentialSmoothing(0.03),
        "one-euro" => new OneEuroFilter(),
        "alpha-beta" => new AlphaBetaFilter(),
        _ => throw new ArgumentException("'" + key + "' is not a filter", nameof(key)),
    };

    /// <summary>The ideal the estimators are judged against: the same effects and gain with no hand processing.</summary>
    public static WeightProfile ReferenceProfile(WeightProfile? basis = null)
        => (basis ?? NamedProfiles.Paper).Without<MotionDeadband>("reference");

    /// <summary>Gain only (Eq. 4–6 blend, the paper profile's G), no other effect: the integration schemes' profile.</summary>
    public static WeightProfile GainOnly { get; } = new WeightProfile("gain-only", new WeightEffect[] { new WeightGain(), new ExperimentalBlend() });

    /// <summary>Each effect the core has, by name, for "that effect switched on alone".</summary>
    public static IReadOnlyList<WeightEffect> AllEffects { get; } = new WeightEffect[]
    {
        new TrackingLossHold(), new MotionDeadband(), new WeightGain(), new ExperimentalBlend(), new FasterMovesFurther(),
        new SpeedCap(), new LoweringGuard(), new OffsetCorrection(), new OffsetRelaxation(), new FloorClamp(),
    };

    /// <summary>A profile with just the effect named <paramref name="effect"/> ("none": no effect at all).</summary>
    public static WeightProfile EffectAlone(string effect)
    {
        if (effect == "none") return new WeightProfile("none", Array.Empty<WeightEffect>());
        foreach (var e in AllEffects)
            if (e.Name == effect) return new WeightProfile(effect, new[] { e });
        throw new ArgumentException("unknown effect '" + effect + "'", nameof(effect));
    }
}
