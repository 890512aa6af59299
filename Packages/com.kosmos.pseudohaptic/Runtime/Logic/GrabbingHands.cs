using System;
using System.Collections.Generic;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// The hands grabbing one object through a grab system's transformer (the Interaction SDK's <c>Grabbable</c>, XR
    /// Interaction Toolkit's <c>XRGrabInteractable</c>), engine-free: each hand's id on the weight's hold and the grab
    /// system's object for it (an interactor), in the order they joined. Both transformers keep their hands here, so
    /// joining, leaving, a full resync against the grab system's own list, and the snapshot a cancel loops over are one
    /// piece of code. Ids are the caller's (<see cref="Add(int, T)"/>, the Interaction SDK's pointer ids) or numbered here
    /// (<see cref="Add(T)"/>). Only a join beyond the capacity allocates; lookups, <see cref="TakeGone"/> and
    /// <see cref="CopyIds"/> never do.
    /// </summary>
    public sealed class GrabbingHands<T> where T : class
    {
        int[] _ids;
        T[] _sources;
        int _count, _nextId = 1;

        public GrabbingHands(int capacity = 4)
        {
            if (capacity < 1) throw new ArgumentOutOfRangeException(nameof(capacity), capacity, "capacity must be at least 1");
            _ids = new int[capacity];
            _sources = new T[capacity];
        }

        /// <summary>Hands grabbing now.</summary>
        public int Count => _count;

        /// <summary>The id of the <paramref name="i"/>-th hand (join order).</summary>
        public int IdAt(int i) => _ids[i];

        /// <summary>The grab system's object of the <paramref name="i"/>-th hand (may be null: the Interaction SDK's non-hand grabs).</summary>
        public T SourceAt(int i) => _sources[i];

        /// <summary>The index of hand <paramref name="id"/>, or −1.</summary>
        public int IndexOf(int id)
        {
            for (int i = 0; i < _count; i++)
                if (_ids[i] == id) return i;
            return -1;
        }

        /// <summary>The index of the hand whose object is <paramref name="source"/> (by reference), or −1.</summary>
        public int IndexOfSource(T source)
        {
            for (int i = 0; i < _count; i++)
                if (ReferenceEquals(_sources[i], source)) return i;
            return -1;
        }

        /// <summary>Hand <paramref name="id"/> joins with <paramref name="source"/>; false (nothing changes) when that id is already here.</summary>
        public bool Add(int id, T source)
        {
            if (IndexOf(id) >= 0) return false;
            if (_count == _ids.Length)
            {
                Array.Resize(ref _ids, _count * 2);
                Array.Resize(ref _sources, _count * 2);
            }
            _ids[_count] = id;
            _sources[_count] = source;
            _count++;
            if (id >= _nextId) _nextId = id == int.MaxValue ? 1 : id + 1;
            return true;
        }

        /// <summary>
        /// <paramref name="source"/> joins under a new id, numbered here, which is returned; a source already here keeps its id.
        /// Numbered ids go up from 1, past every id given or taken so far, and wrap to 1 only after int.MaxValue (then skipping
        /// ids in use): a hand that left is not numbered again, so a hand that grabs as another lets go is a join, never that
        /// hand's motion.
        /// </summary>
        public int Add(T source)
        {
            int i = IndexOfSource(source);
            if (i >= 0) return _ids[i];
            while (IndexOf(_nextId) >= 0 || _nextId == int.MinValue) _nextId = _nextId == int.MaxValue ? 1 : _nextId + 1;
            int id = _nextId;
            Add(id, source);
            return id;
        }

        /// <summary>Hand <paramref name="id"/> leaves; false when it was not here. The others keep their order.</summary>
        public bool Remove(int id)
        {
            int i = IndexOf(id);
            if (i < 0) return false;
            _count--;
            for (int k = i; k < _count; k++)
            {
                _ids[k] = _ids[k + 1];
                _sources[k] = _sources[k + 1];
            }
            _sources[_count] = null;
            return true;
        }

        /// <summary>Every hand leaves.</summary>
        public void Clear()
        {
            for (int i = 0; i < _count; i++) _sources[i] = null;
            _count = 0;
        }

        /// <summary>
        /// A resync against the grab system's own list: removes the first hand whose object is not in <paramref name="current"/>
        /// and gives its id (call until false, ending each one's hold); then <see cref="Add(T)"/> each object of
        /// <paramref name="current"/> not yet here (<see cref="IndexOfSource"/> −1).
        /// </summary>
        public bool TakeGone(IReadOnlyList<T> current, out int id)
        {
            for (int i = 0; i < _count; i++)
            {
                bool present = false;
                for (int k = 0; current != null && k < current.Count && !present; k++) present = ReferenceEquals(current[k], _sources[i]);
                if (present) continue;
                id = _ids[i];
                Remove(id);
                return true;
            }
            id = 0;
            return false;
        }

        /// <summary>
        /// The ids now, into <paramref name="buffer"/> (grown only when too small), and how many: a cancel loops over this
        /// copy, since every hand it cancels leaves while it loops.
        /// </summary>
        public int CopyIds(ref int[] buffer)
        {
            if (buffer == null || buffer.Length < _count) buffer = new int[Math.Max(_count, 4)];
            Array.Copy(_ids, buffer, _count);
            return _count;
        }
    }

    /// <summary>A transformer's frame time: the time since its last step, 0 for a second call in the same frame (the solver then moves nothing).</summary>
    public struct FrameClock
    {
        double _last;
        bool _started;

        /// <summary>The clock starts at <paramref name="now"/> (s), when a hold begins.</summary>
        public void Start(double now)
        {
            _last = now;
            _started = true;
        }

        /// <summary>Seconds since the last call (or <see cref="Start"/>); 0 before a start or when time did not advance or is not finite.</summary>
        public float Delta(double now)
        {
            if (!_started || !double.IsFinite(now))
            {
                Start(now);
                return 0f;
            }
            double dt = now - _last;
            _last = now;
            return dt > 0 ? (float)dt : 0f;
        }
    }
}
