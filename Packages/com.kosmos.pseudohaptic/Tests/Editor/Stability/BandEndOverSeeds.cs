using System;
using Kosmos.PseudoHaptic.Simulation;

namespace Kosmos.PseudoHaptic.Tests.Stability
{
    /// <summary>
    /// Where a light object ends with the motion deadband (<see cref="MotionDeadband"/>) against where the weight without a
    /// band puts it, over 200 seeded Quest-like scenes: the median height over the second before and the second after the
    /// path's end, with the profile and with the profile less its band, on the same poses. What a light object's tests
    /// ask of the band: it absorbs jitter at rest and leaves where a motion ends to the weight.
    /// </summary>
    internal static class BandEndOverSeeds
    {
        /// <summary>The light masses the Quest-like scenes draw from (by the seed), kg: gains from about 1.1 to the cap.</summary>
        internal static readonly double[] Masses = { 0.001, 0.005, 0.01, 0.02 };

        /// <summary>One seed's scene: the poses a headset rendered, the path's end (s), how the object is replayed on them under
        /// a profile, and a line that names the scene.</summary>
        internal struct Scene
        {
            public TraceFrame[] Frames;
            public double End;
            public Func<WeightProfile, double[]> Replay;
            public string Description;
        }

        /// <summary>The signed difference (m) of largest size over seeds 1–200, and the scene it came from. <paramref name="draw"/>
        /// builds seed's scene from a generator seeded with it and the mass the seed picks.</summary>
        internal static double Worst(string profile, Func<int, Random, double, Scene> draw, out string worstCase)
        {
            var withBand = NamedProfiles.Get(profile);
            var noBand = withBand.Without<MotionDeadband>(profile + "-without-band");
            double worst = 0;
            worstCase = "";
            for (int seed = 1; seed <= 200; seed++)
            {
                var scene = draw(seed, new Random(seed), Masses[seed % Masses.Length]);
                var a = scene.Replay(withBand);
                var b = scene.Replay(noBand);
                double d = QuestLikeInput.MedianOver(scene.Frames, i => a[i], scene.End - 1, scene.End + 1)
                           - QuestLikeInput.MedianOver(scene.Frames, i => b[i], scene.End - 1, scene.End + 1);
                if (Math.Abs(d) > Math.Abs(worst)) { worst = d; worstCase = $"seed {seed}: {scene.Description}"; }
            }
            return worst;
        }
    }
}
