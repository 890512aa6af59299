using Kosmos.PseudoHaptic.Cli.CommandLine;
using Kosmos.PseudoHaptic.Cli.Files;
using Kosmos.PseudoHaptic.Evaluation;

namespace Kosmos.PseudoHaptic.Cli.Commands;

/// <summary>
/// <c>pseudohaptic tune --trials T.csv --participant P --out USER.json [--condition C] [--masses LIST] [--confidence C] [--interval bca|percentile]</c>
/// (issue 31; --interval added in the twenty-fifth session): fits this participant's psychometric function on the cue each comparison renders at s = 1 (the existing
/// maximum-likelihood fit, no lapse, on <see cref="CueStrengthTuning.CueDifference"/>), and writes the smallest cue
/// strength at which the scene's adjacent masses are at least the JND's upper confidence bound apart for this person
/// (<see cref="CueStrengthTuning"/>; ALGORITHM.md §12, evaluation.md §9).
/// </summary>
public static class TuneCommand
{
    public static CliCommand Define() => new(
        "tune",
        "Fit one participant's weight-discrimination answers and write the cue strength that puts the scene's adjacent masses one JND apart for them (USER.json, for replay --user and demo --user; ALGORITHM.md §12)",
        Run,
        new[]
        {
            "pseudohaptic tune --trials Packages/com.kosmos.pseudohaptic/Documentation~/examples/study/trials.csv --participant P1 --condition pseudo-haptic --out out/user-P1.json",
        },
        CliCommand.Value("--trials", "T.csv", "the discrimination kit's trials file as the headset writes it: participant,condition,trial,standard,comparison,first,catch,response (standard and comparison in kg, rendered at cue strength 1); catch trials (catch = 1) are left out of the fit", required: true),
        CliCommand.Value("--participant", "P", "whose answers to fit", required: true),
        CliCommand.Value("--out", "USER.json", "where the user's file goes: participant, cueStrength, weber, the fit and the model; replaced whole or not at all", required: true),
        CliCommand.Value("--condition", "C", "the condition to fit (default: the participant's only one; required when they have several)"),
        CliCommand.Value("--masses", "LIST", $"the scene's masses, kg, comma-separated (default Experiment 1's boxes {string.Join(",", CueStrengthTuning.ExperimentOneBoxes)})"),
        CliCommand.Value("--confidence", "C", "one-sided confidence that the tuned strength puts the adjacent masses at least one JND apart for this person: s is tuned on the upper C bound of the fitted JND (1000 seeded bootstrap refits); in [0.5, 0.999], 0.5 = the fitted JND itself (default 0.95)"),
        CliCommand.Value("--interval", "KIND", "how the bootstrap makes that bound, as psychometric's --interval: bca (default) or percentile (the only kind up to version 0.4.0)"));

    public static int Run(string[] args) => Cli.Run(args.Prepend("tune").ToArray());

    /// <summary>
    /// What tune computes from read answers: the participant's trials in the condition (the only one when
    /// <paramref name="condition"/> is null), at the standard with the most trials, fitted (no lapse), and the tuning.
    /// Errors are <see cref="CliException"/>s naming the option or <paramref name="file"/>.
    /// </summary>
    /// <summary>The one-sided confidence with which the tuned strength puts the adjacent masses one JND apart: the strength is
    /// tuned on the upper <see cref="Confidence"/> bound of the fitted JND (the parametric bootstrap's, BCa by default), so that a
    /// JND the finite trials underestimate does not leave the person below 75 % correct.</summary>
    public const double Confidence = 0.95;

    /// <summary>The bootstrap's resamples and seed (fixed: the same file gives the same USER.json).</summary>
    public const int Resamples = 1000;
    public const long BootstrapSeed = 31;

