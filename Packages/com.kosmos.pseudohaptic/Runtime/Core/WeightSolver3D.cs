using System;
using System.Globalization;

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
        double _perMaxOffset; // 1 / the lateral bound: no division by it per frame
        BreakAway _breakAway;
        double _settleTime, _tauOne, _tauTwo, _tau;
        bool _corrected;
        SolverLimits _limits;

        // The hold.
        bool _holding, _brokeAway;
        bool _grip1, _grip2;                 // the driver lets the hand take part (both, from each hold's begin)
        bool _holds1, _holds2;               // the hand has been followed since it gripped (carries its share)
        bool _in1, _in2;                     // followed this frame
        bool _last1, _last2;                 // the last non-empty followed set
        bool _anchorFromPoint;               // the last followed hand let go: anchor the next set at the followed point
        double _join1, _join2;               // steady tracking while waiting to join the other hand, s
        double _k1x, _k1y, _k1z, _k2x, _k2y, _k2z; // each hand's last followable position
        Reach _reach1, _reach2;              // whether a hand could have got to its next pose
        double _cx, _cy, _cz;                // anchor: followed point = hands' mean + c
        bool _hasPair;                       // both hands have been followed together since each last gripped
        double _qx, _qy, _qz;                // the pair's anchor: c while both hands were followed together
        double _vx, _vy, _vz;                // the followed point
        int _usableHands;

        // x/z: object = followed point + A − shown lag, the lag driven by the steady followed point.
        bool _hHas;
        double _ax, _az;                     // object − followed point at the grab, horizontally
        double _ex, _ez;                     // the lateral lag, as the inertia model has it
        double _sx, _sz;                     // the shown lag: the lag bounded by a saturating curve
        double _objX, _objZ;
        double _px, _py, _pz, _pt;           // the followed point and pose time of the last frame (a new pose changes them)
        double _x1, _x2, _z1, _z2, _steadyX, _steadyZ; // the last followed points and their median
        int _steadyCount;
        double _heldFor;                     // frame time the followed point has shown the same pose since the steady point last took it

        // The plausibility gate: a hand farther than the workspace radius from the followed point at the grab is not tracked.
        bool _hasCentre;
        double _wx, _wy, _wz;

        // Break-away.
        bool _hasGrab, _beyond;
        double _gx, _gy, _gz;

        /// <summary>Hands followed together again whose anchor is within this of the one they had return to it as they move
        /// relative to each other; farther, they gripped anew, m.</summary>
        const double PairRestoreDistance = 0.10;

        public WeightSolver3D(WeightModel model, WeightProfile profile = null, double standardSpeed = WeightSolver.DefaultStandardSpeed)
        {
            profile = profile ?? NamedProfiles.Paper;
            _y = new WeightSolver(model, profile, standardSpeed) { GatesWorkspace = false }; // each hand is judged here, in 3D
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

        /// <summary>The horizontal lag of <see cref="LateralInertia"/> the user sees, m (0 without it).</summary>
        public double LagX => _sx;
        public double LagZ => _sz;

        /// <summary>
        /// How far the hand has pulled beyond what the weight allows, m: the y solver's <see cref="WeightSolver.Strain"/>
        /// (the speed cap's lag) and, sideways, how far <see cref="LateralInertia"/>'s lag exceeds the lag it shows, combined
        /// in 3D. Under the offset correction this is what <see cref="BreakAway"/> measures.
        /// </summary>
        public double Strain
        {
            get
            {
                double tx = _ex + _vx - _steadyX, tz = _ez + _vz - _steadyZ;
                double lateral = _tau > 0 ? Math.Sqrt(tx * tx + tz * tz) - Math.Sqrt(_sx * _sx + _sz * _sz) : 0, y = _y.Strain;
                return Math.Sqrt(y * y + lateral * lateral);
            }
        }

        /// <summary>What <see cref="BreakAway"/> compares with its distance, m: <see cref="Strain"/> under the offset
        /// correction; otherwise the distance between the followed point and the object, less the one at the grab.</summary>
        public double BreakAwayMeasure
        {
            get
            {
                if (!_hasGrab) return 0;
                if (_corrected) return Strain;
                double dx = _vx - _objX - _gx, dy = _vy - _y.ObjectY - _gy, dz = _vz - _objZ - _gz;
                return Math.Sqrt(dx * dx + dy * dy + dz * dz);
            }
        }

        /// <summary>The person's cue strength s (<see cref="WeightSolver.CueStrength"/>): the y solver's gain is G^s, and the
        /// lateral inertia's time constant follows that gain. Setting it reconfigures (an invalid value throws naming CueStrength).</summary>
        public double CueStrength
        {
            get => _y.CueStrength;
            set
            {
                if (value == _y.CueStrength) return;
                _y.CueStrength = value;
                Configure(_model, _y.Profile, _y.StandardSpeed);
            }
        }

        /// <summary>Metres from the pivot down to the object's lowest point (the y solver's; the floor keeps the bottom above the support).</summary>
        public double BottomBelowPivot { get => _y.BottomBelowPivot; set => _y.BottomBelowPivot = value; }

        /// <summary>Changes object, profile or user; allowed during a hold (the object continues from where it is).</summary>
        public void Configure(WeightModel model, WeightProfile profile, double standardSpeed)
        {
            if (model == null) throw new ArgumentNullException(nameof(model));
            if (profile == null) throw new ArgumentNullException(nameof(profile));
            var breakAway = profile.Find<BreakAway>();
            if (breakAway != null && profile.Has<OffsetCorrection>() && !profile.Has<SpeedCap>() && !profile.Has<LateralInertia>())
                throw new ArgumentException("profile '" + profile.Name + "': under the offset correction break-away measures how far the hand " +
                    "pulls beyond what the weight allows (the speed cap's lag, or the lateral inertia's beyond its bound); with neither " +
                    "in the profile it could never fire.", nameof(profile));
            if (breakAway != null)
            {
                // A pose farther than the workspace radius from where the hold began is untracked, and the object moves at most
                // maxGain times the hand: hand and object are never farther apart than (1 + maxGain) × radius, nor is any strain.
                double reach = (1 + profile.Limits.MaxGain) * profile.Limits.WorkspaceRadius;
                if (breakAway.Distance > reach)
                    throw new ArgumentException("profile '" + profile.Name + "': break-away's distance " + breakAway.Distance.ToString("R", CultureInfo.InvariantCulture) +
                        " m could never be reached: poses farther than the workspace radius from where the hold began are untracked, so hand and " +
                        "object are never more than (1 + maxGain) × workspaceRadius = " + reach.ToString("R", CultureInfo.InvariantCulture) + " m apart.", nameof(profile));
            }
            var twoHands = profile.Find<TwoHands>();
            // Each hand carries its share, but sharing never makes an object lighter than the standard weight: the golf ball
            // in two hands is still rigid, and an object just heavier than it does not start to lead the hands.
            double share = twoHands != null ? Math.Max(model.MassKg * twoHands.Share, Math.Min(model.MassKg, PhysicalConstants.StandardMassKg)) : model.MassKg;
            var perHand = twoHands != null ? WeightModel.FromMass(share, model.Curve) : model;
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
            _perMaxOffset = inertia != null ? 1 / inertia.MaxOffset : 0;
            _breakAway = profile.Find<BreakAway>();
            _tauOne = tauOne;
            _tauTwo = tauTwo;
            _settleTime = loss != null ? loss.SettleTime : 0;
            _limits = profile.Limits;
            _corrected = profile.Has<OffsetCorrection>();
            ApplyMass(standardSpeed); // the y solver was just configured with the per-hand model: reconfigured only if it is not the one wanted
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
            if (withOffset && !first.IsUsable && !(_twoHands != null && second.IsUsable))
                throw new ArgumentException("first: a grab offset needs a followable hand to place the object relative to.", nameof(first));
            _holding = true;
            _brokeAway = false;
            _grip1 = _grip2 = true;
            _holds1 = _holds2 = _in1 = _in2 = _last1 = _last2 = _anchorFromPoint = false;
            _join1 = _join2 = 0;
            _reach1.Reset();
            _reach2.Reset();
            _cx = _cy = _cz = 0;
            _hasPair = false;
            _hHas = false;
            _ax = _az = _ex = _ez = _sx = _sz = 0;
            _steadyCount = 0;
            _heldFor = 0;
            _hasCentre = false;
            _objX = objectX;
            _objZ = objectZ;
            _hasGrab = _beyond = false;

            Select(first, second, first.IsUsable, second.IsUsable, 0);
            ApplyMass(_y.StandardSpeed);
            if (_in1 || _in2)
            {
                if (withOffset) _y.BeginHoldWithGrabOffset(_vy, grabOffsetY, PoseTime(first, second));
                else _y.BeginHold(_vy, objectY, PoseTime(first, second));
                Anchor();
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
            if (hand == 1) { _grip1 = grips; if (!grips) { _holds1 = false; _reach1.Reset(); } }
            else { _grip2 = grips; if (!grips) { _holds2 = false; _reach2.Reset(); } }
            if (!grips) { Forget(hand); _hasPair = false; } // a new grasp is a new pair
            ApplyMass(_y.StandardSpeed);
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
            if (!(dt > 0)) dt = 0;
            else if (dt > SolverLimits.LongestHitch) dt = SolverLimits.LongestHitch; // as the y solver counts it

            bool holdsBefore = _holds1 && _holds2;
            bool was1 = _in1, was2 = _in2;
            Select(first, second, u1, u2, dt);
            if (holdsBefore != (_holds1 && _holds2)) ApplyMass(_y.StandardSpeed);

            // y: the followed point (confident only when every followed hand is), or nothing when no hand is followed.
            HandSample sample;
            if (_in1 || _in2)
            {
                bool confident = (!_in1 || first.IsHighConfidence) && (!_in2 || second.IsHighConfidence);
                sample = new HandSample(_vy, true, confident, PoseTime(first, second));
            }
            else sample = HandSample.Lost;
            _y.Step(sample, dt);

            bool following = _in1 || _in2, newPose = false;
            double leadX = _px - _steadyX, leadZ = _pz - _steadyZ; // how far the hand was ahead of the steady point
            if (following)
            {
                if (!_hHas) Anchor(); // the first followed hand of a hold begun untracked: the grab is here
                double t = sample.PoseTime;
                newPose = _vx != _px || _vy != _py || _vz != _pz || (double.IsFinite(t) && !(t == _pt));
                _px = _vx; _py = _vy; _pz = _vz; _pt = t;
            }
            // A gap, or a change of the followed hands: the motion across it is taken rigidly.
            bool bridged = following && (was1 != _in1 || was2 != _in2);
            // Across a gap the steady point starts over at the hand: the lead it had joins the lag, so nothing steps.
            if (bridged && _hHas && _tau > 0) { _ex += leadX; _ez += leadZ; }
            // The same pose shown for RepeatTime is the hand seen there again: the steady point takes it, so the lag it drives
            // advances with time when a source repeats its last pose exactly.
            bool again = false;
            if (following && !newPose)
            {
                _heldFor += dt;
                if (_heldFor >= SolverLimits.RepeatTime) { _heldFor = 0; again = true; }
            }
            else _heldFor = 0;
            // Across a change the steady point restarts at the followed point even on a frame with no new pose (a hand let go
            // between two poses): the lead has just joined the lag, and the shown lag would count it twice.
            StepHorizontal(dt, newPose || again || bridged, bridged);
            if (_breakAway != null) CheckBreakAway(newPose);
        }

        /// <summary>Decides which hands are followed this frame and re-anchors the followed point when that changes.</summary>
        void Select(in HandPose first, in HandPose second, bool usable1, bool usable2, double dt)
        {
            bool f1 = _grip1 && usable1 && InWorkspace(first);
            f1 = Reachable(f1, first, ref _reach1, dt);
            bool f2 = _twoHands != null && _grip2 && usable2 && InWorkspace(second);
            f2 = Reachable(f2, second, ref _reach2, dt);
            double p1x = _k1x, p1y = _k1y, p1z = _k1z, p2x = _k2x, p2y = _k2y, p2z = _k2z; // each hand's last position before this frame
            if (f1) { _k1x = first.X; _k1y = first.Y; _k1z = first.Z; }
            if (f2) { _k2x = second.X; _k2y = second.Y; _k2z = second.Z; }
            // A hand joining a hand already followed waits for steady tracking (the profile's settle time); at a hold's begin
            // no hand is followed yet, so every followed hand joins at once.
            bool staying = (_in1 && f1) || (_in2 && f2);
            bool n1 = f1 && (_in1 || !staying || Settled(ref _join1, dt));
            bool n2 = f2 && (_in2 || !staying || Settled(ref _join2, dt));
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
                    // The followed point moves as the hand followed in both sets moved since it was last followed (a set that
                    // changes shares at most one hand; none: it stays where it was). The old set's mean would mix that hand's
                    // fresh position with a leaving hand's stale one, keeping half its motion on the frame its partner is lost.
                    double dx = 0, dy = 0, dz = 0;
                    if (_last1 && n1) { dx = _k1x - p1x; dy = _k1y - p1y; dz = _k1z - p1z; }
                    else if (_last2 && n2) { dx = _k2x - p2x; dy = _k2y - p2y; dz = _k2z - p2z; }
                    Mean(n1, n2, out double nx, out double ny, out double nz);
                    _cx = _vx + dx - nx;
                    _cy = _vy + dy - ny;
                    _cz = _vz + dz - nz;
                }
                if (n1 && n2) Pair(p1x, p1y, p1z, p2x, p2y, p2z);
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

        /// <summary>Both hands are followed. The first time since they gripped, c is the pair's anchor. While one hand was
        /// followed alone, its motion was taken as both hands' (the object is rigid): hands that moved relative to each other
        /// meanwhile (a box tilted about its centre) left that motion in c. Back together within
        /// <see cref="PairRestoreDistance"/> of the pair's anchor, c returns to it out of the hands' relative motion only: on
        /// a frame both hands were followed before too, by at most what the farther-moving hand moved beyond their mean,
        /// so the followed point moves no more than a hand did, and not at all while the hands rest (or move together).
        /// Farther, the hands gripped anew: c is the pair's anchor from now.</summary>
        void Pair(double p1x, double p1y, double p1z, double p2x, double p2y, double p2z)
        {
            if (!_hasPair)
            {
                _hasPair = true;
                _qx = _cx; _qy = _cy; _qz = _cz;
                return;
            }
            if (_cx == _qx && _cy == _qy && _cz == _qz) return;
            double ex = _qx - _cx, ey = _qy - _cy, ez = _qz - _cz, d = Math.Sqrt(ex * ex + ey * ey + ez * ez);
            if (!(_in1 && _in2))
            {
                if (d >= PairRestoreDistance) { _qx = _cx; _qy = _cy; _qz = _cz; }
                return; // the frame they are followed together again: the point stays where it was
            }
            double ax = _k1x - p1x, ay = _k1y - p1y, az = _k1z - p1z, bx = _k2x - p2x, by = _k2y - p2y, bz = _k2z - p2z;
            double mx = 0.5 * (ax + bx), my = 0.5 * (ay + by), mz = 0.5 * (az + bz);
            double budget = Math.Max(Math.Sqrt(ax * ax + ay * ay + az * az), Math.Sqrt(bx * bx + by * by + bz * bz)) - Math.Sqrt(mx * mx + my * my + mz * mz);
            if (!(budget > 0)) return;
            if (d <= budget) { _cx = _qx; _cy = _qy; _cz = _qz; return; }
            double k = budget / d;
            _cx += ex * k;
            _cy += ey * k;
            _cz += ez * k;
        }

        /// <summary>Whether a usable hand's pose can be followed: one a hand could have got to (<see cref="Reach"/>, judged
        /// in 3D as the y estimator judges heights). A refused pose counts as lost time.</summary>
        bool Reachable(bool usable, in HandPose hand, ref Reach reach, double dt)
        {
            reach.Tick(dt, _limits.MaxFrameTime);
            if (usable && reach.TryAccept(hand.X, hand.Y, hand.Z, _limits.MaxHandSpeed)) return true;
            reach.Miss();
            return false;
        }

        /// <summary>The plausibility gate: a hand within <see cref="SolverLimits.WorkspaceRadius"/> of the followed point where
        /// the hold began (any hand until a hold begun untracked follows its first).</summary>
        bool InWorkspace(in HandPose hand)
        {
            if (!_hasCentre) return true;
            double dx = hand.X - _wx, dy = hand.Y - _wy, dz = hand.Z - _wz, r = _limits.WorkspaceRadius;
            return dx * dx + dy * dy + dz * dz <= r * r;
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
        void ApplyMass(double standardSpeed)
        {
            bool two = _holds1 && _holds2 && _twoHands != null;
            var want = two ? _perHand : _model;
            if (!ReferenceEquals(want, _y.Model)) _y.Configure(want, _y.Profile, standardSpeed);
            _tau = two ? _tauTwo : _tauOne;
        }

        /// <summary>The hold starts (or, begun untracked, restarts at its first followed hand): the object is where it
        /// is, the followed point where it is.</summary>
        void Anchor()
        {
            _hHas = true;
            if (!_hasCentre) { _hasCentre = true; _wx = _vx; _wy = _vy; _wz = _vz; }
            _ax = _objX - _vx;
            _az = _objZ - _vz;
            _px = _vx; _py = _vy; _pz = _vz; _pt = double.NaN;
            Remember(_vx, _vz, restart: true);
            _gx = _vx - _objX;
            _gy = _vy - _y.ObjectY;
            _gz = _vz - _objZ;
            _hasGrab = true;
            _beyond = false;
        }

        /// <summary>x/z: the object is the followed point plus the grab's offset, less the lateral lag it shows. The lag
        /// is driven by the steady followed point (the median of its last three poses), so a one-pose glitch never
        /// enters it, and motion across a loss (or a change of the followed hands) is taken rigidly (tracking hid it; the
        /// lag is of motion seen).</summary>
        void StepHorizontal(double dt, bool newPose, bool bridged)
        {
            double dx = 0, dz = 0;
            if (newPose)
            {
                double oldX = _steadyX, oldZ = _steadyZ;
                if (Remember(_vx, _vz, restart: bridged)) { dx = _steadyX - oldX; dz = _steadyZ - oldZ; }
            }

            if (_tau > 0)
            {
                double step = dt < LateralInertia.MaxDecayStep ? dt : LateralInertia.MaxDecayStep;
                double ex = _ex + dx, ez = _ez + dz, perM = _perMaxOffset;
                double n = Math.Sqrt(ex * ex + ez * ez);
                // Implicit decay, faster the further the lag is past the bound: the factor lies in [0, 1), so the lag
                // never changes sign by itself (no overshoot, no oscillation).
                double k = _tau / (_tau + step * (1 + n * perM));
                ex *= k;
                ez *= k;
                if (n * k < 1e-12) ex = ez = 0;
                if (double.IsFinite(ex) && double.IsFinite(ez))
                {
                    _ex = ex;
                    _ez = ez;
                }
                // Shown: the lag plus how far the hand is ahead of the steady point (at most a pose's motion), through a
                // saturating curve, m·tanh(|e|/m): strictly increasing, so heavier still trails more, and never past the
                // bound. When the steady point catches up, what it adds to the lag it takes from the hand's lead: nothing
                // steps back; a one-pose glitch comes and goes with the hand and leaves the lag as it was.
                double tx = _ex + _vx - _steadyX, tz = _ez + _vz - _steadyZ, tn = Math.Sqrt(tx * tx + tz * tz);
                double shown = LateralInertia.ShownShare(tn * perM);
                if (double.IsFinite(shown)) { _sx = tx * shown; _sz = tz * shown; }
            }
            else _ex = _ez = _sx = _sz = 0;

            if (!_hHas) return; // no hand seen yet: the object stays where the hold began
            double x = _vx + _ax - _sx, z = _vz + _az - _sz;
            // Only coordinates a float transform holds, as on y (NaN and ±∞ compare false): two hands followed in turn across
            // the widest workspace re-anchor the followed point beyond it.
            if (Math.Abs(x) <= WeightSolver.MaxCoordinate && Math.Abs(z) <= WeightSolver.MaxCoordinate) { _objX = x; _objZ = z; }
        }

        /// <summary>Keeps the last three followed points (restarting after a gap) and their median; true once it moved.</summary>
        bool Remember(double x, double z, bool restart)
        {
            if (restart) _steadyCount = 0;
            double x1 = _x1, x2 = _x2, z1 = _z1, z2 = _z2;
            _x2 = x1; _x1 = x;
            _z2 = z1; _z1 = z;
            if (_steadyCount < 3) _steadyCount++;
            if (_steadyCount == 1) { _steadyX = x; _steadyZ = z; return false; }
            if (_steadyCount < 3) return false;
            double mx = Median(x, x1, x2), mz = Median(z, z1, z2);
            bool moved = mx != _steadyX || mz != _steadyZ;
            _steadyX = mx;
            _steadyZ = mz;
            return moved;
        }

        static double Median(double a, double b, double c) => Math.Max(Math.Min(a, b), Math.Min(Math.Max(a, b), c));

        /// <summary>The hold ends at the second pose in a row past the distance: a one-pose glitch never drops the object,
        /// and the hold ends no later than one pose interval after the first pose past it.</summary>
        void CheckBreakAway(bool newPose)
        {
            if (!newPose) return; // a new pose is a followed hand's, and the first followed hand anchors the grab
            if (BreakAwayMeasure > _breakAway.Distance)
            {
                if (_beyond)
                {
                    _brokeAway = true;
                    EndHold();
                }
                _beyond = true;
            }
            else _beyond = false;
        }
    }
}
