using System;
using System.Collections.Generic;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// The effects a scene calls for, in the order the frame flows through them (by <see cref="EffectStage"/>,
    /// then as given), and the safety limits. Immutable and shareable by any number of holds. An effect not
    /// listed is never called. See <see cref="NamedProfiles"/> for the paper's presets.
    /// </summary>
    public sealed class WeightProfile
    {
        public string Name { get; }
        public IReadOnlyList<WeightEffect> Effects => _all;
        public SolverLimits Limits { get; }

        /// <summary>Optional smoother of the followed hand height (null: follow each pose exactly, the default).</summary>
        public IHandFilter HandFilter { get; }

        internal readonly WeightEffect[] _all;
        internal readonly WeightEffect[] InputEffects;
        internal readonly WeightEffect[] HandEffects;
        internal readonly WeightEffect[] BaseEffects;
        internal readonly WeightEffect[] LiftEffects;
        internal readonly WeightEffect[] ObjectEffects;
        internal readonly WeightEffect[] PositionEffects;

        /// <summary>The input and position effects a still frame advances (<see cref="WeightEffect.AdvancesWhenStill"/>).</summary>
        internal readonly WeightEffect[] AdvancingWhenStill;

        /// <summary>Every effect of the hand-motion, base, lift and object-motion stages is a function of where the hand is
        /// (<see cref="WeightEffect.IsFunctionOfHand"/>): a frame that repeats the last one's hand reuses the last frame's
        /// weight instead of calling them.</summary>
        public bool WeightIsFunctionOfHand { get; }

        public WeightProfile(string name, IEnumerable<WeightEffect> effects, SolverLimits limits = null, IHandFilter handFilter = null)
        {
            if (string.IsNullOrWhiteSpace(name)) throw new ArgumentException("name must not be empty.", nameof(name));
            if (effects == null) throw new ArgumentNullException(nameof(effects));
            Name = name;
            Limits = limits ?? SolverLimits.Default;
            HandFilter = handFilter;

            var list = new List<WeightEffect>();
            foreach (var e in effects)
            {
                if (e == null) throw new ArgumentException("effects must not contain null.", nameof(effects));
                foreach (var other in list)
                    if (other.GetType() == e.GetType())
                        throw new ArgumentException("effects lists " + e.Name + " twice.", nameof(effects));
                list.Add(e);
            }
            // Stable sort by stage keeps the given order within a stage.
            var sorted = new List<WeightEffect>(list.Count);
            for (int stage = (int)EffectStage.Input; stage <= (int)EffectStage.Hold; stage++)
                foreach (var e in list)
                    if ((int)e.Stage == stage) sorted.Add(e);
            _all = sorted.ToArray();
            InputEffects = OfStage(EffectStage.Input);
            HandEffects = OfStage(EffectStage.HandMotion);
            BaseEffects = OfStage(EffectStage.Base);
            LiftEffects = OfStage(EffectStage.Lift);
            ObjectEffects = OfStage(EffectStage.ObjectMotion);
            PositionEffects = OfStage(EffectStage.Position);
            AdvancingWhenStill = Array.FindAll(_all, e => (e.Stage == EffectStage.Input || e.Stage == EffectStage.Position) && e.AdvancesWhenStill);
            WeightIsFunctionOfHand = true;
            foreach (var e in _all)
                if (e.Stage >= EffectStage.HandMotion && e.Stage <= EffectStage.ObjectMotion && e.Stage != EffectStage.Gain && !e.IsFunctionOfHand)
                    WeightIsFunctionOfHand = false;
        }

        WeightEffect[] OfStage(EffectStage stage) => Array.FindAll(_all, e => e.Stage == stage);

        /// <summary>The profile's effect of type T, or null when the scene does not call for it.</summary>
        public T Find<T>() where T : WeightEffect
        {
            foreach (var e in _all)
                if (e is T t) return t;
            return null;
        }

        public bool Has<T>() where T : WeightEffect => Find<T>() != null;

        /// <summary>A copy with one more effect (or with this one replacing the effect of its type).</summary>
        public WeightProfile With(WeightEffect effect, string name = null)
        {
            if (effect == null) throw new ArgumentNullException(nameof(effect));
            var list = new List<WeightEffect>();
            foreach (var e in _all) if (e.GetType() != effect.GetType()) list.Add(e);
            list.Add(effect);
            return new WeightProfile(name ?? Name + "+" + effect.Name, list, Limits, HandFilter);
        }

        /// <summary>A copy without the effect of type T.</summary>
        public WeightProfile Without<T>(string name = null) where T : WeightEffect
        {
            var list = new List<WeightEffect>();
            foreach (var e in _all) if (!(e is T)) list.Add(e);
            return new WeightProfile(name ?? Name + "-" + typeof(T).Name, list, Limits, HandFilter);
        }

        /// <summary>A copy that smooths the followed hand with <paramref name="filter"/> (null: none).</summary>
        public WeightProfile WithHandFilter(IHandFilter filter, string name = null)
            => new WeightProfile(name ?? Name + (filter != null ? "+" + filter.Name : ""), _all, Limits, filter);

        /// <summary>A copy with other safety limits.</summary>
        public WeightProfile WithLimits(SolverLimits limits, string name = null)
            => new WeightProfile(name ?? Name, _all, limits ?? SolverLimits.Default, HandFilter);

        public override string ToString() => Name + " [" + string.Join(", ", Array.ConvertAll(_all, e => e.Name)) + "]";
    }
}
