using UnityEngine;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// The fields a profile asset had before issue 33, kept only so that Unity reads an old asset's YAML into them: the
    /// first load converts them to the effect list (<see cref="LegacyProfileFields"/>) and marks them read (settle time
    /// NaN), so a saved asset never converts again. Frozen: new effects never appear here.
    /// </summary>
    public sealed partial class PseudoHapticProfile
    {
#pragma warning disable CS0649 // written by Unity's deserializer
        [SerializeField, HideInInspector] bool _trackingLossHold;
        [SerializeField, HideInInspector] float _settleTime = float.NaN;
        [SerializeField, HideInInspector] bool _requireHighConfidence;
        [SerializeField, HideInInspector] bool _motionDeadband;
        [SerializeField, HideInInspector] float _deadbandLagTime;
        [SerializeField, HideInInspector] bool _weightGain;
        [SerializeField, HideInInspector] bool _experimentalBlend;
        [SerializeField, HideInInspector] bool _heightDeceleration;
        [SerializeField, HideInInspector] float _decelerationHeight;
        [SerializeField, HideInInspector] float _decelerationMinFraction;
        [SerializeField, HideInInspector] bool _fasterMovesFurther;
        [SerializeField, HideInInspector] float _fastExponent;
        [SerializeField, HideInInspector] float _slowExponent;
        [SerializeField, HideInInspector] float _restBand;
        [SerializeField, HideInInspector] float _pauseTime;
        [SerializeField, HideInInspector] float _paceSensitivity;
        [SerializeField, HideInInspector] bool _speedCap;
        [SerializeField, HideInInspector] float _speedCapHeadroom;
        [SerializeField, HideInInspector] bool _loweringGuard;
        [SerializeField, HideInInspector] bool _offsetCorrection;
        [SerializeField, HideInInspector] float _offsetThreshold;
        [SerializeField, HideInInspector] float _offsetBand;
        [SerializeField, HideInInspector] bool _offsetRelaxation;
        [SerializeField, HideInInspector] float _relaxationTimeConstant;
        [SerializeField, HideInInspector] float _relaxationStillFraction;
        [SerializeField, HideInInspector] bool _floorClamp;
        [SerializeField, HideInInspector] float _floor;
        [SerializeField, HideInInspector] bool _lateralInertia;
        [SerializeField, HideInInspector] float _lateralTimeConstant;
        [SerializeField, HideInInspector] float _lateralMaxOffset;
        [SerializeField, HideInInspector] bool _twoHands;
        [SerializeField, HideInInspector] float _twoHandsShare;
        [SerializeField, HideInInspector] bool _breakAway;
        [SerializeField, HideInInspector] float _breakAwayDistance;
        [SerializeField, HideInInspector] float _maxGain;
        [SerializeField, HideInInspector] float _maxHandSpeed;
        [SerializeField, HideInInspector] float _maxFrameTime;
        [SerializeField, HideInInspector] float _glideSpeed;
#pragma warning restore CS0649

        /// <summary>Converts the old fields when an old asset filled them (every old asset stored a settle time); true if it did.</summary>
        bool UpgradeLegacyFields()
        {
            if (float.IsNaN(_settleTime)) return false;
            var old = new LegacyProfileFields
            {
                trackingLossHold = _trackingLossHold, settleTime = _settleTime, requireHighConfidence = _requireHighConfidence,
                motionDeadband = _motionDeadband, deadbandLagTime = _deadbandLagTime, weightGain = _weightGain, experimentalBlend = _experimentalBlend,
                heightDeceleration = _heightDeceleration, decelerationHeight = _decelerationHeight, decelerationMinFraction = _decelerationMinFraction,
                fasterMovesFurther = _fasterMovesFurther, fastExponent = _fastExponent, slowExponent = _slowExponent, restBand = _restBand,
                pauseTime = _pauseTime, paceSensitivity = _paceSensitivity, speedCap = _speedCap, speedCapHeadroom = _speedCapHeadroom,
                loweringGuard = _loweringGuard, offsetCorrection = _offsetCorrection, offsetThreshold = _offsetThreshold, offsetBand = _offsetBand,
                offsetRelaxation = _offsetRelaxation, relaxationTimeConstant = _relaxationTimeConstant, relaxationStillFraction = _relaxationStillFraction,
                floorClamp = _floorClamp, floor = _floor, lateralInertia = _lateralInertia, lateralTimeConstant = _lateralTimeConstant,
                lateralMaxOffset = _lateralMaxOffset, twoHands = _twoHands, twoHandsShare = _twoHandsShare, breakAway = _breakAway,
                breakAwayDistance = _breakAwayDistance, maxGain = _maxGain, maxHandSpeed = _maxHandSpeed, maxFrameTime = _maxFrameTime, glideSpeed = _glideSpeed,
            };
            _effects = old.Effects();
            _limits = old.Limits();
            _settleTime = float.NaN;
            return true;
        }
    }
}
