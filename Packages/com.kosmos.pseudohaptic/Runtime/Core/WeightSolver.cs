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
            Model = model;
            if (!ReferenceEquals(profile, Profile))
            {
                _filter = profile.HandFilter?.Create();
                _filter?.Reset(_state.HandY);
            }
            Profile = profile;
            _constants = new SolverConstants(gain, standardSpeed,
                cap != null ? cap.CapFor(model, standardSpeed) : double.PositiveInfinity,
                deadband != null ? deadband.WidthFor(standardSpeed) : 0, limits);
        }

        /// <summary>Starts a hold: the hand is at <paramref name="handY"/> (may be NaN if not yet tracked), the object at <paramref name="objectY"/>.</summary>
        public void BeginHold(double handY, double objectY, double poseTime = double.NaN)
        {
            ConfigurationGuard.InRange(objectY, -MaxCoordinate, MaxCoordinate, nameof(objectY));
            bool handOk = HandSample.IsUsableHeight(handY);
            _state = default;
            _state.IsHolding = true;
            var floor = Profile.Find<FloorClamp>();
            _state.ObjectY = floor != null && objectY < floor.Floor ? floor.Floor : objectY;
            _state.StartY = _state.ObjectY;
            _state.Estimator.Reset(handOk ? handY : double.NaN, poseTime);
            _state.HandY = handOk ? handY : objectY;
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
                ObjectY = _state.ObjectY,
            };

            var effects = Profile.InputEffects;
            for (int i = 0; i < effects.Length; i++) effects[i].Apply(ref f, ref _state, in _constants);

            _state.Estimator.Update(ref f, limits);
            if (f.Reanchored)
            {
                _state.Carry = 0;
                _filter?.Reset(f.HandAfter);
                ResetEffects(f.HandAfter);
            }
            else if (_filter != null)
            {
                // Effects see the filtered hand: its position, displacement and direction.
                f.HandBefore = _state.HandY;
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
            double window = f.MotionInterval > dt ? f.MotionInterval : dt;
            double maxStep = limits.MaxObjectSpeed * (window < limits.MaxFrameTime ? window : limits.MaxFrameTime);
            double step = carry > maxStep ? maxStep : (carry < -maxStep ? -maxStep : carry);
            carry -= step;
            _state.Carry = carry > limits.MaxCarry ? limits.MaxCarry : (carry < -limits.MaxCarry ? -limits.MaxCarry : carry);
            f.NewObjectY = _state.ObjectY + step;

            effects = Profile.PositionEffects;
            for (int i = 0; i < effects.Length; i++) effects[i].Apply(ref f, ref _state, in _constants);

            if (double.IsFinite(f.NewObjectY)) _state.ObjectY = f.NewObjectY;
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
