using UnityEngine;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// A held object's Rigidbody during a hold it controls (paper 3.3): kinematic without interpolation (which would
    /// overwrite the written transform) and without its falling velocity; its state back and the release velocity at
    /// the end. A null body (none, or controlled by the grab system) does nothing.
    /// </summary>
    public struct HeldBody
    {
        readonly Rigidbody _body;
        bool _wasKinematic;
        RigidbodyInterpolation _wasInterpolation;

        public HeldBody(Rigidbody body)
        {
            _body = body;
            _wasKinematic = false;
            _wasInterpolation = RigidbodyInterpolation.None;
        }

        public void Take()
        {
            if (_body == null) return;
            _wasKinematic = _body.isKinematic;
            _wasInterpolation = _body.interpolation;
            if (!_wasKinematic) _body.velocity = _body.angularVelocity = Vector3.zero;
            _body.isKinematic = true;
            _body.interpolation = RigidbodyInterpolation.None;
        }

        public void Restore(Vector3 releaseVelocity)
        {
            if (_body == null) return;
            _body.isKinematic = _wasKinematic;
            _body.interpolation = _wasInterpolation;
            if (_wasKinematic) return;
            _body.velocity = releaseVelocity;
            _body.angularVelocity = Vector3.zero;
        }
    }
}
