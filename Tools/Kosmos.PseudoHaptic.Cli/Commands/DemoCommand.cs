using Kosmos.PseudoHaptic.Cli.CommandLine;
using Kosmos.PseudoHaptic.Cli.Files;
using Kosmos.PseudoHaptic.Cli.Plotting;
using Kosmos.PseudoHaptic.Cli.Traces;
using Kosmos.PseudoHaptic.Simulation;

namespace Kosmos.PseudoHaptic.Cli.Commands;

/// <summary>
/// <c>pseudohaptic demo [--out DIR] [--trace FILE] [--svg]</c>: the paper's scenes without a headset. Calibrates a
/// standard speed from synthetic golf-ball lifts, then lifts Experiment 1's boxes and Experiment 2's water
/// bottles with a simulated Quest 2 hand (30 Hz poses, 45 ms late, 1 mm jitter, 90 Hz frames); with
/// --trace, also replays a recorded hand degraded the same way. Writes a CSV per run and a PNG per scene
/// (with --svg, an SVG beside it), and prints a summary. Issue 10's 3D scene (<see cref="DemoThreeDimensions"/>:
/// a sideways carry, a high lift and a two-hand lift under <c>xyz</c>) is written to <c>xyz-carry-lift</c>.
/// </summary>
public static class DemoCommand
{
    public const string DefaultOut = "out/demo";

    sealed record Item(string Name, double MassKg, string Note);
    sealed record Scene(string Slug, string Title, WeightProfile Profile, IReadOnlyList<Item> Items, TraceFrame[] Frames);
    sealed record Result(Scene Scene, Item Item, double Gain, double MaxOffset, double EndOffset, double[] ObjectY);

    public static CliCommand Define() => new(
        "demo",
        "Simulate the paper's scenes without a headset (calibration, Experiment 1's boxes, Experiment 2's bottles, the offset correction, a 3D carry, Experiment 1 again under the paper's equations as printed): a CSV per run, a PNG per scene, a summary table",
        Run,
        new[]
        {
            "pseudohaptic demo",
            "pseudohaptic demo --out out/demo-lift --trace Packages/com.kosmos.pseudohaptic/Documentation~/examples/lift.csv --svg",
        },
        CliCommand.Value("--out", "DIR", $"the folder to write (default {DefaultOut}, whose parents it creates); it appears whole or not at all"),
        CliCommand.Value("--trace", "FILE", "also replay this recorded hand (replay's CSV format, usable rows spanning at most 300 s), degraded to 30 Hz poses"),
        CliCommand.Value("--user", "USER.json", "the user's file from 'pseudohaptic tune': its cueStrength s scales every scene's cue (gain G^s; default 1)"),
        CliCommand.Flag("--svg", "write an SVG beside each PNG"));