    /// <returns>The standard (kg); the fit on the cue difference (its JND is the fitted Δc*); the fitted JND as the kg above
    /// the standard it means there; the tuning, on the upper <paramref name="confidence"/> bound of Δc*; the trials; the
    /// condition.</returns>
    public static (double Standard, PsychometricFit Fit, double FittedJndKg, CueStrengthTuning Tuning, int Trials, string Condition) Tune(
        IReadOnlyList<TrialAnswer> answers, string participant, string? condition, double[] masses, string file, double confidence = Confidence,
        BootstrapInterval interval = BootstrapInterval.Bca)
    {
        var mine = answers.Where(a => a.Participant == participant).ToList();
        if (mine.Count == 0)
            throw new CliException($"option --participant: {Messages.OneLine(participant)} has no trials in {file} (participants: {Messages.OneLine(string.Join(", ", answers.Select(a => a.Participant).Distinct().Take(10)))})");
        var conditions = mine.Select(a => a.Condition).Distinct().ToList();
        if (condition == null)
        {
            if (conditions.Count > 1)
                throw new CliException($"option --condition: {Messages.OneLine(participant)} has trials in {conditions.Count} conditions of {file} ({Messages.OneLine(string.Join(", ", conditions))}); choose the one with the cue as rendered");
            condition = conditions[0];
        }
        else if (!conditions.Contains(condition))
            throw new CliException($"option --condition: {Messages.OneLine(participant)} has no trials in condition '{Messages.OneLine(condition)}' of {file} (conditions: {Messages.OneLine(string.Join(", ", conditions))})");
        var group = mine.Where(a => a.Condition == condition).ToList();
        // The standard with the most trials (the first such in the file on a tie).
        double standard = group.GroupBy(a => a.Standard).OrderByDescending(g => g.Count()).First().Key;
        var trials = group.Where(a => a.Standard == standard).ToList();
        if (!(standard > 0))
            throw new CliException($"{file}:{trials[0].Line}: standard {NumberText.Format(standard)} is not a mass greater than 0 (kg)");
        // The model's stimulus: each comparison as the cue difference it renders at s = 1 (CueStrengthTuning.CueDifference),
        // so the fitted Gaussian is the model's observer (Weber's law on the rise ratio) and its JND is Δc* itself.
        var frames = ReferenceLift.Frames();
        var cueOf = new Dictionary<double, double>();
        foreach (var a in trials)
        {
            if (cueOf.ContainsKey(a.Comparison)) continue;
            double d = CueStrengthTuning.CueDifference(standard, a.Comparison, WeightSolver.DefaultStandardSpeed, frames);
            if (double.IsNaN(d))
                throw new CliException($"{file}:{a.Line}: comparison {NumberText.Format(a.Comparison)} kg does not rise on the reference lift at cue strength 1: no cue to fit");
            cueOf.Add(a.Comparison, d);
        }
        var fit = PsychometricFit.Fit(trials.Select(a => cueOf[a.Comparison]).ToList(), trials.Select(a => a.Response).ToList());
        if (!fit.Estimable)
            throw new CliException($"{file}: {Messages.OneLine(participant)}{(condition.Length > 0 ? " " + Messages.OneLine(condition) : "")} standard {NumberText.Format(standard)}: the psychometric fit is not estimable ({fit.Reason}); no cue strength can be derived");
        // The JND's upper one-sided bound at the confidence (from 1000 seeded parametric-bootstrap refits, BCa by default, as
        // psychometric's intervals; the plain percentile's bound is too low about twice as often with 84 trials,
        // evaluation.md §8.3): the strength that puts the adjacent masses that far apart reaches 75 % for this person
        // unless the finite trials overestimated their sensitivity beyond that confidence. 0.5: the fitted JND itself.
        double upper = fit.Jnd;
        if (confidence > 0.5)
        {
            var boot = PsychometricBootstrap.Run(fit, Resamples, BootstrapSeed, 1 - 2 * (1 - confidence), interval);
            if (!boot.HasIntervals)
                throw new CliException($"{file}: {Messages.OneLine(participant)}{(condition.Length > 0 ? " " + Messages.OneLine(condition) : "")} standard {NumberText.Format(standard)}: the JND's bootstrap found no refittable resample; no cue strength can be derived");
            upper = Math.Max(fit.Jnd, boot.JndHigh);
        }
        var fitted = CueStrengthTuning.SolveForThresholdCue(standard, fit.Jnd, masses);
        var tuning = upper == fit.Jnd ? fitted : CueStrengthTuning.SolveForThresholdCue(standard, upper, masses);
        return (standard, fit, fitted.JndKg, tuning, trials.Count, condition);
    }

    static int Run(Options o)
    {
        string trialsPath = o.Require("--trials");
        string participant = o.Require("--participant");
        string output = o.Require("--out");
        string? condition = o.Get("--condition");
        double[] masses = UserFile.Masses(o.Get("--masses"));
        double confidence = ConfidenceOption(o.Get("--confidence"));
        var interval = PsychometricCommand.Interval(o.Get("--interval"));
        var target = OutputFile.Check("--out", output, new NamedPath("--trials", trialsPath));

        // Catch trials are attention checks, not levels of the person's function: one missed would raise their cue strength.
        var answers = TrialsCsv.Read(EvaluationInputs.OpenText("--trials", trialsPath), EvaluationInputs.Name(trialsPath), EvaluationInputs.MaxRows, EvaluationInputs.MaxCharacters, leaveOutCatch: true, out _);
        var (standard, fit, fittedJndKg, tuning, trials, chosen) = Tune(answers, participant, condition, masses, Messages.OneLine(trialsPath), confidence, interval);
        condition = chosen;
        double weber = fittedJndKg / standard;
        target.Write(w => w.Write(UserFile.Format(participant, condition, standard, fittedJndKg, weber, tuning, trials, fit.Jnd, confidence)));
        if (!tuning.Reached)
            Console.Error.WriteLine($"pseudohaptic tune: warning: {Messages.OneLine(participant)}: even the largest cue strength {NumberText.Format(WeightSolver.MaxCueStrength)} puts adjacent masses only {NumberText.Fixed(tuning.AdjacentCue / tuning.ThresholdCue, 2)} JND apart; cueStrength set to that bound");
        Console.Out.WriteLine($"tune: {Messages.OneLine(participant)}: Weber {NumberText.Fixed(weber, 3)} (JND {NumberText.Fixed(fittedJndKg, 3)} kg at {NumberText.Format(standard)} kg, {trials} trials; upper {NumberText.Format(confidence)} bound {NumberText.Fixed(tuning.JndKg, 3)} kg) -> cueStrength {NumberText.Fixed(tuning.CueStrength, 3)}{(tuning.Reached ? "" : " (the bound)")} for {string.Join(", ", tuning.Masses.Select(m => NumberText.Format(m)))} kg -> {Messages.OneLine(output)}");
        return 0;
    }

    static double ConfidenceOption(string? text)
    {
        if (text == null) return Confidence;
        if (!NumberText.TryParse(text, out double v) || !double.IsFinite(v))
            throw new CliException($"option --confidence: cannot parse '{Messages.OneLine(text)}' as a number");
        if (!(v >= 0.5 && v <= 0.999)) throw new CliException($"option --confidence: {NumberText.Format(v)} is outside [0.5, 0.999]");
        return v;
    }
}
