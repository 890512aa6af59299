using System;
using System.IO;
using System.Text;
using Kosmos.PseudoHaptic.Evaluation;
using UnityEngine;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// Keeps each user's <see cref="UserCalibration"/> as JSON under <see cref="Application.persistentDataPath"/>,
    /// written to a temporary file and renamed over the old one, so a crash mid-write never leaves a torn file.
    /// The current user's calibration is read once and cached; <see cref="Changed"/> tells components to
    /// reconfigure after a new calibration.
    /// </summary>
    public static class UserCalibrationStore
    {
        public const string DefaultUserId = "default";
        const string FolderName = "Kosmos.PseudoHaptic";

        static string s_currentUserId = DefaultUserId;
        static string s_rootOverride;
        static UserCalibration s_current;
        static bool s_loaded;

        /// <summary>Raised after the current user's calibration was saved, or the current user changed.</summary>
        public static event Action Changed;

        /// <summary>The folder the files live in; tests may point it elsewhere through <see cref="SetRootForTests"/>.</summary>
        public static string Folder => s_rootOverride ?? Path.Combine(Application.persistentDataPath, FolderName);

        /// <summary>Whose calibration <see cref="Current"/> is.</summary>
        public static string CurrentUserId
        {
            get => s_currentUserId;
            set
            {
                string id = string.IsNullOrWhiteSpace(value) ? DefaultUserId : value;
                if (id == s_currentUserId) return;
                s_currentUserId = id;
                s_loaded = false;
                Changed?.Invoke();
            }
        }

        /// <summary>The current user's stored calibration, or null when there is none (or it is unreadable).</summary>
        public static UserCalibration Current
        {
            get
            {
                if (!s_loaded)
                {
                    s_loaded = true;
                    if (!TryLoad(s_currentUserId, out s_current, out string error) && error != null)
                        Debug.LogWarning("Pseudo-haptic weight: the calibration of user '" + s_currentUserId + "' was not used: " + error);
                }
                return s_current;
            }
        }

        /// <summary>The current user's v_std, or the solver's default when the user has not calibrated.</summary>
        public static double StandardSpeedOrDefault => Current != null ? Current.standardSpeed : WeightSolver.DefaultStandardSpeed;

        /// <summary>The current user's cue strength (issue 31), or 1 when the user has none stored.</summary>
        public static double CueStrengthOrDefault => Current != null ? Current.cueStrength : WeightSolver.DefaultCueStrength;

        /// <summary>
        /// Stores a tuned cue strength for <paramref name="userId"/> beside their standard speed (a user without a stored
        /// calibration gets the default standard speed, with no lifts). Throws <see cref="ArgumentException"/> for a strength
        /// outside [1/3, 3], as <see cref="Save"/> does for a record it refuses.
        /// </summary>
        public static string SaveCueStrength(string userId, double cueStrength, double weber)
        {
            if (string.IsNullOrWhiteSpace(userId)) userId = s_currentUserId;
            if (!TryLoad(userId, out UserCalibration c, out _))
                c = new UserCalibration { userId = userId, standardSpeed = WeightSolver.DefaultStandardSpeed };
            c.userId = userId;
            c.cueStrength = cueStrength;
            c.cueWeber = weber;
            c.cueTunedAtUtc = DateTime.UtcNow.ToString("o", System.Globalization.CultureInfo.InvariantCulture);
            return Save(c);
        }

        /// <summary>
        /// The user's file: user-&lt;id made safe&gt;.json, or, when another user's id makes the same safe name ("P 1" and
        /// "P_1"; "P1" and "p1" on a Quest's storage, which ignores case), the first of user-&lt;name&gt;-2.json, -3, … that
        /// is free or records this user (<see cref="OwnedName"/>; each file records its userId). Reads the files it passes.
        /// </summary>
        public static string PathFor(string userId) =>
            OwnedName.Find(Path.Combine(Folder, "user-" + SafeId(userId)), ".json", Normalized(userId), s_fileExists, s_ownerOf);

        static readonly Func<string, bool> s_fileExists = File.Exists;
        static readonly Func<string, string> s_ownerOf = OwnerOf;

        /// <summary>The userId a calibration file records; null when it records none or cannot be read (then it is the first finder's).</summary>
        static string OwnerOf(string path)
        {
            try
            {
                string id = JsonUtility.FromJson<UserCalibration>(File.ReadAllText(path, Encoding.UTF8))?.userId;
                return string.IsNullOrEmpty(id) ? null : Normalized(id);
            }
            catch (Exception e) when (e is IOException || e is UnauthorizedAccessException || e is ArgumentException)
            {
                return null;
            }
        }

        static string Normalized(string userId) => string.IsNullOrWhiteSpace(userId) ? DefaultUserId : userId;

        /// <summary>
        /// Reads a user's calibration. False with a null error when the user has none; false with the reason
        /// when the file exists but cannot be used.
        /// </summary>
        public static bool TryLoad(string userId, out UserCalibration calibration, out string error)
        {
            calibration = null;
            error = null;
            string path = PathFor(userId);
            if (!File.Exists(path)) return false;
            try
            {
                var c = JsonUtility.FromJson<UserCalibration>(File.ReadAllText(path, Encoding.UTF8));
                if (c == null) { error = path + " is empty"; return false; }
                string invalid = c.Validate();
                if (invalid != null) { error = path + ": " + invalid; return false; }
                calibration = c;
                return true;
            }
            catch (Exception e) when (e is IOException || e is UnauthorizedAccessException || e is ArgumentException)
            {
                error = path + " could not be read: " + e.Message;
                return false;
            }
        }

        /// <summary>Stores a calibration (durably: write, sync, rename over the old file, sync the folder; <see cref="AtomicFile"/>) and, for the current user, raises <see cref="Changed"/>.</summary>
        public static string Save(UserCalibration calibration)
        {
            if (calibration == null) throw new ArgumentNullException(nameof(calibration));
            string invalid = calibration.Validate();
            if (invalid != null) throw new ArgumentException("calibration not saved: " + invalid, nameof(calibration));
            if (string.IsNullOrWhiteSpace(calibration.userId)) calibration.userId = s_currentUserId;

            string path = PathFor(calibration.userId);
            // Durable write-then-rename (synced, renamed, folder synced): one write at the end of a calibration, on this thread.
            AtomicFile.CreateDirectory(Path.GetDirectoryName(path));
            AtomicFile.WriteAllText(path, JsonUtility.ToJson(calibration, true));

            if (Normalized(calibration.userId) == s_currentUserId)
            {
                s_current = calibration;
                s_loaded = true;
                Changed?.Invoke();
            }
            return path;
        }

        /// <summary>Points the store at another folder (null: back to persistentDataPath) and forgets the cache.</summary>
        public static void SetRootForTests(string folder)
        {
            s_rootOverride = folder;
            s_loaded = false;
            s_current = null;
        }

        /// <summary>User ids become file names: anything but letters, digits, '-' and '_' becomes '_'.</summary>
        static string SafeId(string userId)
        {
            if (string.IsNullOrWhiteSpace(userId)) return DefaultUserId;
            var sb = new StringBuilder(userId.Length);
            foreach (char ch in userId)
                sb.Append((ch < 128 && char.IsLetterOrDigit(ch)) || ch == '-' || ch == '_' ? ch : '_');
            return sb.ToString();
        }

        [RuntimeInitializeOnLoadMethod(RuntimeInitializeLoadType.SubsystemRegistration)]
        static void ResetStatics()
        {
            // With domain reload off, statics survive play sessions: start each one clean.
            s_currentUserId = DefaultUserId;
            s_rootOverride = null;
            s_current = null;
            s_loaded = false;
            Changed = null;
        }
    }
}
