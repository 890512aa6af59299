using System.Globalization;
using System.Text;
using Kosmos.PseudoHaptic.Cli;
using Kosmos.PseudoHaptic.Evaluation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tools.Tests;

/// <summary>
/// Issue 11's command contracts: psychometric and compare (exact headers, numbers as the engine computes
/// them, degenerate sets marked, errors naming T.csv:LINE or the option with nothing written) and score's
/// optional condition column (files without it unchanged byte for byte).
/// </summary>
public class StudyCliTests : CliTestFolder
{
    public StudyCliTests() : base("ph-study-") { }

    static (int code, string stderr, string stdout) Psychometric(params string[] args) => Capture(() => PsychometricCommand.Run(args));
    static (int code, string stderr, string stdout) Compare(params string[] args) => Capture(() => CompareCommand.Run(args));

    /// <summary>Simulated participants (constant stimuli, 7 levels × 12) in two conditions, plus degenerate ones.</summary>
    static string SimulatedTrials(out List<(string P, string C, double Pse, double Sigma)> truth)
    {
        truth = new();
        var text = new StringBuilder("trial,participant,condition,standard,comparison,response,note\n");
        int row = 0;
        for (int p = 1; p <= 4; p++)
            foreach (var (condition, shift) in new[] { ("off", 0.0), ("on", 0.08) })
            {
                double pse = 1.0 + shift + 0.02 * p, sigma = 0.08 + 0.01 * p;
                truth.Add(("P" + p, condition, pse, sigma));
                var observer = new SimulatedObserver(pse, sigma, 10 * p + (int)(shift * 100));
                var plan = new ConstantStimuliPlan { Standard = 1, Seed = p, Repetitions = 12 };
                foreach (var t in plan.Build("P" + p, condition))
                    text.Append($"{++row},P{p},{condition},1,{t.Comparison.ToString("R", CultureInfo.InvariantCulture)},{observer.Answer(t.Comparison)},x\n");
            }
        // Degenerate: all answers 1; a single level; perfect separation.
        foreach (double c in new[] { 0.8, 1.0, 1.2 }) text.Append($"{++row},Pall,off,1,{c},1,\n");
        text.Append($"{++row},Pone,off,1,1.1,1,\n{++row},Pone,off,1,1.1,0,\n");
        text.Append($"{++row},Psep,off,1,0.9,0,\n{++row},Psep,off,1,1.1,1,\n");
        return text.ToString();
    }

