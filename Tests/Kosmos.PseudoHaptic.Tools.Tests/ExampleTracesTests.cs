using System.Globalization;
using System.Text;
using Kosmos.PseudoHaptic.Simulation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tools.Tests;

/// <summary>
/// The traces the README's and the help's examples replay (Documentation~/examples): a lift as a Quest 2 delivers it,
/// and the same kind of lift while the player walks and snap-turns (the rig's columns, issue 26). The committed files
/// must be what this code generates; set PH_WRITE_EXAMPLES=1 to write them again.
/// </summary>
public class ExampleTracesTests
{
    static string F(double v) => v.ToString("R", CultureInfo.InvariantCulture);

    /// <summary>lift.csv: 0.35 m up, held, and back down; 90 Hz frames, 30 Hz poses 45 ms late, 1 mm jitter, 4.5 s.</summary>
    public static string Lift()
    {
        var path = HandPath.StartAt(0.80).Hold(0.5).MoveTo(1.15, 0.9).Hold(1.2).MoveTo(0.80, 0.9).Hold(1.0);
        var frames = new HeadsetSimulator { FrameRate = 90, PoseRate = 30, Latency = 0.045, JitterSd = 0.001, Seed = 25 }.Render(path);
        var sb = new StringBuilder("t,hand_y,tracked,pose_t\n");
        foreach (var f in frames) sb.Append(F(Math.Round(f.Time, 6))).Append(',').Append(F(Math.Round(f.HandY, 6))).Append(',').Append(f.Tracked ? '1' : '0').Append(',').Append(F(Math.Round(f.PoseTime, 6))).Append('\n');
        return sb.ToString();
    }

    /// <summary>walk-and-turn.csv: a lift with a sideways carry in the rig's frame, while the rig walks forward at
    /// 1.5 m/s and snap-turns 45° twice about the head; hands and rig in world coordinates.</summary>
    public static string WalkAndTurn()
    {
        var sb = new StringBuilder("t,pose_t,hand_x,hand_y,hand_z,tracked,rig_x,rig_y,rig_z,rig_yaw\n");
        var rng = new Random(26);
        double yaw = 0, rx = 0, rz = 0;
        for (int i = 0; i <= 360; i++)
        {
            double t = i / 90.0, pt = Math.Floor(t * 30) / 30;
            static double Smooth(double s) => s * s * s * (10 + s * (-15 + 6 * s));
            double y = 0.9 + 0.3 * Smooth(Math.Clamp((pt - 0.5) / 0.8, 0, 1));
            double x = -0.1 + 0.3 * Smooth(Math.Clamp((pt - 1.6) / 0.8, 0, 1));
            double z = 0.35;
            // Snap turns of 45° at 2.0 s and 3.0 s about the head at the rig's (0, 0); walking forward (the rig's +z) before them.
            double newYaw = t >= 3.0 ? 90 : t >= 2.0 ? 45 : 0;
            yaw = newYaw;
            if (t < 2.0 && i > 0)
            {
                double step = 1.5 / 90, r = yaw * Math.PI / 180;
                rx += step * Math.Sin(r);
                rz += step * Math.Cos(r);
            }
            double c = Math.Cos(yaw * Math.PI / 180), s = Math.Sin(yaw * Math.PI / 180);
            double j() => 0.001 * (rng.NextDouble() - 0.5);
            double wx = rx + x * c + z * s + j(), wy = y + j(), wz = rz - x * s + z * c + j();
            sb.Append(F(Math.Round(t, 6))).Append(',').Append(F(Math.Round(pt, 6))).Append(',')
              .Append(F(Math.Round(wx, 6))).Append(',').Append(F(Math.Round(wy, 6))).Append(',').Append(F(Math.Round(wz, 6))).Append(",1,")
              .Append(F(Math.Round(rx, 6))).Append(",0,").Append(F(Math.Round(rz, 6))).Append(',').Append(F(yaw)).Append('\n');
        }
        return sb.ToString();
    }

    /// <summary>responses.csv: the worked study's answers in its pseudo-haptic condition, without the condition
    /// column (what score and report take for one condition).</summary>
    public static string Responses()
    {
        var lines = StudyExampleTests.Generate().Responses.Split('\n', StringSplitOptions.RemoveEmptyEntries);
        var sb = new StringBuilder("participant,questionnaire,item,response\n");
        foreach (var line in lines.Skip(1))
        {
            var f = line.Split(',');
            if (f[1] == "pseudo-haptic") sb.Append(f[0]).Append(',').Append(f[2]).Append(',').Append(f[3]).Append(',').Append(f[4]).Append('\n');
        }
        return sb.ToString();
    }

    static string Folder => Path.Combine(RepositoryRoot.Path, "Packages", "com.kosmos.pseudohaptic", "Documentation~", "examples");

    [TestCase("lift.csv")]
    [TestCase("walk-and-turn.csv")]
    [TestCase("responses.csv")]
    public void CommittedExampleInputsAreWhatTheCodeGenerates(string name)
    {
        string text = name switch { "lift.csv" => Lift(), "walk-and-turn.csv" => WalkAndTurn(), _ => Responses() };
        if (Environment.GetEnvironmentVariable("PH_WRITE_EXAMPLES") == "1") File.WriteAllText(Path.Combine(Folder, name), text);
        Assert.That(File.ReadAllText(Path.Combine(Folder, name)), Is.EqualTo(text));
    }

    [Test]
    public void CommittedExampleScoresAreWhatScoreWrites()
    {
        string scores = Path.Combine(Path.GetTempPath(), "ph-example-scores-" + Guid.NewGuid().ToString("N") + ".csv");
        try
        {
            var err = new StringWriter();
            var (o, e) = (Console.Out, Console.Error);
            Console.SetOut(TextWriter.Null);
            Console.SetError(err);
            int code;
            try { code = Cli.Cli.Run(new[] { "score", "--responses", Path.Combine(Folder, "responses.csv"), "--out", scores }); }
            finally { Console.SetOut(o); Console.SetError(e); }
            Assert.That(code, Is.EqualTo(0), err.ToString());
            if (Environment.GetEnvironmentVariable("PH_WRITE_EXAMPLES") == "1") File.Copy(scores, Path.Combine(Folder, "scores.csv"), overwrite: true);
            Assert.That(File.ReadAllText(Path.Combine(Folder, "scores.csv")), Is.EqualTo(File.ReadAllText(scores)));
        }
        finally { File.Delete(scores); }
    }
}
