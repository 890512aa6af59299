using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>The paper's Experiment 1 as the package defines it once (issue 34): what the paper says of it holds.</summary>
    public class PaperExperiment1Tests
    {
        [Test]
        public void TheBoxesAreOneSizeAndBIsTheHeaviest()
        {
            Assert.That(PaperExperiment1.BoxNames, Is.EqualTo(new[] { "A", "B", "C" }));
            Assert.That(PaperExperiment1.BoxDensities, Has.Length.EqualTo(3));
            double a = PaperExperiment1.Mass(PaperExperiment1.BoxADensity), b = PaperExperiment1.Mass(PaperExperiment1.BoxBDensity), c = PaperExperiment1.Mass(PaperExperiment1.BoxCDensity);
            Assert.That(b, Is.GreaterThan(a).And.GreaterThan(c), "B was set as the heaviest");
            Assert.That(PaperExperiment1.BoxVolume, Is.EqualTo(PaperExperiment1.BoxEdge * PaperExperiment1.BoxEdge * PaperExperiment1.BoxEdge));
            // Mass is density × volume: doubling the density doubles the mass, and the ratio of two boxes is that of their densities.
            Assert.That(PaperExperiment1.Mass(2 * PaperExperiment1.BoxADensity), Is.EqualTo(2 * a).Within(1e-12));
            Assert.That(b / a, Is.EqualTo(PaperExperiment1.BoxBDensity / PaperExperiment1.BoxADensity).Within(1e-12));
            Assert.That(b, Is.LessThanOrEqualTo(5.0), "within the paper's one-handed 5 kg");
        }

        [Test]
        public void TheProfileIsTheExperimentsNoCorrectionBothHands()
        {
            WeightProfile profile = NamedProfiles.Get(PaperExperiment1.ProfileName);
            Assert.That(profile.Find<OffsetCorrection>(), Is.Null, "no correction was made according to the distance");
            Assert.That(profile.Find<TwoHands>(), Is.Not.Null, "lifted with both hands");
            Assert.That(profile.Find<WeightGain>(), Is.Not.Null);
        }
    }
}
