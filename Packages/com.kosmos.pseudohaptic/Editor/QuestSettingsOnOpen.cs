using System;
using System.IO;
using UnityEditor;
using UnityEngine;

namespace Kosmos.PseudoHaptic.Editor
{
    /// <summary>
    /// When the project opens (or its scripts reload), applies the Quest settings (<see cref="QuestProjectSettings"/>) that
    /// are missing, in a project that opts in with <see cref="OptInFile"/> (this repository does; a package must not change
    /// every project it is installed in), and logs one line saying what it set. So a first open, Unity's own Build & Run
    /// and Play over Link get the Quest settings whether or not a menu item ran first. Nothing is logged when nothing changed.
    /// </summary>
    [InitializeOnLoad]
    public static class QuestSettingsOnOpen
    {
        /// <summary>The opt-in, relative to the project folder.</summary>
        public const string OptInFile = "ProjectSettings/Packages/com.kosmos.pseudohaptic/QuestSettingsOnOpen.json";

        static QuestSettingsOnOpen() => ScheduleApply();

        /// <summary>Applies once the editor has finished loading (asset operations wait until then): EditorApplication.delayCall.</summary>
        public static void ScheduleApply() => EditorApplication.delayCall += Apply;

        /// <summary>Applies the missing settings if the project opted in; returns the log line, or null when nothing was set.</summary>
        public static string Apply(string projectFolder)
        {
            if (!File.Exists(Path.Combine(projectFolder, OptInFile))) return null;
            try
            {
                var changes = QuestProjectSettings.Apply(strict: false);
                if (changes.Count == 0) return null;
                string line = "Kosmos Pseudo-Haptic: set for Quest 2 and Play over Link (" + OptInFile + "): " + string.Join("; ", changes) + ".";
                Debug.Log(line);
                return line;
            }
            catch (Exception e)
            {
                Debug.LogWarning("Kosmos Pseudo-Haptic: the Quest settings could not be applied on open: " + e.Message + " (Tools > Kosmos Pseudo-Haptic > Configure Project for Quest 2 says more).");
                return null;
            }
        }

        static void Apply() => Apply(Directory.GetCurrentDirectory());
    }
}
