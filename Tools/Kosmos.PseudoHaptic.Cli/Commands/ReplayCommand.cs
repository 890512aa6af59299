using Kosmos.PseudoHaptic.Cli.CommandLine;
using Kosmos.PseudoHaptic.Cli.Files;
using Kosmos.PseudoHaptic.Cli.Traces;
using Kosmos.PseudoHaptic.Simulation;

namespace Kosmos.PseudoHaptic.Cli.Commands;

/// <summary>
/// <c>pseudohaptic replay --trace IN.csv --out OUT.csv --mass-kg M [--standard-speed V] [--profile NAME|FILE.json]</c>:
/// runs a recorded trace through the solver, one output row per input row. The contract is in README.md
/// and ALGORITHM.md; other programs depend on it.
/// </summary>
public static class ReplayCommand
{
    public static CliCommand Define() => new(
        "replay",
        "Replay a recorded hand (CSV) through the weight solver: one output row per input row with the object's position and the offset (ALGORITHM.md §10)",
        Run,
        new[]
        {
            "pseudohaptic replay --trace Packages/com.kosmos.pseudohaptic/Documentation~/examples/lift.csv --out out/replayed.csv --mass-kg 2",
            "pseudohaptic replay --trace Packages/com.kosmos.pseudohaptic/Documentation~/examples/walk-and-turn.csv --out - --mass-kg 0.5 --profile xyz --break-away 0.3",
        },
        CliCommand.Value("--trace", "IN.csv", "the recorded hand: columns t (s), hand_y (m), optional tracked, pose_t, hand_x, hand_z, a second hand hand2_*, and the rig's world pose rig_x, rig_y, rig_z (m), rig_yaw (degrees)", required: true),
        CliCommand.Value("--out", "OUT.csv", "where the replay goes ('-': standard output); replaced whole or not at all", required: true),
        CliCommand.Value("--mass-kg", "M", "the held object's mass, kg (> 0)", required: true),
        CliCommand.Value("--standard-speed", "V", $"the user's calibrated standard lifting speed, m/s, {WeightSolver.MinStandardSpeed}–{WeightSolver.MaxStandardSpeed} (default {WeightSolver.DefaultStandardSpeed})"),
        ProfileOption.Define($"which effects act (default {NamedProfiles.PaperName})"),
        CliCommand.Value("--user", "USER.json", "the user's file from 'pseudohaptic tune': its cueStrength s scales the cue (gain G^s; default 1)"),
        CliCommand.Value("--grab-offset", "D", "the object starts D metres below the first usable hand (default 0; negative: above)"),
        CliCommand.Value("--break-away", "D", "let go when the hand pulls D metres too far, two poses in a row: under the offset correction (paper, xyz) D is how far the hand pulls beyond what the weight allows (the strain: the lag of an object moving at most the user's capped speed), without it (paper-experiment, gain) the hand-to-object distance beyond the grab's; at most (1 + maxGain) × workspaceRadius, 48 with the default limits (default: never)"));

    public static int Run(string[] args) => Cli.Run(args.Prepend("replay").ToArray());

