using System;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// One user's calibration as stored on the device (JSON through <see cref="UnityEngine.JsonUtility"/>):
    /// the standard speed v_std measured by <see cref="StandardSpeedCalibration"/> from golf-ball lifts and (format 2,
    /// issue 31) the cue strength tuned from the user's own weight-discrimination threshold
    /// (<see cref="CueStrengthStep"/>). A format-1 file (no cue strength) is still read, with the default strength 1.
    /// </summary>
    [Serializable]
    public sealed class UserCalibration
    {
        public const int CurrentFormat = 2;

        /// <summary>The first format: the standard speed only.</summary>
        public const int FirstFormat = 1;

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

        /// <summary>The cue strength s (<see cref="WeightSolver.CueStrength"/>): 1 until the user's threshold was measured.</summary>
        public double cueStrength = WeightSolver.DefaultCueStrength;

        /// <summary>The Weber fraction the cue strength was tuned from (JND / standard at s = 1); NaN or 0 when not measured.</summary>
        public double cueWeber;

        /// <summary>When the cue strength was tuned, ISO 8601, UTC; empty when not.</summary>
        public string cueTunedAtUtc;

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

        /// <summary>Null when the record can drive the solver; otherwise what is wrong with it. A format-1 record is
        /// brought to the current format here (its cue strength is the default).</summary>
        public string Validate()
        {
            if (format == FirstFormat)
            {
                format = CurrentFormat;
                cueStrength = WeightSolver.DefaultCueStrength;
            }
            if (format != CurrentFormat) return "format " + format + " is neither " + FirstFormat + " nor " + CurrentFormat;
            if (double.IsNaN(cueStrength) || cueStrength < WeightSolver.MinCueStrength || cueStrength > WeightSolver.MaxCueStrength)
                return "cueStrength " + cueStrength.ToString("R", System.Globalization.CultureInfo.InvariantCulture)
                    + " lies outside [" + WeightSolver.MinCueStrength.ToString("R", System.Globalization.CultureInfo.InvariantCulture) + ", " + WeightSolver.MaxCueStrength + "]";
            if (double.IsNaN(standardSpeed) || standardSpeed < WeightSolver.MinStandardSpeed || standardSpeed > WeightSolver.MaxStandardSpeed)
                return "standardSpeed " + standardSpeed.ToString("R", System.Globalization.CultureInfo.InvariantCulture)
                    + " m/s lies outside [" + WeightSolver.MinStandardSpeed + ", " + WeightSolver.MaxStandardSpeed + "]";
            return null;
        }
    }
}
