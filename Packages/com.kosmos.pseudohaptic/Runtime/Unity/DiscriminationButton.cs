using Kosmos.PseudoHaptic.Evaluation;
using UnityEngine;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// An answer button of a <see cref="DiscriminationTask"/> ("this side was heavier"): a trigger box that a
    /// <see cref="FingertipPoker"/> pokes; it reports the contact to its task, whose debounce makes one poke one
    /// answer. The task tells it its side.
    /// </summary>
    [DisallowMultipleComponent]
    [AddComponentMenu("Kosmos/Pseudo-Haptic/Discrimination Button")]
    public sealed class DiscriminationButton : FingertipTrigger
    {
        DiscriminationTask _task;

        public PairSide Side { get; private set; }

        public void Initialize(DiscriminationTask task, PairSide side)
        {
            _task = task;
            Side = side;
        }

        protected override void Touched(double now)
        {
            if (_task != null) _task.Touch(this, now);
        }

        protected override void Stayed(double now)
        {
            if (_task != null) _task.Stay(now);
        }
    }
}
