using Kosmos.PseudoHaptic.Cli.Files;
using Kosmos.PseudoHaptic.Evaluation;
using Kosmos.PseudoHaptic.Simulation;

namespace Kosmos.PseudoHaptic.Cli.Traces;

/// <summary>
/// Reads the replay trace format row by row through the one CSV reader (<see cref="CsvReader"/>: RFC 4180,
/// quoted fields, UTF-8 with or without BOM, LF or CRLF, rows of at most 1 MiB): a header row, columns by
/// name in any order, extra columns ignored, every row with as many fields as the header. Required: <c>t</c>
/// (s) and <c>hand_y</c> (m; may be NaN, Infinity, inf in any case, or empty for no pose); optional
/// <c>tracked</c> (1/0, default 1) and <c>pose_t</c> (s; empty or non-finite for unknown). Blank lines are
/// skipped. Errors name the file and line (the header is line 1). Memory is constant per row.
/// Issue 10 adds, optionally: <c>hand_x,hand_z</c> (both or neither), a second hand <c>hand2_y</c> (required
/// by any other <c>hand2_*</c>, <c>tracked2</c> or <c>pose2_t</c>), <c>hand2_x,hand2_z</c> (both or neither, only
/// with <c>hand_x,hand_z</c>), <c>tracked2</c>, <c>pose2_t</c>, each with the first hand's number rules
/// (<see cref="TryReadRow"/>). Issue 26 adds, optionally, the world pose of the tracking origin in each row:
/// <c>rig_x,rig_y,rig_z</c> (m) and <c>rig_yaw</c> (degrees about +y), all four or none, each value present,
/// finite and within ±<see cref="WeightSolver.MaxCoordinate"/> (<see cref="RigFrame"/>).
/// </summary>
public sealed class TraceCsvReader : IDisposable
{
    readonly CsvReader _csv;
    readonly string _name;
    readonly int _t, _handY, _tracked, _poseT;
    readonly int _handX, _handZ, _hand2X, _hand2Y, _hand2Z, _tracked2, _pose2T;
    readonly int _rigX, _rigY, _rigZ, _rigYaw;

    /// <summary>The rig's columns, in the order their absence is reported.</summary>
    public static readonly string[] RigColumns = { "rig_x", "rig_y", "rig_z", "rig_yaw" };

    public TraceCsvReader(TextReader reader, string name)
    {
        _name = name;
        _csv = new CsvReader(reader, Messages.OneLine(name));
        try
        {
            if (!_csv.ReadHeader()) throw Error(1, "the file is empty; expected a header row with columns t and hand_y");
            _t = _csv.IndexOf("t");
            _handY = _csv.IndexOf("hand_y");
            _tracked = _csv.IndexOf("tracked");
            _poseT = _csv.IndexOf("pose_t");
            _handX = _csv.IndexOf("hand_x");
            _handZ = _csv.IndexOf("hand_z");
            _hand2X = _csv.IndexOf("hand2_x");
            _hand2Y = _csv.IndexOf("hand2_y");
            _hand2Z = _csv.IndexOf("hand2_z");
            _tracked2 = _csv.IndexOf("tracked2");
            _pose2T = _csv.IndexOf("pose2_t");
            _rigX = _csv.IndexOf("rig_x");
            _rigY = _csv.IndexOf("rig_y");
            _rigZ = _csv.IndexOf("rig_z");
            _rigYaw = _csv.IndexOf("rig_yaw");
        }
        catch (EvaluationFormatException e) { throw new CliException(e.Message); }
        int header = _csv.HeaderLine;
        if (_t < 0) throw Error(header, "missing column 't'");
        if (_handY < 0) throw Error(header, "missing column 'hand_y'");
        if ((_handX < 0) != (_handZ < 0))
            throw Error(header, _handX >= 0 ? "column 'hand_x' needs column 'hand_z' (both or neither)" : "column 'hand_z' needs column 'hand_x' (both or neither)");
        if (_hand2Y < 0)
        {
            foreach (var (index, column) in new[] { (_hand2X, "hand2_x"), (_hand2Z, "hand2_z"), (_tracked2, "tracked2"), (_pose2T, "pose2_t") })
                if (index >= 0) throw Error(header, $"column '{column}' needs column 'hand2_y'");
        }
        if ((_hand2X < 0) != (_hand2Z < 0))
            throw Error(header, _hand2X >= 0 ? "column 'hand2_x' needs column 'hand2_z' (both or neither)" : "column 'hand2_z' needs column 'hand2_x' (both or neither)");
        if (_hand2X >= 0 && _handX < 0)
            throw Error(header, "columns 'hand2_x' and 'hand2_z' need columns 'hand_x' and 'hand_z'");
        var rig = new[] { _rigX, _rigY, _rigZ, _rigYaw };
        if (rig.Any(i => i >= 0) && rig.Any(i => i < 0))
        {
            var missing = RigColumns.Where((_, k) => rig[k] < 0).Select(c => $"'{c}'");
            var present = RigColumns.Where((_, k) => rig[k] >= 0).Select(c => $"'{c}'");
            throw Error(header, $"column {string.Join(", ", present)} needs {string.Join(", ", missing)}: the rig's pose is rig_x, rig_y, rig_z and rig_yaw, all four or none");
        }
    }

