using System;

namespace Kosmos.PseudoHaptic
{
    /// <summary>The space a held object's local y lives in: its parent's, as the Unity layer converts it.</summary>
    public interface IParentSpace
    {
        /// <summary>A world point's height in the object's parent space, m.</summary>
        double HeightOf(Vector3d world);
    }

    /// <summary>
    /// One object's hold, engine-free: its <see cref="WeightSolver3D"/>, the hands on it (one or two), the clock,
    /// the hand's and the object's velocity for the release, and the events an observer (the session recorder)
    /// reads. The Unity component converts poses and writes the answer.
    /// </summary>
    /// <remarks>
    /// The solver sees each hand as world x/z and parent-space y (the object's parent is upright, of unit scale).
    /// Two hands: the first hand that grabs begins the hold in the solver's slot 1, a second joins in the other
    /// slot (the solver follows their mean and, with <see cref="TwoHands"/>, gives each its share of the mass);
    /// a hand that lets go leaves its slot (<see cref="WeightSolver3D.SetGrip"/>), a hand that comes takes a free
    /// one, and the solver re-anchors the followed point so nothing steps. A profile without
    /// <see cref="TwoHands"/> gets <c>TwoHands(1)</c> here: both hands are followed, each carrying the whole
    /// mass (the paper's weight, unchanged). The solver steps once per frame, on the call that completes the
    /// frame's poses: when every hand on the object has given one since the last step (two hands calling in any
    /// order). A hand that gives a second pose before the other gave any tells that the other's driver stopped stepping
    /// it (without <see cref="End"/>): the other is silent, taken as lost (its last pose is stale, not a hand held still)
    /// until it gives a pose again, and the frame the first pose began is stepped then, with its own time. x and z are the
    /// solver's (<see cref="Horizontal"/>) when the profile has <see cref="LateralInertia"/>; otherwise the grab
    /// driver moves them as before. A break-away ends the solver's hold: <see cref="BrokeAway"/> tells the
    /// drivers to release, and the last release raises <see cref="Ended"/>. No allocation per frame.
    /// </remarks>
    public sealed class HeldObject
    {
        public const int MaxHands = 2;
        const int Empty = int.MinValue;

        readonly IParentSpace _space;
        readonly int[] _slotHand = { Empty, Empty }; // the hand id in solver slot 1 and 2
        readonly HandPose[] _pose = new HandPose[MaxHands];
        readonly bool[] _fresh = new bool[MaxHands]; // recorded a pose since the solver's last step
        readonly bool[] _silent = new bool[MaxHands]; // its driver stopped stepping it: lost until it gives a pose again
        double _pendingDt, _pendingPoseTime; // the time and pose time the first pose of a frame still incomplete came with
        int _count;
        bool _active; // a hold began and its Ended has not been raised
        WeightProfile _given, _used;
        // The grab's x/z (no lateral inertia): the usable hands' mean plus the object's offset from it, re-anchored
        // whenever the set of usable hands changes, so neither hand's frame order nor a hand joining moves the object.
        int _usableMask = -1;
        Vector3d _centreOffset, _objectNow;
        VelocityTracker _handVelocity, _objectVelocity;
        double _clock;

        public HeldObject(IParentSpace space) => _space = space ?? throw new ArgumentNullException(nameof(space));

        /// <summary>Raised when the first hand's hold began, after each solver step, and when the last hand let go.</summary>
        public event Action Began, Stepped, Ended;

        /// <summary>The 3D solver, null until the first successful configuration.</summary>
        public WeightSolver3D Solver3D { get; private set; }

        /// <summary>Its y solver (configured with the per-hand mass while two hands carry shares), null until configured.</summary>
        public WeightSolver Solver => Solver3D?.Vertical;

        /// <summary>The object's mass, kg (NaN until configured); the y solver may see a per-hand share of it.</summary>
        public double MassKg => Solver3D != null ? Solver3D.Model.MassKg : double.NaN;

        /// <summary>The solver holds the object (false after a break-away, while the hands have not yet let go).</summary>
        public bool IsHeld => Solver3D != null && Solver3D.IsHolding;

        /// <summary>The object has torn loose from the hands (<see cref="BreakAway"/>): every grab driver should release.</summary>
        public bool BrokeAway => _active && Solver3D.BrokeAway;

        /// <summary>x and z are the solver's (the profile has <see cref="LateralInertia"/>); otherwise the grab moves them.</summary>
        public bool MovesHorizontal { get; private set; }

        /// <summary>Hands on the object now.</summary>
        public int HandCount => _count;

        /// <summary>The point the solver follows: world x/z, parent-space y (the last followed one while every hand is lost).</summary>
        public Vector3d HandPoint { get; private set; }

