using System;
using System.Collections.Generic;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// The values of one effect's settings, index for index with its <see cref="EffectDescriptor.Settings"/>: what a
    /// profile file, a Unity list entry or code fills in before <see cref="EffectDescriptor.Create"/> builds the immutable
    /// effect. Starts at the defaults. Not validated until the effect is built (which names the effect and the setting).
    /// </summary>
    public sealed class EffectSettings
    {
        readonly double[] _values;

        public EffectDescriptor Effect { get; }

        public EffectSettings(EffectDescriptor effect)
        {
            Effect = effect ?? throw new ArgumentNullException(nameof(effect));
            _values = new double[effect.Settings.Count];
            for (int i = 0; i < _values.Length; i++) _values[i] = effect.Settings[i].Default;
        }

        public int Count => _values.Length;

        /// <summary>The value of the setting at <paramref name="index"/> (the descriptor's order).</summary>
        public double this[int index]
        {
            get => _values[index];
            set => _values[index] = value;
        }

        /// <summary>The value of the setting at <paramref name="index"/> as a switch (any non-zero is on).</summary>
        public bool Flag(int index) => _values[index] != 0;

        /// <summary>The index of the setting named <paramref name="name"/>, or −1.</summary>
        public int IndexOf(string name)
        {
            for (int i = 0; i < _values.Length; i++)
                if (Effect.Settings[i].Name == name) return i;
            return -1;
        }

        /// <summary>Sets the setting named <paramref name="name"/>; throws naming the effect and the setting when there is none.</summary>
        public EffectSettings Set(string name, double value)
        {
            int i = IndexOf(name);
            if (i < 0)
                throw new ArgumentException("effect '" + Effect.Name + "' has no setting '" + name + "'; its settings: " + Effect.SettingNames() + ".", nameof(name));
            _values[i] = value;
            return this;
        }

        /// <summary>The settings as (name, value) pairs, in the descriptor's order.</summary>
        public IEnumerable<KeyValuePair<string, double>> Pairs()
        {
            for (int i = 0; i < _values.Length; i++) yield return new KeyValuePair<string, double>(Effect.Settings[i].Name, _values[i]);
        }

        /// <summary>Builds the effect (<see cref="EffectDescriptor.Create"/>).</summary>
        public WeightEffect Build() => Effect.Create(this);
    }
}
