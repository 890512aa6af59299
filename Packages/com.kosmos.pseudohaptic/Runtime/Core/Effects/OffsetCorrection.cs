using System;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// Son et al. 2022, §3.1: past a hand–object distance of 0.2 m the object's speed is corrected
    /// "in a gradual deceleration manner", "+0.02 (m) faster if lighter, −0.02 slower if heavier".
    /// Adopted reading (design note, open question 3): the correction acts against the offset's growth.
    /// Over the band from <see cref="Threshold"/> to threshold + <see cref="Band"/> (the paper's 0.02 m) the
    /// object's motion is blended toward the hand's, fully at the band's end, so the offset stops growing;
    /// beyond the band the object is drawn back toward the hand at up to <see cref="PullSpeed"/>, ramping up
    /// over one band width. Position never jumps; speed changes with the offset, so gradually.
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
            double before = frame.OffsetBefore;
            double excess = Math.Abs(before) - Threshold;
            double handMove = frame.HandAfter - frame.HandBefore;
            double after = frame.HandAfter - frame.ObjectY - frame.ObjectDelta;

            if (excess > 0 && Math.Abs(after) > Math.Abs(before))
            {
                double s = excess >= Band ? 1 : excess / Band;
                frame.ObjectDelta += s * (handMove - frame.ObjectDelta);
                after = frame.HandAfter - frame.ObjectY - frame.ObjectDelta;
            }

            double beyond = Math.Abs(after) - (Threshold + Band);
            if (beyond > 0 && PullSpeed > 0)
            {
                double dt = Math.Min(frame.Dt, constants.Limits.MaxFrameTime);
                double speed = beyond >= Band ? PullSpeed : PullSpeed * beyond / Band;
                double pull = Math.Min(beyond, speed * dt);
                frame.ObjectDelta += after > 0 ? pull : -pull;
            }
        }
    }
}
