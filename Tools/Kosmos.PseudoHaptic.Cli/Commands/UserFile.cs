using System.Globalization;
using System.Text;
using System.Text.Json;
using Kosmos.PseudoHaptic.Cli.Files;

namespace Kosmos.PseudoHaptic.Cli.Commands;

/// <summary>
/// USER.json, what <c>tune</c> writes and <c>replay --user</c> / <c>demo --user</c> read (issue 31): one JSON object with
/// at least <c>participant</c> (text), <c>cueStrength</c> (a number in [1/3, 3]) and <c>weber</c>; the readers need only
/// <c>cueStrength</c>. A file that is not JSON, not an object, or whose cueStrength is missing, not a number, not
/// positive or outside the bounds is refused: one line naming the file and the field, exit 2.
/// </summary>
public static class UserFile
{
    public const int FormatVersion = 1;

    /// <summary>The cue strength of USER.json given as <paramref name="option"/>.</summary>
    public static double ReadCueStrength(string option, string path)
    {
        string text = InputFile.ReadSmallText(option, path);
        string name = Messages.OneLine(path);
        JsonDocument doc;
        try { doc = JsonDocument.Parse(text); }
        catch (JsonException e) { throw new CliException($"{option} {name}: not JSON ({e.Message.Split('.')[0]}); expected an object with a field cueStrength"); }
        using (doc)
        {
            if (doc.RootElement.ValueKind != JsonValueKind.Object)
                throw new CliException($"{option} {name}: field cueStrength: the file holds a JSON {doc.RootElement.ValueKind.ToString().ToLowerInvariant()}, not an object");
            if (!doc.RootElement.TryGetProperty("cueStrength", out var value))
                throw new CliException($"{option} {name}: field cueStrength is missing");
            if (value.ValueKind != JsonValueKind.Number || !value.TryGetDouble(out double s))
                throw new CliException($"{option} {name}: field cueStrength: {value.GetRawText()} is not a number");
            if (!(s > 0) || !double.IsFinite(s))
                throw new CliException($"{option} {name}: field cueStrength: must be a positive number, got {NumberText.Format(s)}");
            if (s < WeightSolver.MinCueStrength || s > WeightSolver.MaxCueStrength)
                throw new CliException($"{option} {name}: field cueStrength: must lie in [{NumberText.Format(WeightSolver.MinCueStrength)}, {NumberText.Format(WeightSolver.MaxCueStrength)}], got {NumberText.Format(s)}");
            return s;
        }
    }

    /// <summary>The file tune writes.</summary>
    public static string Format(string participant, string condition, double standardKg, double jndKg, double weber, CueStrengthTuning t, int trials, double fittedCue, double confidence)
    {
        using var stream = new MemoryStream();
        using (var w = new Utf8JsonWriter(stream, new JsonWriterOptions { Indented = true, Encoder = System.Text.Encodings.Web.JavaScriptEncoder.UnsafeRelaxedJsonEscaping }))
        {
            w.WriteStartObject();
            w.WriteNumber("version", FormatVersion);
            w.WriteString("participant", participant);
            w.WriteString("condition", condition);
            w.WriteNumber("cueStrength", t.CueStrength);
            w.WriteBoolean("reached", t.Reached);
            w.WriteNumber("weber", weber);
            w.WriteNumber("standardKg", standardKg);
            w.WriteNumber("jndKg", jndKg);
            w.WriteNumber("confidence", confidence);
            w.WriteNumber("jndKgUpper", t.JndKg);
            w.WriteNumber("trials", trials);
            w.WriteStartArray("masses");
            foreach (double m in t.Masses) w.WriteNumberValue(m);
            w.WriteEndArray();
            w.WriteString("model", "rise ratio: the answers are fitted on c = ln(object rise / hand rise) on the reference lift (0.2 m in 0.6 s, paper-experiment, v_std 0.5 m/s, s = 1); s is the smallest strength at which adjacent masses differ in c by the JND's upper confidence bound; ALGORITHM.md section 12");
            w.WriteNumber("fittedCue", fittedCue);
            w.WriteNumber("thresholdCue", t.ThresholdCue);
            w.WriteNumber("adjacentCue", t.AdjacentCue);
            w.WriteEndObject();
        }
        return Encoding.UTF8.GetString(stream.ToArray()) + "\n";
    }

    /// <summary>Parses --masses: comma-separated kg, at least two, each finite and &gt; 0.</summary>
    public static double[] Masses(string? text)
    {
        if (text == null) return (double[])CueStrengthTuning.ExperimentOneBoxes.Clone();
        var parts = text.Split(',');
        var masses = new double[parts.Length];
        for (int i = 0; i < parts.Length; i++)
        {
            if (!double.TryParse(parts[i].Trim(), NumberStyles.Float, CultureInfo.InvariantCulture, out masses[i]) || !(masses[i] > 0) || !double.IsFinite(masses[i]))
                throw new CliException($"option --masses: '{Messages.OneLine(parts[i])}' is not a finite mass greater than 0 (kg, comma-separated)");
        }
        if (masses.Distinct().Count() < 2) throw new CliException($"option --masses: needs at least two different masses, got '{Messages.OneLine(text)}'");
        return masses;
    }
}