    static int Run(Options o)
    {
        string trace = o.Require("--trace");
        string output = o.Require("--out");
        var solver = CreateReplayed(o, out bool breakAway);
        double grabOffset = GrabOffset(o);
        var target = OutputFile.Check("--out", output, new NamedPath("--trace", trace), new NamedPath("--user", o.Get("--user")), ProfileOption.AsInput(o));

        using var file = TraceCsvReader.OpenText(trace);
        using var reader = new TraceCsvReader(file, trace);
        var summary = new ReplaySummary();
        target.Write(w => summary = Replay(reader, solver, breakAway, grabOffset, w, target.SpareFolder));
        if (!summary.AnyUsable)
            Console.Error.WriteLine($"{Messages.OneLine(trace)}: warning: no row has a usable pose; the object stays at {(reader.HasRig ? "the rig's origin" : "0")} throughout");
        // The calibration told as it is (issue 31): one line on standard error.
        Console.Error.WriteLine("replay: " + CalibrationStatement.Line(solver.Profile, solver.MassKg, solver.StandardSpeed, solver.CueStrength));
        // One line saying what was done; on standard error when the rows went to standard output.
        var say = target.IsStandardOutput ? Console.Error : Console.Out;
        string largest = summary.LargestOffset > 0 || summary.Holds > 0 ? NumberText.Fixed(summary.LargestOffset * 1000, 1) + " mm" : "none";
        say.WriteLine($"replay: {summary.Rows} rows, {summary.Holds} hold{(summary.Holds == 1 ? "" : "s")}{(summary.Released ? " (broken away)" : "")}, largest offset {largest} -> {Messages.OneLine(output)}");
        return 0;
    }

    /// <summary>Builds the solver from --mass-kg, --standard-speed and --profile, naming the option at fault.</summary>
    public static WeightSolver CreateSolver(Options o)
    {
        var (model, profile, speed) = Parse(o);
        return new WeightSolver(model, profile, speed);
    }

    /// <summary>What replay steps: <see cref="PaperLiteralSolver"/> under --profile paper-literal, else the 3D solver.</summary>
    public static IReplayedObject CreateReplayed(Options o, out bool breakAway)
    {
        var (model, profile, _) = Parse(o);
        if (NamedProfiles.IsPaperLiteral(profile))
        {
            breakAway = false;
            if (o.Get("--break-away") != null)
                throw new CliException("option --break-away: the paper-literal profile has no strain and no hold to break (the paper as printed); use paper, paper-experiment, gain or xyz");
            return new ReplayedPaperLiteral(model.MassKg, CueStrength(o), profile.Limits.MaxGain) { StandardSpeed = o.Number("--standard-speed") ?? WeightSolver.DefaultStandardSpeed };
        }
        var solver = CreateSolver3D(o, out breakAway);
        solver.CueStrength = CueStrength(o);
        return new ReplayedSolver3D(solver);
    }

    /// <summary>--user USER.json: its cueStrength (default 1, the cue as Eq. 4–6 give it).</summary>
    public static double CueStrength(Options o)
    {
        string? user = o.Get("--user");
        return user == null ? WeightSolver.DefaultCueStrength : UserFile.ReadCueStrength("--user", user);
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
        try { return new WeightSolver3D(model, profile, speed); }
        catch (ArgumentException e) when (distance.HasValue)
        {
            throw new CliException("option --break-away: " + Messages.WithoutParameter(e)); // a D or a profile where it could never fire
        }
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
        return (WeightModel.FromMass(mass), ProfileOption.Resolve(o.Get(ProfileOption.Name)), speed);
    }

    /// <summary>Streams rows through the solver. Rows before the first usable hand wait until the starting
    /// position is known: the first <see cref="FrameBuffer.InMemory"/> in memory, the rest in a temporary file
    /// beside the output, so memory stays bounded. With the rig's columns (issue 26) each hand is taken into the
    /// rig's frame, the solver runs there, and the object is written back through that row's rig; without them
    /// nothing is transformed. Returns the summary of what was replayed.</summary>
    static ReplaySummary Replay(TraceCsvReader reader, IReplayedObject solver, bool breakAway, double grabOffset, TextWriter w, string spareFolder)
    {
        var columns = new Columns(reader.HasHorizontal, reader.HasSecondHand, breakAway, reader.HasRig);
        w.Write("t,hand_y,object_y,offset");
        if (columns.Horizontal) w.Write(",hand_x,hand_z,object_x,object_z");
        if (columns.SecondHand) w.Write(",hands");
        if (columns.Held) w.Write(",held");
        w.WriteLine();

        bool twoHands = solver.Profile.Has<TwoHands>();
        using var waiting = new FrameBuffer(spareFolder);
        var summary = new ReplaySummary();
        bool holding = false;
        (double X, double Y, double Z)? letGo = null;
        double lastT = double.NaN;
        while (reader.TryReadRow(out TraceRow r))
        {
            summary.Rows++;
            var a = columns.First(r);
            var b = columns.Second(r);
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
                summary.Holds++;
                waiting.Drain(early => Write(w, columns, early, columns.Object(early, solver.ObjectX, solver.ObjectY, solver.ObjectZ), true, ref summary));
            }
            else
            {
                double dt = double.IsFinite(r.First.Time) && double.IsFinite(lastT) ? r.First.Time - lastT : 0;
                solver.Step(a, b, dt);
            }
            if (double.IsFinite(r.First.Time)) lastT = r.First.Time;
            var world = columns.Object(r, solver.ObjectX, solver.ObjectY, solver.ObjectZ);
            // Let go (--break-away): the object stays where it was let go in the world, not in a rig that may walk
            // on; without a rig the solver's frame is the world's and the solver already keeps it there.
            if (columns.Rig && !solver.IsHolding) world = letGo ??= world;
            Write(w, columns, r, world, solver.IsHolding, ref summary);
        }
        summary.Released = holding && !solver.IsHolding;
        summary.AnyUsable = holding || waiting.Count == 0;
        // No usable pose in the whole trace: nothing was ever held (held 0), and the object stays at the origin.
        waiting.Drain(early => Write(w, columns, early, columns.Object(early, 0, 0, 0), false, ref summary));
        return summary;
    }

