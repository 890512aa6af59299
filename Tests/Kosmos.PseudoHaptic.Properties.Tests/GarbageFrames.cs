using FsCheck;
using FsCheck.Fluent;

namespace Kosmos.PseudoHaptic.Properties.Tests;

/// <summary>One frame of whatever a headset, an engine or a scene could hand the solver: ordinary poses and frame times
/// mixed with NaN, infinities, absurd but finite values, signed zeros, subnormals, poses beyond ±10⁵ m, clocks that stop,
/// step back or jump to 1e308, and tracking and confidence flags in any combination.</summary>
public readonly record struct GarbageFrame(double X, double Y, double Z, bool Tracked, bool HighConfidence, double PoseTime, double Dt, bool Grip)
{
    public HandSample Sample => new HandSample(Y, Tracked, HighConfidence, PoseTime);
    public HandPose Pose => new HandPose(X, Y, Z, Tracked, HighConfidence, PoseTime);

    public override string ToString() => $"({X:R}, {Y:R}, {Z:R}{(Tracked ? "" : ", lost")}{(HighConfidence ? "" : ", low")}, t {PoseTime:R}, dt {Dt:R}{(Grip ? "" : ", open")})";
}

/// <summary>A hold fed garbage: the object, the profile, the mass, where the hold begins, and the frames.</summary>
public sealed class GarbageHold
{
    public string Profile = "paper";
    public double MassKg = 1, StartY = 1;
    public GarbageFrame[] Frames = Array.Empty<GarbageFrame>();

    public override string ToString() => $"{Profile}, {MassKg} kg, from {StartY:R} m: " + string.Join(" ", Frames.Select(f => f.ToString()));

    static readonly double[] Specials =
    {
        double.NaN, double.PositiveInfinity, double.NegativeInfinity, 1e300, -1e300, 1e5, -1e5, 99999.99, -99999.99,
        double.Epsilon, -0.0, 0.0, 1e-300, double.MaxValue, double.MinValue, 12.5, -12.5,
    };

    static Gen<double> Coordinate(double low, double high) => Gen.Frequency(
        (6, Gen.Choose(0, 100000).Select(v => low + (high - low) * v / 100000.0)),
        (1, Gen.Elements(Specials)));

    static readonly double[] SpecialDts = { 0, -0.011, double.NaN, double.PositiveInfinity, 1e308, 5, 1e-9, 3600, 1.0 / 30 };

    static Gen<double> FrameTime() => Gen.Frequency((6, Gen.Elements(1.0 / 72, 1.0 / 90, 1.0 / 120)), (1, Gen.Elements(SpecialDts)));

    // Pose times that advance, repeat, step back, are missing or absurd.
    static Gen<double> PoseTime() => Gen.Frequency(
        (6, Gen.Choose(0, 60000).Select(v => v / 1000.0)),
        (1, Gen.Elements(double.NaN, double.PositiveInfinity, -1.0, 1e308, 0.0)));

    static Gen<GarbageFrame> Frame() =>
        from x in Coordinate(-1, 1)
        from y in Coordinate(0, 2)
        from z in Coordinate(-1, 1)
        from tracked in Gen.Frequency((5, Gen.Constant(true)), (1, Gen.Constant(false)))
        from high in Gen.Frequency((5, Gen.Constant(true)), (1, Gen.Constant(false)))
        from time in PoseTime()
        from dt in FrameTime()
        from grip in Gen.Frequency((9, Gen.Constant(true)), (1, Gen.Constant(false)))
        select new GarbageFrame(x, y, z, tracked, high, time, dt, grip);

    public static Arbitrary<GarbageHold> Arbitrary(IReadOnlyList<string> profiles) => Arb.From(Generator(profiles), Shrink);

    /// <summary>Holds under <paramref name="profiles"/>, 1 g to 1 t, from 0–2 m, of 1 to 20 + 20 × size garbage frames.</summary>
    public static Gen<GarbageHold> Generator(IReadOnlyList<string> profiles) =>
        from profile in Gen.Elements(profiles.ToArray())
        from grams in Gen.Elements(1, 10, 45, 100, 500, 1000, 2000, 5000, 100000, 1000000)
        from start in Gen.Choose(0, 2000)
        from frames in Gen.Sized(size => Gen.Choose(1, 20 + 20 * size).SelectMany(n => Gen.ArrayOf(Frame(), n)))
        select new GarbageHold { Profile = profile, MassKg = grams / 1000.0, StartY = start / 1000.0, Frames = frames };

    /// <summary>Shorter runs (halves, then one frame less), then each frame made ordinary in turn.</summary>
    public static IEnumerable<GarbageHold> Shrink(GarbageHold h)
    {
        int n = h.Frames.Length;
        if (n > 1)
        {
            yield return With(h, h.Frames.Take(n / 2).ToArray());
            yield return With(h, h.Frames.Skip(n / 2).ToArray());
            for (int i = 0; i < n; i++) { int skip = i; yield return With(h, h.Frames.Where((_, j) => j != skip).ToArray()); }
        }
        for (int i = 0; i < n; i++)
        {
            var f = h.Frames[i];
            var plain = new GarbageFrame(0, 1, 0, true, true, f.PoseTime, 1.0 / 90, true);
            if (f != plain) { var frames = (GarbageFrame[])h.Frames.Clone(); frames[i] = plain; yield return With(h, frames); }
        }
    }

    static GarbageHold With(GarbageHold h, GarbageFrame[] frames) => new GarbageHold { Profile = h.Profile, MassKg = h.MassKg, StartY = h.StartY, Frames = frames };
}
