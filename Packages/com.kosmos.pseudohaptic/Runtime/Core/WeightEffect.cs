namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// One effect a scene can switch on. Effects are immutable settings objects, shared by every hold that
    /// uses the profile; what a hold remembers lives in <see cref="HoldState"/>. Settings are validated in
    /// the constructor. An effect that is not in the profile is never called: it costs nothing. Each effect declares
    /// what it is once, in its own file (a static <see cref="EffectDescriptor"/>: name, stage, summary, settings with units,
    /// defaults and ranges, and a factory), which the Unity profile list, profile files (<see cref="ProfileJson"/>), the
    /// tool and the docs read; <see cref="EffectRegistry"/> lists them (register an effect of your own there).
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

        /// <summary>
        /// For the input and position stages, asked after a frame that ran the pipeline: true when, on any number of frames
        /// that follow whose sample repeats that frame's bit for bit (a 30 Hz pose over 72–120 Hz frames), whatever their
        /// frame times, <see cref="Apply"/> would write exactly what it wrote on that frame and change nothing in
        /// <paramref name="state"/> but what <see cref="AdvanceStill"/> changes. When every input and position effect says so
        /// and nothing else in the hold is moving, such frames are still: the solver advances its clocks and calls
        /// <see cref="AdvanceStill"/> (where <see cref="AdvancesWhenStill"/>) instead of running the pipeline, and the object
        /// stays where it is (<see cref="WeightSolver"/>, ALGORITHM.md §3). False by default: a scene's own effect is called
        /// every frame unless it overrides this.
        /// </summary>
        protected internal virtual bool IsStill(in HoldState state, in SolverConstants constants) => false;

        /// <summary>True when a still frame changes something of this effect's in the hold (a budget that refills with
        /// time): the solver then calls <see cref="AdvanceStill"/> on each. False by default.</summary>
        protected internal virtual bool AdvancesWhenStill => false;

        /// <summary>A still frame of <paramref name="dt"/> s (sanitised, as <see cref="Apply"/> would see it): changes in
        /// <paramref name="state"/> exactly what <see cref="Apply"/> would. Called only when <see cref="AdvancesWhenStill"/>.</summary>
        protected internal virtual void AdvanceStill(ref HoldState state, in SolverConstants constants, double dt) { }

        /// <summary>Called when a hold begins or the estimator re-anchors, to reset this effect's memory.</summary>
        protected internal virtual void Reset(ref HoldState state, double handY) { }

        public override string ToString() => Name;
    }
}
