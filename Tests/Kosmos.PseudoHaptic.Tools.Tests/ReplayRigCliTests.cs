using System.Globalization;
using System.Text;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tools.Tests;

/// <summary>
/// Issue 26's replay contract: IN may give the tracking origin's world pose per row (<c>rig_x,rig_y,rig_z,rig_yaw</c>);
/// replay weighs the hand in the rig's frame and writes the object back through the rig. The metamorphic property:
/// the same hand path in the rig's frame gives the same object path in the rig's frame whatever the rig does.
/// The rig's rotation is computed here from the issue's formula, independently of the tool's RigFrame.
/// </summary>
public class ReplayRigCliTests : CliTestFolder
{
    public ReplayRigCliTests() : base("ph-replay-rig-") { }

    /// <summary>The largest difference allowed between rig-frame object paths, m (the issue's 1 mm).</summary>
    const double Tolerance = 0.001;

    const int Seeds = 200;

    static string F(double v) => v.ToString("R", CultureInfo.InvariantCulture);

    static double D(string s) => double.Parse(s, CultureInfo.InvariantCulture);

    /// <summary>Unity's Quaternion.Euler(0, yaw, 0) applied to (x, y, z): (x cos θ + z sin θ, y, −x sin θ + z cos θ).</summary>
    static (double X, double Y, double Z) Rotate(double yawDegrees, double x, double y, double z)
    {
        double t = yawDegrees * Math.PI / 180, c = Math.Cos(t), s = Math.Sin(t);
        return (x * c + z * s, y, -x * s + z * c);
    }

    record struct Rig(double X, double Y, double Z, double Yaw)
    {
        public (double X, double Y, double Z) ToWorld(double x, double y, double z)
        {
            var r = Rotate(Yaw, x, y, z);
            return (X + r.X, Y + r.Y, Z + r.Z);
        }

        public (double X, double Y, double Z) ToRig(double x, double y, double z) => Rotate(-Yaw, x - X, y - Y, z - Z);
    }

    /// <summary>One row of a hand path in the rig's frame: 90 Hz frames, 30 Hz poses.</summary>
    record struct HandRow(double T, double PoseT, double X1, double Y1, double Z1, bool Tracked1, double X2, double Y2, double Z2, bool Tracked2);

    /// <summary>A seeded lift with a sideways carry, jitter, a short loss of one hand, and a second hand beside the first.</summary>
    static List<HandRow> HandPath(Random rng)
    {
        double x0 = rng.NextDouble() * 0.4 - 0.2, y0 = 0.8 + 0.2 * rng.NextDouble(), z0 = 0.3 + 0.2 * rng.NextDouble();
        double rise = 0.1 + 0.4 * rng.NextDouble(), liftStart = 0.3 + 0.3 * rng.NextDouble(), liftFor = 0.6 + 0.6 * rng.NextDouble();
        double carry = rng.NextDouble() * 0.6 - 0.3, carryStart = 1.0 + 0.5 * rng.NextDouble();
        double loseFrom = 1.2 + rng.NextDouble(), loseFor = rng.NextDouble() * 0.3;
        int lostHand = rng.Next(3); // 0: none, 1: the first, 2: the second
        var rows = new List<HandRow>();
        static double Smooth(double s) => s * s * s * (10 + s * (-15 + 6 * s));
        for (int i = 0; i <= 270; i++)
        {
            double t = i / 90.0, pt = Math.Floor(t * 30) / 30;
            double y = y0 + rise * Smooth(Math.Clamp((pt - liftStart) / liftFor, 0, 1));
            double x = x0 + carry * Smooth(Math.Clamp((pt - carryStart) / 0.8, 0, 1));
            double J() => 0.001 * (rng.NextDouble() - 0.5);
            bool lost = t >= loseFrom && t < loseFrom + loseFor;
            rows.Add(new HandRow(t, pt, x - 0.15 + J(), y + J(), z0 + J(), !(lost && lostHand == 1), x + 0.15 + J(), y + J(), z0 + J(), !(lost && lostHand == 2)));
        }
        return rows;
    }

    public enum Motion { StillElsewhere, Walk, Turn, Snap, Teleport, Platform, Everything }

