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
    /// <item>From the grab until the hand has shown it moved, the band is a plain backlash on the grab's pose: a push of at
    /// most half a width drags it, closing nothing, and a larger one closes it the more the larger it is. The weight reads that
    /// backlash moved toward what rule 2 gives (run alongside, fading over <see cref="GrabRestPoses"/>) by how far the hand has
    /// shown it moved, 0 to 1, the larger yet of two ramps: the backlash dragged half a width to a width from the grab (a push
    /// that closes the band drags it at least twice as far as it closes it), the steady hand's mean a quarter to a half of a
    /// width from its mean over the first <see cref="EarlyPoses"/> steady poses. At 1 the rules above carry on. Jitter at rest
    /// moves neither, and an unlucky grab pose enters neither (its distance from the mean is not motion), so it never turns
    /// into a drift toward the mean; a slow lift of a few millimetres moves the mean, so it ends where the weight puts it;
    /// and nothing switches at a threshold.</item>
    /// <item>The grab's pose is not where the hand rests (jitter alone puts it up to 5 mm away, and G times that would be
    /// the object's offset once the hand moves): until the hand shows it moved, the hold's first <see cref="EarlyPoses"/>
    /// steady poses move the lift's base and the band together to their mean (<see cref="SettleBase"/>). Once they all
    /// showed a hand at rest, a push is motion or a glitch and the rules after motion take over at once.</item>
    /// </list>
    /// Measured (30 Hz poses over 90 Hz frames, 5 cm lift in 0.4 s): a one-pose glitch of 3 cm at rest, a 0.3 s loss with a
    /// 4 cm snap, a 3 cm heft each leave 1 g and 10 g within 0.1 mm of the clean path in every pipeline profile
    /// (<c>LightObjectDeadbandTests.TheAuditsGlitchSnapAndHeftLeaveNothing</c>); over seeds, within 1 cm
    /// (<c>ArtifactsLeaveALightObjectWhereTheCleanRunDoes</c>, <c>AHeftLeavesALightObjectWhereItWas</c>); jitter of 1.5 mm after
    /// a lift moves 1–40 g less than 1 cm in 10 s from 0.5 s after the hand stops (<c>JitterAfterALiftDoesNotCreep</c>); a slow
    /// lift of 5–20 mm from the grab ends within 0.6 mm of where the weight without a band puts it (within 2.9 mm over 200
    /// Quest-like seeds; <c>ASlowSmallLiftFromTheGrabEndsWhereTheWeightPutsIt</c>), and scanning the lift finely shows no step
    /// (<c>WhereALightObjectEndsHasNoStepAcrossTheGrabsRule</c>).
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

        const double InverseRestPoses = 1.0 / RestPoses;

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
                // Gain ≤ 1: nothing to suppress, nothing lost; the reference is the hand. The half-width is negative while
                // there is no band, so that a gain risen above 1 during the hold is told below, and the steady hand's mean
                // since the band went (fading over RestPoses) is kept for where such a band starts.
                if (!(state.DeadbandHalfWidth < 0)) state.DeadbandGrabCount = 0;
                if (frame.SteadyTaken)
                {
                    // This runs on every new pose of a heavy object, so once the mean fades over RestPoses it multiplies by the
                    // reciprocal instead of dividing (a division here cost a new-pose frame 2.5 ns).
                    double m = state.DeadbandGrabMean;
                    int n = state.DeadbandGrabCount;
                    if (n < RestPoses)
                    {
                        state.DeadbandGrabCount = ++n;
                        state.DeadbandGrabMean = m + FadeStep(m, frame.SteadyHand, n);
                    }
                    else state.DeadbandGrabMean = m + FadeStepByReciprocal(m, frame.SteadyHand, InverseRestPoses);
                }
                state.DeadbandReference = h;
                state.DeadbandHalfWidth = double.NegativeInfinity;
                state.DeadbandRestCount = 1;
                state.DeadbandMoved = 1;
                return;
            }
            if (state.DeadbandHalfWidth < 0)
            {
                // The gain has risen above 1 during the hold. With the hand within the band's width of the grab's pose (at rest
                // where it was grabbed), the band starts as at a grab on the steady hand's mean, a backlash under the grab's
                // rule (a slow lift right after the change ends within 0.59 mm of where the weight without a band puts it;
                // started closed at the hand, 1.02 mm; on the grab's own pose, which may lie 5.6 mm from where the hand rests,
                // the object sat up to 17.1 mm from where that weight puts it: BecomingLightMidHoldTests). Farther from the
                // grab's pose (after a lift, where that mean still lags) it starts closed at the hand, as at the end of a
                // motion, and regrows.
                if (Math.Abs(h - state.DeadbandAnchor) <= w)
                {
                    Reset(ref state, state.DeadbandGrabCount > 0 ? state.DeadbandGrabMean : h);
                    state.DeadbandSettle = NotSettled; // the lift stays measured from the hold's base
                }
                else state.DeadbandHalfWidth = 0;
            }
            double r = state.DeadbandReference, e = state.DeadbandHalfWidth;
            // From the grab until the hand has shown it moved, the band's backlash runs on a reference of its own (the grab's
            // pose, dragged by pushes), and the weight reads it moved toward what the rest rule gives as far as the hand has
            // shown it moved (below).
            bool grab = state.DeadbandMoved < 1;
            if (grab) r = state.DeadbandGrabReference;
            // The band regrows with time, counted between steady poses (only on them: a frame that repeats the hand changes
            // nothing); sustained motion closes it faster than it regrows.
            if (since > 0) e += w * since / RegrowTime;
            if (!(e <= w)) e = w; // at most the width (+∞ at the grab; a gain that fell during the hold)
            double low = h - e, high = h + e;
            // The most the reference may move beyond the hand's own step this frame, times the gain: the object's extra step
            // (the band is open only where the gain is above 1, its width being taken from it).
            double perPose = CloseStep / constants.Gain;
            double spare = frame.AcrossGap ? 0 : perPose;
            bool pushed = r < low || r > high, settledPush = false;
            if (pushed)
            {
                // The hand pushes the band: motion. The band closes by what the push goes beyond it, so sustained motion closes
                // it within its width and the reference ends a motion at the hand, not a half-width behind it, whichever way
                // the motion went; a few millimetres of jitter close it by as much, and it regrows. The reference moves at most
                // the hand's own step plus `spare` (across a gap, no more than the hand's step: the solver glides the rest).
                double push = r < low ? low - r : r - high;
                double step = Math.Abs(frame.HandDelta);
                double close = Math.Max(0, (step < double.PositiveInfinity ? step : 0) - push) + spare;
                if (close > push) close = push;
                // Until the hand has moved, a push jitter could make (up to half a width) drags the band as a plain backlash,
                // closing nothing; a larger one closes it the more the larger it is (all of it from a whole width), and once
                // the hand has shown it moved, as after any motion.
                // Once the hold's first poses have all shown a hand at rest and set where it rests, a push is motion or a glitch,
                // not jitter about an unlucky grab pose: the rule after motion takes over, whose reference goes back to where
                // the hand rests (a plain backlash would keep a glitch's drag: G × up to half a width). It starts from where
                // the push leaves the reference, as after any push, not from the rest rule's run alongside, which may lie a
                // band width from it (the object jumped G times that under a wide band). Only while nothing has shown motion
                // yet: a share of the way already taken (the steady hand's mean drifting with jitter) goes on as the grab's
                // rule has it (taken all the way at the first push, jitter at rest from the grab moved a 10 g object 4.65 mm
                // after its first second, not 1.17 mm).
                settledPush = grab && state.DeadbandSettle == Settled && state.DeadbandMoved == 0;
                if (settledPush) state.DeadbandMoved = 1;
                if (grab) close *= Math.Max(Ramp(push, 0.5 * w, w), state.DeadbandMoved);
                e = e > close ? e - close : 0;
                r = r < low ? h - e : h + e;
                if (settledPush) state.DeadbandRestMean = r;
                // A push ends the rest: the next one starts from where the push leaves the reference.
                if (!grab || settledPush) state.DeadbandRestCount = 1;
            }
            // At rest after a motion: the reference is the mean of the steady hand since the motion ended (and where the motion
            // left it), fading over RestPoses, so where a motion ends does not depend on the path it took there, and jitter
            // moves it by its mean only. Each pose moves it by at most `spare` (the object by 4 mm), and it stays within the band.
            else if (frame.SteadyTaken && !grab) r = RestStep(ref state, r, frame.SteadyHand, perPose, h - e, h + e);
            if (grab)
            {
                // What the rest rule would make of the reference (the rule above, fading over GrabRestPoses only, so that it
                // is at the hand's mean soon after a small motion that pushed nothing): pushed to the band's edge, its mean
                // restarting there, or moving toward the steady hand's mean.
                double rest = state.DeadbandRestMean;
                if (rest < h - e || rest > h + e)
                {
                    rest = rest < h - e ? h - e : h + e;
                    state.DeadbandRestCount = 1;
                }
                else if (frame.SteadyTaken && !settledPush) // (a settled push starts the rule after motion where it leaves the reference)
                {
                    rest = RestStep(ref state, rest, frame.SteadyHand, perPose, h - e, h + e);
                    if (state.DeadbandRestCount > GrabRestPoses) state.DeadbandRestCount = GrabRestPoses;
                }
                // Whether the hand moved: the reference dragged half a width to a width from the grab's pose, or the steady
                // hand's mean since the grab a quarter to a half of a width from its mean over the hold's first EarlyPoses
                // steady poses (jitter moves that mean by its own noise only, and an unlucky grab pose is in neither: it is
                // the rest rule's drift toward the mean from such a pose that the grab's rule keeps away). Each ramps from 0
                // to 1 and the larger yet counts. How far the band has closed is not read: a push closes it by at most what
                // it drags the reference beyond the band, so while the hand goes one way the reference has been dragged at
                // least twice what the band closed, and a ramp of the closing (a quarter to a half of a width) never led the
                // dragged one; only a shake at the grab, out past the band and back past its other side, told them apart.
                double a = state.DeadbandAnchor, mean = state.DeadbandGrabMean;
                int k = state.DeadbandGrabCount;
                // A steady pose farther than a glitch from the first poses' mean ends the settling before it is taken in: a glitch
                // of two or three poses (which the median of three passes) must not become where the hand rests.
                if (state.DeadbandSettle == Settling && frame.SteadyTaken && k > 0 && Math.Abs(frame.SteadyHand - state.DeadbandEarlyMean) > SettleGlitch)
                    state.DeadbandSettle = NotSettled;
                if (frame.SteadyTaken)
                {
                    if (k < RestPoses) state.DeadbandGrabCount = ++k;
                    mean += FadeStep(mean, frame.SteadyHand, k < RestPoses ? k + 1 : RestPoses);
                    state.DeadbandGrabMean = mean;
                    if (k <= EarlyPoses) state.DeadbandEarlyMean += FadeStep(state.DeadbandEarlyMean, frame.SteadyHand, k);
                }
                double moved = state.DeadbandMoved;
                moved = Math.Max(moved, Ramp(Math.Abs(r - a), 0.5 * w, w));
                if (k >= EarlyPoses) moved = Math.Max(moved, Ramp(Math.Abs(mean - state.DeadbandEarlyMean), 0.25 * w, 0.5 * w));
                state.DeadbandMoved = moved;
                if (state.DeadbandSettle == Settling)
                {
                    if (moved > 0 || r != a || frame.Bridged || state.Time - state.DeadbandGrabTime > SettleTime) state.DeadbandSettle = NotSettled;
                    else if (frame.SteadyTaken)
                    {
                        SettleBase(ref state, ref r, k);
                        frame.BaseMeasured = true;
                        if (k >= EarlyPoses) state.DeadbandSettle = Settled;
                    }
                }
                state.DeadbandGrabReference = r;
                state.DeadbandRestMean = rest;
                // The weight reads the backlash moved that share of the way to the rest rule's reference (both within the band):
                // nothing switches at a threshold. Moved all the way, the rest rule carries on from its reference and count.
                r = moved >= 1 ? rest : r + moved * (rest - r);
            }
            state.DeadbandHalfWidth = e;
            state.DeadbandReference = r;
            frame.WeightHand = r;
        }

        /// <summary>The rest rule's step on a steady pose: the reference moves toward the pose by 1/n (n counting the poses since
        /// the last push, capped at RestPoses), at most <paramref name="perPose"/>, within the band.</summary>
        static double RestStep(ref HoldState state, double r, double steady, double perPose, double low, double high)
        {
            int n = state.DeadbandRestCount;
            n = n < RestPoses ? n + 1 : RestPoses;
            state.DeadbandRestCount = n;
            double move = FadeStep(r, steady, n);
            if (move > perPose) move = perPose;
            else if (move < -perPose) move = -perPose;
            r += move;
            if (r < low) r = low;
            else if (r > high) r = high;
            return r;
        }

        /// <summary>
        /// From a grab, while the hand has not shown it moved, each of the hold's first <see cref="EarlyPoses"/> steady poses
        /// moves the lift's base, the band's anchor and its backlash reference to the mean of those poses: the lift of a light
        /// object is measured from where the hand rests at the grab, not from the grab's own pose, which jitter alone puts up
        /// to 5 mm from it. Measured from that pose, a heft or a glitch right after the grab (anything that shows motion, after
        /// which the reference goes to where the hand rests) left the object G times that distance from where it rested
        /// (10.8 mm at 5 g). Base and reference move together, so the object moves with them once, not G times.
        /// The first such pose sets the base to the mean (the solver may already have moved it there from a glitched grab
        /// pose, <c>WeightSolver.AnchorGlitch</c>; no effect of the named profiles moves it before the first steady pose, and
        /// a scene's own base effect that did would lose those two poses' change).
        /// </summary>
        static void SettleBase(ref HoldState state, ref double reference, int poses)
        {
            double mean = state.DeadbandEarlyMean, shift = mean - state.DeadbandAnchor;
            state.DeadbandAnchor = mean;
            reference += shift;
            state.Base = poses == 1 ? mean : state.Base + shift;
        }

        /// <summary><see cref="HoldState.DeadbandSettle"/>: the first poses' mean is not (or no longer) where the lift is measured
        /// from; it is becoming so; it is, all of them having shown a hand at rest.</summary>
        internal const int NotSettled = 0, Settling = 1, Settled = 2;

        /// <summary>How long after the grab its first poses may set where the lift is measured from, s: <see cref="EarlyPoses"/>
        /// steady poses take 0.23 s at Quest's 30 Hz; poses that repeat (a tracker that freezes, taken again every
        /// <see cref="SolverLimits.RepeatTime"/>) would stretch them into the hand's first motion.</summary>
        internal const double SettleTime = 0.3;

        /// <summary>How far a steady pose may lie from the mean of the hold's first poses while they still set where the lift is
        /// measured from, m: more than Quest's jitter at rest (as the solver's own test of the grab's pose).</summary>
        internal const double SettleGlitch = 0.005;

        /// <summary>How many steady poses from the grab make the hold's first mean, against which the hand's later mean tells
        /// a motion (0.2 s at 30 Hz, from the third pose).</summary>
        internal const int EarlyPoses = 6;

        /// <summary>How many steady poses the rest rule's reference averages before the hand has shown it moved: a small motion
        /// that pushed nothing ends with it at the hand's mean within a few tenths of a second.</summary>
        internal const int GrabRestPoses = 6;

        /// <summary>The step of a fading mean <paramref name="mean"/> taking in <paramref name="x"/> as its
        /// <paramref name="n"/>th value (or fading over n): (x − mean) / n.</summary>
        static double FadeStep(double mean, double x, int n) => (x - mean) / n;

        /// <summary>The same step with 1/n given: (x − mean) × <paramref name="reciprocal"/> (a multiplication where a division
        /// would run on every new pose).</summary>
        static double FadeStepByReciprocal(double mean, double x, double reciprocal) => (x - mean) * reciprocal;

        /// <summary>0 at or below <paramref name="from"/>, 1 at or above <paramref name="to"/>, linear between.</summary>
        static double Ramp(double x, double from, double to)
            => !(x > from) ? 0 : x >= to ? 1 : (x - from) / (to - from);

        protected internal override void Reset(ref HoldState state, double handY)
        {
            state.DeadbandReference = state.DeadbandAnchor = handY;
            state.DeadbandHalfWidth = double.PositiveInfinity; // full width at the grab
            state.DeadbandRestCount = 1;
            state.DeadbandGrabReference = state.DeadbandGrabMean = state.DeadbandEarlyMean = state.DeadbandRestMean = handY;
            state.DeadbandGrabCount = 0;
            state.DeadbandMoved = 0;                           // the grab's pose is the reference until the hand first moves
            state.DeadbandSettle = Settling;
            state.DeadbandSteadyTime = state.DeadbandGrabTime = state.Time;
        }
    }
}