        /// <summary>
        /// Where the grab puts the object's x/z when the solver does not move them: the mean of the usable hands (world x/z)
        /// plus the offset the object had from that mean when the set of usable hands last changed; NaN while no hand is usable.
        /// The same for every hand on the object, whichever steps last.
        /// </summary>
        public Vector3d GrabTarget { get; private set; } = Vector3d.NaN;

        /// <summary>The hand as the y solver was given it on the hold's last frame.</summary>
        public HandSample LastHand { get; private set; }

        /// <summary>The frame time given to the last step, s (0 right after the hold began).</summary>
        public double LastDeltaTime { get; private set; }

        /// <summary>The hand point's velocity over its last motion.</summary>
        public Vector3d HandVelocity => _handVelocity.VelocityAt(_clock);

        /// <summary>The object's velocity over its last motion, world space (fed by <see cref="TrackObject"/>).</summary>
        public Vector3d ObjectVelocity => _objectVelocity.VelocityAt(_clock);

        /// <summary>Metres from the object's pivot down to its lowest point (its collider's), for the floor: the agreed solver property.</summary>
        public double BottomBelowPivot { get; set; }

        /// <summary>
        /// Under a profile named <c>paper-literal</c> (<see cref="NamedProfiles.IsPaperLiteral"/>), the paper as printed runs the
        /// object's height: <see cref="PaperLiteralSolver"/> on the followed hand's height (the 3D solver still follows the
        /// hands, and x/z come from the grab); null otherwise.
        /// </summary>
        public PaperLiteralSolver Literal => _literal;

        /// <summary>The object's height the hold gives (parent space), m: the literal solver's under paper-literal, else the solver's.</summary>
        public double ObjectY => _literal != null ? _literal.ObjectY : Solver3D != null ? Solver3D.ObjectY : double.NaN;

        /// <summary>hand − object (parent space), m: the literal solver's under paper-literal, else the y solver's <see cref="WeightSolver.Offset"/>.</summary>
        public double Offset => _literal != null ? LastHand.Y - _literal.ObjectY : Solver != null ? Solver.Offset : double.NaN;

        PaperLiteralSolver _literal;

        /// <summary>Why the last configuration or begin failed; null when it succeeded.</summary>
        public string Error { get; private set; }

        /// <summary>Applies a model, profile and user (standard speed and cue strength) to the solver; allowed during a hold. False,
        /// keeping the last valid one, with <see cref="Error"/>.</summary>
        public bool Configure(WeightModel model, WeightProfile profile, double standardSpeed, double cueStrength = WeightSolver.DefaultCueStrength)
        {
            try
            {
                if (profile == null) throw new ArgumentNullException(nameof(profile));
                if (double.IsNaN(cueStrength) || cueStrength < WeightSolver.MinCueStrength || cueStrength > WeightSolver.MaxCueStrength)
                    throw new ArgumentOutOfRangeException(nameof(cueStrength), cueStrength, "CueStrength must lie in [" + WeightSolver.MinCueStrength + ", " + WeightSolver.MaxCueStrength + "].");
                WeightProfile used = ReferenceEquals(profile, _given) ? _used : WithBothHands(profile);
                if (Solver3D == null) Solver3D = new WeightSolver3D(model, used, standardSpeed);
                else Solver3D.Configure(model, used, standardSpeed);
                Solver3D.CueStrength = cueStrength;
                if (!NamedProfiles.IsPaperLiteral(profile)) _literal = null;
                else if (_literal == null || _literal.MassKg != model.MassKg || _literal.CueStrength != cueStrength || _literal.MaxGain != profile.Limits.MaxGain)
                {
                    var literal = new PaperLiteralSolver(model.MassKg) { CueStrength = cueStrength, MaxGain = profile.Limits.MaxGain };
                    // Mid-hold, the new one continues from where the object is.
                    if (_active && _literal != null) literal.BeginHold(Solver3D.FollowedY, _literal.ObjectY);
                    _literal = literal;
                }
                _given = profile;
                _used = used;
                MovesHorizontal = profile.Has<LateralInertia>();
                Solver3D.BottomBelowPivot = BottomBelowPivot;
            }
            catch (ArgumentException e)
            {
                Error = e.Message;
                return false;
            }
            Error = null;
            return true;
        }

        /// <summary>The profile the solver runs: <paramref name="profile"/>, with <c>TwoHands(1)</c> when it has no <see cref="TwoHands"/>.</summary>
        public static WeightProfile WithBothHands(WeightProfile profile) =>
            profile.Has<TwoHands>() ? profile : profile.With(new TwoHands(1), profile.Name);

