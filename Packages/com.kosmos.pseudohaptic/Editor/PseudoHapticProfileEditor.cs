using System.Collections.Generic;
using UnityEditor;
using UnityEngine;

namespace Kosmos.PseudoHaptic.Editor
{
    /// <summary>
    /// Inspector of <see cref="PseudoHapticProfile"/>, shaped like URP's Volume profile: the core's presets as buttons; the
    /// effect list, each effect a foldout with its one-line summary and its own settings (units in the labels, tooltips from
    /// the effect's declaration), a Remove button, and Up/Down where a neighbour of the same stage lets it move; "Add Effect"
    /// opens a menu of every registered effect by stage with its summary; then the limits, where the hand is drawn, and the
    /// profile as built (or the error naming the effect and the setting). Everything per effect comes from its
    /// <see cref="EffectDescriptor"/>: this inspector has no code per effect.
    /// </summary>
    [CustomEditor(typeof(PseudoHapticProfile))]
    public sealed class PseudoHapticProfileEditor : UnityEditor.Editor
    {
        public override void OnInspectorGUI()
        {
            var profile = (PseudoHapticProfile)target;
            EditorGUILayout.LabelField("Presets", EditorStyles.boldLabel);
            EditorGUILayout.BeginHorizontal();
            foreach (string preset in NamedProfiles.Names)
            {
                if (!GUILayout.Button(preset)) continue;
                Undo.RecordObject(profile, "Apply pseudo-haptic preset " + preset);
                profile.ApplyPreset(preset);
                EditorUtility.SetDirty(profile);
                // The list below may now hold more entries than this event's layout measured (IMGUI would throw "Getting
                // control N's position in a group with only N controls"): end this event; the next lays the new list out.
                GUIUtility.ExitGUI();
            }
            EditorGUILayout.EndHorizontal();
            EditorGUILayout.Space();

            EditorGUILayout.LabelField("Effects", EditorStyles.boldLabel);
            var effects = profile.Effects;
            for (int i = 0; i < effects.Count; i++)
                if (DrawEffect(profile, effects, i)) break; // the list changed: draw it again next time

            if (GUILayout.Button("Add Effect")) ShowAddMenu(profile);
            EditorGUILayout.Space();

            EditorGUILayout.LabelField("Safety limits (every profile)", EditorStyles.boldLabel);
            foreach (var setting in SolverLimits.Settings)
            {
                double value = Value(profile.LimitValues, setting);
                double typed = Field(setting, value);
                if (!typed.Equals(value)) Edit(profile, "Change limit " + setting.Name, () => profile.SetLimit(setting.Name, typed));
            }
            var drawing = (HandDrawingMode)EditorGUILayout.EnumPopup("Hand Drawing", profile.HandDrawing);
            if (drawing != profile.HandDrawing) Edit(profile, "Change hand drawing", () => profile.HandDrawing = drawing);

            EditorGUILayout.Space();
            if (profile.TryBuild(out WeightProfile built, out string error))
                EditorGUILayout.HelpBox("Runs: " + built, MessageType.Info);
            else
                EditorGUILayout.HelpBox(error, MessageType.Error);
        }

        /// <summary>One entry: foldout, summary, settings, buttons. True when it changed the list.</summary>
        static bool DrawEffect(PseudoHapticProfile profile, IReadOnlyList<ProfileEffect> effects, int index)
        {
            var entry = effects[index];
            var d = entry?.Descriptor;
            if (d == null)
            {
                string missing = entry == null ? "(empty entry)" : entry.effect;
                EditorGUILayout.HelpBox(entry == null
                    ? "An empty entry (its effect's type is missing with its assembly): skipped when the profile is built."
                    : "Effect '" + missing + "' is not registered (its assembly is missing or does not register it): the profile is refused until it is registered or removed.",
                    MessageType.Warning);
                if (GUILayout.Button("Remove " + missing)) { Edit(profile, "Remove effect", () => profile.RemoveEffectAt(index)); return true; }
                return false;
            }
            entry.expanded = EditorGUILayout.Foldout(entry.expanded, d.Name + " (" + d.Stage + ")", true);
            if (entry.expanded)
            {
                EditorGUI.indentLevel++;
                EditorGUILayout.LabelField(d.Summary, EditorStyles.wordWrappedMiniLabel);
                var values = entry.Values();
                for (int s = 0; s < d.Settings.Count; s++)
                {
                    double typed = Field(d.Settings[s], values[s]);
                    if (!typed.Equals(values[s]))
                    {
                        string setting = d.Settings[s].Name;
                        Edit(profile, "Change " + d.Name + " " + setting, () => profile.SetSetting(d.Name, setting, typed));
                    }
                }
                EditorGUI.indentLevel--;
            }
            EditorGUILayout.BeginHorizontal();
            bool changed = false;
            if (GUILayout.Button("Remove " + d.Name)) { Edit(profile, "Remove effect " + d.Name, () => profile.RemoveEffect(d.Name)); changed = true; }
            else if (ProfileEffectList.CanMove(Mutable(effects), index, -1) && GUILayout.Button("Up " + d.Name)) { Edit(profile, "Move effect " + d.Name, () => profile.MoveEffect(index, -1)); changed = true; }
            else if (ProfileEffectList.CanMove(Mutable(effects), index, 1) && GUILayout.Button("Down " + d.Name)) { Edit(profile, "Move effect " + d.Name, () => profile.MoveEffect(index, 1)); changed = true; }
            EditorGUILayout.EndHorizontal();
            return changed;
        }

        static IList<ProfileEffect> Mutable(IReadOnlyList<ProfileEffect> effects) => (IList<ProfileEffect>)effects;

        /// <summary>"Add Effect": every registered effect, by stage, with its summary; those already listed are greyed out.</summary>
        static void ShowAddMenu(PseudoHapticProfile profile)
        {
            var menu = new GenericMenu();
            foreach (var item in ProfileEffectList.Menu(Mutable(profile.Effects)))
            {
                var d = item.Key;
                var content = new GUIContent(ProfileEffectList.MenuText(d), d.Summary);
                if (item.Value) menu.AddDisabledItem(content);
                else menu.AddItem(content, false, () => Edit(profile, "Add effect " + d.Name, () => profile.AddEffect(d.Name)));
            }
            menu.ShowAsContext();
        }

        /// <summary>A setting's field: its name and unit as the label; a switch for a boolean.</summary>
        static double Field(SettingDescriptor setting, double value)
        {
            string label = setting.Name + (setting.Unit.Length > 0 ? " (" + setting.Unit + ")" : "");
            if (setting.Kind == SettingKind.Boolean) return EditorGUILayout.Toggle(label, value != 0) ? 1 : 0;
            return EditorGUILayout.DoubleField(label, value);
        }

        static double Value(IReadOnlyList<EffectSettingValue> values, SettingDescriptor setting)
        {
            foreach (var v in values)
                if (v != null && v.name == setting.Name) return v.value;
            return setting.Default;
        }

        static void Edit(PseudoHapticProfile profile, string what, System.Action change)
        {
            Undo.RecordObject(profile, what);
            change();
            EditorUtility.SetDirty(profile);
        }
    }
}
