using System;
using System.Collections.Generic;
using UnityEngine;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// The effects a scene calls for, as an asset: a list of effects, each with its own settings (like URP's Volume profile
    /// and its overrides), and the safety limits. Each entry (<see cref="ProfileEffect"/>, held by <c>[SerializeReference]</c>)
    /// names an effect and its values; what the effect is, which settings it has, their units, defaults and ranges, its
    /// descriptor says (<see cref="EffectRegistry"/>), so this asset has no code per effect and a scene's own registered
    /// effect is listed and built like the package's. <see cref="Build"/> turns it into the core's immutable
    /// <see cref="WeightProfile"/>; the presets are <see cref="NamedProfiles"/> ("paper-literal": an asset of that name is run by
    /// <see cref="PaperLiteralSolver"/>, the paper as printed, whatever its list says). <see cref="ToJson"/> exports the profile file the tool's
    /// <c>--profile</c> reads. Assets saved before the list (flat per-effect fields) are converted when loaded
    /// (<see cref="OnAfterDeserialize"/>, <see cref="LegacyProfileFields"/>). Invalid values are reported naming the effect
    /// and the setting.
    /// </summary>
    [CreateAssetMenu(menuName = "Kosmos/Pseudo-Haptic Profile", fileName = "PseudoHapticProfile", order = 400)]
    public sealed partial class PseudoHapticProfile : ScriptableObject, ISerializationCallbackReceiver
    {
        [Tooltip("Name of the built profile, shown in logs; the asset's name when empty.")]
        [SerializeField] string _profileName;

        [Tooltip("The effects, in the order the frame flows through them (stage by stage; within a stage, as listed).")]
        [SerializeReference] List<ProfileEffect> _effects = new List<ProfileEffect>();

        [Tooltip("The safety limits every profile has (SolverLimits), by name.")]
        [SerializeField] List<EffectSettingValue> _limits = new List<EffectSettingValue>();

        [Header("Where the hand is drawn")]
        [Tooltip("Hand True (the paper): the rendered hand stays with the tracked hand and the object visibly lags. Hand On Object (Samad et al. 2019, Rietzler et al. 2018): the rendered hand is drawn at the object.")]
        [SerializeField] HandDrawingMode _handDrawing = HandDrawingMode.HandTrue;

        /// <summary>The break-away distance an asset offers when it is switched on (the descriptor's default), m.</summary>
        public static readonly float DefaultBreakAwayDistance = (float)BreakAway.Descriptor.Settings[0].Default;

        [NonSerialized] WeightProfile _built;
        [NonSerialized] int _version;

        /// <summary>A new profile asset starts as the "paper" preset.</summary>
        public PseudoHapticProfile()
        {
            CopyFrom(NamedProfiles.Paper);
        }

        /// <summary>Where the rendered hand is drawn while it holds an object of this profile (not a solver setting).</summary>
        public HandDrawingMode HandDrawing
        {
            get => _handDrawing;
            set { _handDrawing = value; MarkChanged(); }
        }

        /// <summary>Changes whenever a setting changes, so holders know to rebuild.</summary>
        public int Version => _version;

        /// <summary>The effect list (entries in list order). Change it through <see cref="AddEffect"/>, <see cref="RemoveEffect"/>,
        /// <see cref="MoveEffect"/> and <see cref="SetSetting"/>, or call <see cref="MarkChanged"/> after changing it.</summary>
        public IReadOnlyList<ProfileEffect> Effects => _effects;

        /// <summary>The limits' values by name.</summary>
        public IReadOnlyList<EffectSettingValue> LimitValues => _limits;

        /// <summary>A new in-memory profile set to the preset <paramref name="presetName"/> (see <see cref="NamedProfiles.Names"/>).</summary>
        public static PseudoHapticProfile CreatePreset(string presetName)
        {
            var profile = CreateInstance<PseudoHapticProfile>();
            profile.ApplyPreset(presetName);
            profile.name = presetName;
            return profile;
        }

        /// <summary>Sets the list and the limits to the named preset of the core; throws on an unknown name.</summary>
        public void ApplyPreset(string presetName)
        {
            CopyFrom(NamedProfiles.Get(presetName));
            _profileName = presetName;
            MarkChanged();
        }

        [ContextMenu("Preset/paper")] void PresetPaper() => ApplyPreset(NamedProfiles.PaperName);
        [ContextMenu("Preset/paper-experiment")] void PresetPaperExperiment() => ApplyPreset(NamedProfiles.PaperExperimentName);
        [ContextMenu("Preset/gain")] void PresetGain() => ApplyPreset(NamedProfiles.GainName);
        [ContextMenu("Preset/xyz")] void PresetXyz() => ApplyPreset(NamedProfiles.XyzName);
        [ContextMenu("Preset/paper-literal")] void PresetPaperLiteral() => ApplyPreset(NamedProfiles.PaperLiteralName);

        /// <summary>The names of every effect a profile asset can list (the registered ones: "weight-gain", …).</summary>
        public static IReadOnlyList<string> EffectNames
        {
            get
            {
                var names = new List<string>();
                foreach (var d in EffectRegistry.All) names.Add(d.Name);
                return names;
            }
        }

        /// <summary>Whether <paramref name="effectName"/> is a registered effect.</summary>
        public static bool IsKnownEffect(string effectName) => effectName != null && EffectRegistry.Find(effectName) != null;

        /// <summary>Whether the list has the effect named <paramref name="effectName"/>; throws on an unknown name.</summary>
        public bool IsEnabled(string effectName) => ProfileEffectList.IndexOf(_effects, EffectRegistry.Get(effectName).Name) >= 0;

        /// <summary>Adds the effect (at its defaults) or removes it (e.g. from a playground button).</summary>
        public void SetEnabled(string effectName, bool on)
        {
            if (on) AddEffect(effectName);
            else RemoveEffect(effectName);
        }

        public bool IsEnabled<T>() where T : WeightEffect => IsEnabled(DescriptorOf(typeof(T)).Name);

        public void SetEnabled<T>(bool on) where T : WeightEffect => SetEnabled(DescriptorOf(typeof(T)).Name, on);

        static EffectDescriptor DescriptorOf(Type t) => EffectRegistry.Find(t) ?? throw new ArgumentException(t.Name + " is not a registered effect.", "effectType");

        /// <summary>Adds the registered effect named <paramref name="effectName"/> at its defaults, in stage order; false when listed.</summary>
        public bool AddEffect(string effectName)
        {
            bool added = ProfileEffectList.Add(_effects, effectName);
            if (added) MarkChanged();
            return added;
        }

        /// <summary>Removes the effect named <paramref name="effectName"/>; false when it was not listed.</summary>
        public bool RemoveEffect(string effectName)
        {
            bool removed = ProfileEffectList.Remove(_effects, effectName);
            if (removed) MarkChanged();
            return removed;
        }

        /// <summary>
        /// Removes the entry at <paramref name="index"/>, whatever it holds: an empty one (its effect's type went missing with
        /// its assembly: Unity keeps it as null) or one whose effect is not registered, which <see cref="RemoveEffect"/> cannot
        /// name. False when <paramref name="index"/> is not an entry's.
        /// </summary>
        public bool RemoveEffectAt(int index)
        {
            if (index < 0 || index >= _effects.Count) return false;
            _effects.RemoveAt(index);
            MarkChanged();
            return true;
        }

        /// <summary>Moves the entry at <paramref name="index"/> up (−1) or down (+1) past a neighbour of the same stage.</summary>
        public bool MoveEffect(int index, int delta)
        {
            bool moved = ProfileEffectList.Move(_effects, index, delta);
            if (moved) MarkChanged();
            return moved;
        }

        /// <summary>Sets one setting of a listed effect (validated when built: <see cref="TryBuild"/> names the effect and field).</summary>
        public void SetSetting(string effectName, string setting, double value)
        {
            int i = ProfileEffectList.IndexOf(_effects, effectName);
            if (i < 0) throw new ArgumentException("effect '" + effectName + "' is not in profile '" + name + "'.", nameof(effectName));
            _effects[i].Set(setting, value);
            MarkChanged();
        }

        /// <summary>The value of one setting of a listed effect.</summary>
        public double GetSetting(string effectName, string setting)
        {
            int i = ProfileEffectList.IndexOf(_effects, effectName);
            if (i < 0) throw new ArgumentException("effect '" + effectName + "' is not in profile '" + name + "'.", nameof(effectName));
            return _effects[i].Get(setting);
        }

        /// <summary>Sets one of the limits (<see cref="SolverLimits.Settings"/>) by name.</summary>
        public void SetLimit(string setting, double value)
        {
            foreach (var v in _limits)
                if (v != null && v.name == setting) { v.value = value; MarkChanged(); return; }
            foreach (var s in SolverLimits.Settings)
                if (s.Name == setting) { _limits.Add(new EffectSettingValue(setting, value)); MarkChanged(); return; }
            throw new ArgumentException("limits have no setting '" + setting + "'.", nameof(setting));
        }

        /// <summary>
        /// The core profile this list describes, built once per change and shared by every object that uses this asset.
        /// Throws <see cref="ArgumentException"/> naming the effect and the setting when a value is invalid.
        /// </summary>
        public WeightProfile Build()
        {
            if (_built != null) return _built;
            string label = !string.IsNullOrWhiteSpace(_profileName) ? _profileName : (!string.IsNullOrWhiteSpace(name) ? name : "custom");
            _built = ProfileEffectList.Build(label, _effects, ProfileEffectList.Limits(_limits));
            return _built;
        }

        /// <summary><see cref="Build"/> without the exception: false and the core's message when a value is invalid.</summary>
        public bool TryBuild(out WeightProfile profile, out string error)
        {
            try
            {
                profile = Build();
                error = null;
                return true;
            }
            catch (ArgumentException e)
            {
                profile = null;
                error = "profile '" + name + "': " + e.Message;
                return false;
            }
        }

        /// <summary>The profile file (<see cref="ProfileJson"/>) the tool's <c>--profile</c> reads.</summary>
        public string ToJson() => ProfileJson.Write(Build());

        /// <summary>Sets the list, the limits and the name from a profile file; <paramref name="source"/> names it in errors
        /// (<see cref="ProfileFormatException"/>: file, line, effect, setting). A hand filter in the file is not kept.</summary>
        public void FromJson(string json, string source)
        {
            var p = ProfileJson.Read(json, source);
            CopyFrom(p);
            _profileName = p.Name;
            MarkChanged();
        }

        void OnValidate() => MarkChanged();

        /// <summary>Tells holders the list or a value changed (the inspector calls it after an edit).</summary>
        public void MarkChanged()
        {
            _built = null;
            unchecked { _version++; }
        }

        void CopyFrom(WeightProfile p)
        {
            _effects = ProfileEffectList.FromProfile(p);
            _limits = ProfileEffectList.LimitValues(p.Limits);
        }

        void ISerializationCallbackReceiver.OnBeforeSerialize() { }

        /// <summary>An asset saved with the flat per-effect fields is converted to the list, once.</summary>
        void ISerializationCallbackReceiver.OnAfterDeserialize() => OnAfterDeserialize();

        internal void OnAfterDeserialize()
        {
            if (UpgradeLegacyFields()) UpgradedUnsaved = true;
            // Whatever rewrote the serialized state (an undo, a revert, a reimport, the first load) leaves the built profile
            // stale: holders rebuild (only an int and a reference: safe off the main thread, where Unity may call this).
            MarkChanged();
        }

        /// <summary>
        /// Read from 0.2.0's flat fields and converted in memory, not yet saved as the list: the editor saves such assets
        /// once when it loads the scripts (Unity saves a ScriptableObject only when it is marked dirty), so that the file
        /// holds the list and nothing depends on the old fields being readable again.
        /// </summary>
        public bool UpgradedUnsaved { get; private set; }

        /// <summary>The asset was saved in the list format (called by the editor after it saved it).</summary>
        public void UpgradeSaved() => UpgradedUnsaved = false;
    }
}
