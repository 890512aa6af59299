using Kosmos.PseudoHaptic.Cli.Accuracy;
using Kosmos.PseudoHaptic.Cli.CommandLine;
using Kosmos.PseudoHaptic.Cli.Files;
using Kosmos.PseudoHaptic.Cli.Plotting;

namespace Kosmos.PseudoHaptic.Cli.Commands;

/// <summary>
/// <c>pseudohaptic accuracy [--trace FILE] [--lifts all|none] [--mass-kg M] [--standard-speed V] [--mocap FILE|none]
/// [--long-minutes N] [--csv OUT.csv] [--costs BENCH_RESULTS] [--chart OUT.png [--svg]]</c>: what each estimator,
/// precision and integration scheme costs in accuracy on Quest-like input. Prints the tables on stdout
/// (progress on stderr). Deterministic: the same arguments print the same tables. accuracy-vs-time.md says
/// what every column means.
/// </summary>
public static class AccuracyCommand
{
    public const string MocapRelative = "../shared/data/mocap-hand-100hz.csv";
    public const double DefaultMassKg = 1.0;
    public const double DefaultLongMinutes = 60;

    /// <summary>Longest long run, min: its frames are held in memory (180 min with a 120 s trace, the lifts and the motion capture: see README; 480 min: 318 MB).</summary>
    public const double MaxLongMinutes = 180;

    public static CliCommand Define() => new(
        "accuracy",
        "Measure what each hand-motion estimator, precision and integration costs in accuracy on Quest-like input: tables on standard output (accuracy-vs-time.md)",
        Run,
        new[]
        {
            "pseudohaptic accuracy --long-minutes 0 --mocap none",
            "pseudohaptic accuracy --trace Packages/com.kosmos.pseudohaptic/Documentation~/examples/lift.csv --lifts none --mocap none --long-minutes 0 --csv out/accuracy.csv",
        },
        CliCommand.Value("--trace", "FILE", "also measure on this recorded hand (replay's CSV format; usable rows spanning at most 120 s)"),
        CliCommand.Choice("--lifts", "measure on the synthetic lifts (default all)", "all", "none"),
        CliCommand.Value("--mass-kg", "M", $"the held object's mass, kg (default {DefaultMassKg})"),
        CliCommand.Value("--standard-speed", "V", $"the standard lifting speed, m/s (default {WeightSolver.DefaultStandardSpeed})"),
        CliCommand.Value("--mocap", "FILE|none", $"the motion-capture trace (default {MocapRelative} beside the repository, when present; none: skip)"),
        CliCommand.Value("--long-minutes", "N", $"minutes of the long run that measures drift, 0–{MaxLongMinutes:0} (default {DefaultLongMinutes:0})"),
        CliCommand.Value("--csv", "OUT.csv", "also write every figure as CSV ('-': standard output; the tables then go to standard error)"),
        CliCommand.Value("--costs", "BENCH_RESULTS", "BenchmarkDotNet's results folder or report CSV: the time each estimator costs, for --chart (default: none, no chart)"),
        CliCommand.Value("--markdown", "OUT.md", "also write the generated page accuracy-results.md: the summaries at this mass and the golf ball's, per source, the long runs, the verdicts, with 95 % intervals"),
        CliCommand.Value("--chart", "OUT.png", "also draw the accuracy-against-time (Pareto) chart; needs --costs"),
        CliCommand.Flag("--svg", "write an SVG beside the chart"),
        CliCommand.Flag("--overwrite", "write --markdown and --chart even where the existing page or chart records other inputs (sources, mass, speed, long runs, costs); without it such a file is refused, exit 2"));

