using System.Globalization;

namespace Kosmos.PseudoHaptic.Cli.Accuracy;

/// <summary>
/// The generated half of accuracy-vs-time.md: <c>pseudohaptic accuracy --markdown</c> writes it (accuracy-results.md)
/// and <c>AccuracyPageTests</c> fails when the committed page differs from what the code produces. Every figure is
/// a mean over the seeded renders with its 95 % interval; a verdict against a target is given only where the
/// interval clears it. Nothing here depends on the clock or the machine: the costs come from a committed
/// BenchmarkDotNet report, the paths are written as the canonical command gives them.
/// </summary>
public static class AccuracyMarkdown
{
    /// <summary>The page, the chart and the costs, from the repository's root.</summary>
    public const string Folder = "Packages/com.kosmos.pseudohaptic/Documentation~";
    public const string PagePath = Folder + "/accuracy-results.md";
    public const string ChartPath = Folder + "/accuracy-pareto.png";
    public const string CostsPath = Folder + "/benchmarks/EstimatorBenchmarks-report.csv";

    /// <summary>The one command that writes the page and the chart.</summary>
    public const string Command = $"pseudohaptic accuracy --markdown {PagePath} --chart {ChartPath} --costs {CostsPath}";

    /// <summary>Issue 4's accuracy targets for the default pipeline.</summary>
    public const double RmsTargetMm = 5, AddedLagTargetMs = 40, CreepTargetMm = 10;

    public static void Write(TextWriter w, AccuracyReport main, AccuracyReport golfBall, IReadOnlyDictionary<string, double>? costs, AccuracyInputs inputs)
    {
        w.Write("# Accuracy of the hand-motion estimators (generated)\n\n");
        w.Write("<!-- Generated: do not edit. AccuracyPageTests fails when this page differs from what the code produces. -->\n");
        // What the page was made from: the command refuses to rewrite it from other inputs (without --overwrite).
        w.Write(inputs.PageComment + "\n\n");
        w.Write($"Written by one command, from the repository's root (the figures are seeded: the same code writes the same page; about 20 seconds on 2 cores):\n\n```sh\n{Command}\n```\n\n");
        w.Write("What is measured and why is in [accuracy-vs-time.md](accuracy-vs-time.md#accuracy); the columns are explained there. ");
        w.Write($"Each true hand is degraded as a Quest 2 delivers it ({Degradation.PoseRate:0} Hz poses, {Degradation.Latency * 1000:0} ms late, jitter of ");
        w.Write($"{string.Join(" and ", Degradation.JitterMm.Select(j => F(j, 0)))} mm sd, held over {string.Join(", ", Degradation.FrameRates.Select(f => F(f, 0)))} Hz frames): ");
        w.Write($"{Degradation.FrameRates.Length * Degradation.JitterMm.Length} conditions, each rendered {Degradation.Replicates} times with its own seed, so **every figure is the mean over ");
        w.Write($"{Degradation.RenderCount} seeded renders, [with its 95 % confidence interval]** (Student's t over the renders; a summary's render k is the mean ");
        w.Write("over the sources of their render k). The seeds are drawn from the hand itself, so a hand scores the same whatever its name or place among the sources. ");
        w.Write($"The long runs are {LongRunStudy.Seeds} seeded runs. `max_mm` is the worst render, not a mean.\n\n");

        w.Write("Sources:\n\n");
        foreach (var s in main.Sources) w.Write($"- `{s.Name}`: {s.Description}\n");
        foreach (var note in main.Notes) w.Write($"- note: {note}\n");
        w.Write('\n');

        w.Write($"## Verdict: the default (`{EstimatorCatalog.Default}`) against issue 4's accuracy targets\n\n");
        w.Write("A target is met where the whole interval lies within it, missed where the whole interval lies beyond it, and undecided otherwise.\n\n");
        w.Write("| target | object | measured: mean [95 % CI] | verdict |\n|---|---|---|---|\n");
        foreach (var (report, label) in new[] { (main, Mass(main)), (golfBall, Mass(golfBall)) })
        {
            var d = report.Summary.FirstOrDefault(r => r.Config == EstimatorCatalog.Default);
            if (d == null) continue;
            w.Write($"| RMS error ≤ {RmsTargetMm:0} mm | {label} | {Ci(d.Rms, 2)} mm | {d.Rms.Verdict(RmsTargetMm)} |\n");
            w.Write($"| added lag ≤ {AddedLagTargetMs:0} ms | {label} | {Ci(d.AddedLag, 1)} ms | {d.AddedLag.Verdict(AddedLagTargetMs)} |\n");
            w.Write($"| creep < {CreepTargetMm:0} mm per 10 s | {label} | {Ci(d.Creep, 3)} mm (worst render {F(d.CreepMaxMm, 3)}) | {CreepVerdict(d.Creep)} |\n");
        }
        w.Write('\n');

        Summary(w, main);
        Summary(w, golfBall);

        w.Write($"## Per source, {Mass(main)}\n\n");
        foreach (var source in main.Sources)
        {
            w.Write($"### `{source.Name}`: {source.Description}\n\n");
            w.Write("| config | rms_mm | raw_mm | max_mm | lag_ms | added_ms |\n|---|---|---|---:|---|---|\n");
            string? group = null;
            foreach (var row in main.PerSource.Where(x => x.Source == source.Name))
            {
                string g = main.Configs.First(c => c.Key == row.Config).Group;
                if (group != null && g != group) w.Write(GroupRow(6));
                group = g;
                var added = Shift(row.Lag, -Degradation.Latency * 1000);
                w.Write($"| {Key(row.Config)} | {Ci(row.Rms, 2)} | {Ci(row.RawRms, 2)} | {F(row.MaxMm, 2)} | {Ci(row.Lag, 0)}{(row.LagWidened ? "*" : "")} | {Ci(added, 0)} |\n");
            }
            w.Write('\n');
        }

        if (main.LongRunDescription != null)
        {
            w.Write($"## Precision and integration over long holds, {Mass(main)}\n\n{main.LongRunDescription}.\n\n");
            w.Write("| scheme | end_mm | max_mm | what |\n|---|---|---|---|\n");
            foreach (var row in main.LongRun) w.Write($"| `{row.Scheme}` | {Small(row.EndError)} | {Small(row.MaxError)} | {row.Description} |\n");
            w.Write('\n');
        }

        w.Write("## Pareto chart\n\n![RMS error against ns per update, labelled with added lag](accuracy-pareto.png)\n\n");
        w.Write($"Each estimator at (ns per update, RMS error at {Mass(main)}), labelled with its added lag; lower left is better. The costs are the ");
        w.Write($"BenchmarkDotNet report committed as `benchmarks/EstimatorBenchmarks-report.csv` (its timings are one machine's on one day; ");
        w.Write("accuracy-vs-time.md says which); the errors are the summary's. The points:\n\n");
        w.Write("| estimator | ns per update | rms_mm | added_ms |\n|---|---:|---|---|\n");
        foreach (var key in EstimatorCatalog.EstimatorKeys.Append(EstimatorCatalog.PaperLiteral))
        {
            var row = main.Summary.FirstOrDefault(r => r.Config == key);
            if (row == null) continue;
            string ns = costs != null && costs.TryGetValue(key, out double c) ? F(c, 1) : "—";
            w.Write($"| {Key(key)} | {ns} | {Ci(row.Rms, 2)} | {Ci(row.AddedLag, 0)} |\n");
        }
    }

