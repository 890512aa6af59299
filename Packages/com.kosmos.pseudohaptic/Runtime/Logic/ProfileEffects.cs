using System;
using System.Collections.Generic;

namespace Kosmos.PseudoHaptic
{
    /// <summary>One setting's value in a profile asset's list (the setting's name, as its effect declares it).</summary>
    [Serializable]
    public sealed class EffectSettingValue
    {
        public string name;
        public double value;

        public EffectSettingValue() { }

        public EffectSettingValue(string name, double value)
        {
            this.name = name;
            this.value = value;
        }
    }

    /// <summary>
    /// One entry of a profile asset's effect list (<c>PseudoHapticProfile</c>, held by <c>[SerializeReference]</c>): the
    /// effect's name and its settings' values by name, so an asset keeps its values when an effect gains a setting (the new
    /// one takes its default) and needs no class per effect. Whatever an effect is, its <see cref="EffectDescriptor"/> says
    /// (<see cref="EffectRegistry"/>): an effect of a scene's own assembly works once its descriptor is registered.
    /// </summary>
    [Serializable]
    public class ProfileEffect
    {
        public string effect;
        public bool expanded = true;
        public List<EffectSettingValue> settings = new List<EffectSettingValue>();

        public ProfileEffect() { }

        /// <summary>An entry of <paramref name="descriptor"/>'s effect at its defaults.</summary>
        public static ProfileEffect Of(EffectDescriptor descriptor) => Of(descriptor.DefaultSettings());

        /// <summary>An entry holding <paramref name="values"/>.</summary>
        public static ProfileEffect Of(EffectSettings values)
        {
            var e = new ProfileEffect { effect = values.Effect.Name };
            foreach (var p in values.Pairs()) e.settings.Add(new EffectSettingValue(p.Key, p.Value));
            return e;
        }

        /// <summary>The registered effect this entry names, or null.</summary>
        public EffectDescriptor Descriptor => EffectRegistry.Find(effect);

        /// <summary>The values as the descriptor orders them: a value the entry lacks takes its default; one the effect no
        /// longer declares is ignored. Throws naming the effect when it is not registered.</summary>
        public EffectSettings Values()
        {
            var d = Descriptor ?? throw new ArgumentException("effect '" + effect + "' is unknown (not registered); known effects: " + Known() + ".", nameof(effect));
            var s = d.DefaultSettings();
            if (settings != null)
                foreach (var v in settings)
                {
                    int i = v == null ? -1 : s.IndexOf(v.name);
                    if (i >= 0) s[i] = v.value;
                }
            return s;
        }

        /// <summary>The value of the setting named <paramref name="setting"/> (its default when the entry lacks it).</summary>
        public double Get(string setting)
        {
            var s = Values();
            int i = s.IndexOf(setting);
            if (i < 0) throw new ArgumentException("effect '" + effect + "' has no setting '" + setting + "'.", nameof(setting));
            return s[i];
        }

        /// <summary>Sets the setting named <paramref name="setting"/>; throws naming the effect when it has no such setting.</summary>
        public void Set(string setting, double value)
        {
            if (Values().IndexOf(setting) < 0) throw new ArgumentException("effect '" + effect + "' has no setting '" + setting + "'.", nameof(setting));
            if (settings == null) settings = new List<EffectSettingValue>();
            foreach (var v in settings)
                if (v != null && v.name == setting) { v.value = value; return; }
            settings.Add(new EffectSettingValue(setting, value));
        }

        /// <summary>The immutable effect; an invalid value throws naming the effect and the setting.</summary>
        public virtual WeightEffect Build() => Values().Build();

        internal static string Known()
        {
            var names = new List<string>();
            foreach (var d in EffectRegistry.All) names.Add(d.Name);
            return string.Join(", ", names);
        }
    }

    /// <summary>
    /// The decisions of a profile asset's effect list, engine-free: building the core's profile, a preset as a list, adding
    /// (in stage order), removing, moving within a stage (the only order that matters: <see cref="WeightProfile"/> runs the
    /// stages in order), what the "Add Effect" menu offers. No code per effect: every effect is its descriptor.
    /// </summary>
    public static class ProfileEffectList
    {
        /// <summary>The core profile the list describes. Throws <see cref="ArgumentException"/> naming the effect and setting.</summary>
        public static WeightProfile Build(string name, IList<ProfileEffect> effects, SolverLimits limits)
        {
            var built = new List<WeightEffect>(effects.Count);
            foreach (var e in effects)
                if (e != null) built.Add(e.Build());
            return new WeightProfile(name, built, limits);
        }

        /// <summary>A profile's effects as list entries, in its order.</summary>
        public static List<ProfileEffect> FromProfile(WeightProfile profile)
        {
            var list = new List<ProfileEffect>(profile.Effects.Count);
            foreach (var e in profile.Effects) list.Add(ProfileEffect.Of(EffectRegistry.Of(e).SettingsOf(e)));
            return list;
        }

