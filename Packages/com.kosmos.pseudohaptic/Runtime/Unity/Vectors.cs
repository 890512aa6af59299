using UnityEngine;

namespace Kosmos.PseudoHaptic
{
    /// <summary>Conversions at the edge between Unity's float vectors and the engine-free <see cref="Vector3d"/>.</summary>
    public static class Vectors
    {
        public static Vector3d ToDouble(this Vector3 v) => new Vector3d(v.x, v.y, v.z);

        public static Vector3 ToUnity(this Vector3d v) => new Vector3((float)v.X, (float)v.Y, (float)v.Z);
    }
}
