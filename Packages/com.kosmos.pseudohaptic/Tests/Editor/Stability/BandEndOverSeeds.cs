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
        /// a profile, how the weight without a band is replayed (on the same poses if null), and a line that names the scene.</summary>
        internal struct Scene
        {
            public TraceFrame[] Frames;
            public double End;
            public Func<WeightProfile, double[]> Replay;
            public Func<WeightProfile, double[]> Reference;
            /// <summary>Whether the difference counts only what the band adds beyond the error the poses give the weight
            /// without a band (that weight on the scene's own poses, against <see cref="Reference"/>): for a lift that starts
            /// before the band has seen where the hand rests, which no weight can measure from anywhere but the poses seen.</summary>
            public bool BeyondPosesOwnError;
            public string Description;
        }

        /// <summary>The same headset without its jitter: the same frames, latency, glitches and low-confidence poses, each pose
        /// where the hand really was. The weight without a band replayed on these is measured from where the hand rested at
        /// the grab, not from the grab's own jittered pose (which would put G times that pose's jitter into the reference).</summary>
        internal static TraceFrame[] WithoutJitter(HeadsetSimulator headset, HandPath path)
        {
            double jitter = headset.JitterSd;
            headset.JitterSd = 0;
            var frames = headset.Render(path);
            headset.JitterSd = jitter;
            return frames;
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
                var b = (scene.Reference ?? scene.Replay)(noBand);
                double d = EndOf(scene, a) - EndOf(scene, b);
                if (scene.BeyondPosesOwnError)
                {
                    double own = EndOf(scene, scene.Replay(noBand)) - EndOf(scene, b);
                    d = Math.Sign(d) * Math.Max(0, Math.Abs(d) - Math.Abs(own));
                }
                if (Math.Abs(d) > Math.Abs(worst)) { worst = d; worstCase = $"seed {seed}: {scene.Description}"; }
            }
            return worst;
        }

        /// <summary>The median height over the second before and the second after the path's end.</summary>
        static double EndOf(Scene scene, double[] y) => QuestLikeInput.MedianOver(scene.Frames, i => y[i], scene.End - 1, scene.End + 1);
    }
}