    /// <summary>The trace gives the rig's world pose (<c>rig_x,rig_y,rig_z,rig_yaw</c>) in every row.</summary>
    public bool HasRig => _rigX >= 0;

    /// <summary>The trace has <c>hand_x</c> and <c>hand_z</c>.</summary>
    public bool HasHorizontal => _handX >= 0;

    /// <summary>The trace has a second hand (<c>hand2_y</c>).</summary>
    public bool HasSecondHand => _hand2Y >= 0;

    /// <summary>The second hand has its own <c>hand2_x</c> and <c>hand2_z</c>.</summary>
    public bool HasSecondHorizontal => _hand2X >= 0;

    /// <summary>The line number of the row last read (where it starts).</summary>
    public int Line => _csv.Line;

    /// <summary>Reads the next row's first hand (<c>t,hand_y,tracked,pose_t</c>); false at the end of the file.
    /// The other columns are still checked.</summary>
    public bool TryRead(out TraceFrame frame)
    {
        bool ok = TryReadRow(out TraceRow row);
        frame = row.First;
        return ok;
    }

    /// <summary>Reads the next row with every hand column; false at the end of the file. A second hand without
    /// its own x/z takes the first hand's (x/z then come from the first hand alone).</summary>
    public bool TryReadRow(out TraceRow row)
    {
        row = default;
        if (!ReadFirst(out row.First)) return false;
        int line = _csv.Line;
        row.HandX = _handX >= 0 ? Coordinate(_handX, "hand_x", line) : 0;
        row.HandZ = _handZ >= 0 ? Coordinate(_handZ, "hand_z", line) : 0;
        if (_hand2Y >= 0)
        {
            row.Hand2Y = Coordinate(_hand2Y, "hand2_y", line);
            row.Hand2X = _hand2X >= 0 ? Coordinate(_hand2X, "hand2_x", line) : row.HandX;
            row.Hand2Z = _hand2Z >= 0 ? Coordinate(_hand2Z, "hand2_z", line) : row.HandZ;
            row.Tracked2 = _tracked2 < 0 || Tracked(_tracked2, "tracked2", line);
            row.Pose2T = _pose2T >= 0 ? Coordinate(_pose2T, "pose2_t", line) : double.NaN;
        }
        else
        {
            row.Hand2X = row.Hand2Y = row.Hand2Z = row.Pose2T = double.NaN;
            row.Tracked2 = false;
        }
        row.Rig = _rigX >= 0
            ? new RigFrame(RigValue(_rigX, "rig_x", line), RigValue(_rigY, "rig_y", line), RigValue(_rigZ, "rig_z", line), RigValue(_rigYaw, "rig_yaw", line))
            : RigFrame.Origin;
        return true;
    }

