using System.Globalization;
using System.Text.RegularExpressions;
using Kosmos.PseudoHaptic;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tools.Tests;

/// <summary>
/// Issue 34 item 6: one Experiment 1 (<see cref="PaperExperiment1"/>) in the demo, the samples and the docs. The demo's
/// summary lists the boxes' masses as density × volume from the one definition; every document that states the boxes
/// states the same size, densities, masses and profile, and none the earlier ones (20 cm, 75/250/125 kg/m³,
/// Experiment-TwoHands).
/// </summary>
public class Experiment1ConsistencyTests
{
    static readonly string[] Documents =
    {
        "Packages/com.kosmos.pseudohaptic/Samples~/Experiment1/README.md",
        "Assets/Samples/README.md",
        "Packages/com.kosmos.pseudohaptic/Documentation~/unity.md",
    };

    static string Masses() => string.Join(", ", new[] { 0, 1 }.Select(i => PaperExperiment1.Mass(PaperExperiment1.BoxDensities[i]).ToString("0.00", CultureInfo.InvariantCulture)))
        + " and " + PaperExperiment1.Mass(PaperExperiment1.BoxDensities[2]).ToString("0.00", CultureInfo.InvariantCulture) + " kg";

    [TestCaseSource(nameof(Documents))]
    public void EveryDocumentStatesTheOneExperiment1(string document)
    {
        string text = Regex.Replace(File.ReadAllText(Path.Combine(RepositoryRoot.Path, document)), @"\s+", " ");
        string edge = (PaperExperiment1.BoxEdge * 100).ToString("0", CultureInfo.InvariantCulture) + " cm";
        Assert.That(text, Does.Contain(edge), "the boxes' size");
        foreach (double density in PaperExperiment1.BoxDensities)
            Assert.That(text, Does.Contain(density.ToString("0", CultureInfo.InvariantCulture)), "density " + density);
        Assert.That(text, Does.Contain(Masses()), "the masses, density × volume");
        Assert.That(text, Does.Contain(PaperExperiment1.ProfileName));
        Assert.That(text, Does.Not.Contain("Experiment-TwoHands").And.Not.Contain("75 kg/m³").And.Not.Contain("20 cm cube"));
    }

    [Test]
    public void TheDemoLiftsTheSameBoxes()
    {
        string dir = Path.Combine(Path.GetTempPath(), "ph-exp1-" + Guid.NewGuid().ToString("N"));
        try
        {
            var result = ToolProcess.Run(Path.GetTempPath(), TimeSpan.FromMinutes(5), "demo", "--out", dir);
            Assert.That(result.Code, Is.EqualTo(0), result.Stderr);
            var rows = result.Stdout.Split('\n').Where(l => l.StartsWith("experiment-1-boxes ", StringComparison.Ordinal) && l.Contains(" box ")).ToList();
            Assert.That(rows, Has.Count.EqualTo(3), result.Stdout);
            for (int i = 0; i < 3; i++)
            {
                var cells = Regex.Split(rows[i].Trim(), @"\s{2,}");
                Assert.That(cells[1], Is.EqualTo("box " + PaperExperiment1.BoxNames[i]));
                Assert.That(double.Parse(cells[2], CultureInfo.InvariantCulture), Is.EqualTo(PaperExperiment1.Mass(PaperExperiment1.BoxDensities[i])).Within(0.0005), rows[i]);
            }
            Assert.That(Directory.GetFiles(Path.Combine(dir, "experiment-1-boxes")).Select(Path.GetFileName), Is.SupersetOf(new[] { "box-a.csv", "box-b.csv", "box-c.csv" }));
        }
        finally { if (Directory.Exists(dir)) Directory.Delete(dir, true); }
    }
}
