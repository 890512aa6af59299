using System;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// Son et al. 2022, §3.1: past a hand–object distance of 0.2 m the object's speed is corrected
    /// "in a gradual deceleration manner", "+0.02 (m) faster if lighter, −0.02 slower if heavier".
    /// Adopted reading (design note, open question 3): the correction acts against the offset's growth, in
    /// the direction that shrinks it. Its strength s rises linearly from 0 at <see cref="Threshold"/> to 1 at
    /// threshold + <see cref="Band"/> (the paper's 0.02 m) and is applied to the offset the frame would
    /// reach, solved exactly, so growth saturates smoothly and the offset never grows past threshold + band,
    /// however large one pose's step. Beyond the band (an offset left by re-anchoring) the object is drawn
    /// back toward the hand at up to <see cref="PullSpeed"/>, ramping up over five band widths. Position
    /// never jumps.
    /// </summary>
    public sealed class OffsetCorrection : WeightEffect
    {
        public override string Name => "offset-correction";
        public override EffectStage Stage => EffectStage.ObjectMotion;

        public double Threshold { get; }
        public double Band { get; }
        public double PullSpeed { get; }

        public OffsetCorrection(double threshold = 0.2, double band = 0.02, double pullSpeed = 0.5)
        {
            Threshold = ConfigurationGuard.InRange(threshold, 0.001, 10, nameof(threshold));
            Band = ConfigurationGuard.InRange(band, 0.001, 10, nameof(band));
            PullSpeed = ConfigurationGuard.InRange(pullSpeed, 0, 10, nameof(pullSpeed));
        }

        protected internal override void Apply(ref MotionFrame frame, ref HoldState state, in SolverConstants constants)
        {
            // Measured against the hand the user sees (before the deadband), since that offset is what must stay bounded.
            double before = Math.Abs(frame.VisibleOffsetBefore);
            double handMove = frame.PoseHandAfter - frame.PoseHandBefore;
            double afterSigned = frame.PoseHandAfter - frame.ObjectY - frame.TotalDelta;
            double after = Math.Abs(afterSigned);

            // Growth from jitter the deadband swallowed is left alone inside the band, or every twitch of a still
            // hand would ratchet the object toward it; past the band's end any growth is stopped.
            if (after > before && after > Threshold && (frame.HandDelta != 0 || after > Threshold + Band))
            {
                // The offset reached solves d = d0 + (1 − s(d))·g, s(d) = clamp((d − T)/B, 0, 1), g = the growth
                // without correction: in the ramp d = (d0 + g·(1 + T/B)) / (1 + g/B), which lies in [T, T + B].
                double g = after - before;
                double target = before >= Threshold + Band ? before : (before + g * (1 + Threshold / Band)) / (1 + g / Band);
                double s = (after - target) / g; // share of the growth removed: blend the object's motion toward the hand's
                frame.TotalDelta += s * (handMove - frame.TotalDelta);
                afterSigned = frame.PoseHandAfter - frame.ObjectY - frame.TotalDelta;
                after = Math.Abs(afterSigned);
            }

            // The pull answers offsets the hand's motion did not make (re-anchoring); it is measured against the
            // deadbanded hand for the same reason.
            afterSigned = frame.HandAfter - frame.ObjectY - frame.TotalDelta;
            after = Math.Abs(afterSigned);
            double beyond = after - (Threshold + Band);
            if (beyond > 0 && PullSpeed > 0)
            {
                double dt = frame.Dt < constants.Limits.MaxFrameTime ? frame.Dt : constants.Limits.MaxFrameTime;
                double ramp = 5 * Band;
                double speed = PullSpeed * (beyond >= ramp ? 1 : beyond / ramp);
                double pull = Math.Min(beyond, speed * dt);
                frame.TotalDelta += afterSigned > 0 ? pull : -pull;
            }
        }
    }
}