        /// <summary>Whether hand <paramref name="hand"/> is on the object.</summary>
        public bool Holds(int hand) => SlotOf(hand) >= 0;

        /// <summary>
        /// Hand <paramref name="hand"/> takes the object at <paramref name="handWorld"/>: the first one begins the hold
        /// (the object where it is: world x/z, local y), a second joins it. False when the solver is not configured,
        /// the hand already holds it, two hands do, the object has broken away, or the solver refuses.
        /// </summary>
        public bool Begin(int hand, Vector3d handWorld, double poseTime, Vector3d objectWorld, double objectLocalY)
        {
            if (Solver3D == null || hand == Empty || SlotOf(hand) >= 0 || _count >= MaxHands || (_count > 0 && !IsHeld)) return false;
            if (_count > 0)
            {
                int free = _slotHand[0] == Empty ? 0 : 1;
                Take(free, hand, handWorld, true, true, poseTime);
                Solver3D.SetGrip(free + 1, true); // joins once steadily tracked; the followed point is re-anchored
                UpdateGrabTarget(); // the grab's x/z re-anchor on the hands as they are when this one joins
                return true;
            }
            Take(0, hand, handWorld, true, true, poseTime);
            try
            {
                Solver3D.BottomBelowPivot = BottomBelowPivot;
                Solver3D.BeginHold(in _pose[0], HandPose.Lost, objectWorld.X, objectLocalY, objectWorld.Z);
            }
            catch (ArgumentException e)
            {
                Error = e.Message;
                _slotHand[0] = Empty;
                _count = 0;
                return false;
            }
            Solver3D.SetGrip(2, false);
            _literal?.BeginHold(_pose[0].IsUsable ? _pose[0].Y : double.NaN, Solver3D.ObjectY);
            _fresh[0] = _fresh[1] = _silent[0] = _silent[1] = false;
            _active = true;
            _clock = 0;
            HandPoint = Followed(_pose[0]);
            _handVelocity.Reset(HandPoint, 0);
            _objectVelocity.Reset(objectWorld, 0);
            _objectNow = objectWorld;
            _usableMask = -1;
            UpdateGrabTarget();
            bool usable = _pose[0].IsUsable;
            LastHand = new HandSample(usable ? _pose[0].Y : double.NaN, usable, usable, poseTime);
            LastDeltaTime = 0;
            Began?.Invoke();
            return true;
        }

        /// <summary>
        /// One frame of hand <paramref name="hand"/>. The call that completes the frame's poses steps the solver and
        /// gets the object's new local y; an earlier call records its pose and gets NaN (nothing to write). Never throws.
        /// </summary>
        public double Step(int hand, Vector3d handWorld, bool tracked, bool highConfidence, double poseTime, double dt)
        {
            int slot = SlotOf(hand);
            if (slot < 0 || !IsHeld) return double.NaN;
            if (_fresh[slot])
            {
                // A second pose of this hand before the other gave one: the other's driver stopped stepping it. Its last pose is
                // stale: it is silent (lost) until it gives one again, and the frame this hand's last pose began is stepped now.
                for (int i = 0; i < MaxHands; i++)
                    if (_slotHand[i] != Empty && !_fresh[i]) _silent[i] = true;
                StepSolver(_pendingDt, _pendingPoseTime);
                if (!IsHeld) return double.NaN; // that step broke the object away
            }
            Take(slot, hand, handWorld, tracked, highConfidence, poseTime);
            _fresh[slot] = true;
            _silent[slot] = false;
            if (!AllFresh())
            {
                // The other hand's pose of this frame is still to come.
                _pendingDt = dt;
                _pendingPoseTime = poseTime;
                return double.NaN;
            }
            return StepSolver(dt, poseTime);
        }

        /// <summary>Steps the solver with the hands' poses as recorded (a silent hand's as lost) and returns the object's local y.</summary>
        double StepSolver(double dt, double poseTime)
        {
            _fresh[0] = _fresh[1] = false;
            for (int i = 0; i < MaxHands; i++)
                if (_silent[i] && _pose[i].IsTracked) _pose[i] = new HandPose(_pose[i].X, _pose[i].Y, _pose[i].Z, false, false, _pose[i].PoseTime);

            WeightSolver3D s = Solver3D;
            s.Step(in _pose[0], in _pose[1], dt);
            bool any = s.FollowedHands > 0;
            if (any) HandPoint = new Vector3d(s.FollowedX, s.FollowedY, s.FollowedZ);
            bool confident = any && (_slotHand[0] == Empty || !_pose[0].IsUsable || _pose[0].IsHighConfidence)
                                 && (_slotHand[1] == Empty || !_pose[1].IsUsable || _pose[1].IsHighConfidence);
            LastHand = new HandSample(any ? s.FollowedY : double.NaN, any, confident, poseTime);
            LastDeltaTime = dt;
            if (dt > 0 && !double.IsInfinity(dt)) _clock += dt;
            if (any) _handVelocity.Add(HandPoint, _clock);
            UpdateGrabTarget();
            double y = _literal != null ? _literal.Step(s.FollowedY, any, dt) : s.ObjectY;
            Stepped?.Invoke();
            return y;
        }