    [Test]
    public void PsychometricFitsMatchTheEngineAndMarkDegenerateSets()
    {
        string trials = Write("T.csv", SimulatedTrials(out var truth));
        string outDir = Path.Combine(_dir, "out");
        var (code, stderr, stdout) = Psychometric("--trials", trials, "--out", outDir, "--bootstrap", "200", "--seed", "5");
        Assert.That(code, Is.EqualTo(0), stderr);
        var lines = File.ReadAllLines(Path.Combine(outDir, "fits.csv"));
        Assert.That(lines[0], Is.EqualTo("participant,condition,standard,n,pse,jnd,weber,sigma,pse_lo,pse_hi,jnd_lo,jnd_hi,deviance,estimable"));
        Assert.That(lines.Length, Is.EqualTo(1 + 8 + 3));
        // Participants in natural order: P1 … P4, then Pall, Pone, Psep; conditions in file order.
        Assert.That(lines.Skip(1).Select(l => l.Split(',')[0] + "/" + l.Split(',')[1]),
            Is.EqualTo(new[] { "P1/off", "P1/on", "P2/off", "P2/on", "P3/off", "P3/on", "P4/off", "P4/on", "Pall/off", "Pone/off", "Psep/off" }));
        var answers = TrialsCsv.Read(new StringReader(File.ReadAllText(trials)), "T.csv");
        foreach (var (p, c, pse, sigma) in truth)
        {
            var f = lines.Single(l => l.StartsWith(p + "," + c + ",", StringComparison.Ordinal)).Split(',');
            var mine = answers.Where(a => a.Participant == p && a.Condition == c).ToList();
            var fit = PsychometricFit.Fit(mine.Select(a => a.Comparison).ToArray(), mine.Select(a => a.Response).ToArray());
            Assert.That(f[3], Is.EqualTo("84"));
            Assert.That(double.Parse(f[4], CultureInfo.InvariantCulture), Is.EqualTo(fit.Pse));
            Assert.That(double.Parse(f[7], CultureInfo.InvariantCulture), Is.EqualTo(fit.Sigma));
            Assert.That(double.Parse(f[5], CultureInfo.InvariantCulture), Is.EqualTo(0.6744897501960817 * fit.Sigma).Within(1e-15));
            Assert.That(double.Parse(f[6], CultureInfo.InvariantCulture), Is.EqualTo(fit.Jnd / 1.0));
            Assert.That(double.Parse(f[8], CultureInfo.InvariantCulture), Is.LessThan(fit.Pse));
            Assert.That(double.Parse(f[9], CultureInfo.InvariantCulture), Is.GreaterThan(fit.Pse));
            Assert.That(f[13], Is.EqualTo("yes"));
            Assert.That(Math.Abs(fit.Pse - pse), Is.LessThan(4 * sigma / Math.Sqrt(84) * 3), "near the truth");
        }
        Assert.That(lines[9], Is.EqualTo("Pall,off,1,3,,,,,,,,,,all answers the same (1)"));
        Assert.That(lines[10], Is.EqualTo("Pone,off,1,2,,,,,,,,,,a single level"));
        Assert.That(lines[11], Does.StartWith("Psep,off,1,2,,,,,,,,,,perfect separation"));
        Assert.That(lines.Any(l => l.Contains("NaN")), Is.False);
        var files = Directory.GetFiles(outDir).Select(Path.GetFileName).ToList();
        Assert.That(files, Does.Contain("report.md").And.Contain("summary.png").And.Contain("fit-001-P1-off.png"));
        Assert.That(files.Count(f => f!.StartsWith("fit-", StringComparison.Ordinal)), Is.EqualTo(11), "a chart per participant × condition");
        Assert.That(stdout, Does.Contain("11 fits"));

        // The same seed gives the same file; another seed other intervals but the same fits.
        string again = Path.Combine(_dir, "again");
        Assert.That(Psychometric("--trials", trials, "--out", again, "--bootstrap", "200", "--seed", "5").code, Is.EqualTo(0));
        Assert.That(File.ReadAllText(Path.Combine(again, "fits.csv")), Is.EqualTo(File.ReadAllText(Path.Combine(outDir, "fits.csv"))));
        string other = Path.Combine(_dir, "other");
        Assert.That(Psychometric("--trials", trials, "--out", other, "--bootstrap", "200", "--seed", "6").code, Is.EqualTo(0));
        var otherLines = File.ReadAllLines(Path.Combine(other, "fits.csv"));
        Assert.That(otherLines[1].Split(',')[4], Is.EqualTo(lines[1].Split(',')[4]));
        Assert.That(otherLines[1].Split(',')[8], Is.Not.EqualTo(lines[1].Split(',')[8]));
    }