    /// <summary>What one replay did, for the line the command prints.</summary>
    struct ReplaySummary
    {
        public long Rows;
        public int Holds;
        public bool Released;
        public bool AnyUsable;

        /// <summary>The largest |hand_y − object_y| over held rows with a usable first hand, m; 0 when there is none.</summary>
        public double LargestOffset;

        public void Offset(double offset)
        {
            if (double.IsFinite(offset) && !(Math.Abs(offset) <= LargestOffset)) LargestOffset = Math.Abs(offset);
        }
    }

    readonly record struct Columns(bool Horizontal, bool SecondHand, bool Held, bool Rig)
    {
        /// <summary>The first hand as the solver takes it: in the rig's frame when the trace gives the rig, else as read.</summary>
        public HandPose First(in TraceRow r) => Rig ? r.InRig(r.FirstPose, Horizontal) : r.FirstPose;

        public HandPose Second(in TraceRow r) => Rig ? r.InRig(r.SecondPose, Horizontal) : r.SecondPose;

        /// <summary>The solver's object in the world: through the row's rig when the trace gives it, else as it is.</summary>
        public (double X, double Y, double Z) Object(in TraceRow r, double x, double y, double z)
        {
            if (!Rig) return (x, y, z);
            r.Rig.ToWorld(x, y, z, out double wx, out double wy, out double wz);
            return (wx, wy, wz);
        }
    }

    /// <summary>One output row, formatted on the stack (no allocation per row, as the one-hand replay); the object
    /// in world coordinates.</summary>
    static void Write(TextWriter w, Columns c, in TraceRow r, (double X, double Y, double Z) world, bool held, ref ReplaySummary summary)
    {
        bool usable = c.First(r).IsUsable;
        double offset = usable ? r.First.HandY - world.Y : double.NaN;
        if (held) summary.Offset(offset);
        Span<char> buffer = stackalloc char[32 * 8 + 16];
        int n = 0;
        n += NumberText.Format(r.First.Time, buffer[n..]); buffer[n++] = ',';
        n += NumberText.Format(r.First.HandY, buffer[n..]); buffer[n++] = ',';
        n += NumberText.Format(world.Y, buffer[n..]); buffer[n++] = ',';
        n += NumberText.Format(offset, buffer[n..]);
        if (c.Horizontal)
        {
            buffer[n++] = ','; n += NumberText.Format(r.HandX, buffer[n..]);
            buffer[n++] = ','; n += NumberText.Format(r.HandZ, buffer[n..]);
            buffer[n++] = ','; n += NumberText.Format(world.X, buffer[n..]);
            buffer[n++] = ','; n += NumberText.Format(world.Z, buffer[n..]);
        }
        if (c.SecondHand) { buffer[n++] = ','; buffer[n++] = (char)('0' + (usable ? 1 : 0) + (c.Second(r).IsUsable ? 1 : 0)); }
        if (c.Held) { buffer[n++] = ','; buffer[n++] = held ? '1' : '0'; }
        buffer[n++] = '\n';
        w.Write(buffer[..n]);
    }
}
