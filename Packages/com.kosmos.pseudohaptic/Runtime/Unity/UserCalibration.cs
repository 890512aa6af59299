using System;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// One user's calibration as stored on the device (JSON through <see cref="UnityEngine.JsonUtility"/>):
    /// the standard speed v_std measured by <see cref="StandardSpeedCalibration"/> from golf-ball lifts.
    /// </summary>
    [Serializable]
    public sealed class UserCalibration
    {
        public const int CurrentFormat = 1;

        public int format = CurrentFormat;
        public string userId;

        /// <summary>v_std, m/s.</summary>
        public double standardSpeed;

        public int liftsUsed;
        public int liftsOffered;

        /// <summary>MAD / median of the used lifts' speeds.</summary>
        public double relativeSpread;

        /// <summary>ISO 8601, UTC.</summary>
        public string calibratedAtUtc;

        /// <summary>The stored record of an accepted calibration result.</summary>
        public static UserCalibration From(string userId, in CalibrationResult result)
        {
            if (!result.IsAccepted) throw new ArgumentException("a rejected calibration (" + result.Reason + ") is not stored.", nameof(result));
            return new UserCalibration
            {
                userId = userId,
                standardSpeed = result.StandardSpeed,
                liftsUsed = result.LiftsUsed,
                liftsOffered = result.LiftsOffered,
                relativeSpread = result.RelativeSpread,
                calibratedAtUtc = DateTime.UtcNow.ToString("o", System.Globalization.CultureInfo.InvariantCulture),
            };
        }

        /// <summary>Null when the record can drive the solver; otherwise what is wrong with it.</summary>
        public string Validate()
        {
            if (format != CurrentFormat) return "format " + format + " is not " + CurrentFormat;
            if (double.IsNaN(standardSpeed) || standardSpeed < WeightSolver.MinStandardSpeed || standardSpeed > WeightSolver.MaxStandardSpeed)
                return "standardSpeed " + standardSpeed.ToString("R", System.Globalization.CultureInfo.InvariantCulture)
                    + " m/s lies outside [" + WeightSolver.MinStandardSpeed + ", " + WeightSolver.MaxStandardSpeed + "]";
            return null;
        }
    }
}
