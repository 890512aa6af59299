using System;
using UnityEngine;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// The volume V of a collider in world units (m³), for m = ρ·V (Son et al. 2022, §3.1). Box, sphere and
    /// capsule scale as PhysX scales them; a mesh's volume is the sum of the signed tetrahedra its triangles
    /// span with the origin (divergence theorem, <see cref="MeshVolume"/>), so it needs a closed mesh. A player build
    /// strips meshes that are not marked Read/Write, so the volume is computed in the editor and stored with the
    /// weight (<see cref="PseudoHapticWeight.StoreMeshVolume"/>); a readable mesh is read only when nothing was stored
    /// for it. Called when an object is configured, never per frame: reading a mesh allocates.
    /// </summary>
    public static class ColliderVolume
    {
        /// <summary>The collider's volume in m³, or false with the reason it cannot be had.</summary>
        public static bool TryGet(Collider collider, out double volume, out string error) =>
            TryGet(collider, null, 0, out volume, out error);

        /// <summary>
        /// The collider's volume in m³; for a mesh collider, <paramref name="storedMeshVolume"/> (mesh units³, stored
        /// at edit time for <paramref name="storedFor"/>) when it was stored for this very mesh, else the mesh read.
        /// </summary>
        public static bool TryGet(Collider collider, Mesh storedFor, double storedMeshVolume, out double volume, out string error)
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
                switch (MeshVolume.Choose(storedFor != null && storedFor == mesh, storedMeshVolume, mesh.isReadable))
                {
                    case MeshVolumeSource.Stored:
                        volume = storedMeshVolume * sx * sy * sz;
                        break;
                    case MeshVolumeSource.ReadMesh:
                        volume = Math.Abs(Mesh(mesh.vertices, mesh.triangles)) * sx * sy * sz;
                        break;
                    default:
                        error = "mesh '" + mesh.name + "' is not readable and no volume was stored for it: select the object in the editor (the weight stores its volume) or enable Read/Write in the mesh's import settings";
                        return false;
                }
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

        /// <summary>
        /// The closed, readable mesh of a <see cref="MeshCollider"/> and its volume (mesh units³), for storing at edit time;
        /// false (mesh null, volume 0) for any other collider or a mesh that cannot be read. Allocates.
        /// </summary>
        public static bool TryReadMesh(Collider collider, out Mesh mesh, out double volume)
        {
            mesh = collider is MeshCollider meshCollider && meshCollider.sharedMesh != null && meshCollider.sharedMesh.isReadable ? meshCollider.sharedMesh : null;
            volume = mesh != null ? Math.Abs(Mesh(mesh.vertices, mesh.triangles)) : 0;
            if (volume > 0 && !double.IsInfinity(volume)) return true;
            mesh = null;
            volume = 0;
            return false;
        }

        public static double Sphere(double radius) => 4.0 / 3.0 * Math.PI * radius * radius * radius;

        /// <summary>A capsule of total height <paramref name="height"/> (caps included); shorter than 2r it is a sphere, as in PhysX.</summary>
        public static double Capsule(double radius, double height)
        {
            double cylinder = Math.Max(0, height - 2 * radius);
            return Math.PI * radius * radius * cylinder + Sphere(radius);
        }

        /// <summary>
        /// The signed volume enclosed by a closed triangle mesh (<see cref="MeshVolume.Signed"/>), in mesh units. Its
        /// sign follows the winding; callers take the magnitude. Allocates a copy of the vertices.
        /// </summary>
        public static double Mesh(Vector3[] vertices, int[] triangles)
        {
            if (vertices == null || triangles == null) return 0;
            var xyz = new float[3 * vertices.Length];
            for (int i = 0; i < vertices.Length; i++)
            {
                xyz[3 * i] = vertices[i].x;
                xyz[3 * i + 1] = vertices[i].y;
                xyz[3 * i + 2] = vertices[i].z;
            }
            return MeshVolume.Signed(xyz, triangles);
        }
    }
}
