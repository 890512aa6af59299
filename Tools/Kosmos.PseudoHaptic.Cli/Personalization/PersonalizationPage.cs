using System.Text;
using Kosmos.PseudoHaptic.Cli.Files;
using Kosmos.PseudoHaptic.Evaluation;

namespace Kosmos.PseudoHaptic.Cli.Personalization;

/// <summary>
/// The generated tables of issue 31: the paper's equations and rules per named profile (from the profiles' effects), the
/// measured dependence on v_std and on the lift's pace (from the solver), the cue strength's effect (from the solver), and
/// tuning on simulated participants (<see cref="TuningEvidence"/>). <c>pseudohaptic personalization --markdown FILE</c>
/// writes them as one page; ALGORITHM.md §12 and evaluation.md §9 hold the same tables between markers, and
/// <c>PersonalizationPageTests</c> fails when either differs from what the code produces.
/// </summary>
public static class PersonalizationPage
{
    public const string PagePath = "Packages/com.kosmos.pseudohaptic/Documentation~/personalization-results.md";
    public const string Command = "pseudohaptic personalization --markdown " + PagePath;

    public static readonly string[] Profiles = { NamedProfiles.PaperName, NamedProfiles.PaperExperimentName, NamedProfiles.GainName, NamedProfiles.XyzName, NamedProfiles.PaperLiteralName };

    /// <summary>The names of the generated blocks, as the documents mark them: <c>&lt;!-- generated: NAME --&gt;</c> … <c>&lt;!-- end generated: NAME --&gt;</c>.</summary>
    public static IReadOnlyList<(string Name, Func<string> Table)> Blocks() => new (string, Func<string>)[]
    {
        ("paper-table", PaperTable), ("speed-table", SpeedTable), ("strength-table", StrengthTable), ("tuning-table", () => TuningEvidence.Table(TuningEvidence.Run())),
    };

    public static string Page()
    {
        var sb = new StringBuilder();
        sb.Append("# The paper per profile, what v_std does, and the cue fitted to each person (generated)\n\n");
        sb.Append("<!-- Generated: do not edit. PersonalizationPageTests fails when this page, or the same tables in ALGORITHM.md §12 and evaluation.md §9, differ from what the code produces. -->\n\n");
        sb.Append("Written by one command, from the repository's root (seeded: the same code writes the same page; a few seconds):\n\n");
        sb.Append("```text\n").Append(Command).Append("\n```\n\n");
        sb.Append("What the tables mean and why is in [ALGORITHM.md §12](ALGORITHM.md#12-the-paper-per-profile-what-v_std-does-and-a-per-person-cue-strength) and [evaluation.md §9](evaluation.md#9-the-cue-fitted-to-each-person-pseudohaptic-tune).\n\n");
        foreach (var (name, table) in Blocks())
            sb.Append("## ").Append(Title(name)).Append("\n\n").Append(Block(name, table())).Append('\n');
        return sb.ToString();
    }

    static string Title(string block) => block switch
    {
        "paper-table" => "The paper's equations and rules, per named profile",
        "speed-table" => "How far v_std and the lift's pace move a 2 kg object",
        "strength-table" => "What the cue strength does",
        _ => "Tuning on simulated participants",
    };

    /// <summary>A table wrapped in its markers, as it appears in the page and the documents.</summary>
    public static string Block(string name, string table) => $"{GeneratedBlock.StartMarker(name)}-->\n{table}{GeneratedBlock.EndMarker(name)}\n";

    // ---- the paper table -------------------------------------------------------------------------------------------

    sealed record Rule(string What, Func<WeightProfile, string> Cell, string Why);

    static bool Literal(WeightProfile p) => NamedProfiles.IsPaperLiteral(p);

