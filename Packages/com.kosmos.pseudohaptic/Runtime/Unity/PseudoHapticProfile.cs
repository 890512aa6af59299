using System;
using System.Collections.Generic;
using UnityEngine;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// The effects a scene calls for, as an asset: one switch and the settings of each of the core's effects,
    /// and the safety limits. <see cref="Build"/> turns it into the core's immutable <see cref="WeightProfile"/>;
    /// the presets copy <see cref="NamedProfiles"/> ("paper", "paper-experiment", "gain", "xyz", "paper-literal": its
    /// effects, Eq. 4–6 and y ≥ 0, run through the package's solver; an asset has no hand filter, so the 1 s window and the
    /// per-frame integration of <see cref="PaperLiteralSolver"/> are the CLI's and the core's). The 3D and
    /// two-hand effects (lateral inertia, two hands, break-away) act through <see cref="WeightSolver3D"/>, which
    /// every <see cref="PseudoHapticWeight"/> runs. Values are validated
    /// by the core when built, and an invalid one is reported with the field's name.
    /// </summary>
    [CreateAssetMenu(menuName = "Kosmos/Pseudo-Haptic Profile", fileName = "PseudoHapticProfile", order = 400)]
    public sealed class PseudoHapticProfile : ScriptableObject
    {
        [Tooltip("Name of the built profile, shown in logs; the asset's name when empty.")]
        [SerializeField] string _profileName;

        [Header("Input: which poses may be followed")]
        [Tooltip("Headset hygiene: low-confidence poses, and the first poses after a loss, are followed but never move what the hold remembers (the lift's base and pace).")]
        [SerializeField] bool _trackingLossHold;
        [SerializeField] float _settleTime;
        [SerializeField] bool _requireHighConfidence;

        [Header("Hand motion")]
        [Tooltip("Backlash on the hand so that tracking jitter at rest moves nothing.")]
        [SerializeField] bool _motionDeadband;
        [SerializeField] float _deadbandLagTime;

        [Header("Gain (Eq. 4–6)")]
        [Tooltip("Eq. 4: the object moves W_std/W as far as the hand.")]
        [SerializeField] bool _weightGain;
        [Tooltip("Eq. 5–6: average with the experimental lift speed of the mass, relative to the golf ball.")]
        [SerializeField] bool _experimentalBlend;

        [Header("Object motion")]
        [Tooltip("§5's next step: an object heavier than the standard rises more slowly the higher the hand has lifted it (never below a floor fraction); a lowering retraces it.")]
        [SerializeField] bool _heightDeceleration;
        [Tooltip("Height scale, m: at this lift a very heavy object rises at the midpoint between full speed and the floor fraction.")]
        [SerializeField] float _decelerationHeight;
        [Tooltip("The floor fraction: the upward motion is never multiplied by less than this, in (0, 1].")]
        [SerializeField] float _decelerationMinFraction;
        [Tooltip("§3.1: a fast lift moves a heavy object further than a slow one over the same distance (the gain's exponent follows the lift's mean speed relative to the user's).")]
        [SerializeField] bool _fasterMovesFurther;
        [Tooltip("The gain's exponent for a hand much faster than the user's standard speed (≤ 1).")]
        [SerializeField] float _fastExponent;
        [Tooltip("The gain's exponent for a hand much slower than it, and at rest (≥ 1).")]
        [SerializeField] float _slowExponent;
        [Tooltip("How far above the lift's base the hand is still at rest, m: a rise starts when it leaves this band.")]
        [SerializeField] float _restBand;
        [Tooltip("A rise that has not gone higher for this long has paused: its pace is settled until the hand is back at the base, s.")]
        [SerializeField] float _pauseTime;
        [Tooltip("How strongly the gain's exponent follows the lift's pace: r = x^(−sensitivity).")]
        [SerializeField] float _paceSensitivity;
        [Tooltip("The user's rescaled experimental speed of the mass: how far the hand pulls beyond it is the hold's strain (break-away reads it under the offset correction).")]
        [SerializeField] bool _speedCap;
        [SerializeField] float _speedCapHeadroom;
        [Tooltip("The lift is measured from the lowest place the hand rested: lowered below it, the object moves with the hand.")]
        [SerializeField] bool _loweringGuard;
        [Tooltip("§3.1: past the threshold (0.2 m at 1 kg, 2 cm more per doubling of the mass), the offset stops growing, smoothly, never past the band.")]
        [SerializeField] bool _offsetCorrection;
        [SerializeField] float _offsetThreshold;
        [SerializeField] float _offsetBand;
        [Tooltip("While the hand is still, a held offset relaxes toward zero (off in the paper's experiments).")]
        [SerializeField] bool _offsetRelaxation;
        [SerializeField] float _relaxationTimeConstant;
        [SerializeField] float _relaxationStillFraction;

        [Header("Position")]
        [Tooltip("§3.1: the object's local y never goes below the floor.")]
        [SerializeField] bool _floorClamp;
        [SerializeField] float _floor;

        [Header("Three dimensions and both hands")]
        [Tooltip("x/z trail the hand for objects heavier than the standard (the solver moves x/z instead of the grab).")]
        [SerializeField] bool _lateralInertia;
        [Tooltip("s, the trailing's time constant at gain 0 (scaled by 1 − gain).")]
        [SerializeField] float _lateralTimeConstant;
        [Tooltip("m, the largest horizontal lag.")]
        [SerializeField] float _lateralMaxOffset;
        [Tooltip("Each of two holding hands carries a share of the mass (the paper's participants lifted with both hands).")]
        [SerializeField] bool _twoHands;
        [Tooltip("The share of the mass each hand carries while both hold (0.5: half each).")]
        [SerializeField] float _twoHandsShare;
        [Tooltip("The object tears loose and falls when the hands pull this far: under the offset correction how far beyond what the weight allows (the strain), without it the distance from where they grabbed; at the second pose in a row past it.")]
        [SerializeField] bool _breakAway;
        [Tooltip("m: the strain under the offset correction, the distance beyond the grab offset without it.")]
        [SerializeField] float _breakAwayDistance;

        [Header("Safety limits (every profile)")]
        [SerializeField] float _maxGain;
        [SerializeField] float _maxHandSpeed;
        [SerializeField] float _maxFrameTime;
        [Tooltip("m/s: how fast an offset the hand's motion did not make (a hand joining, a change of profile) glides away.")]
        [SerializeField] float _glideSpeed;

        [Header("Where the hand is drawn")]
        [Tooltip("Hand True (the paper): the rendered hand stays with the tracked hand and the object visibly lags. Hand On Object (Samad et al. 2019, Rietzler et al. 2018): the rendered hand is drawn at the object.")]
        [SerializeField] HandDrawingMode _handDrawing = HandDrawingMode.HandTrue;

        /// <summary>The break-away distance an asset offers when it is switched on (the core has no default), m.</summary>
        public const float DefaultBreakAwayDistance = 0.25f;

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

        /// <summary>A new in-memory profile set to the preset <paramref name="presetName"/> (see <see cref="NamedProfiles.Names"/>).</summary>
        public static PseudoHapticProfile CreatePreset(string presetName)
        {
            var profile = CreateInstance<PseudoHapticProfile>();
            profile.ApplyPreset(presetName);
            profile.name = presetName;
            return profile;
        }

        /// <summary>Sets every switch and setting to the named preset of the core; throws on an unknown name.</summary>
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

        /// <summary>The effects a profile asset lists, in the order they are built (within a stage, as in NamedProfiles.Paper).</summary>
        static readonly Type[] s_effectTypes =
        {
            typeof(TrackingLossHold), typeof(MotionDeadband), typeof(WeightGain), typeof(ExperimentalBlend), typeof(SpeedCap),
            typeof(LoweringGuard), typeof(OffsetCorrection), typeof(OffsetRelaxation), typeof(FloorClamp),
            typeof(HeightDeceleration), typeof(FasterMovesFurther), typeof(LateralInertia), typeof(TwoHands), typeof(BreakAway),
        };

        /// <summary>The core's names of those effects ("weight-gain", …), index for index.</summary>
        static readonly string[] s_effectNames =
        {
            new TrackingLossHold().Name, new MotionDeadband().Name, new WeightGain().Name, new ExperimentalBlend().Name, new SpeedCap().Name,
            new LoweringGuard().Name, new OffsetCorrection().Name, new OffsetRelaxation().Name, new FloorClamp().Name,
            new HeightDeceleration().Name, new FasterMovesFurther().Name, new LateralInertia().Name, new TwoHands().Name, new BreakAway(DefaultBreakAwayDistance).Name,
        };

        /// <summary>The core's names of the effects a profile asset lists ("weight-gain", …), in build order.</summary>
        public static IReadOnlyList<string> EffectNames => s_effectNames;

        /// <summary>Whether <paramref name="effectName"/> is one of <see cref="EffectNames"/>.</summary>
        public static bool IsKnownEffect(string effectName) => effectName != null && Array.IndexOf(s_effectNames, effectName) >= 0;

        ref bool Switch(int index)
        {
            switch (index)
            {
                case 0: return ref _trackingLossHold;
                case 1: return ref _motionDeadband;
                case 2: return ref _weightGain;
                case 3: return ref _experimentalBlend;
                case 4: return ref _speedCap;
                case 5: return ref _loweringGuard;
                case 6: return ref _offsetCorrection;
                case 7: return ref _offsetRelaxation;
                case 8: return ref _floorClamp;
                case 9: return ref _heightDeceleration;
                case 10: return ref _fasterMovesFurther;
                case 11: return ref _lateralInertia;
                case 12: return ref _twoHands;
                case 13: return ref _breakAway;
                default: throw new ArgumentOutOfRangeException(nameof(index));
            }
        }

        static int IndexOf(string effectName)
        {
            int i = Array.IndexOf(s_effectNames, effectName);
            if (i < 0) throw new ArgumentException("effect '" + effectName + "' is unknown; known: " + string.Join(", ", s_effectNames) + ".", nameof(effectName));
            return i;
        }

        static int IndexOf(Type effectType)
        {
            int i = Array.IndexOf(s_effectTypes, effectType);
            if (i < 0) throw new ArgumentException(effectType.Name + " is not one of the effects a profile asset lists.", nameof(effectType));
            return i;
        }

        /// <summary>Whether the effect named <paramref name="effectName"/> (see <see cref="EffectNames"/>) is switched on.</summary>
        public bool IsEnabled(string effectName) => Switch(IndexOf(effectName));

        /// <summary>Switches the effect named <paramref name="effectName"/> on or off (e.g. from a playground button).</summary>
        public void SetEnabled(string effectName, bool on)
        {
            Switch(IndexOf(effectName)) = on;
            MarkChanged();
        }

        public bool IsEnabled<T>() where T : WeightEffect => Switch(IndexOf(typeof(T)));

        public void SetEnabled<T>(bool on) where T : WeightEffect
        {
            Switch(IndexOf(typeof(T))) = on;
            MarkChanged();
        }

        /// <summary>
        /// The core profile these settings describe, built once per change and shared by every object that
        /// uses this asset. Throws <see cref="ArgumentException"/> naming the field when a value is invalid.
        /// </summary>
        public WeightProfile Build()
        {
            if (_built != null) return _built;
            var effects = new List<WeightEffect>(14);
            // Same order within each stage as NamedProfiles.Paper, so a preset builds exactly the preset.
            if (_trackingLossHold) effects.Add(new TrackingLossHold(_settleTime, _requireHighConfidence));
            if (_motionDeadband) effects.Add(new MotionDeadband(_deadbandLagTime));
            if (_weightGain) effects.Add(new WeightGain());
            if (_experimentalBlend) effects.Add(new ExperimentalBlend());
            if (_heightDeceleration) effects.Add(new HeightDeceleration(_decelerationHeight, _decelerationMinFraction));
            if (_fasterMovesFurther) effects.Add(new FasterMovesFurther(_fastExponent, _slowExponent, _restBand, _pauseTime, _paceSensitivity));
            if (_speedCap) effects.Add(new SpeedCap(_speedCapHeadroom));
            if (_loweringGuard) effects.Add(new LoweringGuard());
            if (_offsetCorrection) effects.Add(new OffsetCorrection(_offsetThreshold, _offsetBand));
            if (_offsetRelaxation) effects.Add(new OffsetRelaxation(_relaxationTimeConstant, _relaxationStillFraction));
            if (_floorClamp) effects.Add(new FloorClamp(_floor));
            if (_lateralInertia) effects.Add(new LateralInertia(_lateralTimeConstant, _lateralMaxOffset));
            if (_twoHands) effects.Add(new TwoHands(_twoHandsShare));
            if (_breakAway) effects.Add(new BreakAway(_breakAwayDistance));
            var limits = new SolverLimits(_maxGain, _maxHandSpeed, _maxFrameTime, _glideSpeed);
            string label = !string.IsNullOrWhiteSpace(_profileName) ? _profileName : (!string.IsNullOrWhiteSpace(name) ? name : "custom");
            _built = new WeightProfile(label, effects, limits);
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

        void OnValidate() => MarkChanged();

        void MarkChanged()
        {
            _built = null;
            unchecked { _version++; }
        }

        /// <summary>Reads every switch and setting from a core profile; effects it lacks keep the core's defaults.</summary>
        void CopyFrom(WeightProfile p)
        {
            var tl = p.Find<TrackingLossHold>();
            _trackingLossHold = tl != null;
            tl = tl ?? new TrackingLossHold();
            _settleTime = (float)tl.SettleTime;
            _requireHighConfidence = tl.RequireHighConfidence;

            var db = p.Find<MotionDeadband>();
            _motionDeadband = db != null;
            _deadbandLagTime = (float)(db ?? new MotionDeadband()).LagTime;

            _weightGain = p.Has<WeightGain>();
            _experimentalBlend = p.Has<ExperimentalBlend>();

            var hd = p.Find<HeightDeceleration>();
            _heightDeceleration = hd != null;
            hd = hd ?? new HeightDeceleration();
            _decelerationHeight = (float)hd.Height;
            _decelerationMinFraction = (float)hd.MinFraction;

            var fm = p.Find<FasterMovesFurther>();
            _fasterMovesFurther = fm != null;
            fm = fm ?? new FasterMovesFurther();
            _fastExponent = (float)fm.FastExponent;
            _slowExponent = (float)fm.SlowExponent;
            _restBand = (float)fm.RestBand;
            _pauseTime = (float)fm.PauseTime;
            _paceSensitivity = (float)fm.Sensitivity;

            var cap = p.Find<SpeedCap>();
            _speedCap = cap != null;
            _speedCapHeadroom = (float)(cap ?? new SpeedCap()).Headroom;

            _loweringGuard = p.Has<LoweringGuard>();

            var oc = p.Find<OffsetCorrection>();
            _offsetCorrection = oc != null;
            oc = oc ?? new OffsetCorrection();
            _offsetThreshold = (float)oc.Threshold;
            _offsetBand = (float)oc.Band;

            var rl = p.Find<OffsetRelaxation>();
            _offsetRelaxation = rl != null;
            rl = rl ?? new OffsetRelaxation();
            _relaxationTimeConstant = (float)rl.TimeConstant;
            _relaxationStillFraction = (float)rl.StillFraction;

            var fc = p.Find<FloorClamp>();
            _floorClamp = fc != null;
            _floor = (float)(fc ?? new FloorClamp()).Floor;

            var li = p.Find<LateralInertia>();
            _lateralInertia = li != null;
            li = li ?? new LateralInertia();
            _lateralTimeConstant = (float)li.TimeConstant;
            _lateralMaxOffset = (float)li.MaxOffset;

            var th = p.Find<TwoHands>();
            _twoHands = th != null;
            _twoHandsShare = (float)(th ?? new TwoHands()).Share;

            var ba = p.Find<BreakAway>();
            _breakAway = ba != null;
            ba = ba ?? new BreakAway(DefaultBreakAwayDistance);
            _breakAwayDistance = (float)ba.Distance;

            SolverLimits l = p.Limits;
            _maxGain = (float)l.MaxGain;
            _maxHandSpeed = (float)l.MaxHandSpeed;
            _maxFrameTime = (float)l.MaxFrameTime;
            _glideSpeed = (float)l.GlideSpeed;
        }
    }
}
