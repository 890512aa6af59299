using System.Globalization;
using System.Text;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tools.Tests;

/// <summary>The replay contract's issue 10 extension: hand_x/hand_z, a second hand, hands, held, --profile xyz,
/// --break-away; and today's columns unchanged by the new ones.</summary>
public class ReplayThreeDimensionCliTests : CliTestFolder
{
    public ReplayThreeDimensionCliTests() : base("ph-replay3d-") { }

    string In(string text, string name = "in.csv") => Write(name, text);

    string Out => Path.Combine(_dir, "out.csv");

    static (int code, string stderr) Replay(params string[] args)
    {
        var (code, stderr, _) = Capture(() => Cli.Cli.Run(args.Prepend("replay").ToArray()));
        return (code, stderr);
    }

    string[] Run(string trace, params string[] options)
    {
        var (code, err) = Replay(new[] { "--trace", In(trace), "--out", Out }.Concat(options).ToArray());
        Assert.That(code, Is.EqualTo(0), err);
        return File.ReadAllLines(Out);
    }

    static List<Dictionary<string, string>> Rows(string[] lines)
    {
        var header = lines[0].Split(',');
        return lines.Skip(1).Select(l => header.Zip(l.Split(',')).ToDictionary(p => p.First, p => p.Second)).ToList();
    }

    static double D(string s) => double.Parse(s, CultureInfo.InvariantCulture);

    static string F(double v) => v.ToString("R", CultureInfo.InvariantCulture);

    /// <summary>A two-hand lift with a sideways carry: 90 Hz frames, 30 Hz poses, with jitter, one hand lost for a while.</summary>
    static List<(double t, double pt, double x1, double y1, double z1, double x2, double y2, double z2, bool tracked1, bool tracked2)> Motion(int seed = 1, double lose2From = 1.2, double lose2For = 0.3)
    {
        var rng = new Random(seed);
        var rows = new List<(double, double, double, double, double, double, double, double, bool, bool)>();
        for (int i = 0; i <= 270; i++)
        {
            double t = i / 90.0, pt = Math.Floor(t * 30) / 30;
            double s = Math.Clamp((pt - 0.3) / 1.0, 0, 1), lift = s * s * s * (10 + s * (-15 + 6 * s));
            double c = Math.Clamp((pt - 1.0) / 0.8, 0, 1), carry = c * c * c * (10 + c * (-15 + 6 * c));
            double j() => 0.002 * (rng.NextDouble() - 0.5);
            rows.Add((t, pt, -0.15 + 0.4 * carry + j(), 0.9 + 0.35 * lift + j(), 0.3 + j(), 0.15 + 0.4 * carry + j(), 0.9 + 0.35 * lift + j(), 0.3 + j(),
                true, !(t >= lose2From && t < lose2From + lose2For)));
        }
        return rows;
    }

    static string Trace(int seed, bool xz, bool second, bool secondXz = true, bool shuffle = false)
    {
        var cols = new List<string> { "t", "hand_y", "tracked", "pose_t" };
        if (xz) cols.AddRange(new[] { "hand_x", "hand_z" });
        if (second) { cols.AddRange(new[] { "hand2_y", "tracked2", "pose2_t" }); if (xz && secondXz) cols.AddRange(new[] { "hand2_x", "hand2_z" }); }
        if (shuffle) cols.Reverse();
        var sb = new StringBuilder(string.Join(",", cols) + "\n");
        foreach (var r in Motion(seed))
        {
            var v = new Dictionary<string, string>
            {
                ["t"] = F(r.t), ["hand_y"] = F(r.y1), ["tracked"] = "1", ["pose_t"] = F(r.pt), ["hand_x"] = F(r.x1), ["hand_z"] = F(r.z1),
                ["hand2_y"] = r.tracked2 ? F(r.y2) : "NaN", ["tracked2"] = r.tracked2 ? "1" : "0", ["pose2_t"] = F(r.pt),
                ["hand2_x"] = F(r.x2), ["hand2_z"] = F(r.z2),
            };
            sb.Append(string.Join(",", cols.Select(c => v[c]))).Append('\n');
        }
        return sb.ToString();
    }

