namespace Kosmos.PseudoHaptic
{
    /// <summary>Where in the one-way per-frame flow an effect acts. A profile runs its effects in this order.</summary>
    public enum EffectStage
    {
        /// <summary>Before the estimator: decides whether this frame's pose may be followed.</summary>
        Input = 0,
        /// <summary>On the hand's displacement, before the gain.</summary>
        HandMotion = 1,
        /// <summary>Folded into the gain G at configuration: costs nothing per frame.</summary>
        Gain = 2,
        /// <summary>On the object's proposed displacement.</summary>
        ObjectMotion = 3,
        /// <summary>On the object's new height, after the speed limit.</summary>
        Position = 4,
        /// <summary>Acts in <see cref="WeightSolver3D"/>, outside the y pipeline (x/z, the second hand, break-away):
        /// the y solver never calls it.</summary>
        Hold = 5,
    }
}
