using Kosmos.PseudoHaptic.Cli.Files;
using Kosmos.PseudoHaptic.Simulation;

namespace Kosmos.PseudoHaptic.Cli.Traces;

/// <summary>
/// A trace's usable poses (tracked, finite hand_y and time) as a true hand for <c>demo</c> and <c>accuracy</c>,
/// read in bounded memory whatever the file: rows are streamed and only usable ones are kept (nothing is
/// buffered before the first usable pose); a row whose time does not advance is skipped; a row less than
/// <see cref="MinStep"/> after the last kept one is skipped too (the trace is taken at most one sample per
/// millisecond); a usable row more than the command's longest span (<see cref="DemoMaxSpan"/>,
/// <see cref="AccuracyMaxSpan"/>) after the first usable one is refused with a message naming its line (a
/// glitched time stamp, or times written in milliseconds). The spans keep the peak memory of either command
/// under 200 MB (README, "Files and paths").
/// </summary>
public static class TraceSamples
{
    /// <summary>Longest span of usable rows <c>demo</c> takes, s (5 minutes).</summary>
    public const double DemoMaxSpan = 300;

    /// <summary>Longest span of usable rows <c>accuracy</c> takes, s (2 minutes; it renders each trace six times and
    /// grids every run at 1 ms, and its long run of --long-minutes comes on top).</summary>
    public const double AccuracyMaxSpan = 120;

    /// <summary>Shortest step between samples kept, s (1 ms).</summary>
    public const double MinStep = 0.001;

    /// <param name="usePoseTime">Take a row's pose_t, when finite, as its time (accuracy); otherwise its frame time t (demo).</param>
    public static (List<double> Times, List<double> Heights) Read(string option, string path, string command, bool usePoseTime, double maxSpan)
    {
        using var file = TraceCsvReader.OpenText(path, option);
        using var reader = new TraceCsvReader(file, path);
        var times = new List<double>();
        var heights = new List<double>();
        int firstLine = 0;
        while (reader.TryReadRow(out var row))
        {
            // The hand's own height: relative to the rig's when the trace gives it (issue 26), as replay weighs it.
            var f = reader.HasRig ? row.First with { HandY = row.First.HandY - row.Rig.Y } : row.First;
            if (!f.IsUsable) continue;
            double t = usePoseTime && double.IsFinite(f.PoseTime) ? f.PoseTime : f.Time;
            if (!double.IsFinite(t)) continue;
            if (times.Count == 0)
            {
                firstLine = reader.Line;
                times.Add(t);
                heights.Add(f.HandY);
                continue;
            }
            if (t - times[0] > maxSpan)
                throw new CliException($"{Messages.OneLine(path)}:{reader.Line}: t = {NumberText.Format(t)} s lies {NumberText.Format(t - times[0])} s after the first usable row (line {firstLine}); {command} takes traces of at most {maxSpan:0} s (a glitched time, or times in milliseconds?)");
            // A step of 1 ms written in decimals may come out a hair short in binary: 1 ns of slack keeps every
            // row of a 1 kHz trace (a trace at 1 kHz or slower is taken whole, as before).
            if (!(t - times[^1] >= MinStep - 1e-9)) continue;
            times.Add(t);
            heights.Add(f.HandY);
        }
        return (times, heights);
    }
}
