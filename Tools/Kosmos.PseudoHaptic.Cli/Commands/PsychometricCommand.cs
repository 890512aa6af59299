using System.Globalization;
using System.Text;
using Kosmos.PseudoHaptic.Cli.CommandLine;
using Kosmos.PseudoHaptic.Cli.Files;
using Kosmos.PseudoHaptic.Evaluation;

namespace Kosmos.PseudoHaptic.Cli;

/// <summary>
/// <c>pseudohaptic psychometric --trials T.csv --out DIR [--lapse L] [--bootstrap N] [--seed S] [--interval bca|percentile] [--without-catch] [--svg]</c> (issue 11; --without-catch added in the twentieth session, --svg in the twenty-second, as issue 13 asks of every chart, --interval in the twenty-fifth):
/// the maximum-likelihood fit of a cumulative Gaussian to 2AFC answers per participant × condition × standard
/// (<see cref="PsychometricFit"/>), PSE, JND, Weber fraction, 95 % bootstrap intervals and deviance.
/// Writes DIR/fits.csv, DIR/report.md, a chart per participant × condition and DIR/summary.png (with --svg, an SVG beside each). Malformed
/// input or a bad option: exit 2, one stderr line naming T.csv:LINE or the option, nothing written.
/// </summary>
public static class PsychometricCommand
{
    public const string Header = "participant,condition,standard,n,pse,jnd,weber,sigma,pse_lo,pse_hi,jnd_lo,jnd_hi,deviance,estimable";
    public const int DefaultResamples = 1000;
    public const long DefaultSeed = 1;
    public const int MaxResamples = 100000;

    public static CliCommand Define() => new(
        "psychometric",
        "Fit 2AFC weight-discrimination answers per participant × condition × standard: PSE, JND, Weber fraction with bootstrap 95 % intervals, charts (evaluation.md §8)",
        Run,
        new[]
        {
            "pseudohaptic psychometric --trials Packages/com.kosmos.pseudohaptic/Documentation~/examples/study/trials.csv --out out/fits --seed 1",
        },
        CliCommand.Value("--trials", "T.csv", "the answers: participant,standard,comparison,response (1 = comparison judged heavier), optional condition; standard and comparison in kg", required: true),
        CliCommand.Value("--out", "DIR", "the folder to write; it appears whole or not at all", required: true),
        CliCommand.Value("--lapse", "L", "a fixed guess and lapse rate gamma = lambda, in [0, 0.5) (default 0)"),
        CliCommand.Value("--bootstrap", "N", $"parametric bootstrap resamples for the 95 % intervals, 0–{MaxResamples} (default {DefaultResamples})"),
        CliCommand.Value("--seed", "S", $"the bootstrap's seed, a whole number (default {DefaultSeed})"),
        CliCommand.Value("--interval", "KIND", "bca: bias-corrected and accelerated percentiles (default; Efron 1987, as Wichmann and Hill 2001b recommend); percentile: plain percentiles, the only kind up to version 0.4.0"),
        CliCommand.Flag("--without-catch", "leave out the rows whose catch column is 1 (attention checks, not levels of the function; one missed catch trial can double a JND without --lapse)"),
        CliCommand.Flag("--svg", "write an SVG beside each PNG"));

    public static int Run(string[] args) => Cli.Run(args.Prepend("psychometric").ToArray());

