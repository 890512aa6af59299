using System;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// A motion deadband (backlash) on the hand the weight reads, only where the gain amplifies jitter: the lift of
    /// an object lighter than the standard moves only when the tracked hand leaves a band of ±width around it, so
    /// millimetre tracking jitter at rest, multiplied by a light object's lead, moves nothing (P4): the object shimmers
    /// with the hand that holds it, no more. At a gain of 1 or less nothing is amplified and the band is 0: the
    /// standard weight is exactly the hand (P1), and a heavier object's jitter is already smaller than the hand's.
    /// Above a gain of 1 the half-width is w = span × (1 − 1/G), span = max(<see cref="JitterSpan"/>,
    /// v_std × <see cref="LagTime"/>). A motion that comes back moves the band's reference by at most w, so it leaves
    /// the lead at most (G − 1) × w different (the backlash's hysteresis).
    /// </summary>
    public sealed class MotionDeadband : WeightEffect
    {
        /// <summary>This effect's name, stage, summary and settings (<see cref="EffectRegistry"/>).</summary>
        public static readonly EffectDescriptor Descriptor = new EffectDescriptor("motion-deadband", EffectStage.HandMotion, typeof(MotionDeadband),
            "design note, open question 2",
            "backlash on the hand the weight reads where the gain amplifies jitter (G > 1): jitter at rest, times a light object's lead, moves nothing",
            s => new MotionDeadband(s[0], s[1]),
            SettingDescriptor.Number<MotionDeadband>("lagTime", "s", 0.006, 0, 0.1, "lag the band may cost at the user's standard speed", e => e.LagTime),
            SettingDescriptor.Number<MotionDeadband>("jitterSpan", "m", 0.012, 0, 0.05, "how far a hand pose at rest wanders over seconds", e => e.JitterSpan));

        public override string Name => Descriptor.Name;
        public override EffectStage Stage => Descriptor.Stage;
        /// <summary>The same hand leaves the band's reference where the last frame put it.</summary>
        protected internal override bool IsFunctionOfHand => true;

        /// <summary>Lag the band may cost at the user's standard speed, s (a fast user's jitter span grows with their speed).</summary>
        public double LagTime { get; }

        /// <summary>How far a Quest 2 hand pose at rest wanders from where it started over seconds, m (about ±3σ of
        /// 1.5 mm jitter, the difference of two such poses).</summary>
        public double JitterSpan { get; }

        public MotionDeadband(double lagTime = 0.006, double jitterSpan = 0.012)
        {
            LagTime = Descriptor.Settings[0].Check(lagTime);
            JitterSpan = Descriptor.Settings[1].Check(jitterSpan);
        }

        /// <summary>The band's half-width for a user and an object's gain, m: max(span, v_std × lag time) × (1 − 1/G)
        /// above a gain of 1, else 0.</summary>
        public double WidthFor(double standardSpeed, double gain)
            => gain > 1 ? Math.Max(LagTime * standardSpeed, JitterSpan) * (1 - 1 / gain) : 0;

        protected internal override void Apply(ref MotionFrame frame, ref HoldState state, in SolverConstants constants)
        {
            double w = constants.DeadbandWidth, h = frame.WeightHand;
            if (w <= 0) { state.DeadbandReference = h; return; } // gain ≤ 1: nothing to suppress, nothing lost
            double r = state.DeadbandReference;
            double next = r < h - w ? h - w : (r > h + w ? h + w : r);
            frame.WeightHand = next;
            state.DeadbandReference = next;
        }

        protected internal override void Reset(ref HoldState state, double handY) => state.DeadbandReference = handY;
    }
}
