using Kosmos.PseudoHaptic.Cli.Files;
using Kosmos.PseudoHaptic.Cli.Traces;
using Kosmos.PseudoHaptic.Simulation;

namespace Kosmos.PseudoHaptic.Cli.Commands;

/// <summary>
/// <c>pseudohaptic replay --trace IN.csv --out OUT.csv --mass-kg M [--standard-speed V] [--profile P]</c>:
/// runs a recorded trace through the solver, one output row per input row. The contract is in README.md
/// and ALGORITHM.md; other programs depend on it.
/// </summary>
public static class ReplayCommand
{
    public const string Usage = "pseudohaptic replay --trace IN.csv --out OUT.csv --mass-kg M [--standard-speed V] [--profile paper|paper-experiment|gain|xyz] [--grab-offset D] [--break-away D]";

    public static int Run(string[] args)
    {
        var o = new Options(args, "--trace", "--out", "--mass-kg", "--standard-speed", "--profile", "--grab-offset", "--break-away");
        string trace = o.Require("--trace");
        string output = o.Require("--out");
        var solver = CreateSolver3D(o, out bool breakAway);
        double grabOffset = GrabOffset(o);
        var target = OutputFile.Check("--out", output, new NamedPath("--trace", trace));

        using var file = TraceCsvReader.OpenText(trace);
        using var reader = new TraceCsvReader(file, trace);
        bool anyUsable = true;
        target.Write(w => anyUsable = Replay(reader, solver, breakAway, grabOffset, w, target.SpareFolder));
        if (!anyUsable) Console.Error.WriteLine($"{Messages.OneLine(trace)}: warning: no row has a usable pose; object_y is 0 throughout");
        return 0;
    }

    /// <summary>Builds the solver from --mass-kg, --standard-speed and --profile, naming the option at fault.</summary>
    public static WeightSolver CreateSolver(Options o)
    {
        var (model, profile, speed) = Parse(o);
        return new WeightSolver(model, profile, speed);
    }

    /// <summary>The 3D solver replay runs (issue 10): --profile, plus --break-away when given.</summary>
    public static WeightSolver3D CreateSolver3D(Options o, out bool breakAway)
    {
        var (model, profile, speed) = Parse(o);
        double? distance = o.Number("--break-away");
        breakAway = distance.HasValue;
        if (distance.HasValue)
        {
            if (!(distance.Value > 0) || double.IsInfinity(distance.Value))
                throw new CliException($"option --break-away: must be a finite number greater than 0 (metres), got {NumberText.Format(distance.Value)}");
            profile = profile.With(new BreakAway(distance.Value));
        }
        return new WeightSolver3D(model, profile, speed);
    }

    /// <summary>--grab-offset D: metres, finite, default 0; the object starts D below the first usable hand (or the
    /// midpoint of both; above it when negative).</summary>
    public static double GrabOffset(Options o)
    {
        double d = o.Number("--grab-offset") ?? 0;
        if (!double.IsFinite(d) || Math.Abs(d) > WeightSolver.MaxCoordinate)
            throw new CliException($"option --grab-offset: must be a finite number of metres, got {NumberText.Format(d)}");
        return d;
    }

    static (WeightModel, WeightProfile, double) Parse(Options o)
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
        return (WeightModel.FromMass(mass), profile, speed);
    }

    /// <summary>Streams rows through the solver. Rows before the first usable hand wait until the starting
    /// position is known: the first <see cref="FrameBuffer.InMemory"/> in memory, the rest in a temporary file
    /// beside the output, so memory stays bounded. Returns false when no row had a usable hand.</summary>
    static bool Replay(TraceCsvReader reader, WeightSolver3D solver, bool breakAway, double grabOffset, TextWriter w, string spareFolder)
    {
        var columns = new Columns(reader.HasHorizontal, reader.HasSecondHand, breakAway);
        w.Write("t,hand_y,object_y,offset");
        if (columns.Horizontal) w.Write(",hand_x,hand_z,object_x,object_z");
        if (columns.SecondHand) w.Write(",hands");
        if (columns.Held) w.Write(",held");
        w.WriteLine();

        bool twoHands = solver.Profile.Has<TwoHands>();
        using var waiting = new FrameBuffer(spareFolder);
        bool holding = false;
        double lastT = double.NaN;
        while (reader.TryReadRow(out TraceRow r))
        {
            var a = r.FirstPose;
            var b = r.SecondPose;
            if (!holding)
            {
                bool one = a.IsUsable, two = twoHands && b.IsUsable;
                if (!one && !two) { waiting.Add(r); continue; }
                // The object starts where the first usable hand is, or at the midpoint of both.
                // With --grab-offset D it starts D below that point, the offset kept exactly (BeginHoldWithGrabOffset):
                // where the floor is not in the way, object_y is the path without the option, less D.
                double x = one && two ? 0.5 * (a.X + b.X) : (one ? a.X : b.X);
                double z = one && two ? 0.5 * (a.Z + b.Z) : (one ? a.Z : b.Z);
                solver.BeginHoldWithGrabOffset(a, twoHands ? b : HandPose.Lost, x, grabOffset, z);
                holding = true;
                waiting.Drain(early => Write(w, columns, early, solver.ObjectX, solver.ObjectY, solver.ObjectZ, true));
            }
            else
            {
                double dt = double.IsFinite(r.First.Time) && double.IsFinite(lastT) ? r.First.Time - lastT : 0;
                solver.Step(a, b, dt);
            }
            if (double.IsFinite(r.First.Time)) lastT = r.First.Time;
            Write(w, columns, r, solver.ObjectX, solver.ObjectY, solver.ObjectZ, solver.IsHolding);
        }
        bool none = waiting.Count == 0;
        waiting.Drain(early => Write(w, columns, early, 0, 0, 0, true));
        return holding || none;
    }

    readonly record struct Columns(bool Horizontal, bool SecondHand, bool Held);

    /// <summary>One output row, formatted on the stack (no allocation per row, as the one-hand replay).</summary>
    static void Write(TextWriter w, Columns c, in TraceRow r, double objectX, double objectY, double objectZ, bool held)
    {
        bool usable = r.FirstPose.IsUsable;
        double offset = usable ? r.First.HandY - objectY : double.NaN;
        Span<char> buffer = stackalloc char[32 * 8 + 16];
        int n = 0;
        n += NumberText.Format(r.First.Time, buffer[n..]); buffer[n++] = ',';
        n += NumberText.Format(r.First.HandY, buffer[n..]); buffer[n++] = ',';
        n += NumberText.Format(objectY, buffer[n..]); buffer[n++] = ',';
        n += NumberText.Format(offset, buffer[n..]);
        if (c.Horizontal)
        {
            buffer[n++] = ','; n += NumberText.Format(r.HandX, buffer[n..]);
            buffer[n++] = ','; n += NumberText.Format(r.HandZ, buffer[n..]);
            buffer[n++] = ','; n += NumberText.Format(objectX, buffer[n..]);
            buffer[n++] = ','; n += NumberText.Format(objectZ, buffer[n..]);
        }
        if (c.SecondHand) { buffer[n++] = ','; buffer[n++] = (char)('0' + (usable ? 1 : 0) + (r.SecondPose.IsUsable ? 1 : 0)); }
        if (c.Held) { buffer[n++] = ','; buffer[n++] = held ? '1' : '0'; }
        buffer[n++] = '\n';
        w.Write(buffer[..n]);
    }
}