    /// <summary>
    /// --interval: BCa by default, the plain percentiles on request; the same resamples (same seed) either way, so the fits,
    /// the unfittable counts and everything but the interval columns are equal, and each interval is the engine's for its kind.
    /// report.md says which kind it holds.
    /// </summary>
    [Test]
    public void TheIntervalOptionChoosesBcaOrThePlainPercentilesOfTheSameResamples()
    {
        string trials = Write("T.csv", SimulatedTrials(out _));
        string bca = Path.Combine(_dir, "bca"), named = Path.Combine(_dir, "named"), percentile = Path.Combine(_dir, "percentile");
        Assert.That(Psychometric("--trials", trials, "--out", bca, "--bootstrap", "200", "--seed", "5").code, Is.EqualTo(0));
        Assert.That(Psychometric("--trials", trials, "--out", named, "--bootstrap", "200", "--seed", "5", "--interval", "bca").code, Is.EqualTo(0));
        Assert.That(Psychometric("--trials", trials, "--out", percentile, "--bootstrap", "200", "--seed", "5", "--interval", "percentile").code, Is.EqualTo(0));
        string fits(string dir) => File.ReadAllText(Path.Combine(dir, "fits.csv"));
        Assert.That(fits(named), Is.EqualTo(fits(bca)), "bca is the default");
        var b = File.ReadAllLines(Path.Combine(bca, "fits.csv"));
        var p = File.ReadAllLines(Path.Combine(percentile, "fits.csv"));
        Assert.That(p.Length, Is.EqualTo(b.Length));
        var rows = PsychometricAnalysis.Fit(TrialsCsv.Read(new StringReader(File.ReadAllText(trials)), "T.csv"), 0, 200, 5);
        int moved = 0;
        for (int i = 1; i < b.Length; i++)
        {
            var fb = b[i].Split(',');
            var fp = p[i].Split(',');
            Assert.That(fp.Take(8).Concat(fp.Skip(12)), Is.EqualTo(fb.Take(8).Concat(fb.Skip(12))), "line " + (i + 1) + ": all but the intervals");
            if (fb[13] != "yes") continue;
            var fit = rows[i - 1].Fit;
            var engine = PsychometricBootstrap.Run(fit, 200, SeedOf(5, i - 1), 0.95, BootstrapInterval.Percentile);
            Assert.That(fp.Skip(8).Take(4).Select(v => double.Parse(v, CultureInfo.InvariantCulture)),
                Is.EqualTo(new[] { engine.PseLow, engine.PseHigh, engine.JndLow, engine.JndHigh }), "line " + (i + 1) + ": the engine's percentiles");
            Assert.That(fb.Skip(8).Take(4).Select(v => double.Parse(v, CultureInfo.InvariantCulture)),
                Is.EqualTo(new[] { rows[i - 1].Bootstrap.PseLow, rows[i - 1].Bootstrap.PseHigh, rows[i - 1].Bootstrap.JndLow, rows[i - 1].Bootstrap.JndHigh }),
                "line " + (i + 1) + ": the engine's BCa ends");
            if (fb[10] != fp[10] || fb[11] != fp[11]) moved++;
        }
        Assert.That(moved, Is.EqualTo(8), "every estimable JND interval moved");
        Assert.That(File.ReadAllText(Path.Combine(bca, "report.md")), Does.Contain("bias-corrected and accelerated percentiles, BCa"));
        Assert.That(File.ReadAllText(Path.Combine(percentile, "report.md")), Does.Contain("percentiles 2.5 and 97.5 (--interval percentile)"));
    }

    /// <summary>The bootstrap seed of the <paramref name="group"/>-th group (from 0) of a file run with --seed <paramref name="seed"/>.</summary>
    static long SeedOf(long seed, int group)
    {
        var seeds = new SeededRandom(seed);
        long s = 0;
        for (int g = 0; g <= group; g++) s = unchecked((long)seeds.NextUInt64());
        return s;
    }

    [Test]
    public void LapseOptionFixesGammaAndLambda()
    {
        string trials = Write("T.csv", SimulatedTrials(out _));
        string outDir = Path.Combine(_dir, "out");
        Assert.That(Psychometric("--trials", trials, "--out", outDir, "--lapse", "0.02", "--bootstrap", "0").code, Is.EqualTo(0));
        var f = File.ReadAllLines(Path.Combine(outDir, "fits.csv"))[1].Split(',');
        var answers = TrialsCsv.Read(new StringReader(File.ReadAllText(trials)), "T.csv").Where(a => a.Participant == "P1" && a.Condition == "off").ToList();
        var fit = PsychometricFit.Fit(answers.Select(a => a.Comparison).ToArray(), answers.Select(a => a.Response).ToArray(), 0.02);
        Assert.That(double.Parse(f[4], CultureInfo.InvariantCulture), Is.EqualTo(fit.Pse));
        Assert.That(f[8], Is.Empty, "no bootstrap: no interval");
        Assert.That(f[13], Is.EqualTo("yes"));
    }

