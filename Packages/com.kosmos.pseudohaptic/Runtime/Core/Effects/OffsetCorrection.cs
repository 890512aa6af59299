using System;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// Son et al. 2022, §3.1: past a hand–object distance of 0.2 m the object's speed is corrected
    /// "in a gradual deceleration manner", "+0.02 (m) faster if lighter, −0.02 slower if heavier".
    /// Adopted reading (design note, open question 3): past the threshold the object moves more and more
    /// with the hand. Its share s of the hand's motion rises linearly from 0 at the threshold T to 1 at
    /// T + <see cref="Band"/> (the paper's 0.02 m), judged at the step's midpoint (reversible: a still
    /// hand's jitter does not ratchet the object), so growth saturates smoothly; the offset the user sees
    /// never grows past T + band, however large one pose's step. Beyond the band (an offset left by
    /// re-anchoring) the object is drawn back toward the hand at up to <see cref="PullSpeed"/>, ramping up over
    /// five band widths. Position never jumps. Offsets are measured from the one at the grab.
    /// The threshold depends on the mass, so the correction keeps weights apart instead of holding every heavy
    /// object at the same offset: T(m) = <see cref="Threshold"/> × clamp(1 + <see cref="PerDoubling"/> · log2(m / 1 kg),
    /// <see cref="MinScale"/>, <see cref="MaxScale"/>): with the defaults 0.2 m at 1 kg and 1 cm more per doubling
    /// of the mass (<see cref="ThresholdFor"/>), so that after the same lift heavier still settles lower.
    /// For objects heavier than the standard it is also lowered by <see cref="PaceShiftAt"/> of the held pace of the
    /// latest motion (<see cref="HoldState.HeldPace"/>), so that under the correction a faster lift, or a user with a
    /// lower v_std, still leaves the object higher (faster moves further); the pull keeps the mass's threshold.
    /// </summary>
    public sealed class OffsetCorrection : WeightEffect
    {
        public override string Name => "offset-correction";
        public override EffectStage Stage => EffectStage.ObjectMotion;

        /// <summary>The threshold for a 1 kg object, m.</summary>
        public double Threshold { get; }
        public double Band { get; }
        public double PullSpeed { get; }

        /// <summary>Relative change of the threshold per doubling of the mass.</summary>
        public double PerDoubling { get; }

        /// <summary>Bounds of the threshold relative to <see cref="Threshold"/>.</summary>
        public double MinScale { get; }
        public double MaxScale { get; }

        /// <summary>Largest lowering of the threshold for a fast lift of an object heavier than the standard, m.</summary>
        public double PaceShift { get; }

        /// <summary>Pace, relative to v_std, at which the threshold is lowered by half of <see cref="PaceShift"/>.</summary>
        public double HalfShiftPace { get; }

        public OffsetCorrection(double threshold = 0.2, double band = 0.02, double pullSpeed = 0.5,
            double perDoubling = 0.05, double minScale = 0.75, double maxScale = 1.14, double paceShift = 0.08, double halfShiftPace = 2)
        {
            PaceShift = ConfigurationGuard.InRange(paceShift, 0, 0.1, nameof(paceShift));
            HalfShiftPace = ConfigurationGuard.InRange(halfShiftPace, 0.01, 100, nameof(halfShiftPace));
            Threshold = ConfigurationGuard.InRange(threshold, 0.001, 10, nameof(threshold));
            Band = ConfigurationGuard.InRange(band, 0.001, 10, nameof(band));
            PullSpeed = ConfigurationGuard.InRange(pullSpeed, 0, 10, nameof(pullSpeed));
            PerDoubling = ConfigurationGuard.InRange(perDoubling, 0, 1, nameof(perDoubling));
            MinScale = ConfigurationGuard.InRange(minScale, 0.01, 1, nameof(minScale));
            MaxScale = ConfigurationGuard.InRange(maxScale, 1, 10, nameof(maxScale));
        }

        /// <summary>
        /// The threshold for an object of <paramref name="massKg"/>, m: Threshold × clamp(1 + PerDoubling · log2(m / 1 kg),
        /// MinScale, MaxScale). Defaults: 0.19 m at 0.5 kg, 0.20 at 1 kg, 0.21 at 2 kg, 0.223 at 5 kg, at most 0.228
        /// (so the visible offset, at most threshold + band, stays ≤ 0.248 m), at least 0.15 (objects up to about 35 g,
        /// the standard weight's lighter neighbours, which lead the hand).
        /// </summary>
        public double ThresholdFor(double massKg)
        {
            double scale = 1 + PerDoubling * Math.Log(massKg) / Math.Log(2); // m ≤ 0: −∞ or NaN, the least
            if (!(scale > MinScale)) scale = MinScale;
            if (scale > MaxScale) scale = MaxScale;
            return Threshold * scale;
        }

        protected internal override void Apply(ref MotionFrame frame, ref HoldState state, in SolverConstants constants)
        {
            double massThreshold = constants.OffsetThreshold; // ThresholdFor(the model's mass), set by the solver
            // Growth stops earlier after a faster lift (faster moves further); the pull back (3.) keeps the mass's own
            // threshold, so a change of pace never draws the object toward the hand by itself.
            double threshold = massThreshold - (constants.Gain < 1 ? PaceShiftAt(state.HeldPace, constants.StandardSpeed) : 0);
            double start = frame.TotalDelta;
            // 1. Inside the band, against the deadbanded hand, by the implicit midpoint rule
            //    d = d0 + (1 − s((d0 + d)/2))·Δ: it is reversible, so jitter back and forth leaves the object where it
            //    was (a rule judged at one end would ratchet a still-held object toward the hand).
            double before = Math.Abs(frame.OffsetBefore);
            double after = Math.Abs(frame.HandAfter - frame.ObjectY - frame.TotalDelta);
            double delta = after - before;
            bool pastThreshold = before > threshold || after > threshold;
            if (delta != 0 && pastThreshold && !(delta < 0 && before >= threshold + Band))
            {
                double reached = MidpointOffset(before, delta, threshold);
                double share = (after - reached) / delta; // of the change the hand's own motion would make
                frame.TotalDelta += share * (frame.HandDelta - frame.TotalDelta);
            }

            // 2. The offset the user sees never grows past the band's end, however large one pose's step.
            double visibleBefore = Math.Abs(frame.VisibleOffsetBefore);
            double visibleAfter = Math.Abs(frame.PoseHandAfter - frame.ObjectY - frame.TotalDelta);
            double ceiling = Math.Max(visibleBefore, threshold + Band);
            if (visibleAfter > ceiling)
            {
                double share = (visibleAfter - ceiling) / (visibleAfter - visibleBefore);
                frame.TotalDelta += share * (frame.PoseHandAfter - frame.PoseHandBefore - frame.TotalDelta);
            }

            // 3. Offsets the hand's motion did not make (re-anchoring) are drawn back, against the deadbanded hand, at up
            //    to PullSpeed, ramping up over five band widths past the band's end (nothing, +0, inside it).
            double afterSigned = frame.HandAfter - frame.ObjectY - frame.TotalDelta;
            double beyond = Math.Max(0, Math.Abs(afterSigned) - (massThreshold + Band));
            double speed = PullSpeed * Math.Min(1, beyond / (5 * Band));
            double pull = Math.Min(beyond, speed * Math.Min(frame.Dt, constants.Limits.MaxFrameTime));
            frame.TotalDelta += afterSigned > 0 ? pull : -pull;
            // Motion toward the hand pays what the speed cap owes. Motion the correction held back from the cap's
            // catch-up (in the band an object catching up with the hand is slowed) is owed again: delayed, not lost, so
            // the catch-up after a fast lift completes (stability.md, known limits, for what is left).
            double extra = frame.TotalDelta - start;
            // Stryker disable once Arithmetic : extra / owed has the sign of extra × owed; with nothing owed (±∞ or NaN) settling changes nothing
            bool paysTheCap = extra * state.CapDeferred > 0;
            if (paysTheCap) SpeedCap.Settle(ref state, extra);
            else if (extra * state.CapDeferred < 0) state.CapDeferred -= extra;
        }

        /// <summary>
        /// How much a lift at <paramref name="pace"/> (m/s, the held pace of the latest motion) lowers the threshold of an
        /// object heavier than the standard, for a user of standard speed <paramref name="standardSpeed"/>:
        /// PaceShift · x / (x + HalfShiftPace), x = pace / v_std. 0 at rest, rising continuously and strictly with x,
        /// below PaceShift: a faster lift (or a slower user) settles closer to the hand, and every object at the same
        /// pace is shifted alike, so the mass order and its gaps are kept.
        /// </summary>
        public double PaceShiftAt(double pace, double standardSpeed)
        {
            double x = Math.Min(Math.Abs(pace) / standardSpeed, double.MaxValue); // an infinite pace: the largest
            return PaceShift * x / (x + HalfShiftPace);
        }

        /// <summary>
        /// The offset d reached from <paramref name="d0"/> when the hand alone would change it by <paramref name="delta"/>:
        /// d = d0 + (1 − s(m))·Δ with m = (d0 + d)/2 and s(m) = clamp((m − T)/B, 0, 1), solved piecewise.
        /// </summary>
        double MidpointOffset(double d0, double delta, double threshold)
        {
            double free = d0 + delta;
            if ((d0 + free) / 2 <= threshold) return free; // s = 0 over the whole step
            // Solved with s linear. Past the band (s = 1) that solution falls short of d0, where the clamped rule stays:
            // nothing grows there.
            double denominator = 1 + delta / (2 * Band);
            // A very large shrink (|Δ| ≥ 1.5 band widths, only ever from inside the band, so 0 < s(d0) < 1): judged at the start.
            double d = denominator > 0.25
                ? (d0 + delta * (1 - (d0 / 2 - threshold) / Band)) / denominator
                : d0 + (1 - (d0 - threshold) / Band) * delta;
            return Math.Max(Math.Min(d0, free), d);
        }
    }
}