    /// <summary>The rig's world pose at each row's time, seeded, within the issue's bounds.</summary>
    static Func<double, Rig> RigMotion(Motion motion, Random rng)
    {
        double U(double lo, double hi) => lo + (hi - lo) * rng.NextDouble();
        var start = new Rig(U(-1000, 1000), U(-50, 50), U(-1000, 1000), U(-180, 180));
        switch (motion)
        {
            case Motion.StillElsewhere:
                return _ => start;
            case Motion.Walk:
            {
                // Smooth locomotion at up to 3 m/s, changing direction and speed once.
                double v1 = U(0, 3), h1 = U(0, 2 * Math.PI), v2 = U(0, 3), h2 = U(0, 2 * Math.PI), turnAt = U(0.5, 2.5);
                return t =>
                {
                    double a = Math.Min(t, turnAt), b = Math.Max(0, t - turnAt);
                    return start with { X = start.X + v1 * a * Math.Cos(h1) + v2 * b * Math.Cos(h2), Z = start.Z + v1 * a * Math.Sin(h1) + v2 * b * Math.Sin(h2) };
                };
            }
            case Motion.Turn:
            {
                // A continuous turn at up to 180°/s about a point beside the origin (the head), as a thumbstick turns.
                double rate = U(-180, 180);
                var pivot = (X: U(-0.5, 0.5), Z: U(-0.5, 0.5));
                return t => Pivoted(start, pivot, rate * t);
            }
            case Motion.Snap:
            {
                // Snap turns of up to 90° each, about the head.
                var pivot = (X: U(-0.5, 0.5), Z: U(-0.5, 0.5));
                var snaps = Enumerable.Range(0, 1 + rng.Next(5)).Select(_ => (At: U(0.2, 2.9), By: U(-90, 90))).OrderBy(s => s.At).ToArray();
                return t => Pivoted(start, pivot, snaps.Where(s => s.At <= t).Sum(s => s.By));
            }
            case Motion.Teleport:
            {
                // Teleports to any place and heading the contract takes (within ±1e5 m).
                var jumps = Enumerable.Range(0, 1 + rng.Next(3))
                    .Select(_ => (At: U(0.2, 2.9), To: new Rig(U(-1e5, 1e5), U(-1e3, 1e3), U(-1e5, 1e5), U(-720, 720)))).OrderBy(j => j.At).ToArray();
                return t => jumps.LastOrDefault(j => j.At <= t, (At: 0.0, To: start)).To;
            }
            case Motion.Platform:
            {
                // An elevator or a vehicle going up and down at up to 2 m/s: y = A sin(ωt), Aω ≤ 2.
                double omega = U(0.5, 6), amplitude = U(0, 2 / omega), phase = U(0, 2 * Math.PI);
                double vx = U(-2, 2), vz = U(-2, 2);
                return t => start with { X = start.X + vx * t * 0.5, Y = start.Y + amplitude * (Math.Sin(omega * t + phase) - Math.Sin(phase)), Z = start.Z + vz * t * 0.5 };
            }
            default:
            {
                var walk = RigMotion(Motion.Walk, rng);
                var turn = RigMotion(Motion.Turn, rng);
                var snap = RigMotion(Motion.Snap, rng);
                var ride = RigMotion(Motion.Platform, rng);
                return t =>
                {
                    var w = walk(t);
                    var r = ride(t);
                    var turned = turn(t).Yaw - turn(0).Yaw + snap(t).Yaw - snap(0).Yaw;
                    return new Rig(w.X, r.Y, w.Z, w.Yaw + turned);
                };
            }
        }
    }

    /// <summary>The rig turned by <paramref name="degrees"/> about a point fixed in its own frame (the head), so that point stays put in the world.</summary>
    static Rig Pivoted(Rig start, (double X, double Z) pivot, double degrees)
    {
        var before = start.ToWorld(pivot.X, 0, pivot.Z);
        var turned = start with { Yaw = start.Yaw + degrees };
        var after = turned.ToWorld(pivot.X, 0, pivot.Z);
        return turned with { X = start.X + before.X - after.X, Z = start.Z + before.Z - after.Z };
    }

