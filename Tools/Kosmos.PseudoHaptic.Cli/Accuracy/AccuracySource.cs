using Kosmos.PseudoHaptic.Cli.Traces;
using Kosmos.PseudoHaptic.Simulation;

namespace Kosmos.PseudoHaptic.Cli.Accuracy;

/// <summary>A true hand the study degrades and replays: a minimum-jerk lift or a recorded trace.</summary>
public sealed record AccuracySource(string Name, string Description, HandPath Hand)
{
    /// <summary>Rise of the synthetic lifts, m, and where they start.</summary>
    public const double Rise = 0.3, Start = 0.9;

    /// <summary>Mean lifting speeds of the three synthetic lifts, m/s.</summary>
    public static readonly (string Name, double MeanSpeed)[] LiftSpeeds = { ("lift-slow", 0.2), ("lift-medium", 0.4), ("lift-fast", 0.8) };

    /// <summary>
    /// A minimum-jerk lift of 0.3 m at <paramref name="meanSpeed"/> and back down: 1.5 s at rest first (so a 1 s
    /// window is full when the lift starts), 1 s at the top, 1 s at the end.
    /// </summary>
    public static AccuracySource Lift(string name, double meanSpeed)
    {
        double seconds = Rise / meanSpeed;
        var path = HandPath.StartAt(Start).Hold(1.5).MoveTo(Start + Rise, seconds).Hold(1.0).MoveTo(Start, seconds).Hold(1.0);
        return new AccuracySource(name, $"{Rise:0.0} m up and down in {seconds:0.###} s each way (mean {meanSpeed:0.0} m/s, peak {1.875 * meanSpeed:0.00} m/s)", path);
    }

    public static IEnumerable<AccuracySource> Lifts()
    {
        foreach (var (name, speed) in LiftSpeeds) yield return Lift(name, speed);
    }

    /// <summary>
    /// A trace in the replay format taken as the true hand: its usable rows (tracked, finite hand_y), at their
    /// pose time when the row has one (repeated poses count once) or else at their frame time, linearly
    /// interpolated; rows whose time does not advance are skipped. Parse errors name the file and line. Read in
    /// bounded memory (<see cref="TraceSamples"/>: at most one sample per ms, a span of at most 180 s).
    /// </summary>
    public static AccuracySource FromTrace(string name, string path, string option = "--trace")
    {
        var (times, heights) = TraceSamples.Read(option, path, "accuracy", usePoseTime: true, TraceSamples.AccuracyMaxSpan);
        if (times.Count < 2 || times[^1] - times[0] < 0.5)
            throw new CliException($"{Files.Messages.OneLine(path)}: needs at least 0.5 s of usable rows (tracked, finite hand_y, time increasing) to serve as the true hand; found {times.Count} row(s)");
        var hand = HandPath.FromSamples(times, heights);
        return new AccuracySource(name, $"{Path.GetFileName(path)}: {times.Count} usable samples over {hand.Duration:0.0} s as the true hand", hand);
    }
}
