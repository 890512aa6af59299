using Kosmos.PseudoHaptic.Cli.Traces;
using Kosmos.PseudoHaptic.Simulation;

namespace Kosmos.PseudoHaptic.Cli.Commands;

/// <summary>
/// <c>pseudohaptic replay --trace IN.csv --out OUT.csv --mass-kg M [--standard-speed V] [--profile P] [--grab-offset D]</c>:
/// runs a recorded trace through the solver, one output row per input row. The contract is in README.md
/// and ALGORITHM.md; other programs depend on it.
/// </summary>
public static class ReplayCommand
{
    public const string Usage = "pseudohaptic replay --trace IN.csv --out OUT.csv --mass-kg M [--standard-speed V] [--profile paper|paper-experiment|gain] [--grab-offset D]";

    public static int Run(string[] args)
    {
        var o = new Options(args, "--trace", "--out", "--mass-kg", "--standard-speed", "--profile", "--grab-offset");
        string trace = o.Require("--trace");
        string output = o.Require("--out");
        var solver = CreateSolver(o);
        double grabOffset = GrabOffset(o);

        using var file = TraceCsvReader.OpenText(trace);
        using var reader = new TraceCsvReader(file, trace);
        bool anyUsable = true;
        AtomicFile.Write(output, w => anyUsable = Replay(reader, solver, w, grabOffset));
        if (!anyUsable) Console.Error.WriteLine($"{trace}: warning: no row has a usable pose; object_y is 0 throughout");
        return 0;
    }

    /// <summary>Builds the solver from --mass-kg, --standard-speed and --profile, naming the option at fault.</summary>
    public static WeightSolver CreateSolver(Options o)
    {
        double mass = o.Number("--mass-kg") ?? throw new CliException("option --mass-kg is required");
        if (!(mass > 0) || double.IsInfinity(mass))
            throw new CliException($"option --mass-kg: must be a finite number greater than 0, got {NumberText.Format(mass)}");
        double speed = o.Number("--standard-speed") ?? WeightSolver.DefaultStandardSpeed;
        if (!(speed >= WeightSolver.MinStandardSpeed && speed <= WeightSolver.MaxStandardSpeed))
            throw new CliException($"option --standard-speed: must lie in [{WeightSolver.MinStandardSpeed}, {WeightSolver.MaxStandardSpeed}] m/s, got {NumberText.Format(speed)}");
        string name = o.Get("--profile") ?? NamedProfiles.PaperName;
        WeightProfile profile;
        try { profile = NamedProfiles.Get(name); }
        catch (ArgumentException) { throw new CliException($"option --profile: unknown profile '{name}'; expected {string.Join(", ", NamedProfiles.Names)}"); }
        return new WeightSolver(WeightModel.FromMass(mass), profile, speed);
    }

    /// <summary>--grab-offset D: metres, finite, default 0; the object starts D below the first usable hand (above it
    /// when negative).</summary>
    public static double GrabOffset(Options o)
    {
        double d = o.Number("--grab-offset") ?? 0;
        if (!double.IsFinite(d) || Math.Abs(d) > WeightSolver.MaxCoordinate)
            throw new CliException($"option --grab-offset: must be a finite number of metres, got {NumberText.Format(d)}");
        return d;
    }

    /// <summary>Streams rows through the solver. Rows before the first usable pose wait in a small buffer
    /// until the starting height is known. Returns false when no row had a usable pose.</summary>
    static bool Replay(TraceCsvReader reader, WeightSolver solver, TextWriter w, double grabOffset)
    {
        w.WriteLine("t,hand_y,object_y,offset");
        var waiting = new List<TraceFrame>();
        bool holding = false;
        double lastT = double.NaN;
        while (reader.TryRead(out var f))
        {
            double objectY;
            if (!holding)
            {
                if (!f.IsUsable) { waiting.Add(f); continue; }
                // The object starts grabOffset below the hand; without a floor in the way its path is exactly the path
                // of grabOffset 0, shifted by −grabOffset (every effect acts on the offset relative to the grab).
                solver.BeginHoldWithGrabOffset(f.HandY, grabOffset, f.PoseTime);
                holding = true;
                foreach (var early in waiting) Write(w, early, solver.ObjectY);
                waiting.Clear();
                objectY = solver.ObjectY;
            }
            else
            {
                double dt = double.IsFinite(f.Time) && double.IsFinite(lastT) ? f.Time - lastT : 0;
                objectY = solver.Step(f.ToSample(), dt);
            }
            if (double.IsFinite(f.Time)) lastT = f.Time;
            Write(w, f, objectY);
        }
        foreach (var early in waiting) Write(w, early, 0);
        return holding || waiting.Count == 0;
    }

    static void Write(TextWriter w, in TraceFrame f, double objectY)
    {
        double offset = f.IsUsable ? f.HandY - objectY : double.NaN;
        w.Write(NumberText.Format(f.Time)); w.Write(',');
        w.Write(NumberText.Format(f.HandY)); w.Write(',');
        w.Write(NumberText.Format(objectY)); w.Write(',');
        w.WriteLine(NumberText.Format(offset));
    }
}