    /// <summary>The trace of a rig-frame hand path, the hands written in the world through <paramref name="rig"/> (null: no rig columns).</summary>
    static string Trace(List<HandRow> rows, Func<double, Rig>? rig, bool horizontal, bool second)
    {
        var sb = new StringBuilder("t,pose_t,hand_y,tracked");
        if (horizontal) sb.Append(",hand_x,hand_z");
        if (second) sb.Append(",hand2_y,tracked2").Append(horizontal ? ",hand2_x,hand2_z" : "");
        if (rig != null) sb.Append(",rig_yaw,rig_x,rig_z,rig_y"); // any order
        sb.Append('\n');
        foreach (var r in rows)
        {
            var g = rig?.Invoke(r.T) ?? new Rig(0, 0, 0, 0);
            // Without hand_x/hand_z the hand is over the rig's origin: only its height is written through the rig.
            var h1 = g.ToWorld(horizontal ? r.X1 : 0, r.Y1, horizontal ? r.Z1 : 0);
            var h2 = g.ToWorld(horizontal ? r.X2 : 0, r.Y2, horizontal ? r.Z2 : 0);
            sb.Append(F(r.T)).Append(',').Append(F(r.PoseT)).Append(',').Append(r.Tracked1 ? F(h1.Y) : "NaN").Append(',').Append(r.Tracked1 ? '1' : '0');
            if (horizontal) sb.Append(',').Append(F(h1.X)).Append(',').Append(F(h1.Z));
            if (second)
            {
                sb.Append(',').Append(r.Tracked2 ? F(h2.Y) : "").Append(',').Append(r.Tracked2 ? '1' : '0');
                if (horizontal) sb.Append(',').Append(F(h2.X)).Append(',').Append(F(h2.Z));
            }
            if (rig != null) sb.Append(',').Append(F(g.Yaw)).Append(',').Append(F(g.X)).Append(',').Append(F(g.Z)).Append(',').Append(F(g.Y));
            sb.Append('\n');
        }
        return sb.ToString();
    }

    List<Dictionary<string, string>> Replay(string trace, params string[] options)
    {
        string input = Write("in.csv", trace), output = Path.Combine(_dir, "out.csv");
        var (code, err, _) = Capture(() => Cli.Cli.Run(new[] { "replay", "--trace", input, "--out", output }.Concat(options).ToArray()));
        Assert.That(code, Is.EqualTo(0), err);
        var lines = File.ReadAllLines(output);
        var header = lines[0].Split(',');
        return lines.Skip(1).Select(l => header.Zip(l.Split(',')).ToDictionary(p => p.First, p => p.Second)).ToList();
    }

    [TestCase("paper"), TestCase("paper-experiment"), TestCase("gain"), TestCase("xyz")]
    public void The_object_follows_the_hand_in_the_rigs_frame_whatever_the_rig_does(string profile) => FollowsInTheRigsFrame(profile, null, Seeds, 1);

    /// <summary>The same at the cue strengths 1/3 and 3 (issue 31), through <c>--user</c>, every tenth seed.</summary>
    [Test]
    public void The_object_follows_the_hand_in_the_rigs_frame_at_other_cue_strengths([Values("paper", "paper-experiment", "gain", "xyz")] string profile, [Values(1.0 / 3, 3.0)] double cueStrength)
        => FollowsInTheRigsFrame(profile, Write("user.json", "{\"cueStrength\": " + cueStrength.ToString("R", CultureInfo.InvariantCulture) + "}"), Seeds, 10);

