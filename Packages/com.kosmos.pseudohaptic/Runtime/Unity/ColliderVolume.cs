using System;
using UnityEngine;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// The volume V of a collider in world units (m³), for m = ρ·V (Son et al. 2022, §3.1). Box, sphere and
    /// capsule scale as PhysX scales them; a mesh's volume is the sum of the signed tetrahedra its triangles
    /// span with the origin (divergence theorem), so it needs a closed mesh that is readable at run time.
    /// Called when an object is configured, never per frame: reading a mesh allocates.
    /// </summary>
    public static class ColliderVolume
    {
        /// <summary>The collider's volume in m³, or false with the reason it cannot be had.</summary>
        public static bool TryGet(Collider collider, out double volume, out string error)
        {
            volume = 0;
            error = null;
            if (collider == null) { error = "no collider to take the volume from"; return false; }
            Vector3 s = collider.transform.lossyScale;
            double sx = Math.Abs(s.x), sy = Math.Abs(s.y), sz = Math.Abs(s.z);

            if (collider is BoxCollider box)
            {
                Vector3 size = box.size;
                volume = Math.Abs((double)size.x * size.y * size.z) * sx * sy * sz;
            }
            else if (collider is SphereCollider sphere)
            {
                double r = Math.Abs(sphere.radius) * Math.Max(sx, Math.Max(sy, sz));
                volume = Sphere(r);
            }
            else if (collider is CapsuleCollider capsule)
            {
                // direction: 0 = x, 1 = y, 2 = z. The radius scales with the larger of the other two axes.
                double axis = capsule.direction == 0 ? sx : capsule.direction == 1 ? sy : sz;
                double across = capsule.direction == 0 ? Math.Max(sy, sz) : capsule.direction == 1 ? Math.Max(sx, sz) : Math.Max(sx, sy);
                volume = Capsule(Math.Abs(capsule.radius) * across, Math.Abs(capsule.height) * axis);
            }
            else if (collider is MeshCollider meshCollider)
            {
                Mesh mesh = meshCollider.sharedMesh;
                if (mesh == null) { error = "the MeshCollider has no mesh"; return false; }
                if (!mesh.isReadable) { error = "mesh '" + mesh.name + "' is not readable: enable Read/Write in its import settings"; return false; }
                volume = Math.Abs(Mesh(mesh.vertices, mesh.triangles)) * sx * sy * sz;
            }
            else
            {
                error = "a " + collider.GetType().Name + " has no volume formula: use a Box, Sphere, Capsule or Mesh collider, or give the mass";
                return false;
            }

            if (!(volume > 0) || double.IsInfinity(volume))
            {
                error = "the collider's volume is " + volume.ToString("R", System.Globalization.CultureInfo.InvariantCulture) + " m³: it must be finite and greater than 0";
                return false;
            }
            return true;
        }

        public static double Sphere(double radius) => 4.0 / 3.0 * Math.PI * radius * radius * radius;

        /// <summary>A capsule of total height <paramref name="height"/> (caps included); shorter than 2r it is a sphere, as in PhysX.</summary>
        public static double Capsule(double radius, double height)
        {
            double cylinder = Math.Max(0, height - 2 * radius);
            return Math.PI * radius * radius * cylinder + Sphere(radius);
        }

        /// <summary>
        /// The signed volume enclosed by a closed triangle mesh: Σ v0·(v1×v2)/6 over its triangles, in mesh
        /// units. Its sign follows the winding; callers take the magnitude. Shared or split vertices (seams)
        /// do not matter, only that the surface is closed.
        /// </summary>
        public static double Mesh(Vector3[] vertices, int[] triangles)
        {
            if (vertices == null || triangles == null) return 0;
            double sum = 0;
            for (int i = 0; i + 2 < triangles.Length; i += 3)
            {
                Vector3 a = vertices[triangles[i]], b = vertices[triangles[i + 1]], c = vertices[triangles[i + 2]];
                // a · (b × c), in double.
                double cx = (double)b.y * c.z - (double)b.z * c.y;
                double cy = (double)b.z * c.x - (double)b.x * c.z;
                double cz = (double)b.x * c.y - (double)b.y * c.x;
                sum += a.x * cx + a.y * cy + a.z * cz;
            }
            return sum / 6.0;
        }
    }
}