    /// <summary>A number column where empty means unknown (NaN).</summary>
    double Coordinate(int index, string column, int line)
    {
        var s = _csv.Span(index);
        double v = double.NaN;
        if (s.Length > 0 && !NumberText.TryParse(s, out v)) throw Error(line, $"column '{column}': cannot parse '{Short(s)}' as a number");
        return v;
    }

    /// <summary>A rig column's value: present, a number, finite and within ±1e5 (metres, or degrees for the yaw).</summary>
    double RigValue(int index, string column, int line)
    {
        var s = _csv.Span(index);
        if (s.Trim().Length == 0) throw Error(line, $"column '{column}' is empty; the rig's pose must be given in every row");
        if (!NumberText.TryParse(s, out double v)) throw Error(line, $"column '{column}': cannot parse '{Short(s)}' as a number");
        if (!double.IsFinite(v) || Math.Abs(v) > WeightSolver.MaxCoordinate)
            throw Error(line, $"column '{column}': {Short(s)} is not a finite number within ±{WeightSolver.MaxCoordinate:0} ({(column == "rig_yaw" ? "degrees" : "m")})");
        return v;
    }

    bool Tracked(int index, string column, int line)
    {
        var s = _csv.Span(index);
        if (s.SequenceEqual("0") || s.Equals("false", StringComparison.OrdinalIgnoreCase)) return false;
        if (s.Length == 0 || s.SequenceEqual("1") || s.Equals("true", StringComparison.OrdinalIgnoreCase)) return true;
        throw Error(line, $"column '{column}': expected 1 or 0, found '{Short(s)}'");
    }

    bool ReadFirst(out TraceFrame frame)
    {
        frame = default;
        try
        {
            if (!_csv.Read()) return false;
        }
        catch (EvaluationFormatException e) { throw new CliException(e.Message); }
        int line = _csv.Line;

        var tText = _csv.Span(_t);
        if (tText.Length == 0) throw Error(line, "column 't' is empty");
        if (!NumberText.TryParse(tText, out double t)) throw Error(line, $"column 't': cannot parse '{Short(tText)}' as a number");

        var yText = _csv.Span(_handY);
        double y = double.NaN;
        if (yText.Length > 0 && !NumberText.TryParse(yText, out y)) throw Error(line, $"column 'hand_y': cannot parse '{Short(yText)}' as a number");

        bool tracked = true;
        if (_tracked >= 0)
        {
            var s = _csv.Span(_tracked);
            if (s.SequenceEqual("0") || s.Equals("false", StringComparison.OrdinalIgnoreCase)) tracked = false;
            else if (!(s.Length == 0 || s.SequenceEqual("1") || s.Equals("true", StringComparison.OrdinalIgnoreCase)))
                throw Error(line, $"column 'tracked': expected 1 or 0, found '{Short(s)}'");
        }

        double poseT = double.NaN;
        if (_poseT >= 0)
        {
            var s = _csv.Span(_poseT);
            if (s.Length > 0 && !NumberText.TryParse(s, out poseT)) throw Error(line, $"column 'pose_t': cannot parse '{Short(s)}' as a number");
        }

        frame = new TraceFrame(t, y, tracked, poseT);
        return true;
    }

    /// <summary>Reads a whole trace file (for short traces only: memory grows with the file).</summary>
    public static List<TraceFrame> ReadAll(string path)
    {
        using var file = OpenText(path);
        using var reader = new TraceCsvReader(file, path);
        var frames = new List<TraceFrame>();
        while (reader.TryRead(out var f)) frames.Add(f);
        return frames;
    }

    /// <summary>Opens a trace named by --trace (messages: "does not exist", "is a folder", ...).</summary>
    public static StreamReader OpenText(string path, string option = "--trace") => InputFile.OpenText(option, path);

    CliException Error(int line, string message) => new($"{Messages.OneLine(_name)}:{line}: {message}");

    static string Short(ReadOnlySpan<char> s) => Messages.OneLine(s.Length <= 40 ? s.ToString() : s[..40].ToString() + "…");

    public void Dispose() => _csv.Dispose();
}
