using UnityEngine;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// Where a held object is: the hold's frame (the rig as it stood at the grab, <see cref="HoldFrame"/>) to and from
    /// the world, the height in the parent's space that the solver works in, and the object's pose written through the
    /// rig as it is now, after each step and again just before rendering. Never writes NaN.
    /// </summary>
    public sealed partial class PseudoHapticWeight
    {
        HoldFrame _frame;             // the rig as it stood at the grab: the hold's frame
        Vector3 _heldPosition;        // the object's position in that frame, as last written
        Quaternion _heldRotation;     // and its rotation at the grab (in that frame it does not turn)

        /// <summary>The point the solver follows, world space (its height converted from the parent's).</summary>
        public Vector3 HandWorldPosition => _frame.Out(Hold.HandPoint.ToUnity() + (transform.parent != null ? transform.parent.position.y : 0) * Vector3.up);

        /// <summary>A world point, now, in the frame the hold is solved in (the rig as it stood at the grab; see <see cref="HoldFrame"/>).</summary>
        public Vector3 InHoldFrame(Vector3 world) => _frame.In(world);

        /// <summary>A direction of the hold's frame (an offset, a velocity) in the world, now.</summary>
        public Vector3 OutOfHoldFrame(Vector3 direction) => _frame.OutDirection(direction);

        // Just before the frame renders (after every LateUpdate): a rig moved late in the frame carries the held object
        // along in this very frame. OVR moves its anchors here too; the object's place in the rig's frame stays the step's.
        void FollowRig()
        {
            if (IsHeld && _frame.Rig != null) Place();
        }

        /// <summary>A world point's height in this object's parent space, the space its local y lives in.</summary>
        public double ParentY(Vector3 world) => transform.parent == null ? world.y : transform.parent.InverseTransformPoint(world).y;

        double IParentSpace.HeightOf(Vector3d world) => ParentY(world.ToUnity());

        /// <summary>The object at <paramref name="held"/> (the hold's frame) with its parent-space height <paramref name="localY"/> (NaN: kept), placed through the rig.</summary>
        void SetHeld(Vector3 held, double localY)
        {
            if (double.IsFinite(localY)) // NaN: nothing to write (another hand's step)
            {
                Transform parent = transform.parent;
                Vector3 local = parent != null ? parent.InverseTransformPoint(held) : held;
                local.y = (float)localY;
                held = parent != null ? parent.TransformPoint(local) : local;
            }
            if (!held.ToDouble().IsFinite) return; // never NaN on a transform
            _heldPosition = held;
            Place();
        }

        /// <summary>Writes the object's world pose: its place in the hold's frame, through the rig as it is now.</summary>
        void Place()
        {
            transform.position = _frame.Out(_heldPosition);
            if (_frame.Rig != null) transform.rotation = _frame.Turn * _heldRotation;
        }
    }
}
