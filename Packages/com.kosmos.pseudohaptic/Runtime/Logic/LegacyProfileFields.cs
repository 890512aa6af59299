using System.Collections.Generic;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// A profile asset as it was saved before issue 33 (one switch and flat settings per effect, floats): read once from an
    /// old asset (<c>PseudoHapticProfile.OnAfterDeserialize</c>) and converted to the effect list, so an old asset builds
    /// exactly the profile it built before, value for value. Frozen: new effects never appear here.
    /// </summary>
    public sealed class LegacyProfileFields
    {
        public bool trackingLossHold, requireHighConfidence, motionDeadband, weightGain, experimentalBlend, heightDeceleration,
            fasterMovesFurther, speedCap, loweringGuard, offsetCorrection, offsetRelaxation, floorClamp, lateralInertia, twoHands, breakAway;

        public float settleTime, deadbandLagTime, decelerationHeight, decelerationMinFraction, fastExponent, slowExponent, restBand,
            pauseTime, paceSensitivity, speedCapHeadroom, offsetThreshold, offsetBand, relaxationTimeConstant, relaxationStillFraction,
            floor, lateralTimeConstant, lateralMaxOffset, twoHandsShare, breakAwayDistance, maxGain, maxHandSpeed, maxFrameTime, glideSpeed;

        /// <summary>The effects the old asset switched on, with its values, in the order its Build added them.</summary>
        public List<ProfileEffect> Effects()
        {
            var list = new List<ProfileEffect>();
            void Add(bool on, string name, params object[] pairs)
            {
                if (!on) return;
                var e = ProfileEffect.Of(EffectRegistry.Get(name));
                for (int i = 0; i < pairs.Length; i += 2)
                    e.Set((string)pairs[i], pairs[i + 1] is bool b ? (b ? 1 : 0) : (double)(float)pairs[i + 1]);
                list.Add(e);
            }
            Add(trackingLossHold, "tracking-loss-hold", "settleTime", settleTime, "requireHighConfidence", requireHighConfidence);
            Add(motionDeadband, "motion-deadband", "lagTime", deadbandLagTime);
            Add(weightGain, "weight-gain");
            Add(experimentalBlend, "experimental-blend");
            Add(heightDeceleration, "height-deceleration", "height", decelerationHeight, "minFraction", decelerationMinFraction);
            Add(fasterMovesFurther, "faster-moves-further", "fastExponent", fastExponent, "slowExponent", slowExponent, "restBand", restBand, "pauseTime", pauseTime, "sensitivity", paceSensitivity);
            Add(speedCap, "speed-cap", "headroom", speedCapHeadroom);
            Add(loweringGuard, "lowering-guard");
            Add(offsetCorrection, "offset-correction", "threshold", offsetThreshold, "band", offsetBand);
            Add(offsetRelaxation, "offset-relaxation", "timeConstant", relaxationTimeConstant, "stillFraction", relaxationStillFraction);
            Add(floorClamp, "floor-clamp", "floor", floor);
            Add(lateralInertia, "lateral-inertia", "timeConstant", lateralTimeConstant, "maxOffset", lateralMaxOffset);
            Add(twoHands, "two-hands", "share", twoHandsShare);
            Add(breakAway, "break-away", "distance", breakAwayDistance);
            return list;
        }

        /// <summary>The old asset's limits (its workspace radius was never stored: the default).</summary>
        public List<EffectSettingValue> Limits() => new List<EffectSettingValue>
        {
            new EffectSettingValue("maxGain", maxGain), new EffectSettingValue("maxHandSpeed", maxHandSpeed),
            new EffectSettingValue("maxFrameTime", maxFrameTime), new EffectSettingValue("glideSpeed", glideSpeed),
        };
    }
}
