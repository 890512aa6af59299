using System;
using System.Globalization;
using System.IO;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// The file or folder of an id (a user's calibration, a recording session) that no other id shares. A name made safe
    /// for the file system can be one for two ids ("P 1" and "P_1" both become "P_1"; "P1" and "p1" are one name where the
    /// file system ignores case, as a Quest's shared storage does), so each such file or folder records its owner, and an
    /// id whose name another id owns goes on to "-2", "-3", …: the first candidate that is its own or free is its own.
    /// The first candidate recording no owner (written before owners were recorded, or unreadable) is taken as the id's own,
    /// so nothing that was found before moves; a later one recording none is another's (no earlier version wrote "-k"
    /// names: it is an id of that name's own). Candidates are tried up to the first free one: one removed by hand hides
    /// those after it from their ids (found again when it is back), and the next of its name takes its place; nothing
    /// another id owns is ever given.
    /// </summary>
    public static class OwnedName
    {
        /// <summary>How many candidates are tried before giving up (an IOException).</summary>
        public const int MaxCandidates = 1000;

        /// <summary>
        /// The path of <paramref name="id"/>'s file or folder: <paramref name="stem"/> + <paramref name="extension"/>, or
        /// <paramref name="stem"/> + "-k" + <paramref name="extension"/> for the first k from 2 whose candidate is free or
        /// records <paramref name="id"/> (ordinal); the first candidate also when it records no owner.
        /// </summary>
        /// <param name="exists">Whether a candidate exists (File.Exists or Directory.Exists).</param>
        /// <param name="ownerOf">The owner an existing candidate records, or null when it records none.</param>
        public static string Find(string stem, string extension, string id, Func<string, bool> exists, Func<string, string> ownerOf)
        {
            if (stem == null) throw new ArgumentNullException(nameof(stem));
            if (exists == null) throw new ArgumentNullException(nameof(exists));
            if (ownerOf == null) throw new ArgumentNullException(nameof(ownerOf));
            extension = extension ?? "";
            for (int k = 1; k <= MaxCandidates; k++)
            {
                string path = k == 1 ? stem + extension : stem + "-" + k.ToString(CultureInfo.InvariantCulture) + extension;
                if (!exists(path)) return path;
                string owner = ownerOf(path);
                if ((owner == null && k == 1) || string.Equals(owner, id, StringComparison.Ordinal)) return path;
            }
            throw new IOException("no free name for '" + id + "' among " + MaxCandidates + " candidates from " + stem + extension);
        }
    }
}
