using Kosmos.PseudoHaptic.Cli.Files;
using Kosmos.PseudoHaptic.Cli.Plotting;
using Kosmos.PseudoHaptic.Simulation;

namespace Kosmos.PseudoHaptic.Cli.Commands;

/// <summary>
/// The demo's 3D scene (issue 10), under the <c>xyz</c> profile: one hand carries a box 0.4 m sideways, lifts it
/// 0.8 m to a high shelf and puts it back; then the second hand joins and both lift it 0.4 m and carry it back.
/// Simulated Quest 2 hands (30 Hz poses, 45 ms late, 1 mm jitter per axis, 90 Hz frames). Writes a CSV per mass
/// and one PNG of x and y over time for every mass.
/// </summary>
public static class DemoThreeDimensions
{
    public const string Slug = "xyz-carry-lift";
    const string Title = "Sideways carry, high lift, two-hand lift (xyz)";

    /// <summary>When the second hand takes hold, s.</summary>
    const double SecondHandFrom = 6.6;

    public sealed record Result(string Name, double MassKg, double MaxLateralLag, double MaxHighLiftOffset, double MaxTwoHandOffset, double MaxTwoHandLateralLag);

    /// <summary>When both hands carry the box back sideways, s (from the x path below).</summary>
    const double TwoHandCarryFrom = 8.5;

    sealed record Frames(double[] T, HandPose[] A, HandPose[] B);

    static readonly (string Name, double MassKg)[] Items =
    {
        // 0.1 kg, not the golf ball: with two hands each carries half, and half a golf ball is lighter than the
        // standard, so it would lead the hands (as a one-hand lift of 22.5 g does).
        ("box 0.1 kg", 0.1), ("box 0.5 kg", 0.5), ("box 2 kg", 2), ("box 5 kg", 5),
    };

    public static List<Result> Run(string folder, double standardSpeed, bool svg, TextWriter log, double cueStrength = 1)
    {
        var frames = Render();
        string dir = Path.Combine(folder, Slug);
        Directory.CreateDirectory(dir);
        var results = new List<Result>();
        var runs = new List<(string Label, double[] X, double[] Y, double[] Z)>();
        foreach (var (name, mass) in Items)
        {
            log.WriteLine($"[xyz] {Title}: {name}");
            var solver = new WeightSolver3D(WeightModel.FromMass(mass), NamedProfiles.Xyz, standardSpeed) { CueStrength = cueStrength };
            int n = frames.T.Length;
            double[] x = new double[n], y = new double[n], z = new double[n];
            int[] hands = new int[n];
            solver.BeginHold(frames.A[0], frames.B[0], frames.A[0].X, frames.A[0].Y, frames.A[0].Z);
            for (int i = 0; i < n; i++)
            {
                if (i > 0) solver.Step(frames.A[i], frames.B[i], frames.T[i] - frames.T[i - 1]);
                x[i] = solver.ObjectX; y[i] = solver.ObjectY; z[i] = solver.ObjectZ; hands[i] = solver.FollowedHands;
            }
            results.Add(Measure(name, mass, frames, x, y));
            WriteCsv(Path.Combine(dir, name.Replace(' ', '-').Replace('.', '_') + ".csv"), frames, x, y, z, hands);
            runs.Add((name, x, y, z));
        }
        Plot(Path.Combine(folder, Slug + ".png"), frames, runs, svg);
        return results;
    }

    /// <summary>Both hands' paths: a box 0.3 m wide, held at its sides; hand 2 is untracked until it takes hold.</summary>
    static Frames Render()
    {
        var x1 = HandPath.StartAt(-0.15).Hold(0.5).MoveTo(0.25, 2.0)       // sideways carry, 0.4 m in 2 s
            .Hold(8.5 - 2.5).MoveTo(-0.15, 1.2).Hold(1.0);                   // both hands carry it back
        var y1 = HandPath.StartAt(0.80).Hold(3.0).MoveTo(1.60, 1.2)        // high lift to a shelf, 0.8 m
            .Hold(0.8).MoveTo(0.80, 1.2).Hold(0.8)                            // put back down
            .MoveTo(1.20, 1.0).Hold(2.7);                                     // two-hand lift, 0.4 m
        // Forward 0.3 m with the sideways carry and back with the two-hand carry: z shows motion, not only jitter.
        var z = HandPath.StartAt(0.35).Hold(0.5).MoveTo(0.65, 2.0).Hold(8.5 - 2.5).MoveTo(0.35, 1.2).Hold(1.0);
        double duration = Math.Max(x1.Duration, y1.Duration);
        var headset = new Func<int, HeadsetSimulator>(seed => new HeadsetSimulator { FrameRate = 90, PoseRate = 30, Latency = 0.045, JitterSd = 0.001, Seed = seed });
        var ax = headset(31).Render(x1, duration - x1.Duration);
        var ay = headset(32).Render(y1, duration - y1.Duration);
        var az = headset(33).Render(z, duration - z.Duration);
        var bx = headset(34).Drop(0, SecondHandFrom).Render(Shift(x1, 0.3), duration - x1.Duration);
        var by = headset(35).Drop(0, SecondHandFrom).Render(y1, duration - y1.Duration);
        var bz = headset(36).Drop(0, SecondHandFrom).Render(z, duration - z.Duration);
        int n = new[] { ax.Length, ay.Length, az.Length, bx.Length, by.Length, bz.Length }.Min();
        var t = new double[n];
        var a = new HandPose[n];
        var b = new HandPose[n];
        for (int i = 0; i < n; i++)
        {
            t[i] = ay[i].Time;
            a[i] = new HandPose(ax[i].HandX(), ay[i].HandY, az[i].HandY, true, true, ay[i].PoseTime);
            b[i] = by[i].Tracked ? new HandPose(bx[i].HandY, by[i].HandY, bz[i].HandY, true, true, by[i].PoseTime) : HandPose.Lost;
        }
        return new Frames(t, a, b);
    }

