using System;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// Son et al. 2022, §3.1: past a hand–object distance of 0.2 m the object's speed is corrected
    /// "in a gradual deceleration manner", "+0.02 (m) faster if lighter, −0.02 slower if heavier".
    /// Adopted reading (design note, open question 3): past the threshold the object moves more and more
    /// with the hand. Its share s of the hand's motion rises linearly from 0 at <see cref="Threshold"/> to 1 at
    /// threshold + <see cref="Band"/> (the paper's 0.02 m), judged at the step's midpoint (reversible: a still
    /// hand's jitter does not ratchet the object), so growth saturates smoothly; the offset the user sees
    /// never grows past threshold + band, however large one pose's step. Beyond the band (an offset left by
    /// re-anchoring) the object is drawn back toward the hand at up to <see cref="PullSpeed"/>, ramping up over
    /// five band widths. Position never jumps.
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
            // 1. Inside the band, against the deadbanded hand, by the implicit midpoint rule
            //    d = d0 + (1 − s((d0 + d)/2))·Δ: it is reversible, so jitter back and forth leaves the object where it
            //    was (a rule judged at one end would ratchet a still-held object toward the hand).
            double before = Math.Abs(frame.OffsetBefore);
            double after = Math.Abs(frame.HandAfter - frame.ObjectY - frame.TotalDelta);
            double delta = after - before;
            if (delta != 0 && (before > Threshold || after > Threshold) && !(delta < 0 && before >= Threshold + Band))
            {
                double reached = MidpointOffset(before, delta);
                double share = (after - reached) / delta; // of the change the hand's own motion would make
                frame.TotalDelta += share * (frame.HandDelta - frame.TotalDelta);
            }

            // 2. The offset the user sees never grows past the band's end, however large one pose's step.
            double visibleBefore = Math.Abs(frame.VisibleOffsetBefore);
            double visibleAfter = Math.Abs(frame.PoseHandAfter - frame.ObjectY - frame.TotalDelta);
            double ceiling = visibleBefore > Threshold + Band ? visibleBefore : Threshold + Band;
            if (visibleAfter > ceiling)
            {
                double share = (visibleAfter - ceiling) / (visibleAfter - visibleBefore);
                frame.TotalDelta += share * (frame.PoseHandAfter - frame.PoseHandBefore - frame.TotalDelta);
            }

            // 3. Offsets the hand's motion did not make (re-anchoring) are drawn back, against the deadbanded hand.
            double afterSigned = frame.HandAfter - frame.ObjectY - frame.TotalDelta;
            double beyond = Math.Abs(afterSigned) - (Threshold + Band);
            if (beyond > 0 && PullSpeed > 0)
            {
                double dt = frame.Dt < constants.Limits.MaxFrameTime ? frame.Dt : constants.Limits.MaxFrameTime;
                double ramp = 5 * Band;
                double speed = PullSpeed * (beyond >= ramp ? 1 : beyond / ramp);
                double pull = Math.Min(beyond, speed * dt);
                frame.TotalDelta += afterSigned > 0 ? pull : -pull;
            }
        }

        /// <summary>
        /// The offset d reached from <paramref name="d0"/> when the hand alone would change it by <paramref name="delta"/>:
        /// d = d0 + (1 − s(m))·Δ with m = (d0 + d)/2 and s(m) = clamp((m − T)/B, 0, 1), solved piecewise.
        /// </summary>
        double MidpointOffset(double d0, double delta)
        {
            double free = d0 + delta;
            if ((d0 + free) / 2 <= Threshold) return free;          // s = 0 over the whole step
            if (d0 >= Threshold + Band && free >= d0) return d0;     // s = 1: past the band nothing grows
            double denominator = 1 + delta / (2 * Band);
            double d = denominator > 0.25
                ? (d0 + delta * (1 - (d0 / 2 - Threshold) / Band)) / denominator
                : d0 + (1 - Clamp01((d0 - Threshold) / Band)) * delta; // a very large shrink: judge at the start
            double m = (d0 + d) / 2;
            if (m > Threshold + Band) d = d0;                        // the step ends past the band: s = 1
            // Between no correction and full correction, whatever rounding says.
            double lo = delta > 0 ? d0 : free, hi = delta > 0 ? free : d0;
            return d < lo ? lo : (d > hi ? hi : d);
        }

        static double Clamp01(double x) => x < 0 ? 0 : (x > 1 ? 1 : x);
    }
}