    static int Run(Options o)
    {
        bool svg = o.Flag("--svg");
        string? given = o.Get("--out");
        string outDir = given ?? DefaultOut;
        string? tracePath = o.Get("--trace");
        string? userPath = o.Get("--user");
        double cueStrength = userPath != null ? UserFile.ReadCueStrength("--user", userPath) : WeightSolver.DefaultCueStrength;
        // The folder is checked (writable, not the trace) and the trace read before anything is computed or created;
        // the folder then appears whole.
        OutputFolder.Check("--out", outDir, Owns, createParents: given == null, new NamedPath("--trace", tracePath), new NamedPath("--user", userPath));
        (List<double> Times, List<double> Heights)? recorded = tracePath != null
            ? TraceSamples.Read("--trace", tracePath, "demo", usePoseTime: false, TraceSamples.DemoMaxSpan) : null;
        if (recorded != null && recorded.Value.Times.Count < 2)
            throw new CliException($"{Messages.OneLine(tracePath!)}: fewer than two usable rows with increasing t");

        double standardSpeed = Calibrate();
        var scenes = Scenes(recorded, tracePath);
        int total = scenes.Sum(s => s.Items.Count), done = 0;
        var results = new List<Result>();
        var results3D = new List<DemoThreeDimensions.Result>();
        var folder = OutputFolder.Begin("--out", outDir, Owns, createParents: given == null, new NamedPath("--trace", tracePath), new NamedPath("--user", userPath));
        folder.Build(temp =>
        {
            foreach (var scene in scenes)
            {
                string dir = Path.Combine(temp, scene.Slug);
                // Steps that create folders run guarded, so SIGINT/SIGTERM cannot race them into leaving one behind.
                Temporaries.Guard(() => Directory.CreateDirectory(dir));
                var sceneResults = new List<Result>();
                foreach (var item in scene.Items)
                {
                    Progress.Writer.WriteLine($"[{++done}/{total}] {scene.Title}: {item.Name}");
                    var (gain, y) = RunItem(scene.Profile, item.MassKg, scene.Frames, standardSpeed, cueStrength);
                    var result = Measure(scene, item, gain, y);
                    sceneResults.Add(result);
                    Temporaries.Guard(() => WriteCsv(Path.Combine(dir, Slug(item.Name) + ".csv"), scene.Frames, y));
                }
                Temporaries.Guard(() => Plot(Path.Combine(temp, scene.Slug + ".png"), scene, sceneResults, svg, standardSpeed));
                results.AddRange(sceneResults);
            }
            results3D = DemoThreeDimensions.Run(temp, standardSpeed, svg, Progress.Writer, cueStrength);
        });
        PrintSummary(results, standardSpeed, outDir, cueStrength);
        PrintSummary3D(results3D);
        Console.WriteLine();
        Console.WriteLine($"demo: {results.Count + results3D.Count} objects lifted in {scenes.Count + 1} scenes (v_std = {NumberText.Fixed(standardSpeed, 3)} m/s) -> {Messages.OneLine(outDir)}");
        return 0;
    }

    /// <summary>One object through the scene's profile: the package's solver, or under <c>paper-literal</c> the paper as
    /// printed (<see cref="PaperLiteralSolver"/>, run as the accuracy page's baseline is); the gain it applies and the heights.</summary>
    static (double Gain, double[] Y) RunItem(WeightProfile profile, double massKg, TraceFrame[] frames, double standardSpeed, double cueStrength)
    {
        var model = WeightModel.FromMass(massKg);
        if (NamedProfiles.IsPaperLiteral(profile))
        {
            double g = WeightSolver.StrengthenedGain(model.Gain(true, true, double.PositiveInfinity), cueStrength, double.PositiveInfinity);
            return (g, Accuracy.IntegratorReplay.Run(new Accuracy.IntegratorReplay.PaperLiteral(massKg, cueStrength), frames));
        }
        var solver = new WeightSolver(model, profile, standardSpeed) { CueStrength = cueStrength };
        return (solver.Gain, TraceReplay.Run(solver, frames));
    }

    /// <summary>Five golf-ball lifts of a simulated user (30 Hz poses, 1.5 mm jitter) through the core's calibration.</summary>
    static double Calibrate()
    {
        Progress.Writer.WriteLine("Calibration: five lifts of a golf ball");
        var times = new List<double[]>();
        var heights = new List<double[]>();
        double[] rises = { 0.32, 0.36, 0.30, 0.38, 0.34 }, durations = { 0.70, 0.78, 0.66, 0.80, 0.74 };
        for (int k = 0; k < rises.Length; k++)
        {
            var path = HandPath.StartAt(0.85).Hold(0.5).MoveTo(0.85 + rises[k], durations[k]).Hold(0.5);
            var frames = new HeadsetSimulator { FrameRate = 30, PoseRate = 30, JitterSd = 0.0015, Seed = 100 + k }.Render(path);
            times.Add(frames.Select(f => f.Time).ToArray());
            heights.Add(frames.Select(f => f.HandY).ToArray());
            var lift = StandardSpeedCalibration.MeasureLift(times[k], heights[k]);
            Progress.Writer.WriteLine($"  lift {k + 1}: {lift}");
        }
        var result = StandardSpeedCalibration.FromLifts(times, heights);
        Progress.Writer.WriteLine($"  {result}");
        return result.IsAccepted ? result.StandardSpeed : WeightSolver.DefaultStandardSpeed;
    }

