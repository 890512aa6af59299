using System;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// A hold in three dimensions, with one or two hands, built on the y solver (<see cref="WeightSolver"/>):
    /// the followed point (one hand, or the midpoint of both) drives the y solver unchanged, and x/z follow it
    /// 1:1, or trail it with <see cref="LateralInertia"/>. With <see cref="TwoHands"/> each holding hand carries
    /// a share of the mass (the y solver is configured with the per-hand mass, so every effect sees it); when
    /// the set of followed hands changes, the followed point is re-anchored so nothing steps. With
    /// <see cref="BreakAway"/> the hold ends by itself when the hand is pulled too far. Same rules as
    /// <see cref="WeightSolver.Step"/>: <see cref="Step"/> never allocates, never throws, never returns a
    /// non-finite position; configuration errors throw naming the field. A scene that moves only y can use
    /// <see cref="WeightSolver"/> directly and pays nothing for x and z.
    /// </summary>
    public sealed class WeightSolver3D
    {
        readonly WeightSolver _y;
        WeightModel _model, _perHand;
        TwoHands _twoHands;
        LateralInertia _inertia;
        BreakAway _breakAway;
        double _settleTime, _tauOne, _tauTwo, _tau, _pullSpeed, _pullRamp;
        bool _requireHighConfidence, _lossHold;
        SolverLimits _limits;

        // The hold.
        bool _holding, _brokeAway;
        bool _grip1 = true, _grip2 = true;   // the driver lets the hand take part
        bool _holds1, _holds2;               // the hand has been followed since it gripped (carries its share)
        bool _in1, _in2;                     // followed this frame
        bool _last1, _last2;                 // the last non-empty followed set
        bool _anchorFromPoint;               // the last followed hand let go: anchor the next set at the followed point
        double _join1, _join2;               // steady tracking while waiting to join the other hand, s
        double _k1x, _k1y, _k1z, _k2x, _k2y, _k2z; // each hand's last followable position
        double _cx, _cy, _cz;                // anchor: followed point = hands' mean + c
        double _vx, _vy, _vz;                // the followed point
        int _usableHands;

        // x/z: object = followed point + A − e.
        bool _hHas;
        double _ax, _az, _ex, _ez, _hLostFor, _hSettle = -1, _hSince, _hPx, _hPz;
        double _gax, _gaz;                   // A when the hand was first followed: re-anchoring moves A away from it
        double _objX, _objZ;

        // Break-away.
        bool _hasGrab;
        double _gx, _gy, _gz, _beyondFor;

        public WeightSolver3D(WeightModel model, WeightProfile profile = null, double standardSpeed = WeightSolver.DefaultStandardSpeed)
        {
            profile = profile ?? NamedProfiles.Paper;
            _y = new WeightSolver(model, profile, standardSpeed);
            Configure(model, profile, standardSpeed);
        }

        /// <summary>The y solver: its state, profile and constants (configured with the per-hand mass while two hands hold).</summary>
        public WeightSolver Vertical => _y;
        public WeightModel Model => _model;
        public WeightProfile Profile => _y.Profile;

        /// <summary>The mass the y solver and every effect see now, kg: the object's, or its per-hand share while two hands hold.</summary>
        public double PerHandMassKg => _y.Model.MassKg;

        public bool IsHolding => _holding;

        /// <summary>The hold ended by itself (<see cref="BreakAway"/>): a grab driver should drop the object.</summary>
        public bool BrokeAway => _brokeAway;

        public double ObjectX => _objX;
        public double ObjectY => _y.ObjectY;
        public double ObjectZ => _objZ;

        /// <summary>Hands usable in the last step's input (tracked, every coordinate finite), 0–2; the second
        /// counts even when the profile ignores it.</summary>
        public int UsableHands => _usableHands;

        /// <summary>Hands the object followed in the last step, 0–2.</summary>
        public int FollowedHands => (_in1 ? 1 : 0) + (_in2 ? 1 : 0);

        /// <summary>Hands that carry a share of the weight now, 0–2.</summary>
        public int HoldingHands => (_holds1 ? 1 : 0) + (_holds2 ? 1 : 0);

        /// <summary>The followed point, as the y solver and x/z see it (the hands' mean plus the re-anchoring offset), m.</summary>
        public double FollowedX => _vx;
        public double FollowedY => _vy;
        public double FollowedZ => _vz;

        /// <summary>The horizontal lag of <see cref="LateralInertia"/>, m (0 without it).</summary>
        public double LagX => _ex;
        public double LagZ => _ez;

        /// <summary>Metres from the pivot down to the object's lowest point (the y solver's; the floor keeps the bottom above the support).</summary>
        public double BottomBelowPivot { get => _y.BottomBelowPivot; set => _y.BottomBelowPivot = value; }

        /// <summary>Changes object, profile or user; allowed during a hold (the object continues from where it is).</summary>
        public void Configure(WeightModel model, WeightProfile profile, double standardSpeed)
        {
            if (model == null) throw new ArgumentNullException(nameof(model));
            if (profile == null) throw new ArgumentNullException(nameof(profile));
            var twoHands = profile.Find<TwoHands>();
            var perHand = twoHands != null ? WeightModel.FromMass(model.MassKg * twoHands.Share, model.Curve) : model;
            _y.Configure(model, profile, standardSpeed);
            var inertia = profile.Find<LateralInertia>();
            double tauOne = inertia != null ? inertia.TimeConstantFor(_y.Gain) : 0;
            _y.Configure(perHand, profile, standardSpeed);
            double tauTwo = inertia != null ? inertia.TimeConstantFor(_y.Gain) : 0;
            var loss = profile.Find<TrackingLossHold>();

            _model = model;
            _perHand = perHand;
            _twoHands = twoHands;
            _inertia = inertia;
            _breakAway = profile.Find<BreakAway>();
            _tauOne = tauOne;
            _tauTwo = tauTwo;
            _settleTime = loss != null ? loss.SettleTime : 0;
            _requireHighConfidence = loss != null && loss.RequireHighConfidence;
            _lossHold = loss != null;
            _limits = profile.Limits;
            var correction = profile.Find<OffsetCorrection>();
            _pullSpeed = correction != null ? correction.PullSpeed : 0;
            _pullRamp = correction != null ? 5 * correction.Band : 1;
            ApplyMass(force: true, standardSpeed);
        }

        /// <summary>One-hand hold: the hand (may be untracked) and where the object is.</summary>
        public void BeginHold(in HandPose hand, double objectX, double objectY, double objectZ)
            => BeginHold(hand, HandPose.Lost, objectX, objectY, objectZ);

        /// <summary>Starts a hold with up to two hands (either may be lost; the second is ignored without <see cref="TwoHands"/>).</summary>
        public void BeginHold(in HandPose first, in HandPose second, double objectX, double objectY, double objectZ)
        {
            ConfigurationGuard.InRange(objectY, -WeightSolver.MaxCoordinate, WeightSolver.MaxCoordinate, nameof(objectY));
            Begin(first, second, objectX, objectY, objectZ, double.NaN);
        }

        /// <summary>
        /// Starts a hold with the object <paramref name="grabOffsetY"/> metres below the followed point (above it when
        /// negative), kept exactly as given (<see cref="WeightSolver.BeginHoldWithGrabOffset"/>): where the floor is not
        /// in the way, y is exactly the path of a hold begun with hand and object together, less the offset. A hand
        /// must be followable (the object is placed relative to it); otherwise this throws naming first.
        /// </summary>
        public void BeginHoldWithGrabOffset(in HandPose first, in HandPose second, double objectX, double grabOffsetY, double objectZ)
        {
            ConfigurationGuard.InRange(grabOffsetY, -WeightSolver.MaxCoordinate, WeightSolver.MaxCoordinate, nameof(grabOffsetY));
            Begin(first, second, objectX, double.NaN, objectZ, grabOffsetY);
        }

        void Begin(in HandPose first, in HandPose second, double objectX, double objectY, double objectZ, double grabOffsetY)
        {
            ConfigurationGuard.InRange(objectX, -WeightSolver.MaxCoordinate, WeightSolver.MaxCoordinate, nameof(objectX));
            ConfigurationGuard.InRange(objectZ, -WeightSolver.MaxCoordinate, WeightSolver.MaxCoordinate, nameof(objectZ));
            bool withOffset = !double.IsNaN(grabOffsetY);
            if (withOffset && !(first.IsUsable && (!_requireHighConfidence || first.IsHighConfidence))
                && !(_twoHands != null && second.IsUsable && (!_requireHighConfidence || second.IsHighConfidence)))
                throw new ArgumentException("first: a grab offset needs a followable hand to place the object relative to.", nameof(first));
            _holding = true;
            _brokeAway = false;
            _grip1 = _grip2 = true;
            _holds1 = _holds2 = _in1 = _in2 = _last1 = _last2 = _anchorFromPoint = false;
            _join1 = _join2 = 0;
            _cx = _cy = _cz = 0;
            _hHas = false;
            _ax = _az = _ex = _ez = _hLostFor = _hSince = 0;
            _hSettle = -1;
            _objX = objectX;
            _objZ = objectZ;
            _hasGrab = false;
            _beyondFor = 0;

            Select(first, second, first.IsUsable, second.IsUsable, 0, begin: true);
            ApplyMass(force: false, _y.StandardSpeed);
            if (_in1 || _in2)
            {
                if (withOffset) _y.BeginHoldWithGrabOffset(_vy, grabOffsetY, PoseTime(first, second));
                else _y.BeginHold(_vy, objectY, PoseTime(first, second));
                _hHas = true;
                _hPx = _vx;
                _hPz = _vz;
                _ax = _gax = objectX - _vx;
                _az = _gaz = objectZ - _vz;
                Grab();
            }
            else _y.BeginHold(double.NaN, objectY);
            _usableHands = (first.IsUsable ? 1 : 0) + (second.IsUsable ? 1 : 0);
        }

        /// <summary>Ends the hold; further steps keep the object where it is.</summary>
        public void EndHold()
        {
            _holding = false;
            _y.EndHold();
        }

        /// <summary>Lets a hand (1 or 2) take part in the hold or not: a hand that lets go is ignored from the next
        /// step and stops carrying its share; one that grips again rejoins like a returning hand.</summary>
        public void SetGrip(int hand, bool grips)
        {
            if (hand != 1 && hand != 2) throw new ArgumentOutOfRangeException(nameof(hand), hand, "hand must be 1 or 2, got " + hand + ".");
            if (hand == 1) { _grip1 = grips; if (!grips) _holds1 = false; }
            else { _grip2 = grips; if (!grips) _holds2 = false; }
            if (!grips) Forget(hand);
            ApplyMass(force: false, _y.StandardSpeed);
        }

        /// <summary>A hand that lets go leaves the last followed set now, so that whatever is followed next (the other
        /// hand, or a new grasp in this slot) is re-anchored to the followed point instead of being taken for this
        /// hand returning from a loss.</summary>
        void Forget(int hand)
        {
            bool was = hand == 1 ? _last1 : _last2, other = hand == 1 ? _last2 : _last1;
            if (!was) return;
            if (other)
            {
                Mean(true, true, out double ox, out double oy, out double oz);
                Mean(hand == 2, hand == 1, out double nx, out double ny, out double nz);
                _cx += ox - nx;
                _cy += oy - ny;
                _cz += oz - nz;
            }
            else _anchorFromPoint = true;
            if (hand == 1) _last1 = false; else _last2 = false;
        }

        /// <summary>One-hand step.</summary>
        public void Step(in HandPose hand, double dt) => Step(hand, HandPose.Lost, dt);

        /// <summary>Advances one rendered frame of <paramref name="dt"/> seconds.</summary>
        public void Step(in HandPose first, in HandPose second, double dt)
        {
            bool u1 = first.IsUsable, u2 = second.IsUsable;
            _usableHands = (u1 ? 1 : 0) + (u2 ? 1 : 0);
            if (!_holding) return;
            if (double.IsPositiveInfinity(dt)) dt = 3600;
            else if (!(dt > 0)) dt = 0;

            bool holdsBefore = _holds1 && _holds2;
            Select(first, second, u1, u2, dt, begin: false);
            if (holdsBefore != (_holds1 && _holds2)) ApplyMass(force: false, _y.StandardSpeed);

            // y: the followed point, or the first hand as it came when nothing is followed (the y solver's own
            // loss handling then sees exactly what a one-hand hold sees).
            HandSample sample;
            if (_in1 || _in2)
            {
                bool confident = (!_in1 || first.IsHighConfidence) && (!_in2 || second.IsHighConfidence);
                sample = new HandSample(_vy, true, confident, PoseTime(first, second));
            }
            else if (!_grip1)
                sample = new HandSample(double.NaN, false, false, first.PoseTime); // the first hand let go
            else if (u1 || !first.IsTracked || !HandSample.IsUsableHeight(first.Y))
                sample = new HandSample(first.Y, first.IsTracked, first.IsHighConfidence, first.PoseTime);
            else
                sample = new HandSample(double.NaN, false, false, first.PoseTime); // x or z garbage: the pose is lost
            _y.Step(sample, dt);

            StepHorizontal(dt);
            if (_breakAway != null) CheckBreakAway(dt);
        }

        /// <summary>Decides which hands are followed this frame and re-anchors the followed point when that changes.</summary>
        void Select(in HandPose first, in HandPose second, bool usable1, bool usable2, double dt, bool begin)
        {
            bool f1 = _grip1 && usable1 && (!_requireHighConfidence || first.IsHighConfidence);
            bool f2 = _twoHands != null && _grip2 && usable2 && (!_requireHighConfidence || second.IsHighConfidence);
            if (f1) { _k1x = first.X; _k1y = first.Y; _k1z = first.Z; }
            if (f2) { _k2x = second.X; _k2y = second.Y; _k2z = second.Z; }
            // A hand joining a hand already followed waits for steady tracking (the profile's settle time).
            bool staying = (_in1 && f1) || (_in2 && f2);
            bool n1 = f1 && (_in1 || !staying || begin || Settled(ref _join1, dt));
            bool n2 = f2 && (_in2 || !staying || begin || Settled(ref _join2, dt));
            if (!f1) _join1 = 0;
            if (!f2) _join2 = 0;
            if (n1 || n2)
            {
                if (_anchorFromPoint)
                {
                    // The last followed hand let go: continue from the followed point where it was.
                    Mean(n1, n2, out double px, out double py, out double pz);
                    _cx = _vx - px;
                    _cy = _vy - py;
                    _cz = _vz - pz;
                    _anchorFromPoint = false;
                }
                else if ((_last1 || _last2) && (n1 != _last1 || n2 != _last2))
                {
                    // Keep the followed point where it was: the old set's mean minus the new set's, at each hand's last position.
                    Mean(_last1, _last2, out double ox, out double oy, out double oz);
                    Mean(n1, n2, out double nx, out double ny, out double nz);
                    _cx += ox - nx;
                    _cy += oy - ny;
                    _cz += oz - nz;
                }
                _last1 = n1;
                _last2 = n2;
                Mean(n1, n2, out double mx, out double my, out double mz);
                _vx = mx + _cx; // exactly mx while nothing was re-anchored (c = 0): y stays the y solver's, bit for bit
                _vy = my + _cy;
                _vz = mz + _cz;
                if (n1) _holds1 = true;
                if (n2) _holds2 = true;
            }
            _in1 = n1;
            _in2 = n2;
        }

        /// <summary>Steady for the settle time yet? The wait restarts whenever the hand cannot be followed (Select).</summary>
        bool Settled(ref double waited, double dt)
        {
            waited += dt;
            return waited >= _settleTime;
        }

        void Mean(bool one, bool two, out double x, out double y, out double z)
        {
            if (one && two) { x = 0.5 * (_k1x + _k2x); y = 0.5 * (_k1y + _k2y); z = 0.5 * (_k1z + _k2z); }
            else if (two) { x = _k2x; y = _k2y; z = _k2z; }
            else { x = _k1x; y = _k1y; z = _k1z; }
        }

        double PoseTime(in HandPose first, in HandPose second)
        {
            double a = _in1 && double.IsFinite(first.PoseTime) ? first.PoseTime : double.NaN;
            double b = _in2 && double.IsFinite(second.PoseTime) ? second.PoseTime : double.NaN;
            if (double.IsNaN(a)) return b;
            if (double.IsNaN(b)) return a;
            return a > b ? a : b;
        }

        /// <summary>The y solver sees the per-hand mass while both hands hold, the whole mass otherwise.</summary>
        void ApplyMass(bool force, double standardSpeed)
        {
            bool two = _holds1 && _holds2 && _twoHands != null;
            var want = two ? _perHand : _model;
            if (force || !ReferenceEquals(want, _y.Model)) _y.Configure(want, _y.Profile, standardSpeed);
            _tau = two ? _tauTwo : _tauOne;
        }

        /// <summary>x/z: follow the followed point's displacement, or re-anchor (the object stays) after a long loss,
        /// a hitch, a settle after a loss, or a step no hand can make; then the lateral lag.</summary>
        void StepHorizontal(double dt)
        {
            var limits = _limits;
            double dx = 0, dz = 0;
            _hSince += dt;
            if (!(_in1 || _in2))
            {
                _hLostFor += dt;
                if (_lossHold) _hSettle = 0;
            }
            else if (!_hHas)
            {
                Reanchor();
            }
            else if (_hSettle >= 0)
            {
                // After a loss, with the tracking-loss hold: wait for steady tracking, then follow from here.
                _hSettle += dt;
                if (_hSettle >= _settleTime) { _hSettle = -1; Reanchor(); }
            }
            else
            {
                double ddx = _vx - _hPx, ddz = _vz - _hPz;
                double window = _hSince < SolverLimits.MinJumpWindow ? SolverLimits.MinJumpWindow : (_hSince > SolverLimits.JumpWindow ? SolverLimits.JumpWindow : _hSince);
                double max = limits.MaxHandSpeed * window;
                if (dt > limits.MaxCatchUpGap || _hLostFor > limits.MaxCatchUpGap || ddx * ddx + ddz * ddz > max * max) Reanchor();
                else
                {
                    if (ddx != 0 || ddz != 0) _hSince = 0;
                    dx = ddx;
                    dz = ddz;
                    _hPx = _vx;
                    _hPz = _vz;
                }
                _hLostFor = 0;
            }

            if (_tau > 0)
            {
                double step = dt < LateralInertia.MaxDecayStep ? dt : LateralInertia.MaxDecayStep;
                double k = _tau / (_tau + step);
                double ex = (_ex + dx) * k, ez = (_ez + dz) * k;
                double n = ex * ex + ez * ez, bound = _inertia.MaxOffset;
                if (n > bound * bound)
                {
                    double s = bound / Math.Sqrt(n);
                    ex *= s;
                    ez *= s;
                }
                else if (n < 1e-24) ex = ez = 0;
                if (double.IsFinite(ex) && double.IsFinite(ez)) { _ex = ex; _ez = ez; }
            }
            else _ex = _ez = 0;

            if (!_hHas) return; // no hand seen yet: the object stays where the hold began
            if (_pullSpeed > 0) PullBack(dt);
            double x = _hPx + _ax - _ex, z = _hPz + _az - _ez;
            if (double.IsFinite(x) && double.IsFinite(z)) { _objX = x; _objZ = z; }
        }

        /// <summary>With the offset correction, what re-anchoring left between hand and object horizontally is drawn back,
        /// as the correction's pull does on y: at up to its pull speed, ramping up over five band widths.</summary>
        void PullBack(double dt)
        {
            double rx = _ax - _gax, rz = _az - _gaz, r = Math.Sqrt(rx * rx + rz * rz);
            double max = _limits.MaxFrameTime, step = dt < max ? dt : max;
            double pull = _pullSpeed * (r >= _pullRamp ? 1 : r / _pullRamp) * step;
            if (pull >= r) { _ax = _gax; _az = _gaz; } // also at r = 0, where the ramp gives pull = 0
            else { double k = 1 - pull / r; _ax = _gax + rx * k; _az = _gaz + rz * k; }
        }

        void Reanchor()
        {
            // The object stays: A absorbs the hand's jump (the lag e stays as it was).
            double followX = _objX + _ex, followZ = _objZ + _ez;
            _hPx = _vx;
            _hPz = _vz;
            _ax = followX - _vx;
            _az = followZ - _vz;
            if (!_hHas) { _gax = _ax; _gaz = _az; }
            _hHas = true;
            _hLostFor = 0;
            _hSince = 0;
            if (!_hasGrab) Grab();
        }

        void Grab()
        {
            _gx = _vx - _objX;
            _gy = _vy - _y.ObjectY;
            _gz = _vz - _objZ;
            _hasGrab = true;
        }

        void CheckBreakAway(double dt)
        {
            if (!(_in1 || _in2) || !_hasGrab) return;
            double dx = _vx - _objX - _gx, dy = _vy - _y.ObjectY - _gy, dz = _vz - _objZ - _gz;
            double d = _breakAway.Distance;
            if (dx * dx + dy * dy + dz * dz > d * d)
            {
                _beyondFor += dt;
                if (_beyondFor >= _breakAway.Dwell)
                {
                    _brokeAway = true;
                    EndHold();
                }
            }
            else _beyondFor = 0;
        }
    }
}
