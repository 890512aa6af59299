using System.Globalization;
using System.Security.Cryptography;
using System.Text;
using Kosmos.PseudoHaptic.Cli.Files;
using Kosmos.PseudoHaptic.Cli.Plotting;

namespace Kosmos.PseudoHaptic.Cli.Accuracy;

/// <summary>
/// What a generated accuracy page and chart were made from (issue 32): the mass, standard speed and long-run
/// minutes, every source by name and by a SHA-256 of its true hand (heights every millisecond), and the costs. The
/// page records it in an HTML comment, the chart in a PNG text chunk. Before the study runs, an existing page or
/// chart that records other inputs is refused (exit 2, one line) unless <c>--overwrite</c> is given, so that a
/// clone without ../shared (three sources instead of four) cannot silently rewrite the committed page.
/// </summary>
public sealed class AccuracyInputs
{
    /// <summary>The page's comment starts with this; the chart's text chunk has this keyword.</summary>
    public const string Marker = "pseudohaptic-accuracy-inputs";

    AccuracyInputs(string summary, string fingerprint)
    {
        Summary = summary;
        Fingerprint = fingerprint;
    }

    /// <summary>Sources and settings in words ("sources lift-slow, lift-medium, lift-fast, mocap; 1 kg; …").</summary>
    public string Summary { get; }

    /// <summary>The first 16 hex digits of the SHA-256 of every input.</summary>
    public string Fingerprint { get; }

    /// <summary>The one line both files record: summary and fingerprint.</summary>
    public string Line => $"{Summary}; fingerprint {Fingerprint}";

    public static AccuracyInputs Of(double massKg, double standardSpeed, double longMinutes, IReadOnlyList<AccuracySource> sources, IReadOnlyDictionary<string, double>? costs)
    {
        static string R(double v) => v.ToString("R", CultureInfo.InvariantCulture);
        var text = new StringBuilder($"mass {R(massKg)}\nspeed {R(standardSpeed)}\nlong {R(longMinutes)}\n");
        foreach (var s in sources)
        {
            text.Append("source ").Append(s.Name).Append(' ').Append(R(s.Hand.Duration)).Append(' ');
            var bytes = new List<byte>();
            for (long ms = 0; ms <= (long)Math.Floor(s.Hand.Duration * 1000); ms++)
                bytes.AddRange(BitConverter.GetBytes(s.Hand.HeightAt(ms / 1000.0)));
            text.Append(Convert.ToHexString(SHA256.HashData(bytes.ToArray()))).Append('\n');
        }
        if (costs != null)
            foreach (var (key, ns) in costs.OrderBy(c => c.Key, StringComparer.Ordinal)) text.Append("cost ").Append(key).Append(' ').Append(R(ns)).Append('\n');
        string fingerprint = Convert.ToHexString(SHA256.HashData(Encoding.UTF8.GetBytes(text.ToString())))[..16].ToLowerInvariant();
        string summary = $"sources {string.Join(", ", sources.Select(s => s.Name))}; {R(massKg)} kg; v_std {R(standardSpeed)} m/s; long runs {R(longMinutes)} min; {(costs != null ? $"costs of {costs.Count} estimators" : "no costs")}";
        return new AccuracyInputs(Messages.OneLine(summary), fingerprint);
    }

    /// <summary>The page's record: an HTML comment of one line.</summary>
    public string PageComment => $"<!-- {Marker}: {Line} -->";

    /// <summary>What an existing page records, or null (no such file, or a page without the record).</summary>
    public static string? OfPage(string path)
    {
        try
        {
            if (!File.Exists(path)) return null;
            using var reader = new StreamReader(path);
            for (int i = 0; i < 20 && reader.ReadLine() is { } line; i++)
                if (line.StartsWith("<!-- " + Marker + ": ", StringComparison.Ordinal) && line.EndsWith(" -->", StringComparison.Ordinal))
                    return line[(Marker.Length + 7)..^4];
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException) { }
        return null;
    }

    /// <summary>What an existing chart records, or null.</summary>
    public static string? OfChart(string path)
    {
        try
        {
            return File.Exists(path) ? PngText.Read(File.ReadAllBytes(path), Marker) : null;
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException) { return null; }
    }

    /// <summary>
    /// Refuses (exit 2) when <paramref name="path"/> records inputs other than these, naming both: the page and the
    /// chart are regenerated only from the inputs they were made from, or with --overwrite.
    /// </summary>
    public void Check(string option, string path, string? recorded)
    {
        if (recorded == null || recorded == Line) return;
        string was = recorded.Contains("; fingerprint ", StringComparison.Ordinal) ? recorded : recorded + " (unreadable)";
        throw new CliException($"{option} {Messages.Path(path)} was made from other inputs ({Messages.OneLine(was)}) than this run's ({Line}); not overwritten (give --overwrite to write it anyway)");
    }
}