    /// <summary>What an existing --out folder may hold to be replaced: the scenes' charts and their folders of CSV files.</summary>
    static readonly OutputFolder.Owns Owns = entry => entry is DirectoryInfo
        ? OutputFolder.FilesEndingWith(folders: true, ".csv")(entry)
        : OutputFolder.FilesEndingWith(folders: false, ".png", ".svg")(entry);

    static List<Scene> Scenes((List<double> Times, List<double> Heights)? recorded, string? tracePath)
    {
        var headset = new HeadsetSimulator { FrameRate = 90, PoseRate = 30, Latency = 0.045, JitterSd = 0.001, Seed = 2022 };
        // Lift 0.35 m, hold, put it back down: the same hand for every object, so only the weight differs.
        var liftAndPlace = headset.Render(HandPath.StartAt(0.80).Hold(0.5).MoveTo(1.15, 0.9).Hold(1.0).MoveTo(0.80, 0.9).Hold(0.7));
        var highLift = headset.Render(HandPath.StartAt(0.75).Hold(0.5).MoveTo(1.45, 1.4).Hold(1.5));

        // Experiment 1 (PaperExperiment1, the samples' too): three boxes of the same size, different densities; B heaviest.
        var boxes = new List<Item> { new("golf ball", PhysicalConstants.StandardMassKg, "the standard weight") };
        for (int b = 0; b < PaperExperiment1.BoxNames.Length; b++)
            boxes.Add(new("box " + PaperExperiment1.BoxNames[b], PaperExperiment1.Mass(PaperExperiment1.BoxDensities[b]), $"{PaperExperiment1.BoxDensities[b]:0} kg/m³"));
        // Experiment 2: water bottles by size (water plus the bottle).
        var bottles = new List<Item>
        {
            new("bottle 0.33 L", 0.330 + 0.015, "330 ml"),
            new("bottle 0.5 L", 0.500 + 0.020, "500 ml"),
            new("bottle 1 L", 1.000 + 0.035, "1 l"),
            new("bottle 2 L", 2.000 + 0.045, "2 l"),
        };
        var scenes = new List<Scene>
        {
            new("experiment-1-boxes", $"Experiment 1: boxes A, B, C ({PaperExperiment1.ProfileName})", NamedProfiles.Get(PaperExperiment1.ProfileName), boxes, liftAndPlace),
            new("experiment-1-literal", "Experiment 1: boxes A, B, C, the paper as printed (paper-literal)", NamedProfiles.PaperLiteral, boxes, liftAndPlace),
            new("experiment-2-bottles", "Experiment 2: water bottles (paper-experiment)", NamedProfiles.PaperExperiment, bottles, liftAndPlace),
            new("offset-correction", "A high lift with the offset correction (paper)", NamedProfiles.Paper,
                new List<Item> { boxes[0], boxes[2], new("box D", 5, $"{5 / PaperExperiment1.BoxVolume:0} kg/m³") }, highLift),
        };
        if (recorded != null)
        {
            var (times, ys) = recorded.Value;
            var frames = new HeadsetSimulator { FrameRate = 90, PoseRate = 30, Latency = 0.045, JitterSd = 0.0, Seed = 7 }
                .Render(HandPath.FromSamples(times, ys));
            scenes.Add(new("recorded-hand", $"Recorded hand ({Messages.OneLine(Path.GetFileName(tracePath))}), as 30 Hz poses (paper)", NamedProfiles.Paper, boxes, frames));
        }
        return scenes;
    }