    static string[] Column(string[] lines, string name)
    {
        int k = Array.IndexOf(lines[0].Split(','), name);
        Assert.That(k, Is.GreaterThanOrEqualTo(0), "column " + name);
        return lines.Skip(1).Select(l => l.Split(',')[k]).ToArray();
    }

    [Test]
    public void ExistingProfilesYIsByteIdenticalWithAndWithoutTheNewColumns([Values("paper", "paper-experiment", "gain")] string profile, [Values(0.045, 0.4, 3.0)] double mass)
    {
        string m = F(mass);
        var plain = Run(Trace(3, false, false), "--mass-kg", m, "--profile", profile);
        // paper-experiment holds a second hand (two hands share the weight, as in the paper's Experiment 2): only x/z are
        // new columns that must change nothing there.
        bool twoHands = profile == "paper-experiment";
        foreach (var (xz, second) in new[] { (true, false), (false, true), (true, true) })
        {
            if (twoHands && second) continue;
            var extended = Run(Trace(3, xz, second, shuffle: true), "--mass-kg", m, "--profile", profile);
            foreach (var c in new[] { "t", "hand_y", "object_y", "offset" })
                Assert.That(Column(extended, c), Is.EqualTo(Column(plain, c)), $"{c} with x/z {xz}, second hand {second}");
            Assert.That(extended[0], Does.StartWith("t,hand_y,object_y,offset"));
        }
        // --break-away far beyond reach changes nothing but adds held.
        var far = Run(Trace(3, true, !twoHands), "--mass-kg", m, "--profile", profile, "--break-away", "5");
        Assert.That(Column(far, "object_y"), Is.EqualTo(Column(plain, "object_y")));
        Assert.That(Column(far, "held"), Has.All.EqualTo("1"));
    }

    [Test]
    public void GrabOffsetShiftsYExactlyAndLeavesXAndZWithTheNewColumns([Values("paper", "xyz")] string profile)
    {
        var plain = Run(Trace(4, true, true), "--mass-kg", "2", "--profile", profile, "--break-away", "0.5");
        var shifted = Run(Trace(4, true, true), "--mass-kg", "2", "--profile", profile, "--break-away", "0.5", "--grab-offset", "0.12");
        Assert.That(shifted[0], Is.EqualTo(plain[0]));
        Assert.That(Column(shifted, "object_x"), Is.EqualTo(Column(plain, "object_x")));
        Assert.That(Column(shifted, "object_z"), Is.EqualTo(Column(plain, "object_z")));
        Assert.That(Column(shifted, "held"), Is.EqualTo(Column(plain, "held")), "break-away measures from where it was grabbed");
        var a = Column(plain, "object_y").Select(D).ToArray();
        var b = Column(shifted, "object_y").Select(D).ToArray();
        for (int i = 0; i < a.Length; i++) Assert.That(b[i], Is.EqualTo(a[i] - 0.12).Within(1e-12), $"row {i + 2}");
    }

    [Test]
    public void ATraceWithNoUsablePoseIsNeverHeld()
    {
        // held is 1 while held: rows before the first usable pose belong to the hold that follows, but with no usable
        // pose at all no hold begins, so every row is 0 (it was 1 on every row).
        var lines = Run("t,hand_y,tracked\n0,0.9,0\n0.1,NaN,1\n0.2,0.9,0\n", "--mass-kg", "1", "--break-away", "0.3");
        Assert.That(lines[0], Is.EqualTo("t,hand_y,object_y,offset,held"));
        Assert.That(Column(lines, "held"), Is.EqualTo(new[] { "0", "0", "0" }));
        var before = Run("t,hand_y,tracked\n0,0.9,0\n0.1,0.95,1\n0.2,0.96,1\n", "--mass-kg", "1", "--break-away", "0.3");
        Assert.That(Column(before, "held"), Is.EqualTo(new[] { "1", "1", "1" }), "an untracked row before the first usable pose is part of the hold");
    }

