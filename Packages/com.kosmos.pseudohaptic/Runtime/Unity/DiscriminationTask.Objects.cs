using Kosmos.PseudoHaptic.Evaluation;
using UnityEngine;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// The task's two objects (the serialized <c>_left</c> and <c>_right</c>): whether they can carry the trials'
    /// masses, which one a lift was of, whether one is held, and each trial's masses put on them, back where they
    /// stood when the task woke.
    /// </summary>
    public sealed partial class DiscriminationTask
    {
        Vector3 _leftHome, _rightHome;

        /// <summary>Why the two objects cannot carry the trials' masses (one missing, or one whose mass does not come from Explicit Mass Kg), or null.</summary>
        public string ObjectsError => _left == null || _right == null ? "the left and right objects are not set"
            : WeightSettings.ExplicitMassError("left", _left.Mass) ?? WeightSettings.ExplicitMassError("right", _right.Mass);

        /// <summary>Whether a participant holds either object (no answer is taken then).</summary>
        bool AnyHeld => (_left != null && _left.IsHeld) || (_right != null && _right.IsHeld);

        /// <summary>Where the objects stand now (at Awake): each trial puts them back there.</summary>
        void RememberHomes()
        {
            if (_left != null) _leftHome = _left.transform.position;
            if (_right != null) _rightHome = _right.transform.position;
        }

        void OnHoldBegan(PseudoHapticWeight weight)
        {
            if (Model.NoteLift(weight == _left, weight == _right)) Show();
        }

        /// <summary>The current trial's masses on the objects, which go back to where they started.</summary>
        bool Applied()
        {
            if (!Model.HasTrial) return true;
            Place(_left, _leftHome, (float)Session.MassAt(PairSide.Left));
            Place(_right, _rightHome, (float)Session.MassAt(PairSide.Right));
            return true;
        }

        static void Place(PseudoHapticWeight weight, Vector3 home, float massKg)
        {
            weight.ExplicitMassKg = massKg;
            weight.transform.position = home;
            var body = weight.GetComponent<Rigidbody>();
            if (body != null && !body.isKinematic) body.velocity = body.angularVelocity = Vector3.zero;
        }
    }
}
