using System.Text;
using Kosmos.PseudoHaptic.Cli.Commands;
using Kosmos.PseudoHaptic.Evaluation;

namespace Kosmos.PseudoHaptic.Cli.Personalization;

/// <summary>
/// Issue 31's evidence on simulated participants. Each observer perceives the model's cue (ln of the object's rise over
/// the hand's on the reference lift, <see cref="ReferenceLift.Cue"/>) with Gaussian noise: the kit's
/// <see cref="SimulatedObserver"/>, seeded, answers "comparison heavier" with probability Φ((c_std − c_cmp)/σ). σ is set so
/// that the observer's Weber fraction for the cue as rendered (s = 1) at the 2 kg standard is the one given (0.05–0.6).
/// Each runs the discrimination kit's method of constant stimuli at s = 1 (9 levels spaced by √(1 + Weber) around 2 kg,
/// <see cref="Repetitions"/> = 80 repetitions: 720 trials, as a pilot would place them), the answers go through the trials
/// file's format and <c>tune</c>'s own code (<see cref="TuneCommand.Tune"/>, the fit on the cue difference, the JND's upper
/// bound at <see cref="Confidence"/>), and the percent correct on Experiment 1's adjacent boxes (A vs C, C vs B: 1.0125 vs 1.6875 kg, 1.6875 vs 2.7 kg) is
/// the observer's own probability of a correct 2AFC answer, before (s = 1) and after (the tuned s). The claim is about all
/// seven observers at once, so each is tuned at the Bonferroni confidence 1 − 0.05/7 (all seven reach 75 % together with
/// at least 95 %). What this tests: the fit, the mapping, the confidence bound and the bounds, given that the observer
/// perceives the model's cue; whether people do is what the headset study measures.
/// </summary>
public static class TuningEvidence
{
    public const double StandardKg = 2.0;
    public const int Repetitions = 80, LevelsEachSide = 4;
    public const string Condition = "pseudo-haptic";
    public static readonly double[] Webers = { 0.05, 0.1, 0.15, 0.2, 0.3, 0.45, 0.6 };

    /// <summary>The per-observer confidence of the evidence: Bonferroni over the seven, so that all reach 75 % at once
    /// with at least 95 % (tune's default for one person is <see cref="TuneCommand.Confidence"/>).</summary>
    public static double Confidence => 1 - 0.05 / Webers.Length;

    public sealed record Row(string Participant, double Weber, double FittedWeber, double BoundWeber, double CueStrength, bool Reached,
                             double BeforeWorst, double BeforePooled, double AfterWorst, double AfterPooled);

    public static long Seed(int k, long batch = 0) => 31_000 + k + 1000 * batch;

    /// <summary>The observers' answers as the headset writes them (TrialsCsv), every observer in one file.</summary>
    public static string TrialsFile(long batch = 0, int repetitions = Repetitions)
    {
        var frames = ReferenceLift.Frames();
        var profile = CueStrengthTuning.Profile;
        double v = WeightSolver.DefaultStandardSpeed;
        double cStd = ReferenceLift.Cue(profile, StandardKg, v, 1, frames);
        var all = new List<Trial>();
        for (int k = 0; k < Webers.Length; k++)
        {
            var observer = Observer(k, frames, batch);
            var levels = Enumerable.Range(-LevelsEachSide, 2 * LevelsEachSide + 1).Select(i => StandardKg * Math.Pow(1 + Webers[k], i / 2.0)).ToArray();
            var cues = levels.ToDictionary(m => m, m => ReferenceLift.Cue(profile, m, v, 1, frames));
            var plan = new ConstantStimuliPlan { Standard = StandardKg, Levels = levels, Repetitions = repetitions, Seed = Seed(k, batch) + 100 };
            var trials = plan.Build(Participant(k), Condition);
            foreach (var t in trials) t.Response = observer.Answer(cStd - cues[t.Comparison]);
            all.AddRange(trials);
        }
        return TrialsCsv.Format(all);
    }