    [TestCase("participant,standard,comparison\nP1,1,1\n", "T.csv:1: missing column 'response'")]
    [TestCase("participant,standard,comparison,response\nP1,1,1.1,1\nP1,1,1.2,2\n", "T.csv:3: response '2'")]
    [TestCase("participant,standard,comparison,response\nP1,1,1.1,yes\n", "T.csv:2: response 'yes'")]
    [TestCase("participant,standard,comparison,response\nP1,1,abc,1\n", "T.csv:2: comparison 'abc' is not a number")]
    [TestCase("participant,standard,comparison,response\nP1,NaN,1,1\n", "T.csv:2: standard 'NaN' is not a finite number")]
    [TestCase("participant,standard,comparison,response\n,1,1,1\n", "T.csv:2: participant is empty")]
    // Issue 32: a weight is positive; a standard of -0.5 kg exited 0 with a Weber fraction of -0.131.
    [TestCase("participant,standard,comparison,response\nP1,0.5,0.4,0\nP1,-0.5,0.6,1\nP1,0.5,0.7,1\n", "T.csv:3: standard -0.5 is not a positive weight (kg)")]
    [TestCase("participant,standard,comparison,response\nP1,0.5,0.4,0\nP1,0,0.6,1\n", "T.csv:3: standard 0 is not a positive weight (kg)")]
    [TestCase("participant,standard,comparison,response\nP1,0.5,0.4,0\nP1,0.5,-0.0,1\n", "T.csv:3: comparison -0.0 is not a positive weight (kg)")]
    [TestCase("participant,standard,comparison,response\nP1,0.5,-0.4,0\n", "T.csv:2: comparison -0.4 is not a positive weight (kg)")]
    [TestCase("participant,standard,comparison,response\nP1,1,1\n", "T.csv:2: expected 4 fields")]
    [TestCase("", "T.csv:1: empty file")]
    public void MalformedTrialsAreRefusedNamingTheLineAndNothingIsWritten(string text, string expected)
    {
        string trials = Write("T.csv", text);
        string outDir = Path.Combine(_dir, "out");
        var (code, stderr, stdout) = Psychometric("--trials", trials, "--out", outDir);
        Assert.That(code, Is.EqualTo(2));
        Assert.That(stderr, Does.StartWith("pseudohaptic psychometric: " + Path.Combine(_dir, expected)));
        Assert.That(stderr.TrimEnd('\n').Split('\n'), Has.Length.EqualTo(1), "one line");
        Assert.That(Directory.Exists(outDir), Is.False, "nothing written");
        Assert.That(Directory.GetFileSystemEntries(_dir).Select(Path.GetFileName), Is.EqualTo(new[] { "T.csv" }));
    }

    [TestCase("--lapse", "x", "option --lapse")]
    [TestCase("--lapse", "0.5", "option --lapse")]
    [TestCase("--lapse", "-0.1", "option --lapse")]
    [TestCase("--bootstrap", "-1", "option --bootstrap")]
    [TestCase("--bootstrap", "1.5", "option --bootstrap")]
    [TestCase("--seed", "abc", "option --seed")]
    [TestCase("--interval", "BCa", "option --interval: 'BCa' is neither bca nor percentile")]
    [TestCase("--interval", "student", "option --interval: 'student' is neither bca nor percentile")]
    [TestCase("--colour", "red", "unknown option '--colour'")]
    public void BadOptionsAreRefusedNamingTheOption(string option, string value, string expected)
    {
        string trials = Write("T.csv", "participant,standard,comparison,response\nP1,1,1.1,1\n");
        string outDir = Path.Combine(_dir, "out");
        var (code, stderr, _) = Psychometric("--trials", trials, "--out", outDir, option, value);
        Assert.That(code, Is.EqualTo(2));
        Assert.That(stderr, Does.Contain(expected));
        Assert.That(stderr.TrimEnd('\n').Split('\n'), Has.Length.EqualTo(1));
        Assert.That(Directory.Exists(outDir), Is.False);
    }

