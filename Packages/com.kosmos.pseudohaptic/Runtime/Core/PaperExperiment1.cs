namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// The paper's Experiment 1 (Son et al. 2022, §6, Fig. 7), one definition for the demo, the samples and the docs: three
    /// wooden boxes A, B, C ("rectangular parallels … of the same size" with "different densities", B "set as the heaviest"),
    /// lifted with both hands, without the offset correction ("no correction was made according to the … distance"): the
    /// <see cref="NamedProfiles.PaperExperiment"/> profile. The paper gives neither the size nor the densities; these are
    /// wood-like (A 300 kg/m³ as a light softwood, C 500 as pine, B 800 as oak) on 15 cm cubes, so the boxes weigh about
    /// 1.0, 2.7 and 1.7 kg and lie within the one-handed 5 kg the paper's speed experiment allows. Mass = density × volume.
    /// </summary>
    public static class PaperExperiment1
    {
        /// <summary>The boxes' edge, m (cubes).</summary>
        public const double BoxEdge = 0.15;

        /// <summary>Densities of boxes A, B and C, kg/m³: B heaviest.</summary>
        public const double BoxADensity = 300, BoxBDensity = 800, BoxCDensity = 500;

        /// <summary>The profile the experiment ran with.</summary>
        public const string ProfileName = NamedProfiles.PaperExperimentName;

        /// <summary>The boxes' names, in the scene's order A, B, C.</summary>
        public static readonly string[] BoxNames = { "A", "B", "C" };

        /// <summary>Their densities, kg/m³, in the same order.</summary>
        public static readonly double[] BoxDensities = { BoxADensity, BoxBDensity, BoxCDensity };

        /// <summary>A box's volume, m³.</summary>
        public const double BoxVolume = BoxEdge * BoxEdge * BoxEdge;

        /// <summary>The mass of a box of <paramref name="density"/> kg/m³, kg.</summary>
        public static double Mass(double density) => density * BoxVolume;
    }
}
