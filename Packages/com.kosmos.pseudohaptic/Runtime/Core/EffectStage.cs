namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// Where in the one-way per-frame flow an effect acts. A profile runs its effects in this order:
    /// pose → <see cref="Input"/> → estimator → <see cref="HandMotion"/> → <see cref="Base"/> → <see cref="Lift"/>
    /// → the weight's offset → <see cref="ObjectMotion"/> → the object's height → <see cref="Position"/>.
    /// </summary>
    public enum EffectStage
    {
        /// <summary>Before the estimator: decides whether this frame's pose may be followed.</summary>
        Input = 0,
        /// <summary>On the hand the weight reads (<see cref="MotionFrame.WeightHand"/>), after the estimator.</summary>
        HandMotion = 1,
        /// <summary>On the base the lift is measured from (<see cref="HoldState.Base"/>, <see cref="MotionFrame.Lift"/>).</summary>
        Base = 2,
        /// <summary>On how the lift becomes offset: the gain this frame (<see cref="MotionFrame.Gain"/>) and the lift it
        /// carries (<see cref="MotionFrame.CarriedLift"/>).</summary>
        Lift = 3,
        /// <summary>Folded into the gain G at configuration: costs nothing per frame.</summary>
        Gain = 4,
        /// <summary>On the weight's offset (<see cref="MotionFrame.Offset"/>) once the solver has computed it.</summary>
        ObjectMotion = 5,
        /// <summary>On the object's new height (<see cref="MotionFrame.NewObjectY"/>).</summary>
        Position = 6,
        /// <summary>Acts in <see cref="WeightSolver3D"/>, outside the y pipeline (x/z, the second hand, break-away):
        /// the y solver never calls it.</summary>
        Hold = 7,
    }
}