        /// <summary>
        /// The object's world position with x/z the solver's when it moves them (<see cref="MovesHorizontal"/>), else the
        /// grab's (<see cref="GrabTarget"/>) when <paramref name="grabMoves"/> and a hand is usable, else <paramref name="objectNow"/>.
        /// </summary>
        public Vector3d Horizontal(Vector3d objectNow, bool grabMoves = false)
        {
            if (!_active) return objectNow;
            if (MovesHorizontal) return new Vector3d(Solver3D.ObjectX, objectNow.Y, Solver3D.ObjectZ);
            Vector3d t = GrabTarget;
            return grabMoves && double.IsFinite(t.X) && double.IsFinite(t.Z) ? new Vector3d(t.X, objectNow.Y, t.Z) : objectNow;
        }

        /// <summary>The object's world position after the step's write, for its release velocity.</summary>
        public void TrackObject(Vector3d objectWorld)
        {
            _objectVelocity.Add(objectWorld, _clock);
            if (objectWorld.IsFinite) _objectNow = objectWorld;
        }

        void UpdateGrabTarget()
        {
            int mask = 0, n = 0;
            double x = 0, z = 0;
            for (int i = 0; i < MaxHands; i++)
            {
                if (_slotHand[i] == Empty || !_pose[i].IsUsable || double.IsNaN(_pose[i].X) || double.IsNaN(_pose[i].Z)) continue;
                mask |= 1 << i;
                n++;
                x += _pose[i].X;
                z += _pose[i].Z;
            }
            if (n == 0)
            {
                GrabTarget = Vector3d.NaN;
                _usableMask = 0;
                return;
            }
            var centre = new Vector3d(x / n, 0, z / n);
            if (mask != _usableMask) _centreOffset = new Vector3d(_objectNow.X - centre.X, 0, _objectNow.Z - centre.Z);
            _usableMask = mask;
            GrabTarget = new Vector3d(centre.X + _centreOffset.X, double.NaN, centre.Z + _centreOffset.Z);
        }

        /// <summary>Hand <paramref name="hand"/> lets go. True when that ended the hold (it was the last hand).</summary>
        public bool End(int hand)
        {
            int slot = SlotOf(hand);
            if (slot < 0) return false;
            _slotHand[slot] = Empty;
            _fresh[slot] = _silent[slot] = false;
            _pose[slot] = HandPose.Lost;
            _count--;
            if (_count > 0)
            {
                if (IsHeld) Solver3D.SetGrip(slot + 1, false); // the other hand continues; its share grows back
                UpdateGrabTarget();
                return false;
            }
            if (IsHeld) Solver3D.EndHold();
            if (_active)
            {
                _active = false;
                Ended?.Invoke();
            }
            return true;
        }

        /// <summary>Every hand lets go (the object was disabled).</summary>
        public void EndAll()
        {
            for (int i = 0; i < MaxHands; i++)
                if (_slotHand[i] != Empty) End(_slotHand[i]);
        }

        /// <summary>The velocity a released body gets under <paramref name="kind"/>.</summary>
        public Vector3d ReleaseVelocity(ReleaseVelocity kind) => WeightSettings.Release(kind, HandVelocity, ObjectVelocity);

        bool AllFresh()
        {
            for (int i = 0; i < MaxHands; i++)
                if (_slotHand[i] != Empty && !_fresh[i] && !_silent[i]) return false;
            return true;
        }

        int SlotOf(int hand)
        {
            if (hand == Empty) return -1;
            for (int i = 0; i < MaxHands; i++)
                if (_slotHand[i] == hand) return i;
            return -1;
        }

        void Take(int slot, int hand, Vector3d world, bool tracked, bool highConfidence, double poseTime)
        {
            if (_slotHand[slot] == Empty) _count++;
            _slotHand[slot] = hand;
            double y = world.IsFinite ? _space.HeightOf(world) : double.NaN;
            _pose[slot] = new HandPose(world.X, y, world.Z, tracked, tracked && highConfidence, poseTime);
        }

        static Vector3d Followed(in HandPose p) => p.IsUsable ? new Vector3d(p.X, p.Y, p.Z) : Vector3d.NaN;
    }
}
