using Kosmos.PseudoHaptic.Simulation;

namespace Kosmos.PseudoHaptic.Cli.Traces;

/// <summary>
/// Reads the replay trace format row by row: comma-separated, a header row, columns by name in any order,
/// extra columns ignored. Required: <c>t</c> (s) and <c>hand_y</c> (m; may be NaN, Infinity, inf in any
/// case, or empty for no pose); optional <c>tracked</c> (1/0, default 1) and <c>pose_t</c> (s; empty or
/// non-finite for unknown). Blank lines are skipped. Errors name the file and line (the header is line 1).
/// </summary>
public sealed class TraceCsvReader : IDisposable
{
    readonly TextReader _reader;
    readonly string _name;
    readonly int _t, _handY, _tracked, _poseT, _needed;
    int _line = 1;

    public TraceCsvReader(TextReader reader, string name)
    {
        _reader = reader;
        _name = name;
        var header = reader.ReadLine() ?? throw Error(1, "the file is empty; expected a header row with columns t and hand_y");
        var columns = header.TrimStart('\uFEFF').Split(',');
        _t = _handY = _tracked = _poseT = -1;
        for (int i = 0; i < columns.Length; i++)
        {
            string c = Unquote(columns[i]).Trim();
            ref int slot = ref _t;
            switch (c)
            {
                case "t": slot = ref _t; break;
                case "hand_y": slot = ref _handY; break;
                case "tracked": slot = ref _tracked; break;
                case "pose_t": slot = ref _poseT; break;
                default: continue;
            }
            if (slot >= 0) throw Error(1, $"column '{c}' appears twice");
            slot = i;
        }
        if (_t < 0) throw Error(1, "missing column 't'");
        if (_handY < 0) throw Error(1, "missing column 'hand_y'");
        _needed = Math.Max(Math.Max(_t, _handY), Math.Max(_tracked, _poseT)) + 1;
    }

    /// <summary>The line number of the row last read.</summary>
    public int Line => _line;

    /// <summary>Reads the next row; false at the end of the file.</summary>
    public bool TryRead(out TraceFrame frame)
    {
        frame = default;
        string? text;
        do
        {
            text = _reader.ReadLine();
            if (text == null) return false;
            _line++;
        } while (text.Trim().Length == 0);

        var fields = text.Split(',');
        if (fields.Length < _needed)
            throw Error(_line, $"expected at least {_needed} fields, found {fields.Length}");

        string tText = Unquote(fields[_t]).Trim();
        if (tText.Length == 0) throw Error(_line, "column 't' is empty");
        if (!NumberText.TryParse(tText, out double t)) throw Error(_line, $"column 't': cannot parse '{Short(tText)}' as a number");

        string yText = Unquote(fields[_handY]).Trim();
        double y = double.NaN;
        if (yText.Length > 0 && !NumberText.TryParse(yText, out y)) throw Error(_line, $"column 'hand_y': cannot parse '{Short(yText)}' as a number");

        bool tracked = true;
        if (_tracked >= 0)
        {
            string s = Unquote(fields[_tracked]).Trim();
            if (s == "0" || s.Equals("false", StringComparison.OrdinalIgnoreCase)) tracked = false;
            else if (!(s.Length == 0 || s == "1" || s.Equals("true", StringComparison.OrdinalIgnoreCase)))
                throw Error(_line, $"column 'tracked': expected 1 or 0, found '{Short(s)}'");
        }

        double poseT = double.NaN;
        if (_poseT >= 0)
        {
            string s = Unquote(fields[_poseT]).Trim();
            if (s.Length > 0 && !NumberText.TryParse(s, out poseT)) throw Error(_line, $"column 'pose_t': cannot parse '{Short(s)}' as a number");
        }

        frame = new TraceFrame(t, y, tracked, poseT);
        return true;
    }

    /// <summary>Reads a whole trace file.</summary>
    public static List<TraceFrame> ReadAll(string path)
    {
        using var file = OpenText(path);
        using var reader = new TraceCsvReader(file, path);
        var frames = new List<TraceFrame>();
        while (reader.TryRead(out var f)) frames.Add(f);
        return frames;
    }

    public static StreamReader OpenText(string path)
    {
        try { return new StreamReader(path); }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException or ArgumentException or NotSupportedException)
        {
            throw new CliException($"{path}: cannot open: {e.Message}");
        }
    }

    CliException Error(int line, string message) => new($"{_name}:{line}: {message}");

    static string Unquote(string s)
    {
        var t = s.Trim();
        return t.Length >= 2 && t[0] == '"' && t[^1] == '"' ? t[1..^1] : t;
    }

    static string Short(string s) => s.Length <= 40 ? s : s[..40] + "…";

    public void Dispose() => _reader.Dispose();
}
