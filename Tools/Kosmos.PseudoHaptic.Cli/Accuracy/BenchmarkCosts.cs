using System.Globalization;

namespace Kosmos.PseudoHaptic.Cli.Accuracy;

/// <summary>
/// Reads the cost of each estimator from BenchmarkDotNet's CSV reports (Tools/Kosmos.PseudoHaptic.Benchmarks
/// writes them to BenchmarkDotNet.Artifacts/results): the rows that have an <c>Estimator</c> column, their
/// <c>Mean</c> in ns per update (units in the header, "Mean [ns]", or in the cell, "23.4 ns", both read).
/// </summary>
public static class BenchmarkCosts
{
    public const string EstimatorColumn = "Estimator";

    /// <summary>Estimator key → ns per update, from one report file or every *-report.csv in a directory.</summary>
    public static Dictionary<string, double> Read(string path)
    {
        var files = Directory.Exists(path) ? Directory.GetFiles(path, "*-report.csv").OrderBy(f => f, StringComparer.Ordinal).ToArray()
            : File.Exists(path) ? new[] { path }
            : throw new CliException($"option --costs: '{path}' is neither a file nor a directory");
        var costs = new Dictionary<string, double>(StringComparer.Ordinal);
        foreach (var file in files)
        {
            var lines = File.ReadAllLines(file);
            if (lines.Length == 0) continue;
            var header = Split(lines[0]);
            int key = header.FindIndex(h => h == EstimatorColumn);
            int mean = header.FindIndex(h => h == "Mean" || h.StartsWith("Mean [", StringComparison.Ordinal));
            if (key < 0 || mean < 0) continue;
            double headerScale = header[mean].Length > 4 ? Scale(header[mean][6..^1]) : double.NaN;
            for (int i = 1; i < lines.Length; i++)
            {
                var cells = Split(lines[i]);
                if (cells.Count <= Math.Max(key, mean)) continue;
                double ns = ParseTime(cells[mean], headerScale);
                if (!double.IsFinite(ns)) throw new CliException($"{file}:{i + 1}: cannot read '{cells[mean]}' as a time");
                costs[cells[key]] = ns;
            }
        }
        if (costs.Count == 0) throw new CliException($"option --costs: no BenchmarkDotNet report with an '{EstimatorColumn}' column in '{path}'");
        return costs;
    }

    static double ParseTime(string cell, double headerScale)
    {
        string text = cell.Trim().Replace(",", "");
        double scale = headerScale;
        int space = text.LastIndexOf(' ');
        if (space > 0)
        {
            scale = Scale(text[(space + 1)..]);
            text = text[..space];
        }
        if (!double.IsFinite(scale)) scale = 1;
        return double.TryParse(text, NumberStyles.Float, CultureInfo.InvariantCulture, out double v) ? v * scale : double.NaN;
    }

    /// <summary>Nanoseconds per unit.</summary>
    static double Scale(string unit) => unit switch
    {
        "ps" => 1e-3,
        "ns" => 1,
        "us" or "μs" or "µs" => 1e3,
        "ms" => 1e6,
        "s" => 1e9,
        _ => double.NaN,
    };

    /// <summary>One CSV line, with double-quoted fields.</summary>
    static List<string> Split(string line)
    {
        var cells = new List<string>();
        var cell = new System.Text.StringBuilder();
        bool quoted = false;
        for (int i = 0; i < line.Length; i++)
        {
            char c = line[i];
            if (quoted)
            {
                if (c == '"' && i + 1 < line.Length && line[i + 1] == '"') { cell.Append('"'); i++; }
                else if (c == '"') quoted = false;
                else cell.Append(c);
            }
            else if (c == '"') quoted = true;
            else if (c == ',') { cells.Add(cell.ToString()); cell.Clear(); }
            else cell.Append(c);
        }
        cells.Add(cell.ToString());
        return cells;
    }
}