    [Test]
    public void CompareTwoConditionsMatchesTheEngine()
    {
        var text = new StringBuilder("participant,condition,questionnaire,score\n");
        double[] off = { 3.1, 2.8, 3.6, 3.0, 2.5, 3.3, 2.9, 3.4 };
        double[] on = { 3.9, 3.0, 4.2, 3.6, 3.1, 3.2, 3.8, 4.4 };
        for (int i = 0; i < off.Length; i++) text.Append($"P{i + 1},off,immersion,{off[i].ToString(CultureInfo.InvariantCulture)}\n");
        for (int i = 0; i < on.Length; i++) text.Append($"P{i + 1},on,immersion,{on[i].ToString(CultureInfo.InvariantCulture)}\n");
        text.Append("P9,off,immersion,3\nP9,on,immersion,\n"); // incomplete in one condition: left out of the pair
        string scores = Write("S.csv", text.ToString());
        string outDir = Path.Combine(_dir, "out");
        var (code, stderr, _) = Compare("--scores", scores, "--out", outDir);
        Assert.That(code, Is.EqualTo(0), stderr);
        var lines = File.ReadAllLines(Path.Combine(outDir, "comparisons.csv"));
        Assert.That(lines[0], Is.EqualTo("questionnaire,condition_a,condition_b,n,mean_diff,diff_lo,diff_hi,t,t_p,w,w_p,dz,r,p_holm,method"));
        Assert.That(lines, Has.Length.EqualTo(2));
        var c = PairedComparison.Compute(off, on);
        string R(double v) => v.ToString("R", CultureInfo.InvariantCulture);
        Assert.That(lines[1], Is.EqualTo($"immersion,off,on,8,{R(c.MeanDifference)},{R(c.DifferenceLow)},{R(c.DifferenceHigh)},{R(c.T)},{R(c.TP)},{R(c.W)},{R(c.WP)},{R(c.Dz)},{R(c.R)},{R(c.WP)},t+wilcoxon-{(c.WilcoxonExact ? "exact" : "normal")}"));
        // d = .8 .2 .6 .6 .2 −.1 .9 1.0 (as doubles): tied |d| → the normal approximation, not the exact p.
        Assert.That(c.HasTies, Is.True);
        Assert.That(lines[1], Does.EndWith("t+wilcoxon-normal"));
        Assert.That(Directory.GetFiles(outDir).Select(Path.GetFileName), Is.EquivalentTo(new[] { "comparisons.csv", "report.md", "chart1-immersion.png" }));
    }

