using System;
using System.Collections.Generic;
using NUnit.Framework;

namespace Kosmos.PseudoHaptic.Tests
{
    /// <summary>
    /// The mesh volume behind m = ρ·V for mesh colliders (Experiment 2's bottles), and the rule that a volume stored at
    /// edit time is what a player build uses. Expected volumes come from closed-form geometry, not from the code.
    /// </summary>
    public class MeshVolumeTests
    {
        /// <summary>A closed mesh from triangles given as corner triples; each triangle is turned to face away from
        /// <paramref name="inside"/> (geometry, independent of the code under test); split vertices (no sharing).</summary>
        static (float[] xyz, int[] triangles) Closed(List<double[][]> faces, double[] inside)
        {
            var xyz = new List<float>();
            var tris = new List<int>();
            foreach (var f in faces)
            {
                double[] a = f[0], b = f[1], c = f[2];
                double[] n = Cross(Sub(b, a), Sub(c, a));
                double[] centre = { (a[0] + b[0] + c[0]) / 3 - inside[0], (a[1] + b[1] + c[1]) / 3 - inside[1], (a[2] + b[2] + c[2]) / 3 - inside[2] };
                if (n[0] * centre[0] + n[1] * centre[1] + n[2] * centre[2] < 0) (b, c) = (c, b);
                foreach (var p in new[] { a, b, c })
                {
                    tris.Add(xyz.Count / 3);
                    xyz.Add((float)p[0]); xyz.Add((float)p[1]); xyz.Add((float)p[2]);
                }
            }
            return (xyz.ToArray(), tris.ToArray());
        }