    [Test]
    public void ColumnsComeInTheContractsOrder()
    {
        Assert.That(Run(Trace(1, true, false), "--mass-kg", "1")[0], Is.EqualTo("t,hand_y,object_y,offset,hand_x,hand_z,object_x,object_z"));
        Assert.That(Run(Trace(1, false, true), "--mass-kg", "1")[0], Is.EqualTo("t,hand_y,object_y,offset,hands"));
        Assert.That(Run(Trace(1, true, true), "--mass-kg", "1", "--profile", "xyz")[0], Is.EqualTo("t,hand_y,object_y,offset,hand_x,hand_z,object_x,object_z,hands"));
        Assert.That(Run(Trace(1, true, true), "--mass-kg", "1", "--break-away", "0.3")[0], Is.EqualTo("t,hand_y,object_y,offset,hand_x,hand_z,object_x,object_z,hands,held"));
        Assert.That(Run(Trace(1, false, false), "--mass-kg", "1", "--break-away", "0.3")[0], Is.EqualTo("t,hand_y,object_y,offset,held"));
    }

    [Test]
    public void HandsCountsUsableHandsAndTheOffsetIsTheFirstHands()
    {
        string trace = "t,hand_y,hand_x,hand_z,hand2_y,hand2_x,hand2_z,tracked2,tracked\n" +
                       "0,1,0,0,1,0.3,0,1,1\n" +      // both
                       "0.01,1,nan,0,1,0.3,0,1,1\n" + // first has a garbage x: not usable
                       "0.02,1,0,0,1,0.3,inf,1,1\n" + // second has a garbage z
                       "0.03,1,0,0,1,0.3,0,0,1\n" +   // second untracked
                       "0.04,1,0,0,,0.3,0,1,0\n" +    // first untracked, second has no y
                       "0.05,1,0,0,1,0.3,1e6,1,1\n";  // second beyond ±10^5 m
        var rows = Rows(Run(trace, "--mass-kg", "1", "--profile", "xyz"));
        Assert.That(rows.Select(r => r["hands"]), Is.EqualTo(new[] { "2", "1", "1", "1", "0", "1" }));
        Assert.That(rows[1]["offset"], Is.EqualTo("NaN"), "the first hand is not usable in that row");
        Assert.That(rows[0]["object_x"], Is.EqualTo("0.15"), "starts at the midpoint of both");
        foreach (var r in rows)
            foreach (var c in new[] { "object_x", "object_y", "object_z" })
                Assert.That(double.IsFinite(D(r[c])), Is.True, c);
    }

    [Test]
    public void TheObjectStartsAtTheFirstUsableHandInEveryAxisAndEarlierRowsShowIt()
    {
        string trace = "t,hand_y,hand_x,hand_z,tracked\n" +
                       "0,nan,5,5,1\n" +
                       "0.01,1.2,0.4,nan,1\n" +
                       "0.02,1.1,0.3,-0.2,1\n" +
                       "0.03,1.1,0.3,-0.2,1\n";
        var rows = Rows(Run(trace, "--mass-kg", "2", "--profile", "xyz"));
        foreach (var r in rows)
        {
            Assert.That(D(r["object_x"]), Is.EqualTo(0.3));
            Assert.That(D(r["object_y"]), Is.EqualTo(1.1));
            Assert.That(D(r["object_z"]), Is.EqualTo(-0.2));
        }
        Assert.That(rows[0]["offset"], Is.EqualTo("NaN"));
        Assert.That(rows[2]["offset"], Is.EqualTo("0"));

        // With two hands and only the second usable first, the object starts at the second hand (xyz) ...
        string two = "t,hand_y,hand2_y\n0,nan,1.4\n0.01,1.0,1.4\n";
        var xyz = Rows(Run(two, "--mass-kg", "1", "--profile", "xyz"));
        Assert.That(D(xyz[0]["object_y"]), Is.EqualTo(1.4));
        // ... but a profile without the two-hand effect waits for the first hand.
        var paper = Rows(Run(two, "--mass-kg", "1", "--profile", "paper"));
        Assert.That(D(paper[0]["object_y"]), Is.EqualTo(1.0));
        Assert.That(paper.Select(r => r["hands"]), Is.EqualTo(new[] { "1", "2" }), "hands is written in every profile");
    }

