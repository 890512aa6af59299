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
    /// One object's hold, engine-free: its <see cref="WeightSolver"/>, the hands on it (one or two), the hand point
    /// the solver follows, the clock, the hand's and the object's velocity for the release, and the events an
    /// observer (the session recorder) reads. The Unity component converts poses and writes the answer.
    /// </summary>
    /// <remarks>
    /// Two hands: the first hand that grabs begins the hold; a second joins it; the hold ends when the last one
    /// lets go. The solver follows one point: the first hand's position moved by the mean motion of the tracked
    /// hands since the set of tracked hands last changed. A hand that joins, leaves, loses or regains tracking
    /// re-anchors that point where it is, so it never jumps. Only the first hand (<see cref="IsLeader"/>) steps
    /// the solver, once per frame; the other's step records its pose. No allocation per frame.
    /// </remarks>
    public sealed class HeldObject
    {
        public const int MaxHands = 2;

        readonly IParentSpace _space;
        readonly int[] _ids = new int[MaxHands];
        readonly Vector3d[] _pos = new Vector3d[MaxHands];
        readonly Vector3d[] _ref = new Vector3d[MaxHands];
        readonly bool[] _tracked = new bool[MaxHands];
        readonly bool[] _contributes = new bool[MaxHands];
        readonly bool[] _lastSeen = new bool[MaxHands]; // contributed just before every hand was lost
        int _count;
        Vector3d _base, _point;
        VelocityTracker _handVelocity, _objectVelocity;
        double _clock;

        public HeldObject(IParentSpace space) => _space = space ?? throw new ArgumentNullException(nameof(space));

        /// <summary>Raised when the first hand's hold began, after each solver step, and when the last hand let go.</summary>
        public event Action Began, Stepped, Ended;

        /// <summary>The core solver, null until the first successful configuration.</summary>
        public WeightSolver Solver { get; private set; }

        public bool IsHeld => Solver != null && Solver.IsHolding;

        /// <summary>Hands on the object now.</summary>
        public int HandCount => _count;

        /// <summary>The point the solver follows, world space (the last tracked one while every hand is lost).</summary>
        public Vector3d HandPoint => _point;

        /// <summary>The hand as the solver was given it on the hold's last frame.</summary>
        public HandSample LastHand { get; private set; }

        /// <summary>The frame time given to the last step, s (0 right after the hold began).</summary>
        public double LastDeltaTime { get; private set; }

        /// <summary>The hand point's velocity over its last motion, world space.</summary>
        public Vector3d HandVelocity => _handVelocity.VelocityAt(_clock);

        /// <summary>The object's velocity over its last motion, world space (fed by <see cref="TrackObject"/>).</summary>
        public Vector3d ObjectVelocity => _objectVelocity.VelocityAt(_clock);

        /// <summary>Metres from the object's pivot down to its lowest point (its collider's), for the floor: the agreed solver property.</summary>
        public double BottomBelowPivot { get; set; }

        /// <summary>Why the last configuration or begin failed; null when it succeeded.</summary>
        public string Error { get; private set; }

        /// <summary>Applies a model, profile and user to the solver; allowed during a hold. False, keeping the last valid one, with <see cref="Error"/>.</summary>
        public bool Configure(WeightModel model, WeightProfile profile, double standardSpeed)
        {
            try
            {
                if (Solver == null) Solver = new WeightSolver(model, profile, standardSpeed);
                else Solver.Configure(model, profile, standardSpeed);
                ApplyBottom();
            }
            catch (ArgumentException e)
            {
                Error = e.Message;
                return false;
            }
            Error = null;
            return true;
        }

        void ApplyBottom()
        {
            Solver.BottomBelowPivot = BottomBelowPivot; // the agreed solver property (issue 9): the floor keeps the bottom up
        }

        /// <summary>Whether hand <paramref name="hand"/> is on the object.</summary>
        public bool Holds(int hand) => Slot(hand) >= 0;

        /// <summary>Whether hand <paramref name="hand"/> is the one that steps the solver.</summary>
        public bool IsLeader(int hand) => _count > 0 && _ids[0] == hand;

        /// <summary>
        /// Hand <paramref name="hand"/> takes the object at <paramref name="handWorld"/>: the first one begins the hold
        /// (the object's current local y, the grab offset objectY − handY going to the solver), a second joins it.
        /// False when the solver is not configured, the hand already holds it, two hands do, or the solver refuses.
        /// </summary>
        public bool Begin(int hand, Vector3d handWorld, double poseTime, Vector3d objectWorld, double objectLocalY)
        {
            if (Solver == null || Slot(hand) >= 0 || _count >= MaxHands) return false;
            bool usable = Usable(handWorld);
            if (_count > 0)
            {
                Add(hand, handWorld, usable);
                Reanchor();
                return true;
            }
            double handY = usable ? _space.HeightOf(handWorld) : double.NaN;
            try
            {
                ApplyBottom();
                Solver.BeginHold(handY, objectLocalY, poseTime);
            }
            catch (ArgumentException e)
            {
                Error = e.Message;
                return false;
            }
            Add(hand, handWorld, usable);
            _base = _point = handWorld;
            Reanchor();
            _clock = 0;
            _handVelocity.Reset(handWorld, 0);
            _objectVelocity.Reset(objectWorld, 0);
            LastHand = new HandSample(handY, usable, usable, poseTime);
            LastDeltaTime = 0;
            Began?.Invoke();
            return true;
        }

        /// <summary>
        /// One frame of hand <paramref name="hand"/>. The leader steps the solver with the combined point and gets the
        /// object's new local y; any other hand records its pose and gets NaN (nothing to write). Never throws.
        /// </summary>
        public double Step(int hand, Vector3d handWorld, bool tracked, bool highConfidence, double poseTime, double dt)
        {
            int slot = Slot(hand);
            if (slot < 0 || !IsHeld) return double.NaN;
            bool usable = tracked && Usable(handWorld);
            _tracked[slot] = usable;
            if (usable) _pos[slot] = handWorld;
            Refresh();
            if (slot != 0) return double.NaN;

            bool any = AnyContributes();
            double handY = any ? _space.HeightOf(_point) : double.NaN;
            var sample = new HandSample(handY, any, any && highConfidence, poseTime);
            double y = Solver.Step(in sample, dt);
            LastHand = sample;
            LastDeltaTime = dt;
            if (dt > 0 && !double.IsInfinity(dt)) _clock += dt;
            if (any) _handVelocity.Add(_point, _clock);
            Stepped?.Invoke();
            return y;
        }

        /// <summary>The object's world position after the step's write, for its release velocity.</summary>
        public void TrackObject(Vector3d objectWorld) => _objectVelocity.Add(objectWorld, _clock);

        /// <summary>Hand <paramref name="hand"/> lets go. True when that ended the hold (it was the last hand).</summary>
        public bool End(int hand)
        {
            int slot = Slot(hand);
            if (slot < 0) return false;
            Vector3d at = Combined(); // where the point is, with the leaving hand still counted
            for (int i = slot; i < _count - 1; i++)
            {
                _ids[i] = _ids[i + 1];
                _pos[i] = _pos[i + 1];
                _ref[i] = _ref[i + 1];
                _tracked[i] = _tracked[i + 1];
                _contributes[i] = _contributes[i + 1];
                _lastSeen[i] = _lastSeen[i + 1];
            }
            _count--;
            if (_count > 0)
            {
                AnchorAt(at);
                return false;
            }
            if (Solver != null && Solver.IsHolding)
            {
                Solver.EndHold();
                Ended?.Invoke();
            }
            return true;
        }

        /// <summary>Every hand lets go (the object was disabled).</summary>
        public void EndAll()
        {
            while (_count > 0) End(_ids[0]);
        }

        /// <summary>The velocity a released body gets under <paramref name="kind"/>.</summary>
        public Vector3d ReleaseVelocity(ReleaseVelocity kind) => WeightSettings.Release(kind, HandVelocity, ObjectVelocity);

        /// <summary>A pose the hands' point may follow: finite and within ±<see cref="WeightSolver.MaxCoordinate"/> m (the solver's rule for heights).</summary>
        static bool Usable(Vector3d p) =>
            HandSample.IsUsableHeight(p.Y) && HandSample.IsUsableHeight(p.X) && HandSample.IsUsableHeight(p.Z);

        int Slot(int hand)
        {
            for (int i = 0; i < _count; i++)
                if (_ids[i] == hand) return i;
            return -1;
        }

        void Add(int hand, Vector3d world, bool usable)
        {
            _ids[_count] = hand;
            _pos[_count] = world;
            _tracked[_count] = usable;
            _contributes[_count] = false;
            _lastSeen[_count] = false;
            _count++;
        }

        bool AnyContributes()
        {
            for (int i = 0; i < _count; i++)
                if (_contributes[i]) return true;
            return false;
        }

        /// <summary>
        /// Recomputes the point. When the set of tracked hands changed, it is re-anchored where it is, except when a
        /// hand that was tracked until every hand was lost comes back: then its motion during the loss counts, as
        /// the solver alone would see it (one hand's point stays its position).
        /// </summary>
        void Refresh()
        {
            bool changed = false, returning = false;
            for (int i = 0; i < _count; i++)
            {
                changed |= _tracked[i] != _contributes[i];
                returning |= _tracked[i] && _lastSeen[i];
            }
            if (!changed) { _point = Combined(); return; }
            if (AnyContributes())
            {
                bool anyLeft = false;
                for (int i = 0; i < _count; i++) anyLeft |= _tracked[i];
                for (int i = 0; i < _count; i++) _lastSeen[i] = !anyLeft && _contributes[i];
                Reanchor();
            }
            else if (returning)
            {
                for (int i = 0; i < _count; i++) { _contributes[i] = _tracked[i]; _lastSeen[i] = false; }
            }
            else Reanchor(); // another hand takes over: continue from where the point is
            _point = Combined();
        }

        void Reanchor() => AnchorAt(AnyContributes() ? Combined() : _point);

        void AnchorAt(Vector3d point)
        {
            _base = point;
            for (int i = 0; i < _count && !_base.IsFinite; i++)
                if (_tracked[i]) _base = _pos[i]; // the hold began untracked: start from the first tracked pose
            for (int i = 0; i < _count; i++)
            {
                _ref[i] = _pos[i];
                _contributes[i] = _tracked[i];
            }
            _point = _base;
        }

        Vector3d Combined()
        {
            Vector3d sum = Vector3d.Zero;
            int n = 0;
            for (int i = 0; i < _count; i++)
            {
                if (!_contributes[i]) continue;
                sum += _pos[i] - _ref[i];
                n++;
            }
            return n == 0 ? _point : _base + sum / n;
        }
    }
}
