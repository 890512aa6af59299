using FsCheck.Fluent;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Properties.Tests;

/// <summary>The solver's rules over generated holds (FsCheck), beside the package's fixed-seed properties.</summary>
[TestFixture]
public class SolverProperties
{
    /// <summary>
    /// Issue 22's rule 1 (P12, ALGORITHM.md §2) on its own family of holds, generated: one lift of 0.15–0.6 m in 0.4–2 s from
    /// rest, sometimes lowered again, clean and with one artifact more (a one-pose glitch of 2–20 cm at rest or in motion, a
    /// loss of up to 1 s, a low-confidence burst of up to 0.6 s, a loss and a 2–8 cm snap), under every named profile the y
    /// solver runs, at the standard weight and 0.5–5 kg: within 1 mm (the standard weight) or 10 mm 0.5 s after the artifact
    /// and at the end. TrackingArtifactTests checks the same over 250 fixed seeds; here FsCheck draws the lift, the artifact
    /// and the headset anew from its seed and shrinks what fails.
    /// </summary>
    [Test]
    public void AnArtifactLeavesNothingOnALift() => Checks.Hold(ArtifactCase.OneLift(), LeavesNothing, 300);

    /// <summary>
    /// The same rule over paths of several moves (ArtifactCase.AnyPath: one to five moves anywhere from 0.5 to 1.6 m, with
    /// pauses). A search, not a test of the rule as stated: over such paths it finds cases beyond 10 mm, each listed with its
    /// cause in ALGORITHM.md (§2, "Rule 1 over generated holds") and quality.md ("Generated properties"). Run it with a seed and
    /// more cases to see one, shrunk:
    /// PSEUDOHAPTIC_PROPERTY_SEED=2 PSEUDOHAPTIC_PROPERTY_SCALE=10 dotnet test Tests/Kosmos.PseudoHaptic.Properties.Tests --filter Name~OnPathsOfSeveralMoves
    /// </summary>
    [Test, Explicit("a search: over paths of several moves the rule has known exceptions (ALGORITHM.md §2)")]
    public void SearchAnArtifactLeavesNothingOnPathsOfSeveralMoves() => Checks.Hold(ArtifactCase.AnyPath(), LeavesNothing, 300);

    /// <summary>Clean and with the artifact, the object is within the rule's bound 0.5 s after the artifact and at the end.
    /// An artifact that hides a new lowest point of the hand is left out: the base is the lowest point the hold saw, and
    /// one no usable pose showed cannot be remembered.</summary>
    static void LeavesNothing(ArtifactCase c)
    {
        var path = c.Path(out double at, out double artifactEnd);
        if (ArtifactCase.HidesALowestPoint(path, at, artifactEnd)) { Prop.Discard<bool>(); return; }
        Expect.AtMost(c.Difference(path, at, artifactEnd, out double bound), bound, "clean and with the artifact, 0.5 s after it or at the end, m");
    }

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

