using System;

namespace Kosmos.PseudoHaptic.Evaluation
{
    /// <summary>
    /// A small random generator that gives the same numbers on every runtime (Unity's Mono and IL2CPP, .NET),
    /// unlike <see cref="System.Random"/>, whose seeded sequence is an implementation detail: xoshiro256**
    /// (Blackman and Vigna 2018) seeded through SplitMix64. Plans, bootstraps and simulated observers are
    /// reproducible from their seed with it.
    /// </summary>
    public sealed class SeededRandom
    {
        ulong s0, s1, s2, s3;

        public SeededRandom(long seed)
        {
            ulong x = unchecked((ulong)seed);
            s0 = SplitMix(ref x);
            s1 = SplitMix(ref x);
            s2 = SplitMix(ref x);
            s3 = SplitMix(ref x);
        }

        static ulong SplitMix(ref ulong x)
        {
            unchecked
            {
                ulong z = x += 0x9E3779B97F4A7C15UL;
                z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9UL;
                z = (z ^ (z >> 27)) * 0x94D049BB133111EBUL;
                return z ^ (z >> 31);
            }
        }

        static ulong Rotl(ulong x, int k) => (x << k) | (x >> (64 - k));

        public ulong NextUInt64()
        {
            unchecked
            {
                ulong result = Rotl(s1 * 5, 7) * 9;
                ulong t = s1 << 17;
                s2 ^= s0;
                s3 ^= s1;
                s1 ^= s2;
                s0 ^= s3;
                s2 ^= t;
                s3 = Rotl(s3, 45);
                return result;
            }
        }

        /// <summary>Uniform in [0, 1), 53 random bits.</summary>
        public double NextDouble() => (NextUInt64() >> 11) * (1.0 / 9007199254740992.0);

        /// <summary>Uniform integer in [0, <paramref name="n"/>), without modulo bias.</summary>
        public int NextInt(int n)
        {
            if (n <= 0) throw new ArgumentOutOfRangeException(nameof(n), n, "must be positive");
            ulong bound = (ulong)n;
            ulong limit = ulong.MaxValue - ulong.MaxValue % bound;
            ulong r;
            do r = NextUInt64(); while (r >= limit);
            return (int)(r % bound);
        }

        /// <summary>A standard normal variate (Box–Muller, the cosine half).</summary>
        public double NextGaussian()
        {
            double u1 = 1.0 - NextDouble(); // (0, 1]
            double u2 = NextDouble();
            return Math.Sqrt(-2 * Math.Log(u1)) * Math.Cos(2 * Math.PI * u2);
        }

        /// <summary>Number of successes in <paramref name="n"/> Bernoulli trials of probability <paramref name="p"/>.</summary>
        public int NextBinomial(int n, double p)
        {
            int k = 0;
            for (int i = 0; i < n; i++) if (NextDouble() < p) k++;
            return k;
        }

        /// <summary>Fisher–Yates shuffle in place.</summary>
        public void Shuffle<T>(T[] items)
        {
            for (int i = items.Length - 1; i > 0; i--)
            {
                int j = NextInt(i + 1);
                T t = items[i];
                items[i] = items[j];
                items[j] = t;
            }
        }
    }
}
