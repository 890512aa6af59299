using System;
using System.Collections.Generic;
using UnityEngine;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// The effects a scene calls for, as an asset: one switch and the settings of each of the core's effects,
    /// and the safety limits. <see cref="Build"/> turns it into the core's immutable <see cref="WeightProfile"/>;
    /// the presets copy <see cref="NamedProfiles"/> ("paper", "paper-experiment", "gain"). Values are validated
    /// by the core when built, and an invalid one is reported with the field's name.
    /// </summary>
    [CreateAssetMenu(menuName = "Kosmos/Pseudo-Haptic Profile", fileName = "PseudoHapticProfile", order = 400)]
    public sealed class PseudoHapticProfile : ScriptableObject
    {
        [Tooltip("Name of the built profile, shown in logs; the asset's name when empty.")]
        [SerializeField] string _profileName;

        [Header("Input: which poses may be followed")]
        [Tooltip("Headset hygiene: low-confidence poses count as lost; after a loss the object waits for steady tracking.")]
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
        [Tooltip("Cap the object's speed at the user's rescaled experimental speed of its mass.")]
        [SerializeField] bool _speedCap;
        [SerializeField] float _speedCapHeadroom;
        [Tooltip("While the hand moves down, the hand–object offset never grows.")]
        [SerializeField] bool _loweringGuard;
        [Tooltip("§3.1: past the threshold, the offset is kept from growing and gradually drawn back.")]
        [SerializeField] bool _offsetCorrection;
        [SerializeField] float _offsetThreshold;
        [SerializeField] float _offsetBand;
        [SerializeField] float _offsetPullSpeed;
        [Tooltip("While the hand is still, a held offset relaxes toward zero (off in the paper's experiments).")]
        [SerializeField] bool _offsetRelaxation;
        [SerializeField] float _relaxationTimeConstant;
        [SerializeField] float _relaxationStillFraction;

        [Header("Position")]
        [Tooltip("§3.1: the object's local y never goes below the floor.")]
        [SerializeField] bool _floorClamp;
        [SerializeField] float _floor;

        [Header("Safety limits (every profile)")]
        [SerializeField] float _maxGain;
        [SerializeField] float _maxObjectSpeed;
        [SerializeField] float _maxFrameTime;
        [SerializeField] float _maxHandSpeed;
        [SerializeField] float _maxCatchUpGap;
        [SerializeField] float _maxCarry;

        [Header("Where the hand is drawn")]
        [Tooltip("Hand True (the paper): the rendered hand stays with the tracked hand and the object visibly lags. Hand On Object (Samad et al. 2019, Rietzler et al. 2018): the rendered hand is drawn at the object.")]
        [SerializeField] HandDrawingMode _handDrawing = HandDrawingMode.HandTrue;

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

        /// <summary>The effects a profile asset lists, in the order they are built (within a stage, as in NamedProfiles.Paper).</summary>
        static readonly Type[] s_effectTypes =
        {
            typeof(TrackingLossHold), typeof(MotionDeadband), typeof(WeightGain), typeof(ExperimentalBlend), typeof(SpeedCap),
            typeof(LoweringGuard), typeof(OffsetCorrection), typeof(OffsetRelaxation), typeof(FloorClamp),
        };

        /// <summary>The core's names of those effects ("weight-gain", …), index for index.</summary>
        static readonly string[] s_effectNames =
        {
            new TrackingLossHold().Name, new MotionDeadband().Name, new WeightGain().Name, new ExperimentalBlend().Name, new SpeedCap().Name,
            new LoweringGuard().Name, new OffsetCorrection().Name, new OffsetRelaxation().Name, new FloorClamp().Name,
        };

        /// <summary>The core's names of the effects a profile asset lists ("weight-gain", …), in build order.</summary>
        public static IReadOnlyList<string> EffectNames => s_effectNames;

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
            var effects = new List<WeightEffect>(9);
            // Same order within each stage as NamedProfiles.Paper, so a preset builds exactly the preset.
            if (_trackingLossHold) effects.Add(new TrackingLossHold(_settleTime, _requireHighConfidence));
            if (_motionDeadband) effects.Add(new MotionDeadband(_deadbandLagTime));
            if (_weightGain) effects.Add(new WeightGain());
            if (_experimentalBlend) effects.Add(new ExperimentalBlend());
            if (_speedCap) effects.Add(new SpeedCap(_speedCapHeadroom));
            if (_loweringGuard) effects.Add(new LoweringGuard());
            if (_offsetCorrection) effects.Add(new OffsetCorrection(_offsetThreshold, _offsetBand, _offsetPullSpeed));
            if (_offsetRelaxation) effects.Add(new OffsetRelaxation(_relaxationTimeConstant, _relaxationStillFraction));
            if (_floorClamp) effects.Add(new FloorClamp(_floor));
            var limits = new SolverLimits(_maxGain, _maxObjectSpeed, _maxFrameTime, _maxHandSpeed, _maxCatchUpGap, _maxCarry);
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

            var cap = p.Find<SpeedCap>();
            _speedCap = cap != null;
            _speedCapHeadroom = (float)(cap ?? new SpeedCap()).Headroom;

            _loweringGuard = p.Has<LoweringGuard>();

            var oc = p.Find<OffsetCorrection>();
            _offsetCorrection = oc != null;
            oc = oc ?? new OffsetCorrection();
            _offsetThreshold = (float)oc.Threshold;
            _offsetBand = (float)oc.Band;
            _offsetPullSpeed = (float)oc.PullSpeed;

            var rl = p.Find<OffsetRelaxation>();
            _offsetRelaxation = rl != null;
            rl = rl ?? new OffsetRelaxation();
            _relaxationTimeConstant = (float)rl.TimeConstant;
            _relaxationStillFraction = (float)rl.StillFraction;

            var fc = p.Find<FloorClamp>();
            _floorClamp = fc != null;
            _floor = (float)(fc ?? new FloorClamp()).Floor;

            SolverLimits l = p.Limits;
            _maxGain = (float)l.MaxGain;
            _maxObjectSpeed = (float)l.MaxObjectSpeed;
            _maxFrameTime = (float)l.MaxFrameTime;
            _maxHandSpeed = (float)l.MaxHandSpeed;
            _maxCatchUpGap = (float)l.MaxCatchUpGap;
            _maxCarry = (float)l.MaxCarry;
        }
    }
}