    static readonly Rule[] Rules =
    {
        new("Eq. 1, W = m·g", _ => "as printed", "the weight of the mass (m = density × volume or given)"),
        new("Eq. 2, W_std = 0.045 kg · g", _ => "as printed", "the golf ball is the standard weight; G(m_std) = 1 in every profile"),
        new("Eq. 3, F_std = W_std · v_std", _ => "not computed", "in any reading linear in the hand's speed v_std cancels (§4)"),
        new("Eq. 4, v_virtual = v_hand · W_std / W", p => !p.Has<WeightGain>() ? "not used"
            : Literal(p) ? $"relative reading, per frame on the 1 s mean speed, capped at {p.Limits.MaxGain:0.##}" : $"relative reading: a gain on the lift, capped at {p.Limits.MaxGain:0.##}",
            "the printed × lost a fraction bar; as a gain the object follows the hand's motion, not an absolute speed (§1)"),
        new("Eq. 5, v_exp = 1.6793 e^(−0.24·W)", p => p.Has<ExperimentalBlend>() ? "changed: e^(−0.24·m), m in kg, relative to the golf ball's" : "not used",
            "with a + sign or W in newtons the fitted speeds are implausible; relative, a still hand leaves the object still (§1)"),
        new("Eq. 6, v_final = (v_virtual + v_exp) / 2", p => p.Has<WeightGain>() && p.Has<ExperimentalBlend>() ? "relative reading: G = ½(W_std/W + v_exp(m)/v_exp(m_std))" : "not used (Eq. 4 alone)",
            "an average of two gains, so the final speed stays a gain on the hand (§1)"),
        new("v_std, the user's standard speed", StandardSpeedUse,
            "the paper customizes through v_std, but it cancels in Eq. 3–6; the package lets it act where the model is not linear (§4), measured below"),
        new("§3.1, the correction past 0.2 m", p => p.Has<OffsetCorrection>() ? "changed: a smooth ceiling, threshold 0.2 m at 1 kg and 2 cm more per doubling, never past 0.28 m" : "not applied",
            "read literally the +0.02/−0.02 makes the offset grow; the ceiling stops it smoothly and keeps the masses in order (§6); the experiments ran without it"),
        new("§3.1, unit time 1 s", p => Literal(p) ? "as printed: the average speed over the last 1 s (the object at rest before the grab), so the object moves G times the change of the hand's 1 s mean height" : "changed: speeds per second; every pose followed as it comes",
            "a 1 s mean lags half a second (accuracy-results.md measures it); read as the unit of speed (§5)"),
        new("§3.1, y ≥ 0", p => !p.Has<FloorClamp>() ? "not applied" : Literal(p) ? "as printed: the object's height ≥ 0" : "as printed: the object's bottom ≥ the floor (0)",
            "the object never goes through the floor (P5)"),
        new("added by the package", Added, "what a headset needs to feed the equations (30 Hz poses, jitter, losses) and the paper's next step (§9 of the paper: xyz, height)"),
        new("cue strength s (issue 31)", p => Literal(p) ? "added: v_final = v_real · G^s" : "added: G^s, capped", "per person, from their own threshold (§12); s = 1 is the gain above bit for bit"),
    };

    static string StandardSpeedUse(WeightProfile p)
    {
        var uses = new List<string>();
        if (p.Has<FasterMovesFurther>()) uses.Add("the lift's pace relative to it shapes a heavy gain (faster moves further)");
        if (p.Has<SpeedCap>()) uses.Add("the strain (speed cap)");
        if (p.Has<MotionDeadband>()) uses.Add("the deadband's width above G = 1");
        if (p.Has<OffsetRelaxation>()) uses.Add("what counts as still");
        return uses.Count == 0 ? "not used (cancels)" : "added: " + string.Join("; ", uses);
    }

    static readonly HashSet<string> PaperEffects = new() { new WeightGain().Name, new ExperimentalBlend().Name, new OffsetCorrection().Name, new FloorClamp().Name, new FasterMovesFurther().Name };

    static string Added(WeightProfile p)
    {
        if (Literal(p)) return "the gain cap (P3)";
        var names = p.Effects.Select(e => e.Name).Where(n => !PaperEffects.Contains(n)).ToList();
        names.Add("the pose estimator and limits");
        return string.Join(", ", names);
    }

    public static string PaperTable()
    {
        var profiles = Profiles.Select(NamedProfiles.Get).ToList();
        var sb = new StringBuilder("| paper | ");
        sb.Append(string.Join(" | ", profiles.Select(p => $"`{p.Name}`"))).Append(" | why |\n|---|");
        foreach (var _ in profiles) sb.Append("---|");
        sb.Append("---|\n");
        foreach (var rule in Rules)
            sb.Append("| ").Append(rule.What).Append(" | ").Append(string.Join(" | ", profiles.Select(rule.Cell))).Append(" | ").Append(rule.Why).Append(" |\n");
        return sb.ToString();
    }

