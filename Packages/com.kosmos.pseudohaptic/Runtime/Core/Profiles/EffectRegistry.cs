using System;
using System.Collections.Generic;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// The effects a profile may list: the package's own (each declares its <see cref="EffectDescriptor"/> in its file; this
    /// list names them once, in the order listings show them) and any a scene or a test assembly registers with
    /// <see cref="Register"/>. No reflection over assemblies (IL2CPP-safe). Lookups by name or type; registration is
    /// thread-safe and idempotent for the same descriptor.
    /// </summary>
    public static class EffectRegistry
    {
        static readonly object s_lock = new object();
        static EffectDescriptor[] s_all = BuiltIn();

        static EffectDescriptor[] BuiltIn() => new[]
        {
            TrackingLossHold.Descriptor, MotionDeadband.Descriptor, LoweringGuard.Descriptor, OffsetRelaxation.Descriptor,
            FasterMovesFurther.Descriptor, HeightDeceleration.Descriptor, WeightGain.Descriptor, ExperimentalBlend.Descriptor,
            OffsetCorrection.Descriptor, SpeedCap.Descriptor, FloorClamp.Descriptor, LateralInertia.Descriptor, TwoHands.Descriptor,
            BreakAway.Descriptor,
        };

        /// <summary>Every registered effect: the package's in their listing order, then registered ones in the order registered.</summary>
        public static IReadOnlyList<EffectDescriptor> All => s_all;

        /// <summary>The package's own effects.</summary>
        public static IReadOnlyList<EffectDescriptor> Package { get; } = BuiltIn();

        /// <summary>Adds an effect (from a scene's or a test's assembly). Registering the same descriptor again does nothing;
        /// another descriptor of a registered name or type throws.</summary>
        public static void Register(EffectDescriptor effect)
        {
            if (effect == null) throw new ArgumentNullException(nameof(effect));
            lock (s_lock)
            {
                foreach (var e in s_all)
                {
                    if (ReferenceEquals(e, effect)) return;
                    if (e.Name == effect.Name || e.EffectType == effect.EffectType)
                        throw new ArgumentException("effect '" + effect.Name + "' (" + effect.EffectType.Name + "): '" + e.Name + "' (" + e.EffectType.Name + ") is registered with that name or type.", nameof(effect));
                }
                var all = new EffectDescriptor[s_all.Length + 1];
                Array.Copy(s_all, all, s_all.Length);
                all[s_all.Length] = effect;
                s_all = all;
            }
        }

        /// <summary>The effect named <paramref name="name"/>, or null.</summary>
        public static EffectDescriptor Find(string name)
        {
            foreach (var e in s_all)
                if (e.Name == name) return e;
            return null;
        }

        /// <summary>The effect of class <paramref name="effectType"/>, or null.</summary>
        public static EffectDescriptor Find(Type effectType)
        {
            foreach (var e in s_all)
                if (e.EffectType == effectType) return e;
            return null;
        }

        /// <summary>The effect named <paramref name="name"/>; throws naming it and the known names otherwise.</summary>
        public static EffectDescriptor Get(string name)
            => Find(name) ?? throw new ArgumentException("effect '" + name + "' is unknown; known effects: " + Names() + ".", nameof(name));

        /// <summary>The descriptor of <paramref name="effect"/>'s class; throws when it was never registered.</summary>
        public static EffectDescriptor Of(WeightEffect effect)
        {
            if (effect == null) throw new ArgumentNullException(nameof(effect));
            return Find(effect.GetType()) ?? throw new ArgumentException("effect '" + effect.Name + "' (" + effect.GetType().FullName + ") is not registered: EffectRegistry.Register its descriptor.", nameof(effect));
        }

        static string Names()
        {
            var all = s_all;
            var names = new string[all.Length];
            for (int i = 0; i < all.Length; i++) names[i] = all[i].Name;
            return string.Join(", ", names);
        }
    }
}
