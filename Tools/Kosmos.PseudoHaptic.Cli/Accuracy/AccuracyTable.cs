using System.Globalization;

namespace Kosmos.PseudoHaptic.Cli.Accuracy;

/// <summary>
/// Prints the accuracy report as plain-text tables (the columns are documented in accuracy-vs-time.md and in
/// <see cref="Columns"/>) and writes it as CSV.
/// </summary>
public static class AccuracyTable
{
    public static readonly string[] SummaryColumns = { "config", "rms_mm", "rms_ci", "raw_mm", "max_mm", "lag_ms", "added_ms", "added_ci", "creep_mm", "rest_mm" };
    public static readonly string[] SourceColumns = { "config", "rms_mm", "rms_ci", "raw_mm", "max_mm", "lag_ms", "added_ms", "added_ci" };
    public static readonly string[] LongRunColumns = { "scheme", "end_mm", "end_ci", "max_mm", "what" };

    public const string Columns =
        "rms_mm   RMS of object − reference, the reference delayed by the headset's 45 ms (what the pipeline adds); every figure is a mean over the seeded renders\n" +
        "rms_ci   half-width of the 95 % confidence interval of rms_mm (Student's t over the renders); added_ci, end_ci likewise\n" +
        "raw_mm   RMS of object − reference as it is, without delay (what the user sees, headset latency included)\n" +
        "max_mm   largest |object − delayed reference| (the worst offset error)\n" +
        "lag_ms   lag of the object behind the undelayed reference, by cross-correlation of object velocity (±200 ms, 1 ms steps; * peak beyond, searched ±1 s)\n" +
        "added_ms lag_ms − the headset's 45 ms: the 30 Hz pose hold (~17 ms), the frame hold (~4–7 ms) and the estimator's own lag\n" +
        "creep_mm how far the object's mean height moves in 10 s of a still hand with jitter\n" +
        "rest_mm  RMS of the object's height about its mean with a still hand (jitter that reaches the object)";

    public static void Write(TextWriter w, AccuracyReport r)
    {
        w.WriteLine($"pseudohaptic accuracy: {F(r.MassKg, 3)} kg object, paper profile gain G = {F(r.Gain, 3)}, standard speed {F(r.StandardSpeed, 2)} m/s");
        w.WriteLine($"degraded: {Degradation.PoseRate:0} Hz poses, {Degradation.Latency * 1000:0} ms late, jitter {string.Join(" and ", Degradation.JitterMm.Select(j => F(j, 0)))} mm (sd), held over {string.Join("/", Degradation.FrameRates.Select(f => F(f, 0)))} Hz frames, each {Degradation.Replicates} times: {Degradation.RenderCount} seeded renders per source");
        w.WriteLine("reference: the noise-free hand, a pose every 1 ms, no latency, through the paper profile without deadband or filter (estimators) or the gain-only profile (integration)");
        w.WriteLine("sources:");
        foreach (var s in r.Sources) w.WriteLine($"  {s.Name,-14} {s.Description}");
        foreach (var note in r.Notes) w.WriteLine("note: " + note);
        w.WriteLine("columns:");
        foreach (var line in Columns.Split('\n')) w.WriteLine("  " + line);
        w.WriteLine();

        w.WriteLine($"== summary: mean over {r.Sources.Count} source(s) and {Degradation.RenderCount} renders (max_mm: the worst); default: {EstimatorCatalog.Default} ==");
        WriteSummary(w, r.Summary);

        foreach (var source in r.Sources)
        {
            w.WriteLine();
            w.WriteLine($"== {source.Name}: {source.Description} ==");
            var rows = r.PerSource.Where(x => x.Source == source.Name).ToList();
            var table = new List<string[]> { SourceColumns };
            string? group = null;
            foreach (var row in rows)
            {
                string g = r.Configs.First(c => c.Key == row.Config).Group;
                if (group != null && g != group) table.Add(Array.Empty<string>());
                group = g;
                table.Add(new[] { row.Config, F(row.RmsMm, 2), Pm(row.Rms.HalfWidth, 2), F(row.RawRmsMm, 2), F(row.MaxMm, 2), Lag(row.LagMs, row.LagWidened), F(row.LagMs - Degradation.Latency * 1000, 0), Pm(row.Lag.HalfWidth, 0) });
            }
            Align(w, table);
        }

        if (r.LongRunDescription != null)
        {
            w.WriteLine();
            w.WriteLine($"== long run: {r.LongRunDescription} ==");
            var table = new List<string[]> { LongRunColumns };
            foreach (var row in r.LongRun) table.Add(new[] { row.Scheme, Small(row.EndErrorMm), "±" + Small(row.EndError.HalfWidth), Small(row.MaxErrorMm), row.Description });
            Align(w, table);
        }
    }

