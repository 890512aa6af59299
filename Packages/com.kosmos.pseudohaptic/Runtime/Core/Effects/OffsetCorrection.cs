using System;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// Son et al. 2022, §3.1: past a hand–object distance of 0.2 m the object's speed is corrected
    /// "in a gradual deceleration manner", "+0.02 (m) faster if lighter, −0.02 slower if heavier".
    /// Adopted reading (design note, open question 3): the correction acts against the offset's growth.
    /// Its strength rises from 0 at <see cref="Threshold"/> to full at threshold + <see cref="Band"/> (the
    /// paper's 0.02 m), where the object moves with the hand and the offset stops growing; beyond the band
    /// the object is also drawn back toward the hand at up to <see cref="PullSpeed"/>. The strength follows
    /// the offset up and is released over <see cref="RampTime"/>, so the object's speed changes gradually
    /// and its position never jumps.
    /// </summary>
    public sealed class OffsetCorrection : WeightEffect
    {
        public override string Name => "offset-correction";
        public override EffectStage Stage => EffectStage.ObjectMotion;

        public double Threshold { get; }
        public double Band { get; }
        public double PullSpeed { get; }
        public double RampTime { get; }

        public OffsetCorrection(double threshold = 0.2, double band = 0.02, double pullSpeed = 0.5, double rampTime = 0.1)
        {
            Threshold = ConfigurationGuard.InRange(threshold, 0.001, 10, nameof(threshold));
            Band = ConfigurationGuard.InRange(band, 0.001, 10, nameof(band));
            PullSpeed = ConfigurationGuard.InRange(pullSpeed, 0, 10, nameof(pullSpeed));
            RampTime = ConfigurationGuard.InRange(rampTime, 0, 10, nameof(rampTime));
        }

        protected internal override void Apply(ref MotionFrame frame, ref HoldState state, in SolverConstants constants)
        {
            double before = frame.OffsetBefore;
            double excess = Math.Abs(before) - Threshold;
            double dt = frame.Dt < constants.Limits.MaxFrameTime ? frame.Dt : constants.Limits.MaxFrameTime;

            // Strength rises with the offset across the band (continuous in position, so the speed changes by at
            // most (1 − G)·v_hand across those 2 cm) and is released over RampTime, so it never lets go at once.
            double target = excess <= 0 ? 0 : (excess >= Band ? 1 : excess / Band);
            double released = RampTime > 0 ? state.CorrectionLevel - dt / RampTime : 0;
            double level = target > released ? target : released;
            state.CorrectionLevel = level;
            if (level <= 0) return;

            double handMove = frame.HandAfter - frame.HandBefore;
            double after = frame.HandAfter - frame.ObjectY - frame.ObjectDelta;
            if (Math.Abs(after) > Math.Abs(before))
            {
                frame.ObjectDelta += level * (handMove - frame.ObjectDelta);
                after = frame.HandAfter - frame.ObjectY - frame.ObjectDelta;
            }

            double beyond = Math.Abs(after) - (Threshold + Band);
            if (beyond > 0 && PullSpeed > 0)
            {
                double ramp = 5 * Band; // full pull speed 5 band-widths past the band
                double speed = level * PullSpeed * (beyond >= ramp ? 1 : beyond / ramp);
                double pull = Math.Min(beyond, speed * dt);
                frame.ObjectDelta += after > 0 ? pull : -pull;
            }
        }

        protected internal override void Reset(ref HoldState state, double handY) => state.CorrectionLevel = 0;
    }
}
