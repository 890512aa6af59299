using FsCheck;
using FsCheck.Fluent;
using Kosmos.PseudoHaptic.Simulation;

namespace Kosmos.PseudoHaptic.Properties.Tests;

/// <summary>A composed profile (<see cref="ComposedProfile"/>) fed garbage frames (<see cref="GarbageHold"/>: its profile
/// and mass are not used; the composed profile's are).</summary>
public sealed record GarbageUnderComposed(ComposedProfile Profile, GarbageHold Hold)
{
    public override string ToString() => Profile + "; from " + Hold.StartY.ToString("R") + " m: " + string.Join(" ", Hold.Frames.Select(f => f.ToString()));

    public static Arbitrary<GarbageUnderComposed> Arbitrary() => Arb.From(
        from p in ComposedProfile.Generator()
        from h in GarbageHold.Generator(new[] { "paper" })
        select new GarbageUnderComposed(p, h),
        c => GarbageHold.Shrink(c.Hold).Select(h => c with { Hold = h }).Concat(ComposedProfile.Shrink(c.Profile).Select(p => c with { Profile = p })));
}

/// <summary>
/// A composed profile on Quest-like clean input: a hand at 0.8 m rests 0.5 s, lifts (or lowers) by 3–60 cm in 0.3–2 s and
/// rests 10.5 s, seen as ArtifactCase's headset sees it (30 Hz poses 45 ms late over 72, 90 or 120 Hz frames, 1–2 mm of
/// jitter, low confidence on three poses in ten above 0.6 m/s) without any artifact. In 3D the hand (or each of two hands,
/// 0.3 m apart, each with its own jitter) moves on y only.
/// </summary>
public sealed class CleanLift
{
    public ComposedProfile Profile = new();
    public int RiseMm = 300, MoveMs = 1000, FrameRate = 90, Seed = 1, JitterUm = 1500;

    public const double Start = 0.8, MovesAt = 0.5, Rest = 10.5;

    public double StopsAt => MovesAt + MoveMs / 1000.0;

    public HandPath Path() => HandPath.StartAt(Start).Hold(MovesAt).MoveTo(Start + RiseMm / 1000.0, MoveMs / 1000.0).Hold(Rest);

    public HeadsetSimulator Headset(int seed) => new()
    {
        FrameRate = FrameRate, PoseRate = 30, Latency = 0.045, JitterSd = JitterUm / 1e6,
        LowConfidenceAboveSpeed = 0.6, LowConfidenceChance = 0.3, Seed = seed,
    };

    public override string ToString() => $"{Profile}; lift {RiseMm} mm in {MoveMs} ms, {FrameRate} Hz, jitter {JitterUm} µm, seed {Seed}";

    internal CleanLift With(Action<CleanLift> change)
    {
        var c = (CleanLift)MemberwiseClone();
        change(c);
        return c;
    }

    public static Gen<CleanLift> Generator(bool limits) =>
        from p in ComposedProfile.Generator(limits)
        from rise in Gen.Frequency((3, Gen.Choose(30, 600)), (1, Gen.Choose(-300, -30)))
        from ms in Gen.Choose(300, 2000)
        from rate in Gen.Elements(72, 90, 120)
        from seed in Gen.Choose(1, 100000)
        from jitter in Gen.Choose(1000, 2000)
        select new CleanLift { Profile = RealHandsPass(p), RiseMm = rise, MoveMs = ms, FrameRate = rate, Seed = seed, JitterUm = jitter };

    /// <summary>The slowest maxHandSpeed a clean run draws, m/s: a fast human reach peaks at 2–6 m/s (ALGORITHM.md §5). A
    /// limit below it declares a real hand (a lift, or 1–2 mm of jitter between 30 Hz poses: 0.05 m/s) a glitch and refuses
    /// its poses, so that the solver follows a hand the input does not show: what the clean run judges (no jump beyond the
    /// hand's own step, no creep at rest) is about the hand. Garbage and the round trip draw the whole range.</summary>
    public const double SlowestRealHandLimit = 2;

    static ComposedProfile RealHandsPass(ComposedProfile p)
        => p.Limits == null || p.Limits[1] >= SlowestRealHandLimit ? p
            : p.With(x => x.Limits[1] = Math.Max(x.Limits[1], SlowestRealHandLimit));

    public static IEnumerable<CleanLift> Shrink(CleanLift c)
    {
        foreach (var p in ComposedProfile.Shrink(c.Profile)) yield return c.With(x => x.Profile = p);
        if (c.RiseMm % 100 != 0) yield return c.With(x => x.RiseMm = (int)Math.Round(c.RiseMm / 100.0) * 100 is var r && Math.Abs(r) >= 30 ? r : Math.Sign(c.RiseMm) * 100);
        if (c.MoveMs != 1000) yield return c.With(x => x.MoveMs = 1000);
        if (c.FrameRate != 90) yield return c.With(x => x.FrameRate = 90);
        if (c.JitterUm != 1500) yield return c.With(x => x.JitterUm = 1500);
        if (c.Seed != 1) yield return c.With(x => x.Seed = 1);
    }
}

/// <summary>What a composed profile's solver did on a run: each frame's object position and the gain the y solver had.</summary>
public sealed class ComposedRun
{
    public double[] X, Y, Z, Gain;
    /// <summary>The hand the solver follows (the y solver's <see cref="WeightSolver.HandY"/>; in 3D the followed point), per
    /// frame: where a pose was refused (lost to the solver), its step on the pose that ends the gap.</summary>
    public double[] FX, FY, FZ;
    /// <summary>…and, in 3D, the hand the y solver follows (filtered, with a hand filter), m.</summary>
    public double[] HY;
    /// <summary>The glide the y solver still has to make (<see cref="HoldState.Glide"/>), m.</summary>
    public double[] Glide;
    /// <summary>The object's height once the hold began (the floor may have raised it).</summary>
    public double StartY;

