using System;

namespace Kosmos.PseudoHaptic
{
    /// <summary>Where a mesh collider's volume comes from when a weight is configured.</summary>
    public enum MeshVolumeSource
    {
        /// <summary>The volume stored with the component in the editor, for this very mesh: no mesh is read.</summary>
        Stored,
        /// <summary>Read from the mesh's vertices and triangles (the mesh is readable).</summary>
        ReadMesh,
        /// <summary>Neither: the mesh is not readable (a player build strips it) and nothing was stored for it.</summary>
        Unavailable,
    }

    /// <summary>
    /// The volume of a closed triangle mesh (divergence theorem: the sum of the signed tetrahedra its triangles span
    /// with the origin), and the rule that lets a player build use a volume computed at edit time. Engine-free;
    /// configuration-time work, never per frame.
    /// </summary>
    public static class MeshVolume
    {
        /// <summary>
        /// The signed volume enclosed by a closed triangle mesh: Σ v0·(v1×v2)/6 over its triangles, in mesh units.
        /// <paramref name="xyz"/> holds the vertices as x0, y0, z0, x1, …; <paramref name="triangles"/> three vertex
        /// indices per triangle. Its sign follows the winding (outward counter-clockwise is positive); callers take
        /// the magnitude. Shared or split vertices (seams) do not matter, only that the surface is closed.
        /// </summary>
        public static double Signed(float[] xyz, int[] triangles)
        {
            if (xyz == null || triangles == null) return 0;
            double sum = 0;
            for (int i = 0; i + 2 < triangles.Length; i += 3)
            {
                int a = 3 * triangles[i], b = 3 * triangles[i + 1], c = 3 * triangles[i + 2];
                double bx = xyz[b], by = xyz[b + 1], bz = xyz[b + 2];
                double cx = xyz[c], cy = xyz[c + 1], cz = xyz[c + 2];
                sum += xyz[a] * (by * cz - bz * cy) + xyz[a + 1] * (bz * cx - bx * cz) + xyz[a + 2] * (bx * cy - by * cx);
            }
            return sum / 6.0;
        }

        /// <summary>
        /// A volume stored for this very mesh (finite, &gt; 0) wins, so a player build reads no mesh; else a readable
        /// mesh is read; else there is none.
        /// </summary>
        public static MeshVolumeSource Choose(bool storedForThisMesh, double storedVolume, bool meshReadable)
        {
            if (storedForThisMesh && storedVolume > 0 && !double.IsInfinity(storedVolume)) return MeshVolumeSource.Stored;
            return meshReadable ? MeshVolumeSource.ReadMesh : MeshVolumeSource.Unavailable;
        }
    }
}
