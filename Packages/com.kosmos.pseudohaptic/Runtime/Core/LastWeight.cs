namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// The weight as the last frame computed it (the hand-motion, base, lift and object-motion stages' results) and the
    /// hand it was computed for. The weight is a function of where the hand is, so a frame that shows no new pose of the
    /// same hand (a 30 Hz pose held over 72–120 Hz frames) gets the same weight: when every effect of those stages says
    /// so (<see cref="WeightEffect.IsFunctionOfHand"/>), the solver copies it from here instead of calling them. Bit for
    /// bit the values the stages would compute again.
    /// </summary>
    internal struct LastWeight
    {
        bool _valid;
        long _hand, _base; // the followed hand (MotionFrame.HandAfter) the weight was computed for and the base as it left it, as bits (−0 is not +0)
        double _weightHand, _lift, _gain, _carriedLift, _offset, _offsetCeiling;

        /// <summary>This frame shows no new pose (nor the same pose taken again by the steady hand, which the base and the pace
        /// read), the hand is bit for bit the one the weight was computed for, and the base is as computing it left it (nothing
        /// else moved it since).</summary>
        public bool Holds(in MotionFrame f, double baseY)
            => _valid && !f.NewPose && !f.SteadyTaken && System.BitConverter.DoubleToInt64Bits(f.HandAfter) == _hand
               && System.BitConverter.DoubleToInt64Bits(baseY) == _base;

        /// <summary>The stages' results into this frame.</summary>
        /// <summary>The results kept are for this followed hand and base (a frame repeating them would get them).</summary>
        public bool IsFor(double hand, double baseY)
            => _valid && System.BitConverter.DoubleToInt64Bits(hand) == _hand && System.BitConverter.DoubleToInt64Bits(baseY) == _base;

        public void CopyTo(ref MotionFrame f)
        {
            f.WeightHand = _weightHand;
            f.Lift = _lift;
            f.Gain = _gain;
            f.CarriedLift = _carriedLift;
            f.Offset = _offset;
            f.OffsetCeiling = _offsetCeiling;
        }

        /// <summary>Keeps this frame's results, computed for the followed hand <paramref name="hand"/>, and the base
        /// <paramref name="baseY"/> as the stages left it.</summary>
        public void Keep(in MotionFrame f, double hand, double baseY)
        {
            _valid = true;
            _hand = System.BitConverter.DoubleToInt64Bits(hand);
            _base = System.BitConverter.DoubleToInt64Bits(baseY);
            _weightHand = f.WeightHand;
            _lift = f.Lift;
            _gain = f.Gain;
            _carriedLift = f.CarriedLift;
            _offset = f.Offset;
            _offsetCeiling = f.OffsetCeiling;
        }

        /// <summary>Nothing kept: the next frame computes the weight (a new hold, a re-anchoring, a new configuration).</summary>
        public void Forget() => _valid = false;
    }
}
