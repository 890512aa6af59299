using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Properties.Tests;

/// <summary>The solver's rules over generated holds (FsCheck), beside the package's fixed-seed properties.</summary>
[TestFixture]
public class SolverProperties
{
    /// <summary>
    /// P8 on garbage (ALGORITHM.md §3: bad frame data is absorbed quietly): whatever the frames hold, <c>Step</c> never
    /// throws and every height it returns is finite and within ±10⁵ m (a float transform holds it), on every profile the
    /// y solver runs and the paper-literal baseline, from 1 g to 1 t.
    /// </summary>
    [Test]
    public void GarbageNeverReachesTheObject() => Checks.Hold(GarbageHold.Arbitrary(NamedProfiles.Names), h =>
    {
        if (NamedProfiles.IsPaperLiteral(NamedProfiles.Get(h.Profile)))
        {
            var literal = new PaperLiteralSolver(h.MassKg);
            literal.BeginHold(h.StartY, h.StartY);
            foreach (var f in h.Frames) Usable(literal.Step(f.Y, f.Tracked, f.Dt), "paper-literal height");
            return;
        }
        var solver = new WeightSolver(WeightModel.FromMass(h.MassKg), NamedProfiles.Get(h.Profile));
        solver.BeginHold(h.StartY, h.StartY);
        foreach (var f in h.Frames) Usable(solver.Step(f.Sample, f.Dt), "height");
    }, 300);

    /// <summary>The same in three dimensions, one hand or two, grips opening and closing: x, y and z stay usable.</summary>
    [Test]
    public void GarbageNeverReachesTheObjectInThreeDimensions() => Checks.Hold(GarbageHold.Arbitrary(NamedProfiles.PipelineNames), h =>
    {
        var solver = new WeightSolver3D(WeightModel.FromMass(h.MassKg), NamedProfiles.Get(h.Profile));
        var first = new HandPose(0, h.StartY, 0);
        solver.BeginHold(first, new HandPose(0.3, h.StartY, 0), 0.15, h.StartY, 0);
        for (int i = 0; i < h.Frames.Length; i++)
        {
            var f = h.Frames[i];
            solver.SetGrip(i % 2 + 1, f.Grip);
            var other = h.Frames[(i + 1) % h.Frames.Length];
            solver.Step(f.Pose, other.Pose, f.Dt);
            Usable(solver.ObjectX, "x"); Usable(solver.ObjectY, "y"); Usable(solver.ObjectZ, "z");
        }
    }, 300);

    static void Usable(double v, string what) => Expect.That(Math.Abs(v) <= WeightSolver.MaxCoordinate, what + " " + v.ToString("R") + " is not a usable coordinate");
}