    static int Run(Options o)
    {
        string trialsPath = o.Require("--trials");
        string outDir = o.Require("--out");
        double lapse = Lapse(o.Get("--lapse"));
        int resamples = Resamples(o.Get("--bootstrap"));
        long seed = Seed(o.Get("--seed"));
        var interval = Interval(o.Get("--interval"));
        var inputs = new[] { new NamedPath("--trials", trialsPath) };
        OutputFolder.Check("--out", outDir, Owns, createParents: false, inputs);

        // Read and check everything, compute, render; only then does the folder appear, whole.
        bool withoutCatch = o.Flag("--without-catch"), svg = o.Flag("--svg");
        var answers = TrialsCsv.Read(EvaluationInputs.OpenText("--trials", trialsPath), EvaluationInputs.Name(trialsPath), EvaluationInputs.MaxRows, EvaluationInputs.MaxCharacters, withoutCatch, out int catchLeftOut);
        var progress = Progress.Writer;
        var rows = PsychometricAnalysis.Fit(answers, lapse, resamples, seed, interval, (done, all) => progress.Write($"\rpsychometric: fit and bootstrap {done}/{all}{(done == all ? "\n" : "")}"));
        var files = new List<(string Name, byte[] Bytes)>();
        var utf8 = new UTF8Encoding(false);
        files.Add(("fits.csv", utf8.GetBytes(FitsCsv(rows))));
        var charts = new List<(string File, string Participant, string Condition)>();
        foreach (var group in Groups(rows))
        {
            string name = $"fit-{charts.Count + 1:000}-{Slug(group.Key.Participant)}{(group.Key.Condition.Length > 0 ? "-" + Slug(group.Key.Condition) : "")}.png";
            files.Add((name, StudyCharts.Psychometric(group.Key.Participant, group.Key.Condition, group.Value, answers).Png()));
            if (svg) files.Add((Path.ChangeExtension(name, ".svg"), utf8.GetBytes(StudyCharts.Psychometric(group.Key.Participant, group.Key.Condition, group.Value, answers).Svg())));
            charts.Add((name, group.Key.Participant, group.Key.Condition));
        }
        if (rows.Count > 0) files.Add(("summary.png", StudyCharts.PsychometricSummary(rows).Png()));
        if (rows.Count > 0 && svg) files.Add(("summary.svg", utf8.GetBytes(StudyCharts.PsychometricSummary(rows).Svg())));
        files.Add(("report.md", utf8.GetBytes(Report(trialsPath, answers.Count, withoutCatch ? catchLeftOut : -1, rows, lapse, resamples, seed, interval, charts, rows.Count > 0))));

        OutputFolder.Begin("--out", outDir, Owns, createParents: false, inputs).Build(temp =>
        {
            foreach (var (name, bytes) in files) File.WriteAllBytes(Path.Combine(temp, name), bytes);
        });

        Console.Out.WriteLine($"{Messages.OneLine(Path.Combine(outDir, "fits.csv"))}: {rows.Count} fits of {answers.Count} trials{(withoutCatch ? $" ({catchLeftOut} catch trials left out)" : "")}, {rows.Count(r => !r.Fit.Estimable)} not estimable; {files.Count} files");
        foreach (var r in rows)
        {
            string what = r.Fit.Estimable
                ? $"PSE {G(r.Fit.Pse)} [{G(r.Bootstrap.PseLow)}, {G(r.Bootstrap.PseHigh)}], JND {G(r.Fit.Jnd)} [{G(r.Bootstrap.JndLow)}, {G(r.Bootstrap.JndHigh)}], Weber {G(r.Weber)}"
                : "not estimable: " + r.Fit.Reason;
            Console.Out.WriteLine($"  {Messages.OneLine(r.Participant)}{(r.Condition.Length > 0 ? " " + Messages.OneLine(r.Condition) : "")} standard {NumberText.Format(r.Standard)}: n = {r.Fit.Trials}, {what}");
        }
        return 0;
    }

    static readonly OutputFolder.Owns Owns = OutputFolder.FilesNamed("fits.csv", "report.md", "fit-*.png", "summary.png", "fit-*.svg", "summary.svg");

    static string G(double v) => double.IsFinite(v) ? v.ToString("G4", CultureInfo.InvariantCulture) : "-";

    static double Lapse(string? text)
    {
        if (text == null) return 0;
        if (!NumberText.TryParse(text, out double v) || !double.IsFinite(v))
            throw new CliException($"option --lapse: cannot parse '{Messages.OneLine(text)}' as a number");
        if (!(v >= 0 && v < 0.5)) throw new CliException($"option --lapse: {NumberText.Format(v)} is outside [0, 0.5)");
        return v;
    }

