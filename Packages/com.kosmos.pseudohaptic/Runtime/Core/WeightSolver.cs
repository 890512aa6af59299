using System;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// The pseudo-haptic weight solver of Son et al. 2022 for one held object: given the tracked hand each
    /// frame, it returns the object's new height so that a heavier object lags behind the hand and a lighter
    /// one leads it. Per frame: pose → input effects → estimator (→ hand filter, if the profile has one) →
    /// hand-motion effects → gain → object-motion effects → speed limit → position effects. Configuration validates and throws; <see cref="Step"/> never
    /// throws, never allocates, and always returns a finite height.
    /// </summary>
    public sealed class WeightSolver
    {
        /// <summary>v_std used when the user has not calibrated, m/s (ALGORITHM.md says why).</summary>
        public const double DefaultStandardSpeed = 0.5;
        public const double MinStandardSpeed = 0.05;
        public const double MaxStandardSpeed = 5.0;

        /// <summary>Hand heights beyond this magnitude, m, are treated as garbage, like NaN.</summary>
        public const double MaxCoordinate = 1e5;

        HoldState _state;
        SolverConstants _constants;
        IHandFilter _filter;

        public WeightModel Model { get; private set; }
        public WeightProfile Profile { get; private set; }
        public double StandardSpeed => _constants.StandardSpeed;
        public double Gain => _constants.Gain;
        public SolverConstants Constants => _constants;

        /// <summary>A copy of the hold's state.</summary>
        public HoldState State => _state;
        public bool IsHolding => _state.IsHolding;
        public double ObjectY => _state.ObjectY;

        /// <summary>The hand height the solver follows, m.</summary>
        public double HandY => _state.HandY;

        /// <summary>hand − object, m: positive when the object hangs below the hand.</summary>
        public double Offset => _state.Offset;

        /// <summary>hand − object when the hold began, m: the effects act on <see cref="Offset"/> less this.</summary>
        public double GrabOffset => _state.GrabOffset;

        double _bottomBelowPivot;

        /// <summary>
        /// Metres from the object's pivot down to its lowest point (finite, ≥ 0; default 0): the floor
        /// (<see cref="FloorClamp"/>) keeps the object's bottom, not its pivot, above the support. The Unity layer
        /// sets it from the collider's extent. Set it before <see cref="BeginHold"/>; an invalid value throws
        /// naming BottomBelowPivot.
        /// </summary>
        public double BottomBelowPivot
        {
            get => _bottomBelowPivot;
            set
            {
                ConfigurationGuard.InRange(value, 0, MaxCoordinate, nameof(BottomBelowPivot));
                _bottomBelowPivot = value;
                var c = _constants;
                _constants = new SolverConstants(c.Gain, c.StandardSpeed, c.CapSpeed, c.DeadbandWidth, c.Limits, value, c.OffsetThreshold);
            }
        }

        public WeightSolver(WeightModel model, WeightProfile profile = null, double standardSpeed = DefaultStandardSpeed)
        {
            Configure(model, profile ?? NamedProfiles.Paper, standardSpeed);
        }

        /// <summary>Changes object, profile or user; allowed during a hold (the object continues from where it is).</summary>
        public void Configure(WeightModel model, WeightProfile profile, double standardSpeed)
        {
            if (model == null) throw new ArgumentNullException(nameof(model));
            if (profile == null) throw new ArgumentNullException(nameof(profile));
            ConfigurationGuard.InRange(standardSpeed, MinStandardSpeed, MaxStandardSpeed, nameof(standardSpeed));
            var limits = profile.Limits;
            double gain = model.Gain(profile.Has<WeightGain>(), profile.Has<ExperimentalBlend>(), limits.MaxGain);
            var cap = profile.Find<SpeedCap>();
            var deadband = profile.Find<MotionDeadband>();
            var correction = profile.Find<OffsetCorrection>();
            Model = model;
            if (!ReferenceEquals(profile, Profile))
            {
                _filter = profile.HandFilter?.Create();
                _filter?.Reset(_state.HandY);
            }
            Profile = profile;
            _constants = new SolverConstants(gain, standardSpeed,
                cap != null ? cap.CapFor(model, standardSpeed) : double.PositiveInfinity,
                deadband != null ? deadband.WidthFor(standardSpeed, gain) : 0, limits, _bottomBelowPivot,
                correction != null ? correction.ThresholdFor(model.MassKg) : 0);
        }

        /// <summary>
        /// Starts a hold: the hand is at <paramref name="handY"/> (may be NaN if not yet tracked), the object at
        /// <paramref name="objectY"/> (raised to the floor if it is below it). hand − object at this moment is the
        /// grab offset (<see cref="GrabOffset"/>); every effect acts on the offset relative to it.
        /// </summary>
        public void BeginHold(double handY, double objectY, double poseTime = double.NaN)
        {
            ConfigurationGuard.InRange(objectY, -MaxCoordinate, MaxCoordinate, nameof(objectY));
            Begin(handY, objectY, double.NaN, poseTime);
        }

        /// <summary>
        /// Starts a hold with the object <paramref name="grabOffset"/> metres below the hand (above it when
        /// negative): <c>BeginHold(handY, handY − grabOffset, poseTime)</c>, except that the grab offset is kept
        /// exactly as given, so that, wherever the floor is not in the way, the object's path is exactly the path
        /// of a hold begun with hand and object together, less <paramref name="grabOffset"/>. The hand must be
        /// usable (the object is placed relative to it); otherwise this throws naming handY.
        /// </summary>
        public void BeginHoldWithGrabOffset(double handY, double grabOffset, double poseTime = double.NaN)
        {
            if (!HandSample.IsUsableHeight(handY))
                throw new ArgumentOutOfRangeException(nameof(handY), handY, "handY must be a usable height (finite, within ±" + MaxCoordinate + " m) to place the object relative to it.");
            ConfigurationGuard.InRange(grabOffset, -MaxCoordinate, MaxCoordinate, nameof(grabOffset));
            Begin(handY, handY - grabOffset, grabOffset, poseTime);
        }

        void Begin(double handY, double objectY, double exactGrabOffset, double poseTime)
        {
            bool handOk = HandSample.IsUsableHeight(handY);
            _state = default;
            _state.IsHolding = true;
            var floor = Profile.Find<FloorClamp>();
            double lowest = floor != null ? floor.Floor + _bottomBelowPivot : double.NegativeInfinity;
            bool raised = objectY < lowest;
            if (raised) objectY = lowest;
            _state.Estimator.Reset(handOk ? handY : double.NaN, poseTime, objectY);
            _state.HandY = handOk ? handY : objectY;
            if (handOk)
            {
                _state.GrabOffset = !raised && double.IsFinite(exactGrabOffset) ? exactGrabOffset : handY - objectY;
                _state.HeldY = handY;
            }
            else
            {
                _state.GrabOffset = 0;
                _state.HeldY = objectY;
            }
            _state.ObjectY = objectY;
            _state.StartY = _state.HeldY;
            _filter?.Reset(_state.HandY);
            ResetEffects(_state.HandY);
        }

        /// <summary>Ends the hold; further steps return the object's last height.</summary>
        public void EndHold() => _state.IsHolding = false;

        /// <summary>Advances one rendered frame of <paramref name="dt"/> seconds and returns the object's new height.</summary>
        public double Step(in HandSample sample, double dt)
        {
            if (!_state.IsHolding) return _state.ObjectY;
            var limits = _constants.Limits;

            // Bad frame times are absorbed: NaN or negative count as no time, infinity as a very long hitch.
            if (double.IsPositiveInfinity(dt)) dt = 3600;
            else if (!(dt > 0)) dt = 0;
            // Compensated (Kahan) sum: the hold's clock keeps the microsecond over millions of frames.
            double add = dt - _state.TimeCompensation, sum = _state.Time + add;
            _state.TimeCompensation = (sum - _state.Time) - add;
            _state.Time = sum;

            var f = new MotionFrame
            {
                Dt = dt,
                PoseY = sample.Y,
                PoseTime = double.IsFinite(sample.PoseTime) ? sample.PoseTime : double.NaN,
                IsHighConfidence = sample.IsHighConfidence,
                Usable = sample.IsUsable,
                ObjectY = _state.HeldY,
            };

            var effects = Profile.InputEffects;
            for (int i = 0; i < effects.Length; i++) effects[i].Apply(ref f, ref _state, in _constants);

            _state.Estimator.Update(ref f, limits);
            if (f.Reanchored)
            {
                // The hand moved, the object did not: to the effects the hand was already there (an offset this
                // leaves is not motion to follow; the offset correction draws it back at its own pace).
                f.HandBefore = f.HandAfter;
                _state.Carry = 0;
                _filter?.Reset(f.HandAfter);
                ResetEffects(f.HandAfter);
            }
            else if (_filter != null)
            {
                // Effects see the filtered hand: its position, displacement and direction.
                f.HandBefore = _state.HandY;
                f.HandFiltered = true;
                if (f.Usable && _state.Estimator.HasPose)
                {
                    double filtered = _filter.Filter(f.HandAfter, f.MotionInterval > 0, f.MotionInterval, dt);
                    if (double.IsFinite(filtered)) f.HandAfter = filtered;
                    else { _filter.Reset(f.HandAfter); }
                }
                else f.HandAfter = _state.HandY;
                f.HandDelta = f.HandAfter - f.HandBefore;
            }
            _state.HandY = f.HandAfter;
            f.PoseHandBefore = f.HandBefore;
            f.PoseHandAfter = f.HandAfter;

            effects = Profile.HandEffects;
            for (int i = 0; i < effects.Length; i++) effects[i].Apply(ref f, ref _state, in _constants);

            f.ObjectDelta = _constants.Gain * f.HandDelta;
            f.Carry = _state.Carry;

            effects = Profile.ObjectEffects;
            for (int i = 0; i < effects.Length; i++) effects[i].Apply(ref f, ref _state, in _constants);

            // Speed limit: motion beyond it is carried to the next frames, never dropped as a jump.
            double carry = f.TotalDelta;
            // Judged over the pose's interval when a pose arrived, so a 30 Hz pose under 120 Hz frames is not a spike.
            double maxStep = limits.MaxObjectSpeed * Math.Min(Math.Max(f.MotionInterval, dt), limits.MaxFrameTime);
            double step = Math.Min(Math.Max(carry, -maxStep), maxStep);
            carry -= step;
            _state.Carry = Math.Min(Math.Max(carry, -limits.MaxCarry), limits.MaxCarry);
            f.NewObjectY = _state.HeldY + step;

            effects = Profile.PositionEffects;
            for (int i = 0; i < effects.Length; i++) effects[i].Apply(ref f, ref _state, in _constants);

            if (double.IsFinite(f.NewObjectY))
            {
                _state.HeldY = f.NewObjectY;
                _state.ObjectY = f.NewObjectY - _state.GrabOffset;
            }
            else _state.Carry = 0; // unreachable with the built-in effects; a custom one must not poison the transform
            if (!double.IsFinite(_state.Carry)) _state.Carry = 0;
            return _state.ObjectY;
        }

        void ResetEffects(double handY)
        {
            var all = Profile._all;
            for (int i = 0; i < all.Length; i++) all[i].Reset(ref _state, handY);
        }
    }
}