    static Result Measure(Scene scene, Item item, double gain, double[] y)
    {
        double max = 0, end = 0;
        for (int i = 0; i < y.Length; i++)
        {
            if (!scene.Frames[i].Tracked || !double.IsFinite(scene.Frames[i].HandY)) continue;
            double off = scene.Frames[i].HandY - y[i];
            if (Math.Abs(off) > Math.Abs(max)) max = off;
            end = off;
        }
        return new Result(scene, item, gain, max, end, y);
    }

    static void WriteCsv(string path, TraceFrame[] frames, double[] y)
    {
        using var w = new StreamWriter(path, false, new System.Text.UTF8Encoding(false)) { NewLine = "\n" };
        w.WriteLine("t,hand_y,object_y,offset");
        for (int i = 0; i < frames.Length; i++)
            w.WriteLine($"{NumberText.Format(frames[i].Time)},{NumberText.Format(frames[i].HandY)},{NumberText.Format(y[i])},{NumberText.Format(frames[i].HandY - y[i])}");
    }

    /// <summary>
    /// A scene's chart: each object's height (its own colour, line pattern and width), the hand over them (black,
    /// dashed, drawn last), the legend under the plot. An object that follows the hand (gain 1: the golf ball) is
    /// drawn as markers, so it shows beside the hand's line rather than under it. With the offset correction, a second
    /// panel shows the offset (hand − object) with the correction (lines), without it (light wide bands, drawn first,
    /// left out where the correction never acts), and each mass's own threshold T(m) from the core
    /// (<see cref="OffsetCorrection.ThresholdFor"/>, thin dashed in its colour).
    /// </summary>
    /// <summary>Below this largest change by the correction (m), the offset with and without it are drawn as one line.</summary>
    const double SameWithoutM = 0.005;

    static void Plot(string path, Scene scene, List<Result> results, bool svg, double standardSpeed)
    {
        var t = scene.Frames.Select(f => f.Time).ToArray();
        var hand = scene.Frames.Select(f => f.Tracked ? f.HandY : double.NaN).ToArray();
        var plot = Charts.Create(scene.Title, "time (s)", "height (m)");
        for (int i = 0; i < results.Count; i++)
        {
            string label = $"{results[i].Item.Name} {results[i].Item.MassKg:0.###} kg";
            if (FollowsHand(hand, results[i].ObjectY)) Charts.Markers(plot, t, results[i].ObjectY, label + " (with the hand: markers)", i, every: 0.1);
            else Charts.Series(plot, t, results[i].ObjectY, label, i);
        }
        Charts.Hand(plot, t, hand, "hand (30 Hz poses)");
        Charts.LegendBelow(plot);
        var correction = scene.Profile.Find<OffsetCorrection>();
        if (correction == null)
        {
            Charts.Save(plot, path, 1000, 600, svg);
            return;
        }
        // What the correction does: the offset with and without it, and the threshold it acts beyond, per mass.
        var uncorrected = scene.Profile.Without<OffsetCorrection>("paper without the offset correction");
        var offsets = Charts.Create("Offset, hand − object: with the correction (lines), without it (light bands)", "time (s)", "offset (m)");
        var corrected = new List<double[]>();
        var same = new bool[results.Count];
        for (int i = 0; i < results.Count; i++)
        {
            var free = TraceReplay.Run(new WeightSolver(WeightModel.FromMass(results[i].Item.MassKg), uncorrected, standardSpeed), scene.Frames);
            var mine = hand.Select((h, k) => h - results[i].ObjectY[k]).ToArray();
            var without = hand.Select((h, k) => h - free[k]).ToArray();
            corrected.Add(mine);
            double acts = 0;
            for (int k = 0; k < t.Length; k++) if (double.IsFinite(mine[k]) && double.IsFinite(without[k])) acts = Math.Max(acts, Math.Abs(mine[k] - without[k]));
            // Drawn first and wide, so the corrected line lies on it and both show; where the correction changes the
            // offset by less than the band's half-width (about 5 mm at the chart's scale) the line would only cover its
            // own band: the two are one line, drawn once and named so.
            same[i] = acts < SameWithoutM;
            if (!same[i]) Charts.Band(offsets, t, without, $"{results[i].Item.Name} without the correction", i);
            double threshold = correction.ThresholdFor(results[i].Item.MassKg);
            Charts.Threshold(offsets, threshold, $"{results[i].Item.Name}: threshold {threshold:0.###} m", Charts.Colour(i));
        }
        for (int i = 0; i < results.Count; i++)
            Charts.Series(offsets, t, corrected[i], same[i] ? $"{results[i].Item.Name} (the correction moves it under 5 mm: the same without)" : results[i].Item.Name, i);
        Charts.LegendBelow(offsets);
        Charts.SavePanels(new[] { plot, offsets }, path, 1000, new[] { 560, 520 }, svg);
    }

