using System;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// The pseudo-haptic weight solver of Son et al. 2022 for one held object: given the tracked hand each
    /// frame, it returns the object's new height so that a heavier object lags behind the hand and a lighter
    /// one leads it. The offset between hand and object has one source: the weight applied to how far the hand
    /// has lifted the object (the lift, from the <see cref="HoldState.Base"/>), so it is a function of where the
    /// hand is, not of the path it took: a motion that comes back, and anything tracking does, leaves no trace.
    /// Per frame: pose → input effects → estimator (→ hand filter, if the profile has one) → hand-motion effects →
    /// base effects → lift effects → offset = lift − gain × carried lift → object-motion effects → object height →
    /// position effects; a frame that repeats the last one's hand reuses the weight the last frame computed
    /// (<see cref="LastWeight"/>), where every effect between the estimator and the offset is a function of the hand,
    /// and a frame that repeats the last one's sample while nothing moves on its own is still: only the clocks advance
    /// (<see cref="WeightEffect.IsStill"/>).
    /// Configuration validates and throws; <see cref="Step"/> never throws, never allocates, and
    /// always returns a finite height.
    /// </summary>
    public sealed class WeightSolver
    {
        /// <summary>v_std used when the user has not calibrated, m/s (ALGORITHM.md says why).</summary>
        public const double DefaultStandardSpeed = 0.5;
        public const double MinStandardSpeed = 0.05;
        public const double MaxStandardSpeed = 5.0;

        /// <summary>The default cue strength s: the gain as Eq. 4–6 give it (ALGORITHM.md §12).</summary>
        public const double DefaultCueStrength = 1.0;

        /// <summary>The weakest cue strength accepted: a third of the departure's exponent (ALGORITHM.md §12).</summary>
        public const double MinCueStrength = 1.0 / 3.0;

        /// <summary>The strongest cue strength accepted (ALGORITHM.md §12).</summary>
        public const double MaxCueStrength = 3.0;

        /// <summary>Hand heights beyond this magnitude, m, are treated as garbage, like NaN.</summary>
        public const double MaxCoordinate = 1e5;

        HoldState _state;
        SolverConstants _constants;
        IHandFilter _filter;
        LastWeight _last;
        HandSample _lastSample;  // the last sample a frame ran the pipeline for
        bool _canBeStill;        // after that frame nothing moves: the same sample again may be a still frame
        bool _stillKnown;        // …and the effects said they would leave the hold as it is (EffectsStill, asked once)
        bool _gatesWorkspace = true;

        /// <summary>Whether this solver's plausibility gate judges the heights it is given against its workspace
        /// (<see cref="SolverLimits.WorkspaceRadius"/>). <see cref="WeightSolver3D"/> judges each hand in 3D before it
        /// gives this solver the followed point, and turns it off here.</summary>
        internal bool GatesWorkspace { get => _gatesWorkspace; set { _gatesWorkspace = value; ForgetLastFrame(); } }

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

        /// <summary>How far the hand has pulled beyond what the weight allows, m: the lag the speed cap holds the object
        /// behind the weight's own offset (0 without <see cref="SpeedCap"/>). <see cref="BreakAway"/> reads it under the
        /// offset correction.</summary>
        public double Strain => _state.Strain;

        /// <summary>hand − object when the hold began, m: the effects act on <see cref="Offset"/> less this.</summary>
        public double GrabOffset => _state.GrabOffset;

        double _bottomBelowPivot;
        double _cueStrength = DefaultCueStrength;

        /// <summary>
        /// The person's cue strength s (issue 31): the solver's gain is G^s, capped at <see cref="SolverLimits.MaxGain"/>,
        /// where G is the gain of Eq. 4–6 (<see cref="WeightModel.Gain"/>). s = 1 (the default) is that gain bit for bit;
        /// s &lt; 1 draws every object toward the hand (less lag, less lead), s &gt; 1 pushes it away; the standard weight's
        /// G = 1 stays 1 at every s, a heavier object's gain stays above 0 and below 1, and the order of the masses is kept
        /// (G ↦ G^s is strictly increasing). Within [<see cref="MinCueStrength"/>, <see cref="MaxCueStrength"/>]; an
        /// invalid value throws naming CueStrength. Setting it reconfigures the solver (the gain is computed here, not per
        /// frame); allowed during a hold, where the change glides like a change of mass.
        /// </summary>
        public double CueStrength
        {
            get => _cueStrength;
            set
            {
                ConfigurationGuard.InRange(value, MinCueStrength, MaxCueStrength, nameof(CueStrength));
                if (value == _cueStrength) return;
                _cueStrength = value;
                Configure(Model, Profile, StandardSpeed);
            }
        }

        /// <summary>
        /// G^s capped at <paramref name="maxGain"/>: the gain a cue strength <paramref name="cueStrength"/> gives an object
        /// whose Eq. 4–6 gain is <paramref name="gain"/>. s = 1 returns <paramref name="gain"/> itself (no power taken).
        /// </summary>
        public static double StrengthenedGain(double gain, double cueStrength, double maxGain)
            => cueStrength == 1.0 ? gain : Math.Min(Math.Pow(gain, cueStrength), maxGain);

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
                _constants = _constants.WithBottomBelowPivot(value);
                ForgetLastFrame();
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
            double gain = StrengthenedGain(model.Gain(profile.Has<WeightGain>(), profile.Has<ExperimentalBlend>(), limits.MaxGain), _cueStrength, limits.MaxGain);
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
            ForgetLastFrame();
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
            _state.GrabOffset = handOk ? (!raised && double.IsFinite(exactGrabOffset) ? exactGrabOffset : handY - objectY) : 0;
            _state.ObjectY = objectY;
            _state.HasWorkspace = handOk;
            _state.WorkspaceY = handOk ? handY : 0;
            Anchor(handOk ? handY : objectY);
        }

        /// <summary>The hold starts (or, for a hold begun untracked, restarts at its first pose) with the hand at
        /// <paramref name="handY"/>: the lift is measured from here and the object is where it is.</summary>
        void Anchor(double handY)
        {
            _state.HandY = handY;
            _state.HeldY = _state.ObjectY + _state.GrabOffset;
            _state.StartY = _state.Base = _state.SteadyY = _state.Pose1 = _state.Pose2 = handY;
            _state.PoseCount = 1;
            _state.AnchorPending = true;
            _state.Glide = _state.LastOffset = 0;
            _state.LastHand = handY;
            _filter?.Reset(handY);
            ResetEffects(handY);
            ForgetLastFrame();
        }

        /// <summary>Nothing of the last frame is reused: the next one weighs and runs every effect.</summary>
        void ForgetLastFrame()
        {
            _last.Forget();
            _canBeStill = _stillKnown = false;
        }

        /// <summary>Ends the hold; further steps return the object's last height.</summary>
        public void EndHold() => _state.IsHolding = false;

        /// <summary>Advances one rendered frame of <paramref name="dt"/> seconds and returns the object's new height.</summary>
        public double Step(in HandSample sample, double dt)
        {
            if (!_state.IsHolding) return _state.ObjectY;

            // Bad frame times are absorbed: NaN or negative count as no time, longer than an hour (infinity, a clock that jumps
            // to 1e308) as an hour's hitch.
            if (!(dt > 0)) dt = 0;
            else if (dt > SolverLimits.LongestHitch) dt = SolverLimits.LongestHitch;

            // A still frame: the sample repeats the last one's bit for bit (a 30 Hz pose over 72–120 Hz frames) and
            // nothing in the hold moves on its own, so the pipeline would leave everything as it is: only the time since
            // the pose passes, and the object stays (bit for bit what the pipeline returns: StillFrameTests). Not when the repeated
            // pose is due to enter the steady window again (SolverLimits.RepeatTime): that frame runs the pipeline.
            // Whether the effects would leave the hold as it is is asked here, on the first frame that repeats the last
            // pipeline frame's sample, before the clock advances (so every field they read is as that frame left it), and kept
            // for the still frames after it (_stillKnown): a frame followed by a new pose never asks.
            if (_canBeStill && SameSample(in sample, in _lastSample) && _state.HeldFor + dt < SolverLimits.RepeatTime
                && (_stillKnown || (_canBeStill = _stillKnown = EffectsStill())))
            {
                AdvanceClock(dt);
                _state.HeldFor += dt;
                _state.Estimator.Advance(dt, _constants.Limits.MaxFrameTime);
                var advancing = Profile.AdvancingWhenStill;
                for (int i = 0; i < advancing.Length; i++) advancing[i].AdvanceStill(ref _state, in _constants, dt);
                return _state.ObjectY;
            }
            AdvanceClock(dt);
            return RunPipeline(in sample, dt);
        }

        /// <summary>Compensated (Kahan) sum: the hold's clock keeps the microsecond over millions of frames.</summary>
        [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
        void AdvanceClock(double dt)
        {
            double add = dt - _state.TimeCompensation, sum = _state.Time + add;
            _state.TimeCompensation = (sum - _state.Time) - add;
            _state.Time = sum;
        }

        /// <summary>The frame's pipeline (kept apart from <see cref="Step"/> so that a still frame does not pay for its
        /// frame record).</summary>
        double RunPipeline(in HandSample sample, double dt)
        {
            var limits = _constants.Limits;
            // Set in place: an object initializer builds a temporary and copies the whole frame into f.
            MotionFrame f = default;
            f.Dt = dt;
            f.PoseY = sample.Y;
            f.PoseTime = double.IsFinite(sample.PoseTime) ? sample.PoseTime : double.NaN;
            f.IsHighConfidence = sample.IsHighConfidence;
            // The plausibility gate: a pose outside the workspace is no hand's (a pose no hand could have reached in the time
            // since the last is the estimator's to refuse).
            f.Usable = sample.IsUsable && InWorkspace(sample.Y);
            f.ObjectY = _state.HeldY;
            f.OffsetCeiling = double.PositiveInfinity;
            // …and a pose no hand could have reached since the last is refused (Reach): the input effects see neither as tracked.
            _state.Estimator.Screen(ref f, limits);

            var effects = Profile.InputEffects;
            for (int i = 0; i < effects.Length; i++) effects[i].Apply(ref f, ref _state, in _constants);

            _state.Estimator.Follow(ref f);
            if (f.Reanchored)
            {
                // The first pose of a hold begun untracked: the grab is here; the object has not moved.
                _state.GrabOffset = f.HandAfter - _state.ObjectY;
                _state.HasWorkspace = true;
                _state.WorkspaceY = f.HandAfter;
                Anchor(f.HandAfter);
            }
            else if (_filter != null)
            {
                // Effects see the filtered hand: its position, displacement and direction.
                f.HandBefore = _state.HandY;
                f.HandFiltered = true;
                if (f.Usable && _state.Estimator.HasPose)
                {
                    double filtered = _filter.Filter(f.HandAfter, f.NewPose, f.MotionInterval, dt);
                    if (double.IsFinite(filtered)) f.HandAfter = filtered;
                    else _filter.Reset(f.HandAfter);
                }
                else f.HandAfter = _state.HandY;
                f.HandDelta = f.HandAfter - f.HandBefore;
            }
            _state.HandY = f.HandAfter;
            if (f.NewPose)
            {
                _state.HeldFor = 0;
                if (!f.Reanchored) Remember(ref f);
            }
            else if (f.Usable && !f.Settling)
            {
                // The same pose, shown for RepeatTime: the hand seen there again. What the hold remembers of the hand (and all it
                // drives: the base, the pace) advances with time, not only with new poses.
                _state.HeldFor += dt;
                if (_state.HeldFor >= SolverLimits.RepeatTime)
                {
                    _state.HeldFor = 0;
                    Remember(ref f);
                }
            }
            else _state.HeldFor = 0;
            f.SteadyHand = _state.SteadyY;
            f.WeightHand = f.HandAfter;
            // A frame that repeats the last one's hand (a pose held over several frames) repeats its weight.
            if (_last.Holds(in f, _state.Base)) _last.CopyTo(ref f);
            else Weigh(ref f);

            double shown = f.Offset + GlideOffset(in f, dt);
            _state.LastOffset = f.Offset;
            _state.LastHand = f.WeightHand;
            if (shown > f.OffsetCeiling) shown = f.OffsetCeiling;
            else if (shown < -f.OffsetCeiling) shown = -f.OffsetCeiling;
            f.NewObjectY = f.WeightHand - shown; // the hand the weight reads: a light object does not shimmer with jitter the deadband swallowed

            effects = Profile.PositionEffects;
            // The first from a call site of its own: with two position effects (the speed cap, then the floor) each call
            // site sees one type, which the JIT's profile-guided devirtualization can inline.
            if (effects.Length > 0) effects[0].Apply(ref f, ref _state, in _constants);
            for (int i = 1; i < effects.Length; i++) effects[i].Apply(ref f, ref _state, in _constants);

            // Only a height a pose could have (finite, within ±MaxCoordinate: a float transform holds it), for the point the hand
            // holds and for the object (the grab offset apart: an object begun far from the hand would otherwise leave the range
            // as the hand moved toward it): a scene's own effect that wrote an absurd offset, however finite, leaves the object
            // where it was for that frame.
            if (Math.Abs(f.NewObjectY) <= MaxCoordinate && Math.Abs(f.NewObjectY - _state.GrabOffset) <= MaxCoordinate)
            {
                _state.HeldY = f.NewObjectY;
                _state.ObjectY = f.NewObjectY - _state.GrabOffset;
            }
            // The same sample again would read the same pose (no new one: the estimator follows it), reuse this weight (the
            // same hand and base), find no change of the offset to glide, and give the position effects the same height.
            // Whether the input and position effects would change anything (settling, a speed cap catching up) is theirs to
            // say (WeightEffect.IsStill); a hand filter may move with time alone.
            _lastSample = sample;
            // Whether the input and position effects would change anything is asked only when the same sample comes again (Step).
            _canBeStill = f.Usable && _filter == null && _state.Glide == 0 && _last.IsFor(f.HandAfter, _state.Base);
            _stillKnown = false;
            return _state.ObjectY;
        }

        /// <summary>The plausibility gate: within <see cref="SolverLimits.WorkspaceRadius"/> of where the hold began (any height
        /// until a hold begun untracked sees its first pose).</summary>
        bool InWorkspace(double y)
            => !_gatesWorkspace || !_state.HasWorkspace || Math.Abs(y - _state.WorkspaceY) <= _constants.Limits.WorkspaceRadius;

        static bool SameSample(in HandSample a, in HandSample b)
            => BitConverter.DoubleToInt64Bits(a.Y) == BitConverter.DoubleToInt64Bits(b.Y)
               && BitConverter.DoubleToInt64Bits(a.PoseTime) == BitConverter.DoubleToInt64Bits(b.PoseTime)
               && a.IsTracked == b.IsTracked && a.IsHighConfidence == b.IsHighConfidence;

        /// <summary>Every input and position effect would leave the hold as it is on the same sample again.</summary>
        bool EffectsStill()
        {
            var effects = Profile.InputEffects;
            for (int i = 0; i < effects.Length; i++) if (!effects[i].IsStill(in _state, in _constants)) return false;
            effects = Profile.PositionEffects;
            for (int i = 0; i < effects.Length; i++) if (!effects[i].IsStill(in _state, in _constants)) return false;
            return true;
        }


        /// <summary>The weight for this frame's hand: hand-motion → base → lift → offset → object-motion effects.</summary>
        void Weigh(ref MotionFrame f)
        {
            double hand = f.HandAfter;
            var effects = Profile.HandEffects;
            for (int i = 0; i < effects.Length; i++) effects[i].Apply(ref f, ref _state, in _constants);

            f.Lift = f.WeightHand - _state.Base;
            effects = Profile.BaseEffects;
            for (int i = 0; i < effects.Length; i++) effects[i].Apply(ref f, ref _state, in _constants);

            f.Gain = _constants.Gain;
            f.CarriedLift = f.Lift;
            effects = Profile.LiftEffects;
            for (int i = 0; i < effects.Length; i++) effects[i].Apply(ref f, ref _state, in _constants);

            // The weight: the object rises Gain times the lift it carries; the rest of the lift is the offset.
            f.Offset = f.Lift - f.Gain * f.CarriedLift;
            effects = Profile.ObjectEffects;
            for (int i = 0; i < effects.Length; i++) effects[i].Apply(ref f, ref _state, in _constants);

            // Kept only where every effect here is a function of the hand; otherwise every frame weighs.
            if (Profile.WeightIsFunctionOfHand) _last.Keep(in f, hand, _state.Base);
        }

        /// <summary>The hand as the hold remembers it: the median of the last three poses since tracking came back
        /// (a one-pose glitch never reaches it), not counting poses while tracking settles.</summary>
        void Remember(ref MotionFrame f)
        {
            // After a gap, or poses not to be remembered, the window starts over: no pose from before it is its neighbour.
            if (f.Bridged || f.Settling) { _state.PoseCount = 0; _state.AnchorPending = false; }
            if (f.Settling) return;
            double y = f.HandAfter, a = _state.Pose1, b = _state.Pose2;
            _state.Pose2 = a;
            _state.Pose1 = y;
            if (_state.PoseCount < 3) _state.PoseCount++;
            if (_state.PoseCount < 3) return;
            double median = Math.Max(Math.Min(y, a), Math.Min(Math.Max(y, a), b));
            if (_state.AnchorPending) f.BaseMeasured = SettleAnchor(b, median);
            f.SteadyTaken = true;
            _state.SteadyY = median;
        }

        /// <summary>
        /// The first three poses of the hold: when the grab's own pose lies more than <see cref="AnchorGlitch"/> from their
        /// median, it may be a glitch, and the lift is measured from the median instead (a hold that began on a glitched pose
        /// would otherwise keep the glitch as weight for good). Jitter stays within it, so a grab at rest is measured from its
        /// own pose. The grab offset stays: the object was placed against the hand as it was seen. A hand that moved fast
        /// through the three poses moves the base by a pose's worth of motion; any change of the offset this makes glides.
        /// Returns whether the base moved.
        /// </summary>
        bool SettleAnchor(double p0, double median)
        {
            _state.AnchorPending = false;
            double shift = median - p0;
            if (!(Math.Abs(shift) > AnchorGlitch)) return false;
            _state.Base += shift;
            _state.StartY += shift;
            return true;
        }

        /// <summary>How far the grab's pose may lie from the median of the first three before the lift is measured from the
        /// median, m: more than Quest's jitter at rest.</summary>
        const double AnchorGlitch = 0.005;

        /// <summary>
        /// The weight's offset changes with the hand, at most as fast as the hand moves (times a light object's lead). A change
        /// the hand's motion does not explain (a change of mass or profile during the hold, such as a second hand joining; the
        /// lift's pace settling after a loss; the base settling on the first poses or relaxing) would move the object while
        /// the hand does not: the object first stays, and the difference glides away at <see cref="SolverLimits.GlideSpeed"/>.
        /// </summary>
        double GlideOffset(in MotionFrame f, double dt)
        {
            double change = f.Offset - _state.LastOffset, glide = _state.Glide;
            // The most the weight's offset moves per metre of lift: 1 − G (a lead of G − 1 for a light object), or up to 1
            // where the height deceleration shapes the lift it carries.
            double slope = f.CarriedLift == f.Lift ? Math.Abs(1 - f.Gain) : Math.Max(1, Math.Abs(1 - f.Gain));
            double moved = f.WeightHand - _state.LastHand; // the hand's motion, not the base's
            double explained = Math.Abs(moved) * slope;
            double step = _constants.Limits.GlideSpeed * Math.Min(dt, _constants.Limits.MaxFrameTime);
            // Nothing gliding and a change the hand's motion explains, or one this frame's step takes away (almost every frame):
            // 0, what the lines below return. Within ±explained, |change| − explained is the size of the change beyond it
            // (x − high above, low − x below: the same subtraction, so the same rounding), ≤ 0 inside. One test that is almost
            // always true and waits for no clamp, so the frame runs on.
            if (glide == 0 && !f.AcrossGap && Math.Abs(change) - explained <= step) return 0;
            double low = -explained, high = explained;
            if (f.AcrossGap)
            {
                // Across a gap the object goes as far as the hand went, never further: the offset may change only with the hand's
                // motion and by at most twice it (object step = hand step − offset change). A light object's lead on the hand's
                // motion across the gap (the offset changing against it) glides, as a heavier object's would.
                if (moved >= 0) { if (low < 0) low = 0; if (high > 2 * moved) high = 2 * moved; }
                else { if (high > 0) high = 0; if (low < 2 * moved) low = 2 * moved; }
            }
            // The change beyond [low, high] (x − clamp(x) is x − high above, x − low below, +0 between; the offsets are finite).
            double excess = change - Math.Min(Math.Max(change, low), high);
            if (glide == 0 && excess <= step && excess >= -step) return 0;
            double g = glide - excess;
            g = g > step ? g - step : (g < -step ? g + step : 0);
            _state.Glide = Math.Abs(g) <= MaxCoordinate ? g : 0; // no glide from an absurd offset a scene's effect wrote (nor ±∞, NaN)
            return _state.Glide;
        }

        void ResetEffects(double handY)
        {
            var all = Profile._all;
            for (int i = 0; i < all.Length; i++) all[i].Reset(ref _state, handY);
        }
    }
}