    static double HandX(this TraceFrame f) => f.HandY;

    static HandPath Shift(HandPath path, double by)
    {
        var times = new List<double>();
        var values = new List<double>();
        for (double t = 0; t <= path.Duration + 1e-9; t += 0.01) { times.Add(t); values.Add(path.HeightAt(t) + by); }
        return HandPath.FromSamples(times, values);
    }

    static Result Measure(string name, double mass, Frames f, double[] x, double[] y)
    {
        double lateral = 0, high = 0, two = 0, twoLateral = 0;
        for (int i = 0; i < x.Length; i++)
        {
            var a = f.A[i];
            bool both = f.B[i].IsUsable;
            double hy = both ? 0.5 * (a.Y + f.B[i].Y) : a.Y;
            double t = f.T[i];
            if (t < 3.0) lateral = Math.Max(lateral, Math.Abs((a.X - f.A[0].X) - (x[i] - x[0])));
            if (t >= 3.0 && t < 6.2) high = Math.Max(high, hy - y[i]);
            if (t >= SecondHandFrom) two = Math.Max(two, hy - y[i]);
            if (t >= TwoHandCarryFrom) twoLateral = Math.Max(twoLateral, Math.Abs((a.X - f.A[0].X) - (x[i] - x[0])));
        }
        return new Result(name, mass, lateral, high, two, twoLateral);
    }

    static void WriteCsv(string path, Frames f, double[] x, double[] y, double[] z, int[] hands)
    {
        using var w = new StreamWriter(path);
        w.WriteLine("t,hand_x,hand_y,hand_z,hand2_x,hand2_y,hand2_z,object_x,object_y,object_z,hands");
        for (int i = 0; i < x.Length; i++)
        {
            var a = f.A[i];
            var b = f.B[i];
            w.WriteLine(string.Join(",", new[] { f.T[i], a.X, a.Y, a.Z, b.X, b.Y, b.Z, x[i], y[i], z[i] }.Select(NumberText.Format)) + "," + hands[i]);
        }
    }

    /// <summary>Smallest span of a panel's y axis, m: a still axis shows as still, not as its millimetres of jitter.</summary>
    const double MinSpan = 0.1;

    /// <summary>
    /// The scene's chart, three panels over one time axis (aligned by <see cref="Charts.SavePanels"/>): the sideways
    /// (x) and forward (z) lag of each object behind the first hand (the hand's displacement since the grab minus the
    /// object's: where the masses differ; the positions themselves would lie on one another), then the height (y) of each object with both hands over them (black dashed:
    /// the first; grey: the second, from when it takes hold). Each y axis spans at least <see cref="MinSpan"/>.
    /// </summary>
    static void Plot(string path, Frames f, List<(string Label, double[] X, double[] Y, double[] Z)> runs, bool svg)
    {
        double[] Lag(Func<HandPose, double> hand, double[] o) => f.A.Select((a, i) => (hand(a) - hand(f.A[0])) - (o[i] - o[0])).ToArray();
        var x = Charts.Create(Title, "", "x: hand − object (m)");
        for (int i = 0; i < runs.Count; i++) Charts.Series(x, f.T, Lag(p => p.X, runs[i].X), runs[i].Label, i);
        var y = Charts.Create("", "time (s)", "y: height (m)");
        for (int i = 0; i < runs.Count; i++) Charts.Series(y, f.T, runs[i].Y, runs[i].Label, i);
        Charts.Line(y, f.T, f.B.Select(p => p.IsUsable ? p.Y : double.NaN).ToArray(), $"second hand (from {SecondHandFrom:0.0} s)", Charts.Colour(7), dashed: false);
        Charts.Hand(y, f.T, f.A.Select(p => p.Y).ToArray(), "first hand (30 Hz poses)");
        var z = Charts.Create("", "", "z: hand − object (m)");
        for (int i = 0; i < runs.Count; i++) Charts.Series(z, f.T, Lag(p => p.Z, runs[i].Z), runs[i].Label, i);
        Charts.LegendBelow(y);
        x.HideLegend();
        z.HideLegend();
        foreach (var panel in new[] { x, z, y })
        {
            var values = panel.GetPlottables().OfType<ScottPlot.Plottables.Scatter>().SelectMany(sc => sc.Data.GetScatterPoints()).Select(c => c.Y).Where(double.IsFinite).ToList();
            double low = values.Min(), high = values.Max(), mid = (low + high) / 2, half = Math.Max(high - low, MinSpan) / 2 * 1.08;
            panel.Axes.SetLimitsY(mid - half, mid + half);
            panel.Axes.SetLimitsX(f.T[0], f.T[^1]);
        }
        Charts.SavePanels(new[] { x, z, y }, path, 1000, new[] { 330, 300, 600 }, svg);
    }
}