        /// <summary>Limits from setting values by name (<see cref="SolverLimits.Settings"/>; a missing one takes its default).</summary>
        public static SolverLimits Limits(IList<EffectSettingValue> values)
        {
            var settings = SolverLimits.Settings;
            var v = new double[settings.Count];
            for (int i = 0; i < v.Length; i++)
            {
                v[i] = settings[i].Default;
                if (values != null)
                    foreach (var s in values)
                        if (s != null && s.name == settings[i].Name) v[i] = s.value;
            }
            try { return new SolverLimits(v[0], v[1], v[2], v[3], v[4]); }
            catch (ArgumentException e) { throw new EffectSettingException("limits: setting '" + e.ParamName + "': " + FirstLine(e.Message), e.ParamName, e); }
        }

        /// <summary><paramref name="limits"/> as setting values.</summary>
        public static List<EffectSettingValue> LimitValues(SolverLimits limits)
        {
            var list = new List<EffectSettingValue>();
            foreach (var s in SolverLimits.Settings) list.Add(new EffectSettingValue(s.Name, s.Read(limits)));
            return list;
        }

        public static int IndexOf(IList<ProfileEffect> effects, string name)
        {
            for (int i = 0; i < effects.Count; i++)
                if (effects[i] != null && effects[i].effect == name) return i;
            return -1;
        }

        /// <summary>Adds <paramref name="entry"/> after the last effect of its stage or an earlier one (so the list reads in the
        /// order the frame flows). False, and nothing changes, when the list has that effect already.</summary>
        public static bool Add(IList<ProfileEffect> effects, ProfileEffect entry)
        {
            var d = entry.Descriptor ?? throw new ArgumentException("effect '" + entry.effect + "' is unknown (not registered); known effects: " + ProfileEffect.Known() + ".", nameof(entry));
            if (IndexOf(effects, d.Name) >= 0) return false;
            int at = 0;
            for (int i = 0; i < effects.Count; i++)
            {
                var other = effects[i]?.Descriptor;
                if (other == null || other.Stage <= d.Stage) at = i + 1;
            }
            effects.Insert(at, entry);
            return true;
        }

        /// <summary>Adds the effect named <paramref name="name"/> at its defaults (see <see cref="Add(IList{ProfileEffect}, ProfileEffect)"/>).</summary>
        public static bool Add(IList<ProfileEffect> effects, string name) => Add(effects, ProfileEffect.Of(EffectRegistry.Get(name)));

        public static bool Remove(IList<ProfileEffect> effects, string name)
        {
            int i = IndexOf(effects, name);
            if (i < 0) return false;
            effects.RemoveAt(i);
            return true;
        }

        /// <summary>Whether the entry at <paramref name="index"/> may move by <paramref name="delta"/> (−1 up, +1 down): only past a
        /// neighbour of the same stage, since the stages run in their order whatever the list's.</summary>
        public static bool CanMove(IList<ProfileEffect> effects, int index, int delta)
        {
            int to = index + delta;
            if (index < 0 || index >= effects.Count || to < 0 || to >= effects.Count || (delta != 1 && delta != -1)) return false;
            var a = effects[index]?.Descriptor;
            var b = effects[to]?.Descriptor;
            return a != null && b != null && a.Stage == b.Stage;
        }

        public static bool Move(IList<ProfileEffect> effects, int index, int delta)
        {
            if (!CanMove(effects, index, delta)) return false;
            var e = effects[index];
            effects[index] = effects[index + delta];
            effects[index + delta] = e;
            return true;
        }

        /// <summary>What the "Add Effect" menu lists: every registered effect, and whether the list has it already.</summary>
        public static List<KeyValuePair<EffectDescriptor, bool>> Menu(IList<ProfileEffect> effects)
        {
            var menu = new List<KeyValuePair<EffectDescriptor, bool>>();
            foreach (var d in EffectRegistry.All) menu.Add(new KeyValuePair<EffectDescriptor, bool>(d, IndexOf(effects, d.Name) >= 0));
            return menu;
        }

        /// <summary>A menu item's text: "Stage/name — summary" (a '/' in the summary would open a submenu: shown as '∕').</summary>
        public static string MenuText(EffectDescriptor d) => d.Stage + "/" + d.Name + " — " + d.Summary.Replace('/', '\u2215');

        /// <summary>
        /// An argument exception's message without the parameter the runtime adds: .NET's " (Parameter 'x')" at its end, Mono's
        /// (Unity's) "\nParameter name: x" and "\nActual value was …" lines; the first line only.
        /// </summary>
        public static string FirstLine(string message)
        {
            int nl = message.IndexOf('\n');
            string line = nl < 0 ? message : message.Substring(0, nl);
            int p = line.IndexOf(" (Parameter '", StringComparison.Ordinal);
            return (p < 0 ? line : line.Substring(0, p)).TrimEnd('\r');
        }
    }
}
