namespace Kosmos.PseudoHaptic
{
    /// <summary>
    /// A hold in <see cref="WeightSolver3D"/> may have a second hand. The object follows the followed hands'
    /// midpoint, and while both hands hold, each carries <see cref="Share"/> of the mass (but never less than the
    /// standard weight, or the whole mass when it is lighter): every effect sees the per-hand mass, so a two-hand lift
    /// of m moves as a one-hand lift of max(m·share, min(m, 45 g)) at the midpoint. When one
    /// hand is lost or lets go the hold goes on with the other, the followed point re-anchored so nothing
    /// steps; a returning hand rejoins after the profile's tracking-loss settle time.
    /// Without this effect the second hand is ignored.
    /// </summary>
    public sealed class TwoHands : WeightEffect
    {
        public override string Name => "two-hands";
        public override EffectStage Stage => EffectStage.Hold;

        /// <summary>The share of the mass each hand carries while both hold, (0, 1].</summary>
        public double Share { get; }

        public TwoHands(double share = 0.5)
        {
            Share = ConfigurationGuard.InRange(share, 0.001, 1, nameof(share));
        }

        protected internal override void Apply(ref MotionFrame frame, ref HoldState state, in SolverConstants constants) { }
    }
}
