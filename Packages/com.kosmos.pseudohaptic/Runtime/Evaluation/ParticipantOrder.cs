using System;
using System.Collections.Generic;

namespace Kosmos.PseudoHaptic.Evaluation
{
    /// <summary>
    /// The order participants are reported in, as the paper's tables list them: natural order, runs of digits
    /// compared as numbers (P2 before P10), the rest ordinally; ties broken ordinally so the order is total.
    /// </summary>
    public sealed class ParticipantOrder : IComparer<string>
    {
        public static readonly ParticipantOrder Instance = new ParticipantOrder();

        public int Compare(string a, string b)
        {
            if (ReferenceEquals(a, b)) return 0;
            if (a == null) return -1;
            if (b == null) return 1;
            int i = 0, j = 0;
            while (i < a.Length && j < b.Length)
            {
                if (IsDigit(a[i]) && IsDigit(b[j]))
                {
                    int si = i, sj = j;
                    while (i < a.Length && IsDigit(a[i])) i++;
                    while (j < b.Length && IsDigit(b[j])) j++;
                    int c = CompareDigits(a, si, i, b, sj, j);
                    if (c != 0) return c;
                }
                else
                {
                    int c = a[i].CompareTo(b[j]);
                    if (c != 0) return c;
                    i++;
                    j++;
                }
            }
            int rest = (a.Length - i).CompareTo(b.Length - j);
            return rest != 0 ? rest : string.CompareOrdinal(a, b);
        }

        static bool IsDigit(char c) => c >= '0' && c <= '9';

        /// <summary>Compares two digit runs by value, however long, without parsing them.</summary>
        static int CompareDigits(string a, int aStart, int aEnd, string b, int bStart, int bEnd)
        {
            while (aStart < aEnd - 1 && a[aStart] == '0') aStart++;
            while (bStart < bEnd - 1 && b[bStart] == '0') bStart++;
            int length = (aEnd - aStart).CompareTo(bEnd - bStart);
            if (length != 0) return length;
            for (; aStart < aEnd; aStart++, bStart++)
                if (a[aStart] != b[bStart]) return a[aStart].CompareTo(b[bStart]);
            return 0;
        }

        /// <summary>Sorts stably by participant, keeping the given order among equal ids.</summary>
        public static List<T> Sort<T>(IEnumerable<T> items, Func<T, string> participant)
        {
            var list = new List<T>(items);
            var keyed = new List<KeyValuePair<int, T>>(list.Count);
            for (int k = 0; k < list.Count; k++) keyed.Add(new KeyValuePair<int, T>(k, list[k]));
            keyed.Sort((x, y) =>
            {
                int c = Instance.Compare(participant(x.Value), participant(y.Value));
                return c != 0 ? c : x.Key.CompareTo(y.Key);
            });
            for (int k = 0; k < keyed.Count; k++) list[k] = keyed[k].Value;
            return list;
        }
    }
}
