using System;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// The paper covers lifting only (design note, open question 4). While the hand moves down, the offset
    /// between hand and object (relative to the one at the grab) never grows past what it was, or past
    /// <see cref="Slack"/>: a heavy object the hand lowers past follows it down instead of hanging above it, and
    /// a light one does not dive below it. The slack is tracking jitter's size: without it, every downward
    /// jitter of a still hand would drag an object held near the hand down and every upward one would lift it by
    /// only G times as much, a ratchet. Holding still moves nothing.
    /// </summary>
    public sealed class LoweringGuard : WeightEffect
    {
        public override string Name => "lowering-guard";
        public override EffectStage Stage => EffectStage.ObjectMotion;

        /// <summary>Offsets up to this size, m, may grow while lowering (jitter at rest is not lowering).</summary>
        public double Slack { get; }

        public LoweringGuard(double slack = 0.005)
        {
            Slack = ConfigurationGuard.InRange(slack, 0, 0.1, nameof(slack));
        }

        protected internal override void Apply(ref MotionFrame frame, ref HoldState state, in SolverConstants constants)
        {
            if (frame.HandDelta >= 0) return;
            double limit = Math.Abs(frame.OffsetBefore);
            if (limit < Slack) limit = Slack;
            double centre = frame.HandAfter - frame.ObjectY; // the delta that would leave no offset
            double lo = centre - limit, hi = centre + limit;
            double total = frame.TotalDelta;
            if (total < lo) frame.TotalDelta = lo;
            else if (total > hi) frame.TotalDelta = hi;
            else return;
            SpeedCap.Settle(ref state, frame.TotalDelta - total);
        }
    }
}
