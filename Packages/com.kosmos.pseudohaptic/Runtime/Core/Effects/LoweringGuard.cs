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

        /// <summary>For this long after it acted, s of pose time, the guard gives its pull back if the hand turns back up: a one-pose
        /// glitch down and back, or jitter, then leaves no trace (a one-sided pull would ratchet the object down).</summary>
        public const double GiveBackTime = 0.2;

        protected internal override void Apply(ref MotionFrame frame, ref HoldState state, in SolverConstants constants)
        {
            state.GuardAge += frame.MotionInterval; // pose time: every frame clock expires the debt at the same pose
            if (state.GuardAge > GiveBackTime) state.GuardDebt = 0;
            if (frame.HandDelta > 0)
            {
                // The hand turned back up: return what the guard added, moving the object at most as the hand moves.
                // The give-back lies between 0 and room: it moves the object toward the hand's own motion, never past it.
                double room = frame.HandDelta - frame.ObjectDelta; // > 0 for a heavy object, < 0 for a light one
                double back = Math.Min(Math.Max(-state.GuardDebt, Math.Min(room, 0)), Math.Max(room, 0));
                frame.ObjectDelta += back;
                state.GuardDebt += back;
                return;
            }
            if (frame.HandDelta == 0) return;
            double limit = Math.Max(Math.Abs(frame.OffsetBefore), Slack);
            double centre = frame.HandAfter - frame.ObjectY; // the delta that would leave no offset
            double total = frame.TotalDelta;
            double bounded = Math.Min(Math.Max(total, centre - limit), centre + limit);
            double added = bounded - total;
            frame.TotalDelta = bounded;
            state.GuardDebt += added;
            if (added != 0) state.GuardAge = 0; // the give-back window counts from when the guard last acted
            SpeedCap.Settle(ref state, added);
        }

        protected internal override void Reset(ref HoldState state, double handY)
        {
            state.GuardDebt = 0;
            state.GuardAge = 0;
        }
    }
}
