using System.Globalization;
using System.Text;
using Kosmos.PseudoHaptic.Cli;
using Kosmos.PseudoHaptic.Evaluation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tools.Tests;

/// <summary>
/// The worked example of evaluation.md ("Weight discrimination"): eight simulated participants, two
/// conditions, built by the package's own plan and simulated observers. The committed inputs under
/// Documentation~/examples/study must be what this code generates (so the document stays true); set
/// PH_WRITE_STUDY_EXAMPLE=1 to write them again.
/// </summary>
public class StudyExampleTests
{
    public static readonly string[] Conditions = { "visual", "pseudo-haptic" };

    /// <summary>trials.csv and responses.csv of the example.</summary>
    public static (string Trials, string Responses) Generate()
    {
        var population = new SeededRandom(2022);
        var trials = new StringBuilder(TrialsCsv.Header).Append('\n');
        var responses = new StringBuilder("participant,condition,questionnaire,item,response\n");
        for (int p = 1; p <= 8; p++)
        {
            string participant = "P" + p;
            double pse = 0.5 + 0.015 * population.NextGaussian();
            for (int c = 0; c < Conditions.Length; c++)
            {
                // The pseudo-haptic condition: weight shown by the lag, so finer discrimination (smaller σ).
                double sigma = (c == 0 ? 0.09 : 0.06) * (0.8 + 0.4 * population.NextDouble());
                var observer = new SimulatedObserver(pse, sigma, 100 * p + c);
                var plan = new ConstantStimuliPlan
                {
                    Standard = 0.5,
                    Levels = new[] { 0.35, 0.4, 0.45, 0.5, 0.55, 0.6, 0.65 },
                    Repetitions = 12,
                    CatchLevels = new[] { 0.25, 1.0 },
                    CatchRepetitions = 2,
                    Seed = 10 * p + c,
                };
                var list = plan.Build(participant, Conditions[c]);
                observer.AnswerAll(list);
                foreach (var t in list) trials.Append(TrialsCsv.FormatRow(t)).Append('\n');
                // Part 1 (weight detection): agreement a little higher with the effect; items 4 and 7 reverse-coded.
                for (int item = 1; item <= 10; item++)
                {
                    double mean = c == 0 ? 3.0 : 3.6;
                    int answer = (int)Math.Round(Math.Clamp(mean + 0.9 * population.NextGaussian(), 1, 5));
                    if (item == 4 || item == 7) answer = 6 - answer;
                    responses.Append($"{participant},{Conditions[c]},weight-detection,{item},{answer}\n");
                }
            }
        }
        return (trials.ToString(), responses.ToString());
    }

    static string Folder => Path.Combine(RepositoryRoot.Path, "Packages", "com.kosmos.pseudohaptic", "Documentation~", "examples", "study");

    [Test]
    public void CommittedExampleInputsAreWhatTheCodeGenerates()
    {
        var (trials, responses) = Generate();
        if (Environment.GetEnvironmentVariable("PH_WRITE_STUDY_EXAMPLE") == "1")
        {
            Directory.CreateDirectory(Folder);
            File.WriteAllText(Path.Combine(Folder, "trials.csv"), trials);
            File.WriteAllText(Path.Combine(Folder, "responses.csv"), responses);
        }
        Assert.That(File.ReadAllText(Path.Combine(Folder, "trials.csv")), Is.EqualTo(trials));
        Assert.That(File.ReadAllText(Path.Combine(Folder, "responses.csv")), Is.EqualTo(responses));
    }
}
