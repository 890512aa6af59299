namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// One effect a scene can switch on. Effects are immutable settings objects, shared by every hold that
    /// uses the profile; what a hold remembers lives in <see cref="HoldState"/>. Settings are validated in
    /// the constructor. An effect that is not in the profile is never called: it costs nothing.
    /// </summary>
    public abstract class WeightEffect
    {
        /// <summary>Short, stable name used in profiles, files and the command line.</summary>
        public abstract string Name { get; }

        public abstract EffectStage Stage { get; }

        /// <summary>The per-frame work. Must not allocate, throw, or produce a non-finite value.</summary>
        protected internal abstract void Apply(ref MotionFrame frame, ref HoldState state, in SolverConstants constants);

        /// <summary>
        /// True when this effect is a function of where the hand is: on a frame that shows no new pose and whose followed
        /// hand is bit for bit the last frame's, it would write exactly what it wrote on the last frame and change nothing
        /// in the hold (it reads no frame time, no clock, nothing that differs between such frames). When every effect of
        /// the hand-motion, base, lift and object-motion stages says so, the solver reuses the last frame's results of
        /// those stages instead of calling them (<see cref="LastWeight"/>). False by default: such an effect is called
        /// every frame.
        /// </summary>
        protected internal virtual bool IsFunctionOfHand => false;

        /// <summary>Called when a hold begins or the estimator re-anchors, to reset this effect's memory.</summary>
        protected internal virtual void Reset(ref HoldState state, double handY) { }

        public override string ToString() => Name;
    }
}
