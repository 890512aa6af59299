using System;

namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// A person does not lift 5 kg as fast as a golf ball (design note, open question 2): the object's
    /// speed is capped at the experimental speed of its mass rescaled to this user,
    /// v_cap = headroom · v_std · v_exp(m)/v_exp(m_std). At the standard weight the cap is headroom · v_std,
    /// never below the user's standard speed; the default headroom 2.5 clears the peak of a smooth lift
    /// (1.875 × its mean speed) with room for the speed noise of jittery 60 Hz poses. Speed is judged over the pose's own interval, so 30 Hz poses under
    /// 120 Hz frames are not mistaken for fourfold spikes. Capped motion is lost: the object lags more.
    /// </summary>
    public sealed class SpeedCap : WeightEffect
    {
        public override string Name => "speed-cap";
        public override EffectStage Stage => EffectStage.ObjectMotion;

        /// <summary>Multiple of the user's rescaled experimental speed allowed, ≥ 1.</summary>
        public double Headroom { get; }

        public SpeedCap(double headroom = 2.5)
        {
            Headroom = ConfigurationGuard.InRange(headroom, 1, 100, nameof(headroom));
        }

        /// <summary>The cap for an object and a user, m/s.</summary>
        public double CapFor(WeightModel model, double standardSpeed) => Headroom * standardSpeed * model.ExperimentalRatio;

        protected internal override void Apply(ref MotionFrame frame, ref HoldState state, in SolverConstants constants)
        {
            // Over the pose's interval when a pose arrived; otherwise over the frame, for a hand filter that moves
            // the followed hand between poses.
            double window = frame.MotionInterval > 0 ? frame.MotionInterval : frame.Dt;
            if (window <= 0) return;
            double max = constants.CapSpeed * window;
            if (frame.ObjectDelta > max) frame.ObjectDelta = max;
            else if (frame.ObjectDelta < -max) frame.ObjectDelta = -max;
        }
    }
}
