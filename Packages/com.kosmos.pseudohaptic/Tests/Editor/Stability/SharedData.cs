using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests.Stability
{
    /// <summary>
    /// The project's shared data (../shared/data beside the repository): present in this project's CI and
    /// development machines, absent in a user's Unity project. Tests that need it call <see cref="RequireFile"/>,
    /// which reports the test as ignored, with the reason, where the folder is absent.
    /// </summary>
    internal static class SharedData
    {
        public static string RequireFile(string name)
        {
            foreach (var start in new[] { TestContext.CurrentContext.TestDirectory, Environment.CurrentDirectory })
                for (var dir = new DirectoryInfo(start); dir != null; dir = dir.Parent)
                {
                    string candidate = Path.Combine(dir.FullName, "shared", "data", name);
                    if (File.Exists(candidate)) return candidate;
                }
            SharedFolder.Missing("../shared/data/" + name + " is absent (it lives beside the package's repository, not in a user's project)");
            return null;
        }

        /// <summary>Reads the t and hand_y columns of a CSV with a header.</summary>
        public static (double[] t, double[] y) ReadHand(string path)
        {
            var lines = File.ReadAllLines(path);
            var header = lines[0].Split(',');
            int ti = Array.IndexOf(header, "t"), yi = Array.IndexOf(header, "hand_y");
            var t = new List<double>();
            var y = new List<double>();
            for (int i = 1; i < lines.Length; i++)
            {
                if (lines[i].Trim().Length == 0) continue;
                var f = lines[i].Split(',');
                t.Add(double.Parse(f[ti], CultureInfo.InvariantCulture));
                y.Add(double.Parse(f[yi], CultureInfo.InvariantCulture));
            }
            return (t.ToArray(), y.ToArray());
        }
    }
}