    [Test]
    public void CompareThreeConditionsRunsFriedmanFirstAndHolmCorrects()
    {
        var text = new StringBuilder("participant,condition,questionnaire,score\n");
        var rng = new SeededRandom(9);
        var values = new Dictionary<string, double[]>();
        foreach (string cond in new[] { "none", "weak", "strong" }) values[cond] = new double[10];
        for (int p = 0; p < 10; p++)
        {
            values["none"][p] = 2 + rng.NextDouble();
            values["weak"][p] = values["none"][p] + 0.3 * rng.NextDouble();
            values["strong"][p] = values["none"][p] + 0.2 + rng.NextDouble();
            foreach (string cond in new[] { "none", "weak", "strong" })
                text.Append($"P{p + 1},{cond},weight-detection,{values[cond][p].ToString("R", CultureInfo.InvariantCulture)}\n");
        }
        string outDir = Path.Combine(_dir, "out");
        var (code, stderr, _) = Compare("--scores", Write("S.csv", text.ToString()), "--out", outDir);
        Assert.That(code, Is.EqualTo(0), stderr);
        var lines = File.ReadAllLines(Path.Combine(outDir, "comparisons.csv"));
        Assert.That(lines, Has.Length.EqualTo(1 + 1 + 3));
        var friedman = FriedmanTest.Compute(Enumerable.Range(0, 10).Select(p => (IReadOnlyList<double>)new[] { values["none"][p], values["weak"][p], values["strong"][p] }).ToList());
        string R(double v) => v.ToString("R", CultureInfo.InvariantCulture);
        Assert.That(lines[1], Is.EqualTo($"weight-detection,*,*,10,,,,{R(friedman.Statistic)},{R(friedman.P)},,,,,,friedman"));
        var pairs = new[] { ("none", "weak"), ("none", "strong"), ("weak", "strong") };
        var ps = pairs.Select(p => PairedComparison.Compute(values[p.Item1], values[p.Item2]).WP).ToArray();
        var holm = Holm.Adjust(ps);
        for (int i = 0; i < 3; i++)
        {
            var f = lines[2 + i].Split(',');
            Assert.That((f[1], f[2]), Is.EqualTo(pairs[i]));
            Assert.That(f[10], Is.EqualTo(R(ps[i])));
            Assert.That(f[13], Is.EqualTo(R(holm[i])));
        }
    }

    [TestCase("participant,questionnaire,score\nP1,immersion,3\n", "S.csv:1: missing column 'condition'")]
    [TestCase("participant,condition,questionnaire,score\nP1,a,immersion,x\n", "S.csv:2: score 'x'")]
    [TestCase("participant,condition,questionnaire,score\nP1,a,immersion,3\nP1,a,immersion,4\n", "S.csv:3: duplicate score")]
    [TestCase("participant,condition,questionnaire,score\nP1,a,,3\n", "S.csv:2: questionnaire is empty")]
    public void MalformedScoresAreRefusedNamingTheLine(string text, string expected)
    {
        string scores = Write("S.csv", text);
        var (code, stderr, _) = Compare("--scores", scores, "--out", Path.Combine(_dir, "out"));
        Assert.That(code, Is.EqualTo(2));
        Assert.That(stderr, Does.StartWith("pseudohaptic compare: " + Path.Combine(_dir, expected)));
        Assert.That(Directory.Exists(Path.Combine(_dir, "out")), Is.False);
    }

    const string Responses =
        "participant,questionnaire,item,response\n" +
        "P2,self-assessment,1,7\n" +
        "P10,self-assessment,1,4\n" +
        "P1,self-assessment,1,9\n" +
        "P1,immersion,1,3\n";

    [Test]
    public void ScoreWithoutConditionIsByteForByteAsBefore()
    {
        string responses = Write("R.csv", Responses);
        string output = Path.Combine(_dir, "S.csv");
        var (code, stderr, _) = Score("--responses", responses, "--out", output);
        Assert.That(code, Is.EqualTo(0), stderr);
        // The scores as the package computed them before conditions existed.
        var before = ScoresCsv.Format(ScoreCalculator.ScoreAll(ResponsesCsv.Parse(Responses, "R.csv", QuestionnaireCatalogForTests())));
        Assert.That(File.ReadAllBytes(output), Is.EqualTo(new UTF8Encoding(false).GetBytes(before)));
        Assert.That(File.ReadAllText(output), Is.EqualTo("participant,questionnaire,score\nP1,immersion,\nP1,self-assessment,9\nP2,self-assessment,7\nP10,self-assessment,4\n"));
    }

