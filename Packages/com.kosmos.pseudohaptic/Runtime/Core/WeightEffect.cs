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

        /// <summary>Called when a hold begins or the estimator re-anchors, to reset this effect's memory.</summary>
        protected internal virtual void Reset(ref HoldState state, double handY) { }

        public override string ToString() => Name;
    }
}