        static double[] Sub(double[] a, double[] b) => new[] { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
        static double[] Cross(double[] a, double[] b) => new[] { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };

        /// <summary>A right prism over a regular <paramref name="sides"/>-gon (Unity's cylinder is one), axis along y.</summary>
        static (float[] xyz, int[] triangles) Prism(int sides, double radius, double height, double[] offset)
        {
            var faces = new List<double[][]>();
            double[] P(double angle, double y) => new[] { offset[0] + radius * Math.Cos(angle), offset[1] + y, offset[2] + radius * Math.Sin(angle) };
            double[] bottom = { offset[0], offset[1], offset[2] }, top = { offset[0], offset[1] + height, offset[2] };
            for (int i = 0; i < sides; i++)
            {
                double t0 = 2 * Math.PI * i / sides, t1 = 2 * Math.PI * (i + 1) / sides;
                faces.Add(new[] { bottom, P(t0, 0), P(t1, 0) });
                faces.Add(new[] { top, P(t0, height), P(t1, height) });
                faces.Add(new[] { P(t0, 0), P(t1, 0), P(t1, height) });
                faces.Add(new[] { P(t0, 0), P(t1, height), P(t0, height) });
            }
            return Closed(faces, new[] { offset[0], offset[1] + height / 2, offset[2] });
        }

        [Test]
        public void AUnitCubeIsOneAndItsMirrorMinusOne()
        {
            // 8 shared corners, 12 triangles wound counter-clockwise seen from outside.
            float[] xyz = { 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1 };
            int[] t =
            {
                0, 2, 1, 0, 3, 2, // z = 0, normal -z
                4, 5, 6, 4, 6, 7, // z = 1, normal +z
                0, 1, 5, 0, 5, 4, // y = 0, normal -y
                3, 7, 6, 3, 6, 2, // y = 1, normal +y
                0, 4, 7, 0, 7, 3, // x = 0, normal -x
                1, 2, 6, 1, 6, 5, // x = 1, normal +x
            };
            Assert.That(MeshVolume.Signed(xyz, t), Is.EqualTo(1.0).Within(1e-12));
            var flipped = (int[])t.Clone();
            for (int i = 0; i < flipped.Length; i += 3) (flipped[i + 1], flipped[i + 2]) = (flipped[i + 2], flipped[i + 1]);
            Assert.That(MeshVolume.Signed(xyz, flipped), Is.EqualTo(-1.0).Within(1e-12));
            // A list that ends in an incomplete triangle (one or two stray indices) counts its whole triangles only.
            foreach (int stray in new[] { 1, 2 })
            {
                var ragged = new int[t.Length + stray];
                t.CopyTo(ragged, 0);
                Assert.That(MeshVolume.Signed(xyz, ragged), Is.EqualTo(1.0).Within(1e-12), stray + " stray indices");
            }
        }

        [Test]
        public void APrismHoldsItsPolygonTimesItsHeightWhereverItStands([Range(0, 199)] int seed)
        {
            var random = new Random(seed);
            int sides = random.Next(3, 65);
            double radius = 0.1 + random.NextDouble(), height = 0.1 + 2 * random.NextDouble();
            double[] offset = { 4 * random.NextDouble() - 2, 4 * random.NextDouble() - 2, 4 * random.NextDouble() - 2 };
            var (xyz, t) = Prism(sides, radius, height, offset);
            double polygon = sides / 2.0 * radius * radius * Math.Sin(2 * Math.PI / sides);
            // Float vertices: a relative error of about 1e-7 times the offset over the size, far below the 0.16 % by which
            // even a 64-gon falls short of its circle (a circle's formula would fail here).
            double tolerance = 1e-5 * (1 + 3 / Math.Min(radius, height));
            Assert.That(Math.Abs(MeshVolume.Signed(xyz, t)), Is.EqualTo(polygon * height).Within(tolerance * polygon * height));
        }

        [Test]
        public void UnitysCylinderIsSmallerThanTheCircleItApproximates()
        {
            // Unity's built-in cylinder: radius 0.5, height 2 (this is why the bottles correct their height).
            var (xyz, t) = Prism(20, 0.5, 2, new double[] { 0, -1, 0 });
            double circle = Math.PI * 0.25 * 2;
            Assert.That(Math.Abs(MeshVolume.Signed(xyz, t)) / circle, Is.EqualTo(20 / (2 * Math.PI) * Math.Sin(2 * Math.PI / 20)).Within(1e-6));
        }

        [Test]
        public void AnOpenMeshHasNoVolumeOfItsOwn()
        {
            // The formula needs a closed surface: without its lid a prism's "volume" depends on where the origin is.
            var (xyz, t) = Prism(12, 0.5, 1, new double[] { 0, 0, 0 });
            var kept = new List<int>();
            for (int i = 0; i < t.Length; i += 3)
                if ((i / 3) % 4 != 1) kept.AddRange(new[] { t[i], t[i + 1], t[i + 2] }); // every top face (the second of each four) dropped
            int[] open = kept.ToArray();
            double here = MeshVolume.Signed(xyz, open);
            var moved = (float[])xyz.Clone();
            for (int i = 1; i < moved.Length; i += 3) moved[i] += 10;
            Assert.That(MeshVolume.Signed(moved, open), Is.Not.EqualTo(here).Within(1e-3));
        }

        [Test]
        public void NothingToMeasureIsZero()
        {
            Assert.That(MeshVolume.Signed(null, new[] { 0, 1, 2 }), Is.EqualTo(0));
            Assert.That(MeshVolume.Signed(new float[9], null), Is.EqualTo(0));
        }

        [TestCase(true, 0.002, false, MeshVolumeSource.Stored)]            // player build: stripped mesh, stored volume
        [TestCase(true, 0.002, true, MeshVolumeSource.Stored)]             // stored wins even when readable: no read at run time
        [TestCase(false, 0.002, true, MeshVolumeSource.ReadMesh)]          // stored for another mesh: stale
        [TestCase(false, 0.002, false, MeshVolumeSource.Unavailable)]
        [TestCase(true, 0.0, true, MeshVolumeSource.ReadMesh)]             // nothing stored
        [TestCase(true, 0.0, false, MeshVolumeSource.Unavailable)]
        [TestCase(true, -0.002, false, MeshVolumeSource.Unavailable)]
        [TestCase(true, double.NaN, true, MeshVolumeSource.ReadMesh)]
        [TestCase(true, double.PositiveInfinity, false, MeshVolumeSource.Unavailable)]
        public void AStoredVolumeIsUsedOnlyForItsOwnMesh(bool storedForThisMesh, double stored, bool readable, MeshVolumeSource expected)
        {
            Assert.That(MeshVolume.Choose(storedForThisMesh, stored, readable), Is.EqualTo(expected));
        }
    }
}