    static int Resamples(string? text)
    {
        if (text == null) return DefaultResamples;
        if (!int.TryParse(text.Trim(), NumberStyles.AllowLeadingSign, CultureInfo.InvariantCulture, out int n))
            throw new CliException($"option --bootstrap: '{Messages.OneLine(text)}' is not a whole number");
        if (n < 0 || n > MaxResamples) throw new CliException($"option --bootstrap: {n} is outside 0 … {MaxResamples}");
        return n;
    }

    /// <summary>--interval: bca (the default) or percentile.</summary>
    public static BootstrapInterval Interval(string? text)
    {
        switch (text?.Trim())
        {
            case null: case "bca": return BootstrapInterval.Bca;
            case "percentile": return BootstrapInterval.Percentile;
            default: throw new CliException($"option --interval: '{Messages.OneLine(text)}' is neither bca nor percentile");
        }
    }

    /// <summary>How report.md names the intervals' kind.</summary>
    public static string IntervalText(BootstrapInterval interval) => interval == BootstrapInterval.Bca
        ? "bias-corrected and accelerated percentiles, BCa (Efron 1987): the percentiles moved by the share of refits below the fit and by the skew of the jackknife over trials"
        : "percentiles 2.5 and 97.5 (--interval percentile)";

    static long Seed(string? text)
    {
        if (text == null) return DefaultSeed;
        if (!long.TryParse(text.Trim(), NumberStyles.AllowLeadingSign, CultureInfo.InvariantCulture, out long s))
            throw new CliException($"option --seed: '{Messages.OneLine(text)}' is not a whole number");
        return s;
    }

    /// <summary>fits.csv: numbers round-trip invariant; empty where not defined, never NaN.</summary>
    public static string FitsCsv(IReadOnlyList<PsychometricRow> rows)
    {
        var text = new StringBuilder(Header).Append('\n');
        foreach (var r in rows)
        {
            var f = r.Fit;
            var b = r.Bootstrap;
            text.Append(CsvTable.Escape(r.Participant)).Append(',').Append(CsvTable.Escape(r.Condition)).Append(',')
                .Append(N(r.Standard)).Append(',').Append(f.Trials.ToString(CultureInfo.InvariantCulture)).Append(',');
            if (f.Estimable)
            {
                text.Append(N(f.Pse)).Append(',').Append(N(f.Jnd)).Append(',').Append(N(r.Weber)).Append(',').Append(N(f.Sigma)).Append(',')
                    .Append(N(b.PseLow)).Append(',').Append(N(b.PseHigh)).Append(',').Append(N(b.JndLow)).Append(',').Append(N(b.JndHigh)).Append(',')
                    .Append(N(f.Deviance)).Append(",yes");
            }
            else text.Append(",,,,,,,,,").Append(CsvTable.Escape(f.Reason));
            text.Append('\n');
        }
        return text.ToString();
    }

    /// <summary>A number as the files write it; empty when not finite (a Weber fraction of standard 0, an interval with no resamples).</summary>
    static string N(double v) => double.IsFinite(v) ? NumberText.Format(v) : "";

    static List<KeyValuePair<(string Participant, string Condition), List<PsychometricRow>>> Groups(IReadOnlyList<PsychometricRow> rows)
    {
        var groups = new List<KeyValuePair<(string, string), List<PsychometricRow>>>();
        foreach (var r in rows)
        {
            if (groups.Count == 0 || groups[^1].Key != (r.Participant, r.Condition))
                groups.Add(new((r.Participant, r.Condition), new List<PsychometricRow>()));
            groups[^1].Value.Add(r);
        }
        return groups;
    }

