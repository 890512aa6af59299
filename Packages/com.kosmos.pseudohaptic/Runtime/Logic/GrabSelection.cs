using System;

namespace Kosmos.PseudoHaptic
{
    /// <summary>The objects a hand could grab, as the Unity layer sees them (its enabled weights).</summary>
    public interface IGrabCandidates
    {
        int Count { get; }

        /// <summary>The point of object <paramref name="index"/> nearest the hand (its collider's), world space; NaN for none.</summary>
        Vector3d ClosestPoint(int index, Vector3d hand);

        /// <summary>How many hands hold object <paramref name="index"/> now.</summary>
        int HandsOn(int index);
    }

    /// <summary>Which object a pinch takes: the nearest within reach that has room for one more hand.</summary>
    public static class GrabSelection
    {
        /// <summary>
        /// The index of the candidate whose nearest point is closest to <paramref name="hand"/>, within
        /// <paramref name="reach"/> metres (inclusive), among those held by fewer than <paramref name="handsPerObject"/>
        /// hands; the first such on a tie; −1 for none (or a hand that is not finite).
        /// </summary>
        public static int Nearest(Vector3d hand, double reach, int handsPerObject, IGrabCandidates candidates)
        {
            if (candidates == null || !hand.IsFinite || !(reach >= 0)) return -1;
            int best = -1;
            double bestSq = reach * reach;
            int n = candidates.Count;
            for (int i = 0; i < n; i++)
            {
                if (candidates.HandsOn(i) >= handsPerObject) continue;
                Vector3d p = candidates.ClosestPoint(i, hand);
                if (!p.IsFinite) continue;
                double d = (p - hand).SqrLength;
                if (d <= bestSq && (best < 0 || d < bestSq))
                {
                    best = i;
                    bestSq = d;
                }
            }
            return best;
        }
    }
}