    /// <summary>Builds the solver <paramref name="p"/> names; null when <see cref="WeightSolver3D"/> refuses the profile,
    /// which must be exactly when <see cref="ComposedProfile.RefusedIn3D"/> says so, with a message naming break-away.</summary>
    public static object Solver(ComposedProfile p, WeightProfile profile)
    {
        var model = WeightModel.FromMass(p.MassKg);
        if (p.Solver == SolverKind.Y) return new WeightSolver(model, profile, p.StandardSpeed);
        try
        {
            var s = new WeightSolver3D(model, profile, p.StandardSpeed);
            Expect.That(!p.RefusedIn3D(), "WeightSolver3D accepted a profile it should refuse");
            return s;
        }
        catch (ArgumentException e) when (p.RefusedIn3D())
        {
            Expect.That(e.Message.Contains("break-away"), "refused without naming break-away: " + e.Message);
            return null;
        }
    }

    /// <summary>Garbage frames, as SolverProperties' garbage properties feed them (in 3D: grips opening and closing, the
    /// second hand the next frame's pose).</summary>
    public static ComposedRun Garbage(ComposedProfile p, WeightProfile profile, GarbageHold h)
    {
        var solver = Solver(p, profile);
        if (solver == null) return null;
        int n = h.Frames.Length;
        var r = new ComposedRun { X = new double[n], Y = new double[n], Z = new double[n], Gain = new double[n] };
        if (solver is WeightSolver y)
        {
            y.BeginHold(h.StartY, h.StartY);
            r.StartY = y.ObjectY;
            for (int i = 0; i < n; i++) { r.Y[i] = y.Step(h.Frames[i].Sample, h.Frames[i].Dt); r.Gain[i] = y.Gain; }
            return r;
        }
        var s = (WeightSolver3D)solver;
        bool two = p.Solver == SolverKind.TwoHands;
        var first = new HandPose(0, h.StartY, 0);
        s.BeginHold(first, two ? new HandPose(0.3, h.StartY, 0) : HandPose.Lost, two ? 0.15 : 0, h.StartY, 0);
        r.StartY = s.ObjectY;
        for (int i = 0; i < n; i++)
        {
            var f = h.Frames[i];
            if (two) s.SetGrip(i % 2 + 1, f.Grip);
            s.Step(f.Pose, two ? h.Frames[(i + 1) % n].Pose : HandPose.Lost, f.Dt);
            r.X[i] = s.ObjectX; r.Y[i] = s.ObjectY; r.Z[i] = s.ObjectZ; r.Gain[i] = s.Vertical.Gain;
        }
        return r;
    }

    /// <summary>Rendered frames of one hand (two for two hands: the second 0.3 m to the side, jittered by another seed).</summary>
    public static TraceFrame[][] Render(CleanLift c)
    {
        var path = c.Path();
        var one = c.Headset(c.Seed).Render(path);
        return c.Profile.Solver == SolverKind.TwoHands ? new[] { one, c.Headset(c.Seed + 7919).Render(path) } : new[] { one };
    }

    static readonly double[] HandX = { 0, 0.3 };

    public static HandPose Pose(TraceFrame[][] hands, int hand, int i)
    {
        var f = hands[hand][i];
        return new HandPose(HandX[hand], f.HandY, 0, f.Tracked, f.Tracked && !f.LowConfidence, f.PoseTime);
    }

    /// <summary>Replays the rendered frames from the first (usable: the input is clean) with hand and object together.</summary>
    public static ComposedRun Clean(ComposedProfile p, WeightProfile profile, TraceFrame[][] hands)
    {
        var solver = Solver(p, profile);
        if (solver == null) return null;
        var frames = hands[0];
        int n = frames.Length;
        var r = new ComposedRun { X = new double[n], Y = new double[n], Z = new double[n], Gain = new double[n], FX = new double[n], FY = new double[n], FZ = new double[n], HY = new double[n], Glide = new double[n] };
        if (solver is WeightSolver y)
        {
            y.BeginHold(frames[0].HandY, frames[0].HandY, frames[0].PoseTime);
            r.Y[0] = y.ObjectY; r.Gain[0] = y.Gain; r.FY[0] = r.HY[0] = y.HandY; r.Glide[0] = y.State.Glide;
            for (int i = 1; i < n; i++) { r.Y[i] = y.Step(frames[i].ToSample(), frames[i].Time - frames[i - 1].Time); r.Gain[i] = y.Gain; r.FY[i] = r.HY[i] = y.HandY; r.Glide[i] = y.State.Glide; }
            return r;
        }
        var s = (WeightSolver3D)solver;
        bool two = hands.Length == 2;
        s.BeginHold(Pose(hands, 0, 0), two ? Pose(hands, 1, 0) : HandPose.Lost, two ? 0.15 : 0, two ? (hands[0][0].HandY + hands[1][0].HandY) / 2 : frames[0].HandY, 0);
        for (int i = 0; i < n; i++)
        {
            if (i > 0) s.Step(Pose(hands, 0, i), two ? Pose(hands, 1, i) : HandPose.Lost, frames[i].Time - frames[i - 1].Time);
            r.X[i] = s.ObjectX; r.Y[i] = s.ObjectY; r.Z[i] = s.ObjectZ; r.Gain[i] = s.Vertical.Gain;
            r.FX[i] = s.FollowedX; r.FY[i] = s.FollowedY; r.FZ[i] = s.FollowedZ; r.HY[i] = s.Vertical.HandY; r.Glide[i] = s.Vertical.State.Glide;
        }
        return r;
    }
}