    static void Summary(TextWriter w, AccuracyReport r)
    {
        w.Write($"## Summary, {Mass(r)} (gain {F(r.Gain, 3)}), mean over {r.Sources.Count} sources\n\n");
        w.Write("| config | rms_mm | raw_mm | max_mm | lag_ms | added_ms | creep_mm | rest_mm |\n|---|---|---|---:|---|---|---|---|\n");
        string? group = null;
        foreach (var row in r.Summary)
        {
            if (group != null && row.Group != group) w.Write(GroupRow(8));
            group = row.Group;
            w.Write($"| {Key(row.Config)} | {Ci(row.Rms, 2)} | {Ci(row.RawRms, 2)} | {F(row.MaxMm, 2)} | {Ci(row.Lag, 0)}{(row.LagWidened ? "*" : "")} | {Ci(row.AddedLag, 0)} | {Ci(row.Creep, 2)} | {Ci(row.Rest, 2)} |\n");
        }
        w.Write("\n`*`: the lag's correlation peak lay on the ±200 ms edge in some render and was searched over ±1 s.\n\n");
    }

    static string GroupRow(int columns) => "| *integration and precision: gain-only profile, judged against the gain-only solver* |" + string.Concat(Enumerable.Repeat(" |", columns - 1)) + "\n";

    static string Key(string config) => config == EstimatorCatalog.Default ? $"**{config}** (default)" : config;

    static string Mass(AccuracyReport r) => r.MassKg == PhysicalConstants.StandardMassKg ? $"golf ball {F(r.MassKg, 3)} kg" : $"{F(r.MassKg, 3)} kg";

    /// <summary>Creep is a one-sided target (strictly less than).</summary>
    static string CreepVerdict(Interval i) => !(i.N > 1) ? "not measured" : i.High < CreepTargetMm ? "met" : i.Low >= CreepTargetMm ? "missed" : "undecided (the interval holds the target)";

    static Interval Shift(Interval i, double by) => new(i.Mean + by, i.Low + by, i.High + by, i.N);

    static string Ci(Interval i, int decimals) =>
        !double.IsFinite(i.Mean) ? "n/a" : !double.IsFinite(i.Low) ? F(i.Mean, decimals) : $"{F(i.Mean, decimals)} [{F(i.Low, decimals)}, {F(i.High, decimals)}]";

    /// <summary>Millimetres from nanometres up: fixed decimals above 1 µm, else scientific.</summary>
    static string Small(Interval i)
    {
        static string S(double mm) => Math.Abs(mm) < 0.001 && mm != 0 ? mm.ToString("0.0E+0", CultureInfo.InvariantCulture) : mm.ToString("0.000", CultureInfo.InvariantCulture);
        return double.IsFinite(i.Low) ? $"{S(i.Mean)} [{S(i.Low)}, {S(i.High)}]" : S(i.Mean);
    }

    static string F(double v, int decimals) => double.IsFinite(v) ? v.ToString("F" + decimals, CultureInfo.InvariantCulture) : "n/a";
}
