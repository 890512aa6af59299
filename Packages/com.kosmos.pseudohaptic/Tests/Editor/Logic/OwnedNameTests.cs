using System.Collections.Generic;
using System.IO;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>The name of an id's file or folder that no other id shares (<see cref="OwnedName"/>).</summary>
    public sealed class OwnedNameTests
    {
        /// <summary>Candidates that exist, with the owner each records (null: none).</summary>
        static string Find(string id, Dictionary<string, string> existing) =>
            OwnedName.Find("d/user-P_1", ".json", id, existing.ContainsKey, p => existing[p]);

        [Test]
        public void TheFirstCandidateThatIsFreeOrTheIdsOwnIsTaken()
        {
            var none = new Dictionary<string, string>();
            Assert.That(Find("P 1", none), Is.EqualTo("d/user-P_1.json"), "free");

            var taken = new Dictionary<string, string> { ["d/user-P_1.json"] = "P_1" };
            Assert.That(Find("P_1", taken), Is.EqualTo("d/user-P_1.json"), "its own");
            Assert.That(Find("P 1", taken), Is.EqualTo("d/user-P_1-2.json"), "another's: the next");
            Assert.That(Find("p_1", taken), Is.EqualTo("d/user-P_1-2.json"), "ids differ in case (ordinal)");

            taken["d/user-P_1-2.json"] = "P 1";
            taken["d/user-P_1-3.json"] = "P.1";
            Assert.That(Find("P 1", taken), Is.EqualTo("d/user-P_1-2.json"));
            Assert.That(Find("P.1", taken), Is.EqualTo("d/user-P_1-3.json"));
            Assert.That(Find("P/1", taken), Is.EqualTo("d/user-P_1-4.json"));
        }

        [Test]
        public void ACandidateThatRecordsNoOwnerIsTheFirstIdsThatFindsIt()
        {
            // Written before owners were recorded, or unreadable: what was found before is still found.
            var legacy = new Dictionary<string, string> { ["d/user-P_1.json"] = null, ["d/user-P_1-2.json"] = "P_1" };
            Assert.That(Find("P 1", legacy), Is.EqualTo("d/user-P_1.json"));
            Assert.That(Find("P_1", legacy), Is.EqualTo("d/user-P_1.json"), "the first candidate it finds, before its own");

            // A later candidate recording no owner is an id of that very name's (no earlier version wrote "-k" names): the
            // id "P_1-2"'s folder from before is not given to "P 1".
            var named = new Dictionary<string, string> { ["d/user-P_1.json"] = "P_1", ["d/user-P_1-2.json"] = null };
            Assert.That(Find("P 1", named), Is.EqualTo("d/user-P_1-3.json"));
        }

        [Test]
        public void EveryCandidateTakenIsAnIOErrorNamingTheId()
        {
            var full = new Dictionary<string, string> { ["d/user-P_1.json"] = "x" };
            for (int k = 2; k <= OwnedName.MaxCandidates; k++) full["d/user-P_1-" + k + ".json"] = "x";
            var e = Assert.Throws<IOException>(() => Find("P 1", full));
            Assert.That(e.Message, Is.EqualTo("no free name for 'P 1' among " + OwnedName.MaxCandidates + " candidates from d/user-P_1.json"));
            full.Remove("d/user-P_1-" + OwnedName.MaxCandidates + ".json");
            Assert.That(Find("P 1", full), Is.EqualTo("d/user-P_1-" + OwnedName.MaxCandidates + ".json"), "the last candidate is tried");
        }
    }
}