    void FollowsInTheRigsFrame(string profile, string? user, int seeds, int every)
    {
        int releasedSeeds = 0;
        double largestMove = 0, largestDifference = 0;
        for (int seed = 1; seed <= seeds; seed += every)
        {
            var rng = new Random(seed * 7919 + profile.Length);
            var hand = HandPath(rng);
            bool horizontal = rng.Next(4) != 0, second = rng.Next(2) == 0;
            string mass = F(Math.Round(0.05 + 2.95 * rng.NextDouble(), 3));
            var options = new[] { "--mass-kg", mass, "--profile", profile, "--break-away", "0.3" };
            if (user != null) options = options.Concat(new[] { "--user", user }).ToArray();
            var still = Replay(Trace(hand, null, horizontal, second), options);
            if (still.Any(r => r["held"] == "0")) releasedSeeds++;
            foreach (Motion motion in Enum.GetValues<Motion>())
            {
                var rig = RigMotion(motion, rng);
                var moved = Replay(Trace(hand, rig, horizontal, second), options);
                Assert.That(moved.Count, Is.EqualTo(still.Count));
                for (int i = 0; i < moved.Count; i++)
                {
                    string where = $"seed {seed}, {motion}, {(horizontal ? "xyz" : "y only")}{(second ? ", two hands" : "")}, mass {mass} kg, row {i + 1} (t = {hand[i].T:0.000} s)";
                    // A break-away never fires from the rig's motion: held row for row as with the rig standing still.
                    Assert.That(moved[i]["held"], Is.EqualTo(still[i]["held"]), where);
                    if (still[i]["held"] == "0") continue; // let go: it stays in the world, not in the rig
                    var g = rig(hand[i].T);
                    double ox = horizontal ? D(moved[i]["object_x"]) : g.X, oz = horizontal ? D(moved[i]["object_z"]) : g.Z;
                    var inRig = g.ToRig(ox, D(moved[i]["object_y"]), oz);
                    Assert.That(inRig.Y, Is.EqualTo(D(still[i]["object_y"])).Within(Tolerance), "object_y in the rig's frame, " + where);
                    largestDifference = Math.Max(largestDifference, Math.Abs(inRig.Y - D(still[i]["object_y"])));
                    if (horizontal)
                    {
                        Assert.That(inRig.X, Is.EqualTo(D(still[i]["object_x"])).Within(Tolerance), "object_x in the rig's frame, " + where);
                        Assert.That(inRig.Z, Is.EqualTo(D(still[i]["object_z"])).Within(Tolerance), "object_z in the rig's frame, " + where);
                        largestDifference = Math.Max(largestDifference, Math.Max(Math.Abs(inRig.X - D(still[i]["object_x"])), Math.Abs(inRig.Z - D(still[i]["object_z"]))));
                        largestMove = Math.Max(largestMove, Math.Abs(ox - D(still[i]["object_x"])));
                    }
                    if (second) Assert.That(moved[i]["hands"], Is.EqualTo(still[i]["hands"]), where);
                }
            }
        }
        // The property is not vacuous: the rig carried the object far in the world.
        Assert.That(largestMove, Is.GreaterThan(100), "the rigs moved the object in the world");
        TestContext.WriteLine($"{profile}{(user != null ? " (" + File.ReadAllText(user) + ")" : "")}: {seeds / every} seeds × {Enum.GetValues<Motion>().Length} rig motions; {releasedSeeds} seeds broke away with the rig standing still; largest rig-frame difference {largestDifference:E2} m");
    }

    [Test]
    public void The_rig_turns_as_Unitys_Quaternion_Euler_about_y()
    {
        // Under xyz the object lags sideways behind a carry along the rig's +x. With the rig at (5, 1, -2) turned 90°,
        // the rig's +x is the world's −z: Quaternion.Euler(0, 90, 0) * Vector3.right = (0, 0, −1).
        var hand = HandPath(new Random(3));
        var still = Replay(Trace(hand, null, true, false), "--mass-kg", "2", "--profile", "xyz");
        var turned = Replay(Trace(hand, _ => new Rig(5, 1, -2, 90), true, false), "--mass-kg", "2", "--profile", "xyz");
        for (int i = 0; i < still.Count; i++)
        {
            Assert.That(D(turned[i]["object_x"]), Is.EqualTo(5 + D(still[i]["object_z"])).Within(1e-9), $"row {i + 1}");
            Assert.That(D(turned[i]["object_y"]), Is.EqualTo(1 + D(still[i]["object_y"])).Within(1e-9), $"row {i + 1}");
            Assert.That(D(turned[i]["object_z"]), Is.EqualTo(-2 - D(still[i]["object_x"])).Within(1e-9), $"row {i + 1}");
            Assert.That(turned[i]["hand_x"], Is.Not.EqualTo(still[i]["hand_x"]), "hand_x stays the world's, as given");
        }
    }

