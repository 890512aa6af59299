namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// Which colliders are touching a trigger, by instance id, decided once when each contact begins (is it a
    /// fingertip?) so the contact's every later frame costs a lookup, not a component search. A few contacts at a
    /// time; no allocation once it has grown to the most contacts seen.
    /// </summary>
    public sealed class ContactSet
    {
        int[] _ids = new int[4];
        int _count;

        public int Count => _count;

        public bool Contains(int id)
        {
            for (int i = 0; i < _count; i++)
                if (_ids[i] == id) return true;
            return false;
        }

        public void Add(int id)
        {
            if (Contains(id)) return;
            if (_count == _ids.Length) System.Array.Resize(ref _ids, _count * 2);
            _ids[_count++] = id;
        }

        public void Remove(int id)
        {
            for (int i = 0; i < _count; i++)
                if (_ids[i] == id)
                {
                    _ids[i] = _ids[--_count];
                    return;
                }
        }

        public void Clear() => _count = 0;
    }
}