    public static void WriteSummary(TextWriter w, IReadOnlyList<SummaryRow> summary)
    {
        var table = new List<string[]> { SummaryColumns };
        string? group = null;
        foreach (var row in summary)
        {
            if (group != null && row.Group != group) table.Add(Array.Empty<string>());
            group = row.Group;
            table.Add(new[] { row.Config, F(row.RmsMm, 2), Pm(row.Rms.HalfWidth, 2), F(row.RawRmsMm, 2), F(row.MaxMm, 2), Lag(row.LagMs, row.LagWidened), F(row.AddedLagMs, 0), Pm(row.Lag.HalfWidth, 0), F(row.CreepMm, 2), F(row.RestMm, 2) });
        }
        Align(w, table);
    }

    /// <summary>Every figure as CSV: summary rows, then one row per source, then one per render and one per still-hand render.</summary>
    public static void WriteCsv(TextWriter w, AccuracyReport r)
    {
        w.WriteLine("kind,config,group,source,render,rms_mm,rms_lo,rms_hi,raw_mm,max_mm,lag_ms,added_ms,added_lo,added_hi,creep_mm,creep_lo,creep_hi,rest_mm");
        string Group(string config) => r.Configs.First(c => c.Key == config).Group;
        foreach (var s in r.Summary)
            w.WriteLine(string.Join(',', "summary", s.Config, s.Group, "", "", N(s.RmsMm), N(s.Rms.Low), N(s.Rms.High), N(s.RawRmsMm), N(s.MaxMm), N(s.LagMs), N(s.AddedLagMs), N(s.AddedLag.Low), N(s.AddedLag.High), N(s.CreepMm), N(s.Creep.Low), N(s.Creep.High), N(s.RestMm)));
        double latency = Degradation.Latency * 1000;
        foreach (var s in r.PerSource)
            w.WriteLine(string.Join(',', "source", s.Config, Group(s.Config), s.Source, "", N(s.RmsMm), N(s.Rms.Low), N(s.Rms.High), N(s.RawRmsMm), N(s.MaxMm), N(s.LagMs), N(s.LagMs - latency), N(s.Lag.Low - latency), N(s.Lag.High - latency), "", "", "", ""));
        foreach (var s in r.PerSource)
            foreach (var (render, m) in s.Runs)
                w.WriteLine(string.Join(',', "run", s.Config, Group(s.Config), s.Source, render, N(m.RmsMm), "", "", N(m.RawRmsMm), N(1000 * m.MaxAbs), N(m.LagMs), N(m.LagMs - latency), "", "", "", "", "", ""));
        foreach (var s in r.Rest)
            foreach (var (render, m) in s.Runs)
                w.WriteLine(string.Join(',', "rest", s.Config, Group(s.Config), "still", render, "", "", "", "", "", "", "", "", "", N(1000 * m.CreepM), "", "", N(1000 * Math.Sqrt(m.RestSumSquares / Math.Max(1, m.RestCount)))));
    }

    static string Pm(double halfWidth, int decimals) => double.IsFinite(halfWidth) ? "±" + F(halfWidth, decimals) : "";

    static string Lag(double ms, bool widened) => double.IsFinite(ms) ? F(ms, 0) + (widened ? "*" : "") : "n/a";

    static string F(double v, int decimals) => double.IsFinite(v) ? v.ToString("F" + decimals, CultureInfo.InvariantCulture) : "n/a";

    static string N(double v) => double.IsFinite(v) ? v.ToString("G6", CultureInfo.InvariantCulture) : "";

    /// <summary>Millimetres from nanometres to metres: fixed decimals above 1 µm, else scientific.</summary>
    static string Small(double mm) => mm == 0 ? "0" : mm < 0.001 ? mm.ToString("0.0E+0", CultureInfo.InvariantCulture) : mm.ToString("0.000", CultureInfo.InvariantCulture);

    /// <summary>Printed between the estimator rows and the integration/precision rows of a table.</summary>
    public const string GroupBreak = "-- integration and precision: gain-only profile, judged against the gain-only solver --";

    static void Align(TextWriter w, List<string[]> rows)
    {
        int columns = rows.Max(r => r.Length);
        var widths = new int[columns];
        foreach (var r in rows)
            for (int c = 0; c < r.Length; c++) widths[c] = Math.Max(widths[c], r[c].Length);
        foreach (var r in rows)
        {
            if (r.Length == 0) { w.WriteLine(GroupBreak); continue; }
            var parts = new string[r.Length];
            for (int c = 0; c < r.Length; c++)
                parts[c] = c == 0 || rows[0][c] == "what" ? r[c].PadRight(widths[c]) : r[c].PadLeft(widths[c]);
            w.WriteLine(string.Join("  ", parts).TrimEnd());
        }
    }
}
