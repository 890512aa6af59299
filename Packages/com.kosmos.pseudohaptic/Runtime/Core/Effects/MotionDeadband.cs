using System;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// A motion deadband on the hand the weight reads, only where the gain amplifies jitter: the lift of an object lighter
    /// than the standard moves only when the tracked hand leaves a band of ±e around the band's reference, so millimetre
    /// tracking jitter at rest, multiplied by a light object's lead, moves nothing (P4): the object shimmers with the hand
    /// that holds it, no more. At a gain of 1 or less nothing is amplified and the band is 0: the standard weight is exactly
    /// the hand (P1), and a heavier object's jitter is already smaller than the hand's.
    /// Above a gain of 1 the full half-width is w = span × (1 − 1/G), span = max(<see cref="JitterSpan"/>,
    /// v_std × <see cref="LagTime"/>). The band is not a plain backlash (whose reference, after any motion, sits at one edge,
    /// so that a one-pose glitch, a re-acquisition snap or a heft that crosses to the other edge moves it by 2w and the
    /// object by G × 2w: 42–48 mm at 1–10 g):
    /// <list type="bullet">
    /// <item>A push closes the band (e shrinks by what the push goes beyond it, the reference moving at most
    /// <see cref="CloseStep"/> / G beyond the hand's own step; across a gap no further than the hand's step), so sustained
    /// motion ends with the reference at the hand, whichever way it went. The band regrows with time between steady poses
    /// (0 to w in <see cref="RegrowTime"/>).</item>
    /// <item>At rest (a steady pose within the band) the reference is the mean of the steady hand (the median of three, blind
    /// to a one-pose glitch) since the last push, fading over <see cref="RestPoses"/>, moving at most CloseStep / G a pose and
    /// never leaving the band: where the hand comes to rest decides where the reference ends, not the path there.</item>
    /// <item>From the grab until the hand first moves (the band more than half closed, or the reference pushed a width from
    /// the grab), the grab's pose is the reference and a push of at most half a width drags it as a plain backlash: jitter at
    /// rest never turns an unlucky grab pose into a drift toward the mean.</item>
    /// </list>
    /// Measured (30 Hz poses over 90 Hz frames, 5 cm lift in 0.4 s): a one-pose glitch of 3 cm at rest, a 0.3 s loss with a
    /// 4 cm snap, a 3 cm heft each leave 1 g and 10 g within 0.1 mm of the clean path in every pipeline profile
    /// (<c>LightObjectDeadbandTests.TheAuditsGlitchSnapAndHeftLeaveNothing</c>); over seeds, within 1 cm
    /// (<c>ArtifactsLeaveALightObjectWhereTheCleanRunDoes</c>, <c>AHeftLeavesALightObjectWhereItWas</c>); jitter of 1.5 mm after
    /// a lift moves 1–40 g less than 1 cm in 10 s from 0.5 s after the hand stops (<c>JitterAfterALiftDoesNotCreep</c>).
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

        /// <summary>Time the band takes to regrow from closed to its full width once the hand stops pushing it, s: a few
        /// poses, longer than the hand's own deceleration at the end of a lift, shorter than jitter takes to wander.</summary>
        internal const double RegrowTime = 0.25;

        /// <summary>The most one pose may close the band, times the gain, m: the object's extra step while the band closes
        /// (the reference catching up with the hand) stays well within a centimetre of the hand's own, G times.</summary>
        internal const double CloseStep = 0.004;

        /// <summary>How many steady poses the reference averages at rest before older ones fade (an exponential mean over
        /// about a second at 30 Hz).</summary>
        internal const int RestPoses = 30;

        protected internal override void Apply(ref MotionFrame frame, ref HoldState state, in SolverConstants constants)
        {
            double w = constants.DeadbandWidth, h = frame.WeightHand;
            double since = 0;
            if (frame.SteadyTaken)
            {
                // Time counts between steady poses only: a frame that repeats the hand changes nothing.
                since = state.Time - state.DeadbandSteadyTime;
                state.DeadbandSteadyTime = state.Time;
            }
            if (w <= 0)
            {
                // Gain ≤ 1: nothing to suppress, nothing lost. Should the gain rise above 1 during the hold, the band starts
                // closed at the hand, as at the end of a motion, and regrows.
                state.DeadbandReference = h;
                state.DeadbandHalfWidth = 0;
                state.DeadbandRestCount = 1;
                return;
            }
            double r = state.DeadbandReference, e = state.DeadbandHalfWidth;
            // The band regrows with time, counted between steady poses (only on them: a frame that repeats the hand changes
            // nothing); sustained motion closes it faster than it regrows.
            if (since > 0) e += w * since / RegrowTime;
            if (!(e <= w)) e = w; // at most the width (+∞ at the grab; a gain that fell during the hold)
            double low = h - e, high = h + e;
            // The most the reference may move beyond the hand's own step this frame, times the gain: the object's extra step
            // (the band is open only where the gain is above 1, its width being taken from it).
            double perPose = CloseStep / constants.Gain;
            double spare = frame.AcrossGap ? 0 : perPose;
            if (r < low || r > high)
            {
                // The hand pushes the band: motion. The band closes by what the push goes beyond it, so sustained motion closes
                // it within its width and the reference ends a motion at the hand, not a half-width behind it, whichever way
                // the motion went; a few millimetres of jitter close it by as much, and it regrows. The reference moves at most
                // the hand's own step plus `spare` (across a gap, no more than the hand's step: the solver glides the rest).
                double push = r < low ? low - r : r - high;
                double step = Math.Abs(frame.HandDelta);
                double close = Math.Max(0, (step < double.PositiveInfinity ? step : 0) - push) + spare;
                if (close > push) close = push;
                // Until the hand first moves, the band is the grab's: a push jitter could make (up to half a width) drags it
                // as a plain backlash, closing nothing.
                if (state.DeadbandRestCount == 0 && push <= 0.5 * w) close = 0;
                e = e > close ? e - close : 0;
                r = r < low ? h - e : h + e;
                // A push ends the rest: the next one starts from where the push leaves the reference. At the grab the grab's
                // pose stays the reference (as the lift's base does) until the hand has moved: the band more than half
                // closed, or the reference pushed more than a width from where the hold began (jitter at rest does neither,
                // so it never turns an unlucky grab pose into a drift toward the mean).
                if (state.DeadbandRestCount > 0 || e < 0.5 * w || Math.Abs(r - state.DeadbandAnchor) > w) state.DeadbandRestCount = 1;
            }
            else if (frame.SteadyTaken)
            {
                int n = state.DeadbandRestCount;
                if (n > 0)
                {
                    // At rest after a motion: the reference is the mean of the steady hand since the motion ended (and where
                    // the motion left it), fading over RestPoses, so where a motion ends does not depend on the path it took
                    // there, and jitter moves it by its mean only. Each pose moves it by at most `spare` (the object by 4 mm),
                    // and it stays within the band.
                    n = n < RestPoses ? n + 1 : RestPoses;
                    state.DeadbandRestCount = n;
                    double move = (frame.SteadyHand - r) / n;
                    if (move > perPose) move = perPose;
                    else if (move < -perPose) move = -perPose;
                    r += move;
                    if (r < low) r = low;
                    else if (r > high) r = high;
                }
            }
            state.DeadbandHalfWidth = e;
            state.DeadbandReference = r;
            frame.WeightHand = r;
        }

        protected internal override void Reset(ref HoldState state, double handY)
        {
            state.DeadbandReference = state.DeadbandAnchor = handY;
            state.DeadbandHalfWidth = double.PositiveInfinity; // full width at the grab
            state.DeadbandRestCount = 0;                       // the grab's pose is the reference until the hand first moves
            state.DeadbandSteadyTime = state.Time;
        }
    }
}