    public static string Participant(int k) => "O" + (k + 1);

    /// <summary>Observer k: its σ on the cue puts its JND at s = 1 at Weber × 2 kg.</summary>
    public static SimulatedObserver Observer(int k, Simulation.TraceFrame[] frames, long batch = 0)
    {
        var profile = CueStrengthTuning.Profile;
        double v = WeightSolver.DefaultStandardSpeed;
        double jndCue = Math.Abs(ReferenceLift.Cue(profile, StandardKg, v, 1, frames) - ReferenceLift.Cue(profile, StandardKg * (1 + Webers[k]), v, 1, frames));
        return new SimulatedObserver(0, jndCue / PsychometricFit.JndFactor, Seed(k, batch));
    }

    public static List<Row> Run(long batch = 0, int repetitions = Repetitions, double? confidence = null)
    {
        var frames = ReferenceLift.Frames();
        var answers = TrialsCsv.Read(new StringReader(TrialsFile(batch, repetitions)), "trials.csv", int.MaxValue, long.MaxValue, leaveOutCatch: true, out _); // as tune reads
        var boxes = CueStrengthTuning.ExperimentOneBoxes;
        var rows = new List<Row>();
        for (int k = 0; k < Webers.Length; k++)
        {
            var observer = Observer(k, frames, batch);
            var (standard, _, fittedJndKg, tuning, _, _) = TuneCommand.Tune(answers, Participant(k), Condition, boxes, "trials.csv", confidence ?? Confidence);
            var (beforeWorst, beforePooled) = PercentCorrect(observer, 1, frames);
            var (afterWorst, afterPooled) = PercentCorrect(observer, tuning.CueStrength, frames);
            rows.Add(new Row(Participant(k), Webers[k], fittedJndKg / standard, tuning.JndKg / standard, tuning.CueStrength, tuning.Reached, beforeWorst, beforePooled, afterWorst, afterPooled));
        }
        return rows;
    }

    /// <summary>The observer's probability of a correct answer on each adjacent pair of Experiment 1's boxes at strength s:
    /// the worse pair's, and the mean over the pairs (each pair equally often), in percent.</summary>
    public static (double Worst, double Pooled) PercentCorrect(SimulatedObserver observer, double s, Simulation.TraceFrame[] frames)
    {
        var boxes = CueStrengthTuning.ExperimentOneBoxes;
        var cues = boxes.Select(m => ReferenceLift.Cue(CueStrengthTuning.Profile, m, WeightSolver.DefaultStandardSpeed, s, frames)).ToArray();
        var p = Enumerable.Range(0, boxes.Length - 1).Select(i => 100 * observer.Probability(Math.Abs(cues[i] - cues[i + 1]))).ToArray();
        return (p.Min(), p.Average());
    }

    public static string Table(List<Row> rows)
    {
        var sb = new StringBuilder($"| observer | Weber at s = 1 | fitted Weber | upper {NumberText.Fixed(100 * Confidence, 1)} % bound | tuned s | before: worse pair | before: both pairs | after: worse pair | after: both pairs |\n|---|---:|---:|---:|---:|---:|---:|---:|---:|\n");
        foreach (var r in rows)
            sb.Append($"| {r.Participant} | {NumberText.Fixed(r.Weber, 2)} | {NumberText.Fixed(r.FittedWeber, 3)} | {NumberText.Fixed(r.BoundWeber, 3)} | {NumberText.Fixed(r.CueStrength, 3)}{(r.Reached ? "" : " (bound)")} | {NumberText.Fixed(r.BeforeWorst, 1)} % | {NumberText.Fixed(r.BeforePooled, 1)} % | {NumberText.Fixed(r.AfterWorst, 1)} % | {NumberText.Fixed(r.AfterPooled, 1)} % |\n");
        return sb.ToString();
    }
}