    /// <summary>A file-name-safe form of a participant or condition: letters, digits, '-', '_' kept, the rest '_'.</summary>
    public static string Slug(string text)
    {
        var sb = new StringBuilder();
        foreach (char c in text) sb.Append(char.IsAsciiLetterOrDigit(c) || c == '-' || c == '_' ? c : '_');
        string s = sb.ToString();
        return s.Length > 40 ? s[..40] : s;
    }

    /// <param name="catchLeftOut">Catch trials left out (--without-catch), or −1 when catch trials are fitted like the rest.</param>
    static string Report(string trialsPath, int trials, int catchLeftOut, IReadOnlyList<PsychometricRow> rows, double lapse, int resamples, long seed, BootstrapInterval interval, List<(string File, string Participant, string Condition)> charts, bool summary)
    {
        var md = new StringBuilder();
        md.Append("# Psychometric fits\n\n");
        md.Append($"Source: `{Messages.OneLine(Path.GetFileName(trialsPath))}`, {trials} trials{(catchLeftOut >= 0 ? $" ({catchLeftOut} catch trials left out, --without-catch)" : "")}, {rows.Count} fits (participant × condition × standard).\n\n");
        md.Append("Ψ(x) = γ + (1 − γ − λ)·Φ((x − μ)/σ), fitted by maximum likelihood to the binary answers (1 = comparison judged heavier), ");
        md.Append($"γ = λ = {NumberText.Format(lapse)}{(lapse == 0 ? " (no lapses)" : " (fixed, --lapse)")}. PSE = μ; JND = σ·Φ⁻¹(0.75) ≈ 0.6745·σ; Weber fraction = JND / standard; ");
        md.Append("deviance = the binomial deviance over the comparison levels against the saturated model. ");
        md.Append(resamples > 0
            ? $"95 % intervals of PSE and JND: parametric bootstrap, {resamples} resamples, seed {seed.ToString(CultureInfo.InvariantCulture)} ({IntervalText(interval)}; resamples that cannot be fitted left out).\n\n"
            : "No bootstrap (--bootstrap 0): no intervals.\n\n");
        md.Append("| participant | condition | standard | n | PSE | 95 % CI | JND | 95 % CI | Weber | σ | deviance | estimable |\n");
        md.Append("|---|---|---:|---:|---:|---|---:|---|---:|---:|---:|---|\n");
        foreach (var r in rows)
        {
            var f = r.Fit;
            var b = r.Bootstrap;
            string cell(double v) => double.IsFinite(v) ? v.ToString("G5", CultureInfo.InvariantCulture) : "—";
            string ci(double lo, double hi) => double.IsFinite(lo) ? $"[{cell(lo)}, {cell(hi)}]" : "—";
            md.Append($"| {Cell(r.Participant)} | {Cell(r.Condition)} | {cell(r.Standard)} | {f.Trials} | ");
            if (f.Estimable)
                md.Append($"{cell(f.Pse)} | {ci(b.PseLow, b.PseHigh)} | {cell(f.Jnd)} | {ci(b.JndLow, b.JndHigh)} | {cell(r.Weber)} | {cell(f.Sigma)} | {cell(f.Deviance)} | yes{(b.Failed > 0 && resamples > 0 ? $" ({b.Failed} of {resamples} resamples not fittable)" : "")} |\n");
            else
                md.Append($"— | — | — | — | — | — | — | {Cell(f.Reason)} |\n");
        }
        md.Append('\n');
        if (summary) md.Append("## Summary\n\n![PSE and JND per participant](summary.png)\n\n");
        if (charts.Count > 0)
        {
            md.Append("## Per participant\n\nProportion judged heavier at each comparison level with its 95 % Wilson interval, the fitted curve, the PSE (50 %) and the JND (from the PSE to the 75 % point).\n\n");
            foreach (var c in charts) md.Append($"![{Cell(c.Participant)} {Cell(c.Condition)}]({c.File})\n\n");
        }
        return md.ToString();
    }

    static string Cell(string text) => Messages.OneLine(text).Replace("|", "\\|");
}
