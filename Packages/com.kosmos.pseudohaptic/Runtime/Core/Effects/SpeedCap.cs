using System;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// A person does not lift 5 kg as fast as a golf ball (design note, open question 2): an object heavier than
    /// the standard moves no faster than the experimental speed of its mass rescaled to this user,
    /// v_cap = headroom · v_std · v_exp(m)/v_exp(m_std). The standard weight and lighter objects are not capped (the
    /// golf ball is rigid in the hand, P1). The default headroom 2.5 clears the peak of a smooth lift at the
    /// user's standard speed (1.875 × its mean speed) with room for jittery poses.
    /// Capped motion is deferred, not lost: the object keeps rising at v_cap after the hand stops until it has
    /// made up what the cap held back (at most <see cref="SolverLimits.MaxCarry"/>), so a faster lift never ends
    /// lower than a slower one (the cap never reverses <see cref="FasterMovesFurther"/>). Motion of the hand in
    /// the other direction cancels what is owed; the lowering guard, the offset correction and the floor settle it
    /// when they change the motion. The cap is judged per pose, over the pose's own interval: the object's speed
    /// over each pose never exceeds v_cap, and every frame clock showing the same poses gives the same motion.
    /// With a hand filter, which moves the hand between poses, each frame is judged over its own time.
    /// </summary>
    public sealed class SpeedCap : WeightEffect
    {
        public override string Name => "speed-cap";
        public override EffectStage Stage => EffectStage.ObjectMotion;

        /// <summary>Multiple of the user's rescaled experimental speed allowed, ≥ 1.</summary>
        public double Headroom { get; }

        public SpeedCap(double headroom = 2.5)
        {
            Headroom = ConfigurationGuard.InRange(headroom, 1, 100, nameof(headroom));
        }

        /// <summary>The cap for an object and a user, m/s: infinite for the standard weight and lighter objects.</summary>
        public double CapFor(WeightModel model, double standardSpeed)
            => model.MassKg > PhysicalConstants.StandardMassKg ? Headroom * standardSpeed * model.ExperimentalRatio : double.PositiveInfinity;

        protected internal override void Apply(ref MotionFrame frame, ref HoldState state, in SolverConstants constants)
        {
            double cap = constants.CapSpeed;
            // Stryker disable once Statement : a shortcut: an infinite allowance changes nothing below
            if (!(cap < double.PositiveInfinity)) return;
            // Judged per pose, over the pose's own interval, so every frame clock that shows the same poses makes the
            // same decisions; a frame without a new pose moves nothing and pays nothing. A hand filter spreads each
            // pose's motion over the frames after it: then every frame is judged over its own time (over the pose's
            // interval on its frame and again on the frames after, the object would outrun the cap). Motion an effect
            // makes on a frame without a new pose is judged over the frame.
            double window = frame.HandFiltered ? frame.Dt
                : (frame.MotionInterval > 0 ? frame.MotionInterval : (frame.ObjectDelta != 0 ? frame.Dt : 0));
            double allowed = cap * window; // no window, no allowance: motion in no time waits for the next frames
            double wanted = frame.ObjectDelta + state.CapDeferred; // a hand that turns back cancels what it is owed
            double step = Math.Min(Math.Max(wanted, -allowed), allowed);
            frame.ObjectDelta = step;
            double deferred = wanted - step, limit = constants.Limits.MaxCarry;
            state.CapDeferred = Math.Min(Math.Max(deferred, -limit), limit);
        }

        /// <summary>An effect after the cap changed the object's motion by <paramref name="extra"/>: in the direction of
        /// what the cap owes, that pays the debt; against it, a constraint blocked that much of it. Either way the
        /// debt shrinks by |extra| (never changing sign), so nothing is owed twice or pushed against a constraint.</summary>
        internal static void Settle(ref HoldState state, double extra)
        {
            double owed = state.CapDeferred;
            double left = Math.Abs(owed) - Math.Abs(extra);
            state.CapDeferred = left <= 0 ? 0 : (owed > 0 ? left : -left);
        }

        protected internal override void Reset(ref HoldState state, double handY) => state.CapDeferred = 0;
    }
}