    // ---- the v_std and pace table -----------------------------------------------------------------------------------

    public static readonly double[] StandardSpeeds = { 0.25, 0.5, 1.0 };
    public static readonly double[] LiftSeconds = { 1.0, 0.6, 0.3, 1.0 / 6 };
    public const double TableMassKg = 2.0;

    static string Mm(double metres) => NumberText.Fixed(metres * 1000, 1);

    public static string SpeedTable()
    {
        var sb = new StringBuilder("| profile | ");
        sb.Append(string.Join(" | ", StandardSpeeds.Select(v => $"v_std {NumberText.Format(v)}"))).Append(" | spread | ");
        sb.Append(string.Join(" | ", LiftSeconds.Select(s => $"pace {NumberText.Fixed(ReferenceLift.Rise / s, 2)} m/s"))).Append(" | spread |\n|---|");
        sb.Append(string.Concat(Enumerable.Repeat("---:|", StandardSpeeds.Length + LiftSeconds.Length + 2))).Append('\n');
        foreach (var name in Profiles)
        {
            var profile = NamedProfiles.Get(name);
            var byUser = StandardSpeeds.Select(v => ReferenceLift.EndLag(profile, TableMassKg, v)).ToList();
            var byPace = LiftSeconds.Select(s => ReferenceLift.EndLag(profile, TableMassKg, WeightSolver.DefaultStandardSpeed, 1, s)).ToList();
            sb.Append($"| `{name}` | ").Append(string.Join(" | ", byUser.Select(Mm))).Append(" | ").Append(Mm(byUser.Max() - byUser.Min())).Append(" | ");
            sb.Append(string.Join(" | ", byPace.Select(Mm))).Append(" | ").Append(Mm(byPace.Max() - byPace.Min())).Append(" |\n");
        }
        return sb.ToString();
    }

    // ---- the cue strength table -------------------------------------------------------------------------------------

    public static readonly double[] Strengths = { 1.0 / 3, 0.5, 1, 2, 3 };

    public static string StrengthTable()
    {
        var profile = CueStrengthTuning.Profile;
        var frames = ReferenceLift.Frames();
        var masses = new[] { 0.1 }.Concat(CueStrengthTuning.ExperimentOneBoxes).ToArray();
        var sb = new StringBuilder("| s | ");
        // The heaviest adjacent pair of the boxes (C and B): the pair whose lags come closest as s grows.
        double lighter = masses[masses.Length - 2], heavier = masses[masses.Length - 1];
        string pair = $"{NumberText.Format(lighter)} vs {NumberText.Format(heavier)} kg";
        sb.Append(string.Join(" | ", masses.Select(m => $"{NumberText.Format(m)} kg: lag mm (rise ratio)"))).Append($" | {pair}: lag difference mm | {pair}: cue difference |\n|---:|");
        sb.Append(string.Concat(Enumerable.Repeat("---:|", masses.Length + 2))).Append('\n');
        foreach (double s in Strengths)
        {
            var lags = masses.Select(m => ReferenceLift.EndLag(profile, m, WeightSolver.DefaultStandardSpeed, s, frames)).ToArray();
            double c1 = ReferenceLift.Cue(profile, lighter, WeightSolver.DefaultStandardSpeed, s, frames), c2 = ReferenceLift.Cue(profile, heavier, WeightSolver.DefaultStandardSpeed, s, frames);
            sb.Append($"| {NumberText.Fixed(s, 3)} | ");
            sb.Append(string.Join(" | ", lags.Select(l => $"{Mm(l)} ({NumberText.Fixed((ReferenceLift.Rise - l) / ReferenceLift.Rise, 3)})")));
            sb.Append($" | {Mm(lags[masses.Length - 1] - lags[masses.Length - 2])} | {NumberText.Fixed(c1 - c2, 3)} |\n");
        }
        return sb.ToString();
    }
}