    static int Run(Options o)
    {
        bool svg = o.Flag("--svg");
        double mass = o.Number("--mass-kg") ?? DefaultMassKg;
        if (!(mass > 0) || double.IsInfinity(mass))
            throw new CliException($"option --mass-kg: must be a finite number greater than 0, got {NumberText.Format(mass)}");
        double speed = o.Number("--standard-speed") ?? WeightSolver.DefaultStandardSpeed;
        if (!(speed >= WeightSolver.MinStandardSpeed && speed <= WeightSolver.MaxStandardSpeed))
            throw new CliException($"option --standard-speed: must lie in [{WeightSolver.MinStandardSpeed}, {WeightSolver.MaxStandardSpeed}] m/s, got {NumberText.Format(speed)}");
        double minutes = o.Number("--long-minutes") ?? DefaultLongMinutes;
        if (!(minutes >= 0 && minutes <= MaxLongMinutes))
            throw new CliException($"option --long-minutes: must lie in [0, {MaxLongMinutes:0}] (the long run is held in memory), got {NumberText.Format(minutes)}");
        string? costsPath = o.Get("--costs"), chartPath = o.Get("--chart");
        if (chartPath != null && costsPath == null) throw new CliException("option --chart needs --costs (BenchmarkDotNet's results folder or report CSV)");
        if (svg && chartPath == null) throw new CliException($"option --svg needs --chart (the SVG is written beside the PNG)");
        if (svg && chartPath == "-") throw new CliException($"option --svg needs --chart to be a file (the SVG is written beside the PNG), not standard output");
        // Outputs are checked before anything is read: never an input, never a folder, never a missing folder.
        string? trace = o.Get("--trace"), mocapOption = o.Get("--mocap"), csv = o.Get("--csv"), markdown = o.Get("--markdown");
        // Every file read is an input an output must not replace: the motion capture found by default, and the reports in a
        // --costs folder, too.
        string? mocapInput = mocapOption == null ? FindMocap() : mocapOption == "none" ? null : mocapOption;
        var inputs = new[] { new NamedPath("--trace", trace), new NamedPath("--mocap", mocapInput), new NamedPath("--costs", costsPath) }
            .Concat(BenchmarkCosts.ReportFiles(costsPath).Select(f => new NamedPath("--costs", f))).ToArray();
        var csvOut = csv != null ? OutputFile.Check("--csv", csv, inputs) : null;
        var chartOut = chartPath != null ? OutputFile.Check("--chart", chartPath, inputs) : null;
        string? svgPath = svg ? Path.ChangeExtension(chartPath!, ".svg") : null;
        var svgOut = svgPath != null ? OutputFile.Check("--svg", svgPath, inputs) : null;
        var markdownOut = markdown != null ? OutputFile.Check("--markdown", markdown, inputs) : null;
        var outputs = new[] { ("--csv", csv), ("--chart", chartPath), ("--markdown", markdown), ("--svg", svgPath) }.Where(x => x.Item2 != null && x.Item2 != "-").ToList();
        for (int i = 0; i < outputs.Count; i++)
            for (int j = 0; j < i; j++)
            {
                var (a, b) = (outputs[j], outputs[i]);
                bool same = Path.GetFullPath(a.Item2!) == Path.GetFullPath(b.Item2!)
                    || FileIdentity.Of(a.Item2!).Exists && FileIdentity.Of(a.Item2!).SameAs(FileIdentity.Of(b.Item2!));
                if (same) throw new CliException($"{b.Item1} {Messages.Path(b.Item2!)} is the same file as {a.Item1} {Messages.Path(a.Item2!)}");
            }
        if (trace != null) InputFile.Check("--trace", trace);
        var costs = costsPath != null ? BenchmarkCosts.Read(costsPath) : null;

        var notes = new List<string>();
        var sources = new List<AccuracySource>();
        switch (o.Get("--lifts") ?? "all")
        {
            case "all": sources.AddRange(AccuracySource.Lifts()); break;
            case "none": break;
            case var other: throw new CliException($"option --lifts: expected all or none, got '{other}'");
        }
        if (trace != null) sources.Add(AccuracySource.FromTrace("trace", trace));
        string? mocap = o.Get("--mocap");
        if (mocap == null)
        {
            mocap = FindMocap();
            if (mocap == null) notes.Add($"motion-capture trace {MocapRelative} (beside the repository root) not found: skipped");
        }
        else if (mocap == "none") mocap = null;
        // The same file given twice (--trace as the motion capture) is measured once.
        if (mocap != null && trace != null && FileIdentity.Of(trace).SameAs(FileIdentity.Of(mocap)))
            notes.Add("--trace is the motion-capture trace: measured once, as mocap");
        else if (mocap != null) sources.Add(AccuracySource.FromTrace("mocap", mocap, "--mocap"));
        if (sources.Count == 0) throw new CliException("nothing to measure: --lifts none without --trace or a motion-capture trace");
        // A generated page or chart is rewritten only from the inputs it records (issue 32: without ../shared the
        // committed page lost a source), checked before the study runs.
        var inputsRecord = AccuracyInputs.Of(mass, speed, minutes, sources, costs);
        if (!o.Flag("--overwrite"))
        {
            if (markdownOut != null && !markdownOut.IsStandardOutput) inputsRecord.Check("--markdown", markdown!, AccuracyInputs.OfPage(markdown!));
            if (chartOut != null && !chartOut.IsStandardOutput) inputsRecord.Check("--chart", chartPath!, AccuracyInputs.OfChart(chartPath!));
        }

        var model = WeightModel.FromMass(mass);
        var report = AccuracyStudy.Run(new AccuracyStudy.Settings(model, speed, sources, minutes, notes), Progress.Writer);
        // The page also gives the golf ball's summary (gain 1): the same sources, no long run.
        var golfBall = markdownOut != null
            ? AccuracyStudy.Run(new AccuracyStudy.Settings(WeightModel.FromMass(PhysicalConstants.StandardMassKg), speed, sources, 0, notes), Progress.Writer)
            : null;
        // With an output on standard output ("-"), the tables go to standard error.
        bool stdoutTaken = csvOut?.IsStandardOutput == true || chartOut?.IsStandardOutput == true || markdownOut?.IsStandardOutput == true;
        var say = stdoutTaken ? Console.Error : Console.Out;
        AccuracyTable.Write(say, report);

        csvOut?.Write(w => AccuracyTable.WriteCsv(w, report));
        markdownOut?.Write(w => AccuracyMarkdown.Write(w, report, golfBall!, costs, inputsRecord));
        if (chartOut != null && costs != null)
        {
            // The PNG (with its inputs record) and the SVG beside it (--svg), each through its own output file.
            chartOut.WriteWith(temp =>
            {
                ParetoChart.Save(temp, report, costs, false);
                File.WriteAllBytes(temp, PngText.With(File.ReadAllBytes(temp), AccuracyInputs.Marker, inputsRecord.Line));
            });
            svgOut?.Write(w => w.Write(ParetoChart.Svg(report, costs)));
        }
        var written = new[] { csv, markdown, chartPath }.Where(p => p != null).Select(p => Messages.Path(p!)).ToList();
        say.WriteLine();
        say.WriteLine($"accuracy: {report.Configs.Count} configurations on {sources.Count} sources × {Degradation.RenderCount} seeded renders at {NumberText.Fixed(mass, 3)} kg{(golfBall != null ? " and the golf ball" : "")}{(minutes > 0 ? $", {LongRunStudy.Seeds} long runs of {minutes:0.##} min" : "")}{(written.Count > 0 ? " -> " + string.Join(", ", written) : "")}");
        return 0;
    }

    /// <summary>The motion-capture trace beside the repository that holds the current directory or this tool, if there is one.</summary>
    static string? FindMocap()
    {
        foreach (var start in new[] { Directory.GetCurrentDirectory(), AppContext.BaseDirectory })
            for (var dir = new DirectoryInfo(start); dir != null; dir = dir.Parent)
                if (File.Exists(Path.Combine(dir.FullName, "Packages", "com.kosmos.pseudohaptic", "package.json")))
                {
                    string candidate = Path.GetFullPath(Path.Combine(dir.FullName, MocapRelative));
                    if (File.Exists(candidate)) return candidate;
                    break;
                }
        return null;
    }
}
