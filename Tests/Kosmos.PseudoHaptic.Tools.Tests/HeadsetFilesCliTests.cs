using System.Globalization;
using System.Text;
using Kosmos.PseudoHaptic.Evaluation;
using Kosmos.PseudoHaptic.Simulation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tools.Tests;

/// <summary>
/// The files the headset writes (issue 6, items 4 and 5), read by the commands that consume them: a hold
/// recorded as SessionRecorder records it, replayed by <c>pseudohaptic replay</c>; a questionnaire session's
/// responses file, scored by <c>pseudohaptic score</c>.
/// </summary>
public class HeadsetFilesCliTests
{
    string _dir = "";

    [SetUp]
    public void SetUp()
    {
        _dir = Path.Combine(Path.GetTempPath(), "ph-headset-" + Guid.NewGuid().ToString("N"));
        Directory.CreateDirectory(_dir);
    }

    [TearDown]
    public void TearDown() => Directory.Delete(_dir, recursive: true);

    static (int code, string stderr) Run(params string[] args)
    {
        var err = new StringWriter();
        var oldErr = Console.Error;
        Console.SetError(err);
        try { return (Cli.Cli.Run(args), err.ToString()); }
        finally { Console.SetError(oldErr); }
    }

    static double D(string s) => double.Parse(s, CultureInfo.InvariantCulture);

    /// <summary>A 2-second lift at 90 Hz with 30 Hz poses and a short tracking loss, recorded frame by frame.</summary>
    static HoldRecording RecordLift(WeightSolver solver)
    {
        var recording = new HoldRecording();
        var begin = new HandSample(0.8, true, true, 0);
        solver.BeginHold(begin.Y, begin.Y, begin.PoseTime);
        recording.Begin(solver, in begin);
        for (int i = 1; i < 180; i++)
        {
            double t = i / 90.0, poseT = Math.Floor(t * 30) / 30, u = Math.Min(1, poseT);
            var sample = i is >= 100 and < 106 ? HandSample.Lost : new HandSample(0.8 + 0.3 * u * u * u * (10 - 15 * u + 6 * u * u), true, true, poseT);
            solver.Step(in sample, 1 / 90.0);
            recording.Step(solver, in sample, 1 / 90.0);
        }
        solver.EndHold();
        return recording;
    }

    [TestCase(NamedProfiles.PaperName, 2.0)]
    [TestCase(NamedProfiles.PaperExperimentName, 0.3)]
    [TestCase(NamedProfiles.GainName, 5.0)]
    public void ARecordedHoldReplaysWithOneRowPerFrameAndTheRecordedHeights(string profile, double massKg)
    {
        var recording = RecordLift(new WeightSolver(WeightModel.FromMass(massKg), NamedProfiles.Get(profile), 0.5));
        string trace = Path.Combine(_dir, "hold-001-box.csv");
        using (var writer = new StreamWriter(trace, false, new UTF8Encoding(false))) recording.WriteCsv(writer);
        string output = Path.Combine(_dir, "replayed.csv");

        var (code, err) = Run("replay", "--trace", trace, "--out", output, "--mass-kg", massKg.ToString(CultureInfo.InvariantCulture),
                              "--profile", profile, "--standard-speed", "0.5");

        Assert.That(code, Is.EqualTo(0), err);
        Assert.That(err.TrimEnd('\n').Split('\n'), Has.Length.EqualTo(1), "the calibration line (issue 31) and nothing else");
        Assert.That(err, Does.StartWith("replay: v_std 0.5 m/s: "));
        var lines = File.ReadAllLines(output);
        Assert.That(lines[0], Does.StartWith("t,hand_y,object_y"));
        Assert.That(lines.Length - 1, Is.EqualTo(recording.Count), "one row per recorded frame");
        for (int i = 0; i < recording.Count; i++)
        {
            string[] f = lines[i + 1].Split(',');
            Assert.That(D(f[0]), Is.EqualTo(recording[i].Time), "t, row " + i);
            Assert.That(D(f[2]), Is.EqualTo(recording[i].ObjectY).Within(1e-9), "object_y, row " + i);
        }
    }

    [Test]
    public void ARecordedHoldIsPlottedByDemo()
    {
        var recording = RecordLift(new WeightSolver(WeightModel.FromMass(1.0)));
        string trace = Path.Combine(_dir, "hold-001-box.csv");
        using (var writer = new StreamWriter(trace, false, new UTF8Encoding(false))) recording.WriteCsv(writer);
        string output = Path.Combine(_dir, "demo");
        var outWriter = new StringWriter();
        var oldOut = Console.Out;
        Console.SetOut(outWriter);
        try
        {
            var (code, err) = Run("demo", "--out", output, "--trace", trace);
            Assert.That(code, Is.EqualTo(0), err);
        }
        finally { Console.SetOut(oldOut); }
        Assert.That(outWriter.ToString(), Does.Contain("recorded-hand"));
        Assert.That(File.ReadAllBytes(Path.Combine(output, "recorded-hand.png")).Take(4), Is.EqualTo(new byte[] { 137, 80, 78, 71 }));
    }

    [Test]
    public void AQuestionnaireSessionsFileIsWhatScoreReads()
    {
        string package = Path.Combine(RepositoryRoot.Path, "Packages", "com.kosmos.pseudohaptic", "Runtime", "Evaluation", "Questionnaires");
        var catalog = QuestionnaireJson.LoadDirectory(package);
        string responses = Path.Combine(_dir, "responses.csv");
        foreach (string participant in new[] { "P1", "P2, left" })
        {
            var session = new QuestionnaireSession(catalog, participant, responses);
            session.Answer(1);
            session.Back(); // change an answer on the way: its row is replaced, not repeated
            while (!session.IsFinished)
            {
                var q = session.CurrentQuestionnaire;
                session.Answer(q.Id == QuestionnaireCatalog.SelfAssessmentId ? 9 : q.ScaleMax);
            }
        }
        string scores = Path.Combine(_dir, "S.csv");

        var (code, err) = Run("score", "--responses", responses, "--out", scores);

        Assert.That(code, Is.EqualTo(0), err);
        Assert.That(File.ReadAllLines(scores), Is.EqualTo(new[]
        {
            "participant,questionnaire,score",
            // every answer the top of the scale: the reversed items count 1 (Part 1: 8 × 5 + 2 × 1; Part 2: 6 × 5 + 4 × 1)
            "P1,weight-detection,4.2",
            "P1,immersion,3.4",
            "P1,self-assessment,9",
            "\"P2, left\",weight-detection,4.2",
            "\"P2, left\",immersion,3.4",
            "\"P2, left\",self-assessment,9",
        }));
    }
}