    [Test]
    public void Without_the_rig_columns_nothing_is_transformed_and_a_rig_at_the_origin_changes_nothing()
    {
        var hand = HandPath(new Random(5));
        var none = Replay(Trace(hand, null, true, true), "--mass-kg", "1.5", "--profile", "xyz");
        var origin = Replay(Trace(hand, _ => new Rig(0, 0, 0, 0), true, true), "--mass-kg", "1.5", "--profile", "xyz");
        for (int i = 0; i < none.Count; i++)
            foreach (var column in new[] { "object_x", "object_y", "object_z", "offset", "hands" })
                Assert.That(origin[i][column], Is.EqualTo(none[i][column]), $"row {i + 1}, {column}");
    }

    [Test]
    public void After_a_break_away_the_object_stays_in_the_world_while_the_rig_walks_on()
    {
        // A hand that yanks 0.6 m up in 0.1 s under paper-experiment with 3 kg: the object is let go.
        var sb = new StringBuilder("t,hand_y,rig_x,rig_y,rig_z,rig_yaw\n");
        for (int i = 0; i <= 180; i++)
        {
            double t = i / 90.0, y = 1.0 + 0.6 * Math.Clamp((t - 0.5) / 0.1, 0, 1);
            sb.Append($"{F(t)},{F(y + 0)},{F(2 * t)},0,0,0\n"); // the rig walks along +x at 2 m/s
        }
        var rows = Replay(sb.ToString(), "--mass-kg", "3", "--profile", "paper-experiment", "--break-away", "0.3");
        int first = rows.FindIndex(r => r["held"] == "0");
        Assert.That(first, Is.GreaterThan(0), "the yank broke away");
        Assert.That(rows.Skip(first).Select(r => r["object_y"]).Distinct().Count(), Is.EqualTo(1), "the let-go object stays put");
    }

    [TestCase("t,hand_y,rig_x,rig_y,rig_z\n0,1,0,0,0\n", "in.csv:1: column 'rig_x', 'rig_y', 'rig_z' needs 'rig_yaw'")]
    [TestCase("t,hand_y,rig_yaw\n0,1,0\n", "in.csv:1: column 'rig_yaw' needs 'rig_x', 'rig_y', 'rig_z'")]
    [TestCase("t,hand_y,rig_x,rig_y,rig_z,rig_yaw\n0,1,0,0,0,0\n0.1,1,0,,0,0\n", "in.csv:3: column 'rig_y' is empty")]
    [TestCase("t,hand_y,rig_x,rig_y,rig_z,rig_yaw\n0,1,NaN,0,0,0\n", "in.csv:2: column 'rig_x': NaN is not a finite number within ±100000")]
    [TestCase("t,hand_y,rig_x,rig_y,rig_z,rig_yaw\n0,1,0,0,-inf,0\n", "in.csv:2: column 'rig_z': -inf is not a finite number")]
    [TestCase("t,hand_y,rig_x,rig_y,rig_z,rig_yaw\n0,1,100000.5,0,0,0\n", "in.csv:2: column 'rig_x': 100000.5 is not a finite number within ±100000")]
    [TestCase("t,hand_y,rig_x,rig_y,rig_z,rig_yaw\n0,1,0,0,0,north\n", "in.csv:2: column 'rig_yaw': cannot parse 'north' as a number")]
    public void A_rig_column_missing_or_a_value_missing_or_out_of_range_is_refused_naming_file_line_and_column(string trace, string message)
    {
        string input = Write("in.csv", trace), output = Path.Combine(_dir, "out.csv");
        var (code, err, _) = Capture(() => Cli.Cli.Run(new[] { "replay", "--trace", input, "--out", output, "--mass-kg", "1" }));
        Assert.That(code, Is.EqualTo(2));
        Assert.That(err, Does.Contain("/" + message), "the path as given, then the line and the column");
        Assert.That(err.Trim().Split('\n'), Has.Length.EqualTo(1));
        Assert.That(File.Exists(output), Is.False, "nothing written");
        Assert.That(File.Exists(input));
    }
}