    /// <summary>Whether an object keeps within 2 mm of the hand in at least 80 % of the tracked frames (gain 1).</summary>
    static bool FollowsHand(double[] hand, double[] y)
    {
        int near = 0, all = 0;
        for (int k = 0; k < hand.Length; k++)
        {
            if (!double.IsFinite(hand[k])) continue;
            all++;
            if (Math.Abs(hand[k] - y[k]) <= 0.002) near++;
        }
        return all > 0 && near >= 0.8 * all;
    }

    static void PrintSummary(List<Result> results, double standardSpeed, string outDir, double cueStrength)
    {
        Console.WriteLine($"standard speed v_std = {NumberText.Fixed(standardSpeed, 3)} m/s (calibrated from five synthetic golf-ball lifts)");
        // The calibration told as it is (issue 31), on Experiment 1's heaviest box (B) under the profile its scene runs.
        Console.WriteLine("what it does: " + CalibrationStatement.Line(NamedProfiles.Get(PaperExperiment1.ProfileName),
            PaperExperiment1.Mass(PaperExperiment1.BoxBDensity), standardSpeed, cueStrength));
        if (cueStrength != WeightSolver.DefaultCueStrength) Console.WriteLine($"cue strength s = {NumberText.Fixed(cueStrength, 3)} (--user): every gain is G^s");
        Console.WriteLine();
        Console.WriteLine($"{"scene",-22} {"object",-14} {"mass kg",8} {"gain",6} {"max offset m",13} {"end offset m",13}");
        foreach (var r in results)
            Console.WriteLine($"{r.Scene.Slug,-22} {r.Item.Name,-14} {NumberText.Fixed(r.Item.MassKg, 3),8} {NumberText.Fixed(r.Gain, 3),6} {NumberText.Fixed(r.MaxOffset, 3),13} {NumberText.Fixed(r.EndOffset, 3),13}");
        Console.WriteLine();
        Console.WriteLine($"offset = hand − object (positive: the object lags below the hand). CSV and PNG files in {Messages.OneLine(Path.GetFullPath(outDir))}");
    }

    static void PrintSummary3D(List<DemoThreeDimensions.Result> results)
    {
        Console.WriteLine();
        Console.WriteLine($"{DemoThreeDimensions.Slug} (xyz): one hand carries 0.4 m sideways (0.3 m forward) and lifts 0.8 m; then two hands lift 0.4 m and carry it back");
        Console.WriteLine($"{"object",-14} {"mass kg",8} {"max x lag m",12} {"high lift max offset m",23} {"two-hand max offset m",22} {"two-hand carry max x lag m",27}");
        foreach (var r in results)
            Console.WriteLine($"{r.Name,-14} {NumberText.Fixed(r.MassKg, 3),8} {NumberText.Fixed(r.MaxLateralLag, 3),12} {NumberText.Fixed(r.MaxHighLiftOffset, 3),23} {NumberText.Fixed(r.MaxTwoHandOffset, 3),22} {NumberText.Fixed(r.MaxTwoHandLateralLag, 3),27}");
    }

    static string Slug(string name) => new string(name.ToLowerInvariant().Select(c => char.IsLetterOrDigit(c) || c == '.' ? c : '-').ToArray()).Trim('-');
}
