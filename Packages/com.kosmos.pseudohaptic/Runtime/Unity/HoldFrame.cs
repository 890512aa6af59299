using UnityEngine;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// The frame a hold is solved in (issue 26): the tracking space (the rig) as it stood when the hold began. Hands are
    /// tracked in the rig; walking, turning, teleporting or riding a platform moves the rig, not the hand. A world point
    /// goes into this frame through the rig as it is now and out of the rig as it was at the grab, so the solver sees only
    /// what the hand did in the rig; its answer comes back through the rig as it is now, so the rig's motion carries the
    /// object rigidly. With no rig (null), or a rig that has not moved, the frame is the world. The rig's scale is ignored
    /// (tracking spaces are not scaled).
    /// </summary>
    public struct HoldFrame
    {
        Transform _rig;
        Vector3 _grabPosition;
        Quaternion _grabRotation;

        /// <summary>The frame of <paramref name="rig"/> as it stands now (null: the world).</summary>
        public static HoldFrame At(Transform rig) => rig == null ? default
            : new HoldFrame { _rig = rig, _grabPosition = rig.position, _grabRotation = rig.rotation };

        public Transform Rig => _rig;

        /// <summary>The rig's rotation since the grab (identity without a rig).</summary>
        public Quaternion Turn => _rig == null ? Quaternion.identity : _rig.rotation * Quaternion.Inverse(_grabRotation);

        /// <summary>A world point, now, in the hold's frame.</summary>
        public Vector3 In(Vector3 world) => _rig == null ? world
            : _grabPosition + _grabRotation * (Quaternion.Inverse(_rig.rotation) * (world - _rig.position));

        /// <summary>A point of the hold's frame in the world, now.</summary>
        public Vector3 Out(Vector3 held) => _rig == null ? held
            : _rig.position + _rig.rotation * (Quaternion.Inverse(_grabRotation) * (held - _grabPosition));

        /// <summary>A direction of the hold's frame (a velocity, an offset) in the world, now.</summary>
        public Vector3 OutDirection(Vector3 held) => _rig == null ? held : Turn * held;
    }
}
