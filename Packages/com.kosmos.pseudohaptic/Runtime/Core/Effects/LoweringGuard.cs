using System;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// The paper covers lifting only (design note, open question 4). While the hand moves down, the offset
    /// between hand and object never grows: a heavy object the hand lowers past follows it down instead of
    /// hanging above it, and a light one does not dive below it. Holding still moves nothing.
    /// </summary>
    public sealed class LoweringGuard : WeightEffect
    {
        public override string Name => "lowering-guard";
        public override EffectStage Stage => EffectStage.ObjectMotion;

        protected internal override void Apply(ref MotionFrame frame, ref HoldState state, in SolverConstants constants)
        {
            if (frame.HandDelta >= 0) return;
            double limit = Math.Abs(frame.OffsetBefore);
            double centre = frame.HandAfter - frame.ObjectY; // the delta that would leave no offset
            double lo = centre - limit, hi = centre + limit;
            double total = frame.TotalDelta;
            if (total < lo) frame.TotalDelta = lo;
            else if (total > hi) frame.TotalDelta = hi;
        }
    }
}
