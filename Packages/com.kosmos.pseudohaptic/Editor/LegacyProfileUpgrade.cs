using UnityEditor;
using UnityEngine;

namespace Kosmos.PseudoHaptic.Editor
{
    /// <summary>
    /// Profile assets written by 0.2.0 (flat fields) are converted to the effect list when they load
    /// (<see cref="PseudoHapticProfile.UpgradedUnsaved"/>), in memory: Unity writes a ScriptableObject back only when it is
    /// marked dirty. Once the editor has loaded the scripts, this saves every such asset, so that the file holds the list
    /// and the conversion never has to run again.
    /// </summary>
    [InitializeOnLoad]
    public static class LegacyProfileUpgrade
    {
        static LegacyProfileUpgrade() => EditorApplication.delayCall += () => SaveUpgraded();

        /// <summary>Saves the profile assets converted from 0.2.0's fields and not saved since; returns how many.</summary>
        public static int SaveUpgraded()
        {
            int saved = 0;
            foreach (string guid in AssetDatabase.FindAssets("t:" + nameof(PseudoHapticProfile)))
            {
                var profile = AssetDatabase.LoadAssetAtPath<PseudoHapticProfile>(AssetDatabase.GUIDToAssetPath(guid));
                if (profile == null || !profile.UpgradedUnsaved) continue;
                EditorUtility.SetDirty(profile);
                AssetDatabase.SaveAssetIfDirty(profile);
                profile.UpgradeSaved();
                saved++;
            }
            if (saved > 0)
                Debug.Log("Kosmos Pseudo-Haptic: " + saved + " profile asset(s) written by 0.2.0 saved in the effect-list format.");
            return saved;
        }
    }
}
