using System;
using System.Collections.Generic;
using Kosmos.PseudoHaptic.Evaluation;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests.Evaluation
{
    /// <summary>
    /// The order participants are reported in (evaluation.md §2: natural order, P2 before P10): runs of digits
    /// compared as numbers however long, the rest character by character, a shorter id first when the other goes on,
    /// ties of equal value (P1, P01) broken ordinally so that the order is total; null first.
    /// </summary>
    public class ParticipantOrderTests
    {
        /// <summary>Ascending, written out by hand from the rules above.</summary>
        static readonly string[] Ascending =
        {
            null, "", "P0", "P00", "P0a", "P01", "P1", "P01a", "P1a", "P2", "P9", "P10", "P11", "P20",
            "P99999999999999999999", "P100000000000000000000", "PA", "Pa",
        };

        [Test]
        public void EveryPairOfIdsComparesAsTheNaturalOrderSaysAndTheOtherWayRound()
        {
            var order = ParticipantOrder.Instance;
            for (int i = 0; i < Ascending.Length; i++)
            {
                string copy = Ascending[i] == null ? null : new string(Ascending[i].ToCharArray());
                Assert.That(order.Compare(Ascending[i], copy), Is.EqualTo(0), "'" + Ascending[i] + "' with itself");
                for (int j = i + 1; j < Ascending.Length; j++)
                {
                    Assert.That(order.Compare(Ascending[i], Ascending[j]), Is.LessThan(0), "'" + Ascending[i] + "' before '" + Ascending[j] + "'");
                    Assert.That(order.Compare(Ascending[j], Ascending[i]), Is.GreaterThan(0), "'" + Ascending[j] + "' after '" + Ascending[i] + "'");
                }
            }
        }

        [Test]
        public void SortingAnyShuffleGivesTheNaturalOrder()
        {
            var random = new Random(7);
            for (int round = 0; round < 20; round++)
            {
                var ids = new List<string>(Ascending);
                for (int k = ids.Count - 1; k > 0; k--)
                {
                    int m = random.Next(k + 1);
                    (ids[k], ids[m]) = (ids[m], ids[k]);
                }
                ids.Sort(ParticipantOrder.Instance);
                Assert.That(ids, Is.EqualTo(Ascending));
            }
        }

        [Test]
        public void SortKeepsTheGivenOrderAmongEqualIds()
        {
            var rows = new[] { ("P10", 1), ("P2", 2), ("P10", 3), ("P2", 4), ("P1", 5) };
            var sorted = ParticipantOrder.Sort(rows, r => r.Item1);
            Assert.That(sorted, Is.EqualTo(new[] { ("P1", 5), ("P2", 2), ("P2", 4), ("P10", 1), ("P10", 3) }));
        }
    }
}
