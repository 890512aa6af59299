using System;
using System.Collections.Generic;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// What an effect is, declared once in the effect's own file: its name, stage, where it comes from, a one-line summary,
    /// its settings, and a factory from settings to the immutable, validated effect. The Unity profile's list, the profile
    /// file (<see cref="ProfileJson"/>), the tool's listing and the generated effects table of ALGORITHM.md all read it;
    /// none has code of its own per effect. An effect of a scene or a test assembly declares one too and registers it
    /// (<see cref="EffectRegistry.Register"/>). Immutable; no reflection.
    /// </summary>
    public sealed class EffectDescriptor
    {
        /// <summary>Short, stable name (<see cref="WeightEffect.Name"/>).</summary>
        public string Name { get; }
        public EffectStage Stage { get; }
        /// <summary>The effect's class.</summary>
        public Type EffectType { get; }
        /// <summary>One line: what the effect does.</summary>
        public string Summary { get; }
        /// <summary>Where it comes from (a section of the paper, a design note, an issue).</summary>
        public string Source { get; }
        public IReadOnlyList<SettingDescriptor> Settings { get; }

        readonly Func<EffectSettings, WeightEffect> _create;

        public EffectDescriptor(string name, EffectStage stage, Type effectType, string source, string summary,
            Func<EffectSettings, WeightEffect> create, params SettingDescriptor[] settings)
        {
            if (string.IsNullOrWhiteSpace(name)) throw new ArgumentException("an effect needs a name.", nameof(name));
            if (effectType == null || !typeof(WeightEffect).IsAssignableFrom(effectType))
                throw new ArgumentException("effect '" + name + "': effectType must be a WeightEffect.", nameof(effectType));
            Name = name;
            Stage = stage;
            EffectType = effectType;
            Source = source ?? "";
            Summary = summary ?? "";
            _create = create ?? throw new ArgumentNullException(nameof(create));
            settings = settings ?? new SettingDescriptor[0];
            for (int i = 0; i < settings.Length; i++)
            {
                if (settings[i] == null) throw new ArgumentException("effect '" + name + "': a setting is null.", nameof(settings));
                for (int j = 0; j < i; j++)
                    if (settings[j].Name == settings[i].Name)
                        throw new ArgumentException("effect '" + name + "' declares setting '" + settings[i].Name + "' twice.", nameof(settings));
            }
            Settings = (SettingDescriptor[])settings.Clone();
        }

        /// <summary>Settings at their defaults.</summary>
        public EffectSettings DefaultSettings() => new EffectSettings(this);

        /// <summary>The effect these settings describe. Throws <see cref="ArgumentException"/> whose message names the effect
        /// and the setting when a value is invalid.</summary>
        public WeightEffect Create(EffectSettings settings)
        {
            if (settings == null) throw new ArgumentNullException(nameof(settings));
            if (settings.Effect != this) throw new ArgumentException("settings of '" + settings.Effect.Name + "' given to '" + Name + "'.", nameof(settings));
            for (int i = 0; i < Settings.Count; i++)
            {
                try { Settings[i].Check(settings[i]); }
                catch (ArgumentException e) { throw Named(Settings[i].Name, e); }
            }
            WeightEffect effect;
            try { effect = _create(settings); }
            catch (ArgumentException e) { throw Named(e.ParamName, e); }
            if (effect == null || effect.GetType() != EffectType || effect.Name != Name || effect.Stage != Stage)
                throw new InvalidOperationException("effect '" + Name + "': its factory built " + (effect == null ? "nothing" : effect.GetType().Name + " '" + effect.Name + "' of stage " + effect.Stage) + ".");
            return effect;
        }

        /// <summary>The settings an effect of this kind holds.</summary>
        public EffectSettings SettingsOf(WeightEffect effect)
        {
            if (effect == null || effect.GetType() != EffectType) throw new ArgumentException("not a '" + Name + "' effect.", nameof(effect));
            var s = new EffectSettings(this);
            for (int i = 0; i < Settings.Count; i++) s[i] = Settings[i].Read(effect);
            return s;
        }

        ArgumentException Named(string setting, ArgumentException e)
        {
            string what = string.IsNullOrEmpty(setting) ? "" : " setting '" + setting + "':";
            return new EffectSettingException("effect '" + Name + "':" + what + " " + FirstLine(e.Message), setting, e);
        }

        /// <summary>An ArgumentException's message without the "(Parameter …)" line .NET appends.</summary>
        internal static string FirstLine(string message)
        {
            int nl = message.IndexOf('\n');
            string line = nl < 0 ? message : message.Substring(0, nl);
            int p = line.IndexOf(" (Parameter '", StringComparison.Ordinal);
            return (p < 0 ? line : line.Substring(0, p)).TrimEnd('\r');
        }

        internal string SettingNames()
        {
            if (Settings.Count == 0) return "none";
            var names = new string[Settings.Count];
            for (int i = 0; i < names.Length; i++) names[i] = Settings[i].Name;
            return string.Join(", ", names);
        }

        public override string ToString() => Name;
    }

    /// <summary>An invalid setting of an effect or of the limits: the message names the effect (or "limits") and the setting,
    /// on one line, as written (no "(Parameter …)" appended); <see cref="ArgumentException.ParamName"/> is the setting.</summary>
    public sealed class EffectSettingException : ArgumentException
    {
        readonly string _message;

        public EffectSettingException(string message, string setting, Exception inner) : base(message, setting, inner) => _message = message;

        public override string Message => _message;
    }
}
