using Kosmos.PseudoHaptic.Simulation;

namespace Kosmos.PseudoHaptic.Cli.Traces;

/// <summary>
/// One row of a replay trace with every hand column (issue 10): the first hand's <c>t,hand_y,tracked,pose_t</c>
/// as a <see cref="TraceFrame"/>, its optional <c>hand_x,hand_z</c>, and the optional second hand
/// (<c>hand2_x,hand2_y,hand2_z,tracked2,pose2_t</c>). Absent x/z columns read as 0, an absent second hand as lost.
/// Issue 26: the rig's world pose in that row (<c>rig_x,rig_y,rig_z,rig_yaw</c>; the origin without them).
/// </summary>
public struct TraceRow
{
    public TraceFrame First;
    public double HandX, HandZ;
    public double Hand2X, Hand2Y, Hand2Z;
    public bool Tracked2;
    public double Pose2T;
    public RigFrame Rig;

    /// <summary>The first hand as the 3D solver takes it (the trace's <c>tracked</c> stands for confidence too).</summary>
    public HandPose FirstPose => new(HandX, First.HandY, HandZ, First.Tracked, First.Tracked, First.PoseTime);

    public HandPose SecondPose => new(Hand2X, Hand2Y, Hand2Z, Tracked2, Tracked2, Pose2T);

    /// <summary>
    /// A hand's world pose in the rig's frame, as the solver takes it. With <paramref name="horizontal"/> false
    /// (no <c>hand_x,hand_z</c> columns) only the height is known: the hand is taken over the rig's origin
    /// (x = z = 0 in the rig's frame), so a rig that walks or turns moves nothing but what it carries.
    /// </summary>
    public readonly HandPose InRig(in HandPose world, bool horizontal)
    {
        if (horizontal) return Rig.ToRig(world);
        return new HandPose(0, world.Y - Rig.Y, 0, world.IsTracked, world.IsHighConfidence, world.PoseTime);
    }
}