    [Test]
    public void ATwoHandLiftOfMReplaysAsAOneHandLiftOfHalfMAtTheMidpoint([Values(0.3, 2, 6)] double mass)
    {
        var motion = Motion(5, lose2From: 99);
        var both = new StringBuilder("t,pose_t,hand_x,hand_y,hand_z,hand2_x,hand2_y,hand2_z,pose2_t\n");
        var mid = new StringBuilder("t,pose_t,hand_x,hand_y,hand_z\n");
        foreach (var r in motion)
        {
            both.Append(CultureInfo.InvariantCulture, $"{F(r.t)},{F(r.pt)},{F(r.x1)},{F(r.y1)},{F(r.z1)},{F(r.x2)},{F(r.y2)},{F(r.z2)},{F(r.pt)}\n");
            mid.Append(CultureInfo.InvariantCulture, $"{F(r.t)},{F(r.pt)},{F(0.5 * (r.x1 + r.x2))},{F(0.5 * (r.y1 + r.y2))},{F(0.5 * (r.z1 + r.z2))}\n");
        }
        var two = Run(both.ToString(), "--mass-kg", F(mass), "--profile", "xyz");
        var one = Run(mid.ToString(), "--mass-kg", F(mass / 2), "--profile", "xyz");
        foreach (var c in new[] { "object_x", "object_y", "object_z" })
            Assert.That(Column(two, c), Is.EqualTo(Column(one, c)), c);
        // and it lags: heavier trails the sideways carry and ends below the hands after the lift
        var rows = Rows(two);
        Assert.That(rows.Max(r => 0.5 * (D(r["hand_x"]) + 0.3) - D(r["object_x"])) , Is.GreaterThan(0.005));
    }

    [Test]
    public void ASecondHandLostAndBackMovesNothingWhileTheHandsRest()
    {
        var sb = new StringBuilder("t,hand_x,hand_y,hand_z,hand2_x,hand2_y,hand2_z,tracked2\n");
        for (int i = 0; i < 300; i++)
        {
            bool lost = i >= 100 && i < 160;
            sb.Append(CultureInfo.InvariantCulture, $"{F(i / 90.0)},-0.2,1.0,0.3,{(lost ? "nan" : "0.2")},{(lost ? "nan" : "1.1")},0.4,{(lost ? 0 : 1)}\n");
        }
        var rows = Rows(Run(sb.ToString(), "--mass-kg", "2", "--profile", "xyz"));
        foreach (var c in new[] { "object_x", "object_y", "object_z" })
            Assert.That(rows.Select(r => r[c]).Distinct().Count(), Is.EqualTo(1), c + " never moves");
        Assert.That(rows.Select(r => r["hands"]).Distinct(), Is.EquivalentTo(new[] { "2", "1" }));
    }

    [Test]
    public void BreakAwayEndsTheHoldAndTheObjectStaysWhereItWasLetGo()
    {
        // A fast 0.8 m lift of 10 kg: the object lags up to 0.22 m below the hand, past a 0.15 m break-away.
        var sb = new StringBuilder("t,hand_y,pose_t\n");
        for (int i = 0; i <= 180; i++)
        {
            double t = i / 90.0, pt = Math.Floor(t * 30) / 30, s = Math.Clamp((pt - 0.3) / 0.8, 0, 1);
            sb.Append(CultureInfo.InvariantCulture, $"{F(t)},{F(0.9 + 0.8 * s * s * s * (10 + s * (-15 + 6 * s)))},{F(pt)}\n");
        }
        var rows = Rows(Run(sb.ToString(), "--mass-kg", "10", "--break-away", "0.15"));
        int ended = rows.FindIndex(r => r["held"] == "0");
        Assert.That(ended, Is.GreaterThan(0));
        Assert.That(rows.Skip(ended).All(r => r["held"] == "0"), Is.True, "the hold does not restart");
        Assert.That(rows.Skip(ended).Select(r => r["object_y"]).Distinct().Count(), Is.EqualTo(1), "the object stays where it was let go");
        Assert.That(D(rows[ended]["offset"]), Is.GreaterThan(0.15));
        var without = Rows(Run(sb.ToString(), "--mass-kg", "10"));
        Assert.That(rows.Take(ended).Select(r => r["object_y"]), Is.EqualTo(without.Take(ended).Select(r => r["object_y"])), "identical until it breaks");
    }

