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
/// </summary>
public sealed class TraceCsvReader : IDisposable
{
    readonly CsvReader _csv;
    readonly string _name;
    readonly int _t, _handY, _tracked, _poseT;

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
        }
        catch (EvaluationFormatException e) { throw new CliException(e.Message); }
        if (_t < 0) throw Error(_csv.HeaderLine, "missing column 't'");
        if (_handY < 0) throw Error(_csv.HeaderLine, "missing column 'hand_y'");
    }

    /// <summary>The line number of the row last read (where it starts).</summary>
    public int Line => _csv.Line;

    /// <summary>Reads the next row; false at the end of the file.</summary>
    public bool TryRead(out TraceFrame frame)
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
