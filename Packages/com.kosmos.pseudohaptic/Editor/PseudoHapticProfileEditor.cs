using UnityEditor;
using UnityEngine;

namespace Kosmos.PseudoHaptic.Editor
{
    /// <summary>Inspector of <see cref="PseudoHapticProfile"/>: the core's presets as buttons, and the profile as built.</summary>
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
            }
            EditorGUILayout.EndHorizontal();
            EditorGUILayout.Space();

            DrawDefaultInspector();

            EditorGUILayout.Space();
            if (profile.TryBuild(out WeightProfile built, out string error))
                EditorGUILayout.HelpBox("Runs: " + built, MessageType.Info);
            else
                EditorGUILayout.HelpBox(error, MessageType.Error);
        }
    }
}
