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

    /// <summary>The report files <see cref="Read"/> reads from <paramref name="path"/> (none when it is null or missing).</summary>
    public static string[] ReportFiles(string? path)
        => path == null ? Array.Empty<string>()
            : Directory.Exists(path) ? Directory.GetFiles(path, "*-report.csv").OrderBy(f => f, StringComparer.Ordinal).ToArray()
            : File.Exists(path) ? new[] { path } : Array.Empty<string>();

    /// <summary>Estimator key → ns per update, from one report file or every *-report.csv in a directory.</summary>
    public static Dictionary<string, double> Read(string path)
    {
        var files = Directory.Exists(path) || File.Exists(path) ? ReportFiles(path)
            : throw new CliException($"--costs {Files.Messages.Path(path)}: does not exist");
        var costs = new Dictionary<string, double>(StringComparer.Ordinal);
        foreach (var file in files)
        {
            using var csv = new Kosmos.PseudoHaptic.Evaluation.CsvReader(Files.InputFile.OpenText("--costs", file), Files.Messages.OneLine(file));
            if (!csv.ReadHeader()) continue;
            var header = csv.Header.ToList();
            int key = header.FindIndex(h => h == EstimatorColumn);
            int mean = header.FindIndex(h => h == "Mean" || h.StartsWith("Mean [", StringComparison.Ordinal));
            if (key < 0 || mean < 0) continue;
            double headerScale = header[mean].Length > 4 ? Scale(header[mean][6..^1]) : double.NaN;
            while (csv.Read())
            {
                double ns = ParseTime(csv[mean], headerScale);
                if (!double.IsFinite(ns)) throw new CliException($"{Files.Messages.OneLine(file)}:{csv.Line}: cannot read '{Files.Messages.OneLine(csv[mean])}' as a time");
                costs[csv[key]] = ns;
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
}
