namespace Kosmos.PseudoHaptic.Cli.Commands;

/// <summary>What <c>replay</c> and <c>demo</c> step: the package's <see cref="WeightSolver3D"/>, or the paper as printed
/// (<see cref="PaperLiteralSolver"/>, profile <c>paper-literal</c>).</summary>
public interface IReplayedObject
{
    WeightProfile Profile { get; }
    double MassKg { get; }
    double StandardSpeed { get; }
    double CueStrength { get; }
    bool IsHolding { get; }
    double ObjectX { get; }
    double ObjectY { get; }
    double ObjectZ { get; }
    void BeginHoldWithGrabOffset(in HandPose first, in HandPose second, double objectX, double grabOffsetY, double objectZ);
    void Step(in HandPose first, in HandPose second, double dt);
}

/// <summary>The package's solver, as replay has always run it.</summary>
public sealed class ReplayedSolver3D(WeightSolver3D solver) : IReplayedObject
{
    public WeightSolver3D Solver { get; } = solver;
    public WeightProfile Profile => Solver.Profile;
    public double MassKg => Solver.Model.MassKg;
    public double StandardSpeed => Solver.Vertical.StandardSpeed;
    public double CueStrength => Solver.CueStrength;
    public bool IsHolding => Solver.IsHolding;
    public double ObjectX => Solver.ObjectX;
    public double ObjectY => Solver.ObjectY;
    public double ObjectZ => Solver.ObjectZ;
    public void BeginHoldWithGrabOffset(in HandPose first, in HandPose second, double objectX, double grabOffsetY, double objectZ)
        => Solver.BeginHoldWithGrabOffset(first, second, objectX, grabOffsetY, objectZ);
    public void Step(in HandPose first, in HandPose second, double dt) => Solver.Step(first, second, dt);
}

/// <summary>
/// <c>paper-literal</c>: the paper's y (<see cref="PaperLiteralSolver"/>) from the first hand only, as the accuracy
/// page's baseline runs it (the hold begins at the first usable row, dt from the rows' times); the paper moves objects on
/// y only, so x and z keep the grab's horizontal offset to the first hand and stay where they were while it is not usable.
/// </summary>
public sealed class ReplayedPaperLiteral(double massKg, double cueStrength, double maxGain) : IReplayedObject
{
    readonly PaperLiteralSolver _solver = new(massKg) { CueStrength = cueStrength, MaxGain = maxGain };
    double _x, _z, _gx, _gz, _grabY;
    bool _holding;

    public WeightProfile Profile => NamedProfiles.PaperLiteral;
    public double MassKg => massKg;
    public double StandardSpeed { get; init; } = WeightSolver.DefaultStandardSpeed;
    public double CueStrength => _solver.CueStrength;
    public bool IsHolding => _holding;
    public double ObjectX => _x;
    // The solver holds the object at the hand; the grab's offset is taken off at the end, so that the path with an offset
    // is the path without it shifted by −D exactly (issue 9's contract), not integrated from another height.
    public double ObjectY => _solver.ObjectY - _grabY;
    public double ObjectZ => _z;

    public void BeginHoldWithGrabOffset(in HandPose first, in HandPose second, double objectX, double grabOffsetY, double objectZ)
    {
        _grabY = grabOffsetY;
        _solver.BeginHold(first.Y, first.Y);
        _x = objectX;
        _z = objectZ;
        _gx = objectX - first.X;
        _gz = objectZ - first.Z;
        _holding = true;
    }

    public void Step(in HandPose first, in HandPose second, double dt)
    {
        _solver.Step(first.Y, first.IsUsable, dt);
        if (first.IsUsable) { _x = first.X + _gx; _z = first.Z + _gz; }
    }
}