    [Test]
    public void ScoreCarriesTheConditionColumnAfterTheParticipant()
    {
        string responses = Write("R.csv",
            "participant,questionnaire,item,response,condition\n" +
            "P2,self-assessment,1,7,with\n" +
            "P1,self-assessment,1,9,without\n" +
            "P1,self-assessment,1,6,with\n" +
            "P2,self-assessment,1,5,without\n");
        string output = Path.Combine(_dir, "S.csv");
        var (code, stderr, _) = Score("--responses", responses, "--out", output);
        Assert.That(code, Is.EqualTo(0), stderr);
        Assert.That(File.ReadAllText(output), Is.EqualTo(
            "participant,condition,questionnaire,score\n" +
            "P1,with,self-assessment,6\n" +
            "P1,without,self-assessment,9\n" +
            "P2,with,self-assessment,7\n" +
            "P2,without,self-assessment,5\n"));
        // And compare reads it.
        var (c2, e2, _) = Compare("--scores", output, "--out", Path.Combine(_dir, "cmp"));
        Assert.That(c2, Is.EqualTo(0), e2);
        Assert.That(File.ReadAllLines(Path.Combine(_dir, "cmp", "comparisons.csv"))[1], Does.StartWith("self-assessment,with,without,2,0.5,"));
    }

    [Test]
    public void PsychometricAndCompareWithSvgWriteAnSvgOfTheSameSizeBesideEachChart()
    {
        // Issue 13: every chart through ScottPlot, "and an SVG beside each PNG when asked (--svg)"; these two refused it.
        string examples = Path.Combine(RepositoryRoot.Path, "Packages", "com.kosmos.pseudohaptic", "Documentation~", "examples", "study");
        var runs = new (string Name, Func<string, string[], (int, string, string)> Run)[]
        {
            ("psychometric", (dir, extra) => Psychometric(new[] { "--trials", Path.Combine(examples, "trials.csv"), "--out", dir, "--bootstrap", "20" }.Concat(extra).ToArray())),
            ("compare", (dir, extra) => Compare(new[] { "--scores", Path.Combine(examples, "psychophysics.csv"), "--out", dir }.Concat(extra).ToArray())),
        };
        foreach (var (name, run) in runs)
        {
            string plain = Path.Combine(_dir, name + "-png"), both = Path.Combine(_dir, name + "-svg");
            var (code, stderr, _) = run(plain, Array.Empty<string>());
            Assert.That(code, Is.EqualTo(0), stderr);
            Assert.That(Directory.GetFiles(plain, "*.svg"), Is.Empty, name + ": no SVG unless asked");
            for (int pass = 0; pass < 2; pass++) // the second replaces the folder the first wrote, SVGs and all
            {
                (code, stderr, _) = run(both, new[] { "--svg" });
                Assert.That(code, Is.EqualTo(0), name + " pass " + pass + ": " + stderr);
            }
            var pngs = Directory.GetFiles(both, "*.png").Select(f => Path.GetFileName(f)).OrderBy(f => f, StringComparer.Ordinal).ToArray();
            Assert.That(pngs, Is.EqualTo(Directory.GetFiles(plain, "*.png").Select(f => Path.GetFileName(f)).OrderBy(f => f, StringComparer.Ordinal).ToArray()), name + ": the same charts");
            Assert.That(pngs, Is.Not.Empty);
            Assert.That(Directory.GetFiles(both, "*.svg").Select(Path.GetFileName).OrderBy(f => f, StringComparer.Ordinal),
                Is.EqualTo(pngs.Select(f => Path.ChangeExtension(f, ".svg")).ToArray()), name + ": one SVG beside each PNG");
            foreach (string png in pngs)
            {
                var (width, height) = ChartFiles.IhdrSize(File.ReadAllBytes(Path.Combine(both, png)));
                ChartFiles.AssertSvg(Path.Combine(both, Path.ChangeExtension(png, ".svg")), width, height);
            }
        }
    }

    static QuestionnaireCatalog QuestionnaireCatalogForTests()
    {
        string folder = Path.Combine(RepositoryRoot.Path, "Packages", "com.kosmos.pseudohaptic", "Runtime", "Evaluation", "Questionnaires");
        return QuestionnaireJson.LoadDirectory(folder);
    }
}
