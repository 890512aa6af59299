using System;
using NUnit.Framework;
using UnityEngine;

namespace Kosmos.PseudoHaptic.Tests
{
    public sealed class ColliderVolumeTests : PlayModeFixture
    {
        static double VolumeOf(Collider c)
        {
            Assert.That(ColliderVolume.TryGet(c, out double v, out string error), Is.True, error);
            return v;
        }

        [Test]
        public void BoxScalesWithTheTransform()
        {
            var go = Track(new GameObject("box"));
            var box = go.AddComponent<BoxCollider>();
            box.size = new Vector3(1, 2, 3);
            go.transform.localScale = new Vector3(0.1f, 0.1f, -0.1f);
            Assert.That(VolumeOf(box), Is.EqualTo(0.006).Within(1e-6));
        }

        [Test]
        public void SphereTakesTheLargestScale()
        {
            var go = Track(new GameObject("sphere"));
            var sphere = go.AddComponent<SphereCollider>();
            sphere.radius = 0.5f;
            go.transform.localScale = new Vector3(0.1f, 0.2f, 0.1f);
            Assert.That(VolumeOf(sphere), Is.EqualTo(4.0 / 3.0 * Math.PI * 0.001).Within(1e-7));
        }

        [Test]
        public void CapsuleIsACylinderWithTwoHalfSpheres()
        {
            var go = Track(new GameObject("capsule"));
            var capsule = go.AddComponent<CapsuleCollider>();
            capsule.radius = 0.05f;
            capsule.height = 0.3f;
            capsule.direction = 1;
            double expected = Math.PI * 0.0025 * 0.2 + 4.0 / 3.0 * Math.PI * 0.000125;
            Assert.That(VolumeOf(capsule), Is.EqualTo(expected).Within(1e-6));
        }

        [Test]
        public void AClosedMeshIsMeasuredBySignedTetrahedra()
        {
            var go = Track(GameObject.CreatePrimitive(PrimitiveType.Cube));
            UnityEngine.Object.DestroyImmediate(go.GetComponent<Collider>());
            var mesh = go.AddComponent<MeshCollider>();
            mesh.sharedMesh = go.GetComponent<MeshFilter>().sharedMesh;
            go.transform.localScale = new Vector3(0.2f, 0.1f, 0.3f);
            Assert.That(VolumeOf(mesh), Is.EqualTo(0.006).Within(1e-6));
        }

        [Test]
        public void TheTetrahedronSumOfAUnitCubeIsOne()
        {
            // Eight corners of the unit cube, twelve outward triangles.
            var v = new[]
            {
                new Vector3(0, 0, 0), new Vector3(1, 0, 0), new Vector3(1, 1, 0), new Vector3(0, 1, 0),
                new Vector3(0, 0, 1), new Vector3(1, 0, 1), new Vector3(1, 1, 1), new Vector3(0, 1, 1),
            };
            int[] t =
            {
                0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4,
                3, 7, 6, 3, 6, 2, 0, 4, 7, 0, 7, 3, 1, 2, 6, 1, 6, 5,
            };
            Assert.That(Math.Abs(ColliderVolume.Mesh(v, t)), Is.EqualTo(1.0).Within(1e-9));
        }
    }
}