    [TestCase("t,hand_y,hand_x\n0,1,0\n", 1, "hand_z")]
    [TestCase("t,hand_y,hand_z\n0,1,0\n", 1, "hand_x")]
    [TestCase("t,hand_y,hand2_x,hand2_z,hand2_y\n0,1,0,0,1\n", 1, "hand_x")]
    [TestCase("t,hand_y,tracked2\n0,1,1\n", 1, "hand2_y")]
    [TestCase("t,hand_y,pose2_t\n0,1,1\n", 1, "hand2_y")]
    [TestCase("t,hand_y,hand_x,hand_z,hand2_x\n0,1,0,0,1\n", 1, "hand2_y")]
    [TestCase("t,hand_y,hand_x,hand_z,hand2_y,hand2_x\n0,1,0,0,1,0\n", 1, "hand2_z")]
    [TestCase("t,hand_y,hand_x,hand_z\n0,1,0,0\n0.1,1,abc,0\n", 3, "hand_x")]
    [TestCase("t,hand_y,hand_x,hand_z\n0,1,0,0\n0.1,1,0,1e\n", 3, "hand_z")]
    [TestCase("t,hand_y,hand2_y\n0,1,1\n0.1,1,x\n", 3, "hand2_y")]
    [TestCase("t,hand_y,hand2_y,tracked2\n0,1,1,2\n", 2, "tracked2")]
    [TestCase("t,hand_y,hand2_y,pose2_t\n0,1,1,0\n0.1,1,1,now\n", 3, "pose2_t")]
    [TestCase("t,hand_y,hand_x,hand_z,hand2_y,hand2_x,hand2_z\n0,1,0,0,1,0,zz\n", 2, "hand2_z")]
    public void MalformedNewColumnsNameTheFileAndLineAndWriteNothing(string trace, int line, string what)
    {
        foreach (var profile in new[] { "paper", "xyz" })
        {
            var (code, err) = Replay("--trace", In(trace), "--out", Out, "--mass-kg", "1", "--profile", profile);
            Assert.That(code, Is.EqualTo(2), err);
            Assert.That(err.TrimEnd('\n').Split('\n'), Has.Length.EqualTo(1), "one stderr line");
            Assert.That(err, Does.Contain($"in.csv:{line}:").And.Contain(what));
            Assert.That(File.Exists(Out), Is.False, "nothing written");
        }
    }

    [TestCase("0"), TestCase("-0.1"), TestCase("nan"), TestCase("inf"), TestCase("far")]
    public void BadBreakAwayNamesTheOption(string value)
    {
        var (code, err) = Replay("--trace", In("t,hand_y\n0,1\n"), "--out", Out, "--mass-kg", "1", "--break-away", value);
        Assert.That(code, Is.EqualTo(2));
        Assert.That(err, Does.Contain("--break-away"));
        Assert.That(File.Exists(Out), Is.False);
    }

    [Test]
    public void XyzIsAKnownProfileAndNamedInTheUnknownProfileMessage()
    {
        var (code, err) = Replay("--trace", In("t,hand_y\n0,1\n"), "--out", Out, "--mass-kg", "1", "--profile", "xyzw");
        Assert.That(code, Is.EqualTo(2));
        Assert.That(err, Does.Contain("xyz"));
        Assert.That(Run("t,hand_y\n0,1\n0.1,1.1\n", "--mass-kg", "1", "--profile", "xyz"), Has.Length.EqualTo(3));
    }

    [Test]
    public void ABreakAwayNoPoseCanReachIsRefused()
    {
        // Issue 23: "a D that can never fire under a profile is refused with a clear error"; 100 and 1e5 ran and never fired.
        foreach (string d in new[] { "100", "1e5" })
        {
            var (code, err) = Replay("--trace", In("t,hand_y\n0,1\n0.1,1.1\n"), "--out", Out, "--mass-kg", "1", "--profile", "xyz", "--break-away", d);
            Assert.That(code, Is.EqualTo(2), err);
            Assert.That(err, Is.EqualTo($"pseudohaptic replay: option --break-away: profile 'xyz+break-away': break-away's distance {(d == "100" ? "100" : "100000")} m could never be reached: " +
                "poses farther than the workspace radius from where the hold began are untracked, so hand and object are never more than (1 + maxGain) × workspaceRadius = 48 m apart.\n"));
            Assert.That(File.Exists(Out), Is.False);
        }
        Assert.That(Run("t,hand_y\n0,1\n0.1,1.1\n", "--mass-kg", "1", "--profile", "xyz", "--break-away", "48"), Has.Length.EqualTo(3));
    }
}
